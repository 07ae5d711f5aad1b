"""GUI benchmark: frames per second of the main screen while a cycle runs, and cold start.

    QT_QPA_PLATFORM=offscreen .venv/bin/python benchmarks/gui_bench.py [--size 1024x768]

Cold start: wall time from launching a fresh Python process to the main screen painted with
the first machine snapshot (imports, QApplication, database, machine link, window, first
frame), measured by the parent process; target 2 s.

Frames per second: the real machine layer in-process on a simulated clock (1/30 s of machine
time per frame, as on the panel), a cycle running (homed, recipe selected, board loaded);
each frame is one poll of the snapshot, the update of the main screen and the paint of what
changed. Printed with and without the time spent simulating the machine (on the panel the
machine runs in its own process, so the GUI's own rate is the one that matters); target 30.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

COLD_START_CHILD = """
import os, sys, time
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
sys.path.insert(0, {root!r})
from pathlib import Path
from app.config import load_config
from app.data.database import Database
from app.machine.local_link import LocalMachineLink
from app.screens.application import create_main_window, ensure_application
from app.screens.screenshots import quiet_offscreen_noise
with quiet_offscreen_noise():
    app = ensure_application()
    db_path = Path({db!r})
    link = LocalMachineLink.create(load_config(), db_path, advance_per_poll_s=0.01)
    database = Database.open(db_path)
    window = create_main_window(link, database)
    window.resize({w}, {h})
    window.show()
    while window.poller.snapshot is None:
        window.poller.poll()
    app.processEvents()
    window.repaint()
    print("painted", flush=True)
    link.close()
"""


def cold_start_s(db_template: Path, size: tuple[int, int], runs: int) -> list[float]:
    times: list[float] = []
    for _ in range(runs):
        with tempfile.TemporaryDirectory() as tmp:
            db = Path(tmp) / "stave.db"
            shutil.copyfile(db_template, db)
            code = COLD_START_CHILD.format(root=str(ROOT), db=str(db), w=size[0], h=size[1])
            start = time.perf_counter()
            out = subprocess.run(
                [sys.executable, "-c", code], capture_output=True, text=True, check=True
            )
            elapsed = time.perf_counter() - start
            if "painted" not in out.stdout:
                raise RuntimeError(f"cold start child failed: {out.stderr}")
            times.append(elapsed)
    return times


def frames_per_second(db_template: Path, size: tuple[int, int], frames: int) -> dict[str, float]:
    from app.config import load_config
    from app.data.database import Database
    from app.machine.commands import Home, LoadBoard, SelectRecipe, Start
    from app.machine.local_link import LocalMachineLink
    from app.machine.states import CycleStep, MachineState
    from app.screens.application import create_main_window, ensure_application
    from app.screens.main_window import MainWindow
    from app.screens.screenshots import quiet_offscreen_noise

    with tempfile.TemporaryDirectory() as tmp, quiet_offscreen_noise():
        db_path = Path(tmp) / "stave.db"
        shutil.copyfile(db_template, db_path)
        app = ensure_application()
        link = LocalMachineLink.create(load_config(), db_path, advance_per_poll_s=0.1)
        database = Database.open(db_path)
        window = create_main_window(link, database)
        assert isinstance(window, MainWindow)
        window.poller.stop()
        window.resize(*size)
        window.show()

        def run_until(done: object, limit: int = 100_000) -> None:
            for _ in range(limit):
                window.poller.poll()
                app.processEvents()
                snapshot = window.poller.snapshot
                if snapshot is not None and done(snapshot):  # type: ignore[operator]
                    return
            raise RuntimeError("machine did not get there")

        run_until(lambda s: s.state is not MachineState.POWER_UP)
        if window.poller.snapshot is not None and not window.poller.snapshot.all_homed:
            link.send(Home())
            run_until(lambda s: s.state is MachineState.READY and s.all_homed)
        recipe_id = database.list_recipes()[0].id
        assert recipe_id is not None
        link.send(SelectRecipe(recipe_id))
        run_until(lambda s: s.recipe_id == recipe_id)
        link.send(Start())
        link.send(LoadBoard())
        run_until(lambda s: s.cycle.step is CycleStep.CUTTING_A)

        link.advance_per_poll_s = 1.0 / 30.0  # machine time as on the panel
        machine_s = 0.0
        frame_s: list[float] = []
        start = time.perf_counter()
        for _ in range(frames):
            t0 = time.perf_counter()
            snapshot = link.latest()  # the machine's share (another process on the panel)
            t1 = time.perf_counter()
            machine_s += t1 - t0
            if snapshot is not None:
                window.poller.snapshot = snapshot
                window.on_snapshot(snapshot)
            app.processEvents()  # paints what changed
            frame_s.append(time.perf_counter() - t1)
            if snapshot is not None and snapshot.state is not MachineState.AUTOMATIC:
                link.send(Start())
                link.send(LoadBoard())
        total = time.perf_counter() - start
        gui_s = total - machine_s

        # Worst case: the whole window repainted every frame.
        full: list[float] = []
        for _ in range(min(frames, 200)):
            t0 = time.perf_counter()
            snapshot = link.latest()
            t1 = time.perf_counter()
            if snapshot is not None:
                window.on_snapshot(snapshot)
            window.repaint()
            full.append(time.perf_counter() - t1)
        window.close()
        link.close()
        database.close()
    ordered = sorted(frame_s)
    return {
        "frames": float(frames),
        "fps_total": frames / total,
        "fps_gui": frames / gui_s,
        "frame_p50_ms": statistics.median(frame_s) * 1000,
        "frame_p99_ms": ordered[min(len(ordered) - 1, round(0.99 * (len(ordered) - 1)))] * 1000,
        "fps_full_repaint": len(full) / sum(full),
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="1024x768", help="window size WxH")
    parser.add_argument("--frames", type=int, default=600)
    parser.add_argument("--cold-runs", type=int, default=3)
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.lower().split("x"))
    from app.data.database import Database

    with tempfile.TemporaryDirectory() as tmp:
        template = Path(tmp) / "template.db"
        Database.open(template).close()
        fps = frames_per_second(template, (width, height), args.frames)
        cold = cold_start_s(template, (width, height), args.cold_runs)
    print(f"window {width}x{height}, main screen, cycle running ({int(fps['frames'])} frames)")
    print(f"  frames per second, GUI only (machine in its own process): {fps['fps_gui']:.0f}")
    print(f"  frames per second, GUI + simulated machine in-process:    {fps['fps_total']:.0f}")
    print(f"  GUI frame time p50 {fps['frame_p50_ms']:.1f} ms, p99 {fps['frame_p99_ms']:.1f} ms")
    print(f"  whole window repainted every frame: {fps['fps_full_repaint']:.0f} fps")
    print(
        f"cold start to the main screen: median {statistics.median(cold):.2f} s "
        f"(runs: {', '.join(f'{c:.2f}' for c in cold)})"
    )
    ok = fps["fps_gui"] >= 30 and statistics.median(cold) <= 2.0
    print("targets (30 fps, 2 s):", "met" if ok else "NOT met")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
