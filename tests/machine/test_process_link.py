"""The machine in its own process: snapshots arrive, commands act, close is clean, and the
machine stops by itself when the operator application dies."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time
from dataclasses import replace
from pathlib import Path

from app.config import load_config
from app.machine import commands as cmd
from app.machine.process_link import ProcessMachineLink
from app.machine.states import MachineState


def wait_for(link: ProcessMachineLink, predicate, timeout_s: float = 20.0):  # type: ignore[no-untyped-def]
    end = time.monotonic() + timeout_s
    while time.monotonic() < end:
        snapshot = link.latest()
        if snapshot is not None and predicate(snapshot):
            return snapshot
        time.sleep(0.02)
    raise AssertionError(f"timed out; last snapshot state {link.latest() and link.latest().state}")


def test_snapshots_commands_and_clean_close(tmp_path: Path) -> None:
    config = load_config()
    axes = {n: replace(a, absolute_encoder=True) for n, a in config.axes.items()}
    link = ProcessMachineLink.start(
        replace(config, axes=axes), tmp_path / "stave.db", realtime_priority=False
    )
    try:
        first = wait_for(link, lambda s: s.state is MachineState.READY)
        assert first.backend == "sim" and len(first.axes) == 3
        link.send(cmd.EnterManual())
        wait_for(link, lambda s: s.state is MachineState.MANUAL)
        link.send(cmd.JogStep("X", 10.0))
        moved = wait_for(link, lambda s: s.axis("X").position > first.axis("X").position + 9.9)
        assert moved.seq > first.seq
    finally:
        link.close()
    assert not link.alive()
    assert link.lateness["periods"] > 10  # the loop reported its timing on the way out


def test_machine_stops_when_the_gui_process_dies(tmp_path: Path) -> None:
    """A parent that dies without closing the link: the machine process notices and ends."""
    script = textwrap.dedent(f"""
        import sys, time
        from pathlib import Path
        from app.config import load_config
        from app.machine.process_link import ProcessMachineLink
        link = ProcessMachineLink.start(load_config(), Path({str(tmp_path / "stave.db")!r}),
                                        realtime_priority=False)
        link.wait_for_snapshot(30.0)
        print(link._process.pid, flush=True)
        time.sleep(60)
    """)
    parent = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    try:
        machine_pid = int(parent.stdout.readline())  # type: ignore[union-attr]
        os.kill(parent.pid, signal.SIGKILL)
        parent.wait(10)
        end = time.monotonic() + 15
        while time.monotonic() < end:
            try:
                os.kill(machine_pid, 0)
            except ProcessLookupError:
                break
            time.sleep(0.05)
        else:
            os.kill(machine_pid, signal.SIGKILL)
            raise AssertionError("the machine process outlived the operator application")
    finally:
        if parent.poll() is None:
            parent.kill()
        parent.stdout.close()  # type: ignore[union-attr]


def test_previews_wait_in_a_bounded_queue_while_the_screens_are_behind(tmp_path: Path) -> None:
    """A screen process that hangs but stays alive reads nothing: the previews a recipe
    change makes do not pile up in the machine process, and the newest one still arrives
    once the screens read again."""
    config = load_config()
    axes = {n: replace(a, absolute_encoder=True) for n, a in config.axes.items()}
    link = ProcessMachineLink.start(
        replace(config, axes=axes), tmp_path / "stave.db", realtime_priority=False
    )
    try:
        wait_for(link, lambda s: s.state is MachineState.READY and s.plan_id != 0)
        for recipe_id in (2, 3, 4, 5, 6, 7) * 2:  # twelve previews; the screens read none
            link.send(cmd.SelectRecipe(recipe_id))
            time.sleep(0.1)
        time.sleep(0.5)
        assert link._plans_queue.qsize() <= 4
        newest = wait_for(link, lambda s: s.recipe_id == 7)
        end = time.monotonic() + 10.0
        while link.plan(newest.plan_id) is None and time.monotonic() < end:
            time.sleep(0.05)
        assert link.plan(newest.plan_id) is not None
    finally:
        link.close()
