"""Executor lateness: how late each 4 ms period of the machine loop starts, measured in the
machine process, with the machine cutting staves on the simulated backend.

Two runs of ``--seconds`` each (default 60): the machine process alone, then the same with
the operator application in this process, showing the main screen and its live plan view
(offscreen Qt: the rendering work is real, only the pixels go nowhere).

    .venv/bin/python benchmarks/latency_bench.py [--seconds 60] [--period-ms 4]

Prints p50, p99 and max lateness in ms, the number of periods and the overruns (a period
started more than 5 periods late). Target: p99 at most 0.5 ms with the GUI running.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
from dataclasses import replace
from pathlib import Path

from app.config import MachineConfig, load_config
from app.machine import commands as cmd
from app.machine.process_link import ProcessMachineLink
from app.machine.snapshot import MachineSnapshot
from app.machine.states import MachineState


def bench_config(period_ms: float) -> MachineConfig:
    """The shipped machine with absolute encoders (no homing) and boards loaded by a
    simulated operator, so that cycles follow each other."""
    config = load_config()
    axes = {n: replace(a, absolute_encoder=True) for n, a in config.axes.items()}
    settings = {
        **config.backend_settings,
        "sim": {**config.backend_settings.get("sim", {}), "auto_load": True},
    }
    return replace(config, axes=axes, backend_settings=settings, period_s=period_ms / 1000.0)


def ready_to_start(snapshot: MachineSnapshot | None) -> bool:
    """READY, and Start allowed now (no refusal): the simulated operator presses Start."""
    return (
        snapshot is not None
        and snapshot.state is MachineState.READY
        and snapshot.allowed.get("Start") is None
    )


def keep_cutting(link: ProcessMachineLink) -> None:
    if ready_to_start(link.latest()):
        link.send(cmd.Start())


def run_alone(config: MachineConfig, db: Path, seconds: float) -> dict[str, float]:
    link = ProcessMachineLink.start(config, db)
    end = time.monotonic() + seconds
    while time.monotonic() < end and link.alive():
        keep_cutting(link)
        time.sleep(0.05)
    pieces = link.latest().pieces_total if link.latest() else 0
    link.close()
    return {**link.lateness, "pieces": float(pieces)}


def run_with_gui(config: MachineConfig, db: Path, seconds: float) -> dict[str, float]:
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from PySide6.QtCore import QTimer

    from app.data.database import Database
    from app.screens.application import create_main_window, ensure_application

    app = ensure_application()
    link = ProcessMachineLink.start(config, db)
    with Database.open(db) as database:
        window = create_main_window(link, database)
        window.resize(1024, 768)
        window.show()
        driver = QTimer()
        driver.timeout.connect(lambda: keep_cutting(link))
        driver.start(50)
        QTimer.singleShot(int(seconds * 1000), app.quit)
        app.exec()
        driver.stop()
        snapshot = link.latest()
        pieces = snapshot.pieces_total if snapshot else 0
        link.close()
        window.close()
    return {**link.lateness, "pieces": float(pieces)}


def show(name: str, stats: dict[str, float]) -> None:
    print(
        f"{name:<28} p50 {stats.get('p50_ms', float('nan')):6.3f} ms   "
        f"p99 {stats.get('p99_ms', float('nan')):6.3f} ms   "
        f"max {stats.get('max_ms', float('nan')):7.3f} ms   "
        f"periods {int(stats.get('periods', 0)):6d}   overruns {int(stats.get('overruns', 0))}"
        f"   staves cut {int(stats.get('pieces', 0))}"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--period-ms", type=float, default=4.0)
    args = parser.parse_args()
    config = bench_config(args.period_ms)
    print(
        f"executor lateness at {args.period_ms:g} ms, {args.seconds:g} s per run, "
        f"{os.cpu_count()} cores"
    )
    with tempfile.TemporaryDirectory() as tmp:
        show("machine process alone", run_alone(config, Path(tmp) / "a.db", args.seconds))
        show("with the operator GUI", run_with_gui(config, Path(tmp) / "b.db", args.seconds))


if __name__ == "__main__":
    main()
