"""The machine in its own OS process, joined to the GUI by a command queue and a snapshot
queue (the shape of LinuxCNC's motion/GUI split).

Why a process: measured on these machines, a 4 ms setpoint loop in a thread beside a Qt GUI
that plots at 30 fps is 6-9 ms late at p99 (the GIL); in its own process, 1.4 ms, and with
SCHED_FIFO where the system permits it, 0.05 ms. The GUI's rendering can never delay a
setpoint, and if the GUI dies the machine notices and stops safely.

Nothing here blocks the GUI: ``send`` puts on a queue, ``latest`` drains what has arrived.
The machine side never blocks on the GUI either: a full snapshot queue drops the snapshot.
"""

from __future__ import annotations

import concurrent.futures
import contextlib
import logging
import multiprocessing
import multiprocessing.queues
import os
import queue
import signal
import time
from pathlib import Path
from typing import Any

from app.config import MachineConfig
from app.machine.commands import Command, Shutdown
from app.machine.snapshot import MachineSnapshot, PlanPreview

log = logging.getLogger(__name__)

SNAPSHOT_PERIOD_S = 0.02  # 50 Hz to the screens
_SNAPSHOT_QUEUE_SIZE = 4
# Previews wait here for the screens, which keep only the newest: a hung screen process
# that stays alive must not let one preview a board pile up in the machine process.
_PLAN_QUEUE_SIZE = 4


def _try_realtime_priority() -> str:
    """SCHED_FIFO where permitted (root or CAP_SYS_NICE on the panel PC); else normal."""
    try:
        os.sched_setscheduler(0, os.SCHED_FIFO, os.sched_param(20))
        return "SCHED_FIFO"
    except (AttributeError, PermissionError, OSError):
        return "SCHED_OTHER"


def machine_process_main(
    config: MachineConfig,
    db_path: str,
    commands: multiprocessing.queues.Queue[Any],
    snapshots: multiprocessing.queues.Queue[Any],
    plans: multiprocessing.queues.Queue[Any],
    parent_pid: int,
    realtime_priority: bool = True,
) -> None:
    """Entry point of the machine process."""
    from app.logging_setup import setup_logging
    from app.machine.runtime import MachineRuntime

    setup_logging(config.log_dir, config.log_level, console=False, file_name="machine.log")
    policy = _try_realtime_priority() if realtime_priority else "SCHED_OTHER"
    planner_pool = concurrent.futures.ThreadPoolExecutor(
        max_workers=1, thread_name_prefix="planner"
    )
    runtime = MachineRuntime.create(
        config, Path(db_path), threaded_store=True, submit=planner_pool.submit
    )
    log.info("machine process started (%s, period %.1f ms)", policy, config.period_s * 1e3)
    runtime.start()
    controller = runtime.controller
    running = True

    def stop_on_signal(_signum: int, _frame: object) -> None:
        # systemd stops the whole service with SIGTERM: end the loop, then the normal
        # shutdown switches the spindle off and disables the drives.
        nonlocal running
        running = False

    signal.signal(signal.SIGTERM, stop_on_signal)
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl+C goes to the GUI, which closes us
    last_publish = 0.0
    published_plan = 0

    def between() -> None:
        nonlocal running, last_publish, published_plan
        while True:
            try:
                command = commands.get_nowait()
            except queue.Empty:
                break
            if isinstance(command, Shutdown):
                running = False
            else:
                controller.post(command)
        now = time.monotonic()
        if now - last_publish >= SNAPSHOT_PERIOD_S:
            last_publish = now
            snapshot = controller.snapshot()
            with contextlib.suppress(queue.Full):
                snapshots.put_nowait(snapshot)
            if snapshot.plan_id != published_plan:
                preview = controller.plan_preview(snapshot.plan_id)
                try:
                    if preview is not None:
                        plans.put_nowait(preview)
                    published_plan = snapshot.plan_id
                except queue.Full:
                    pass  # the screens are behind (or hung): offered again next time
            if os.getppid() != parent_pid:
                log.error("the operator application is gone: stopping the machine")
                running = False

    try:
        runtime.run_realtime(lambda: running, between)
    except Exception:
        log.exception("machine loop failed")
        raise
    finally:
        stats = runtime.lateness.summary()
        log.info("machine loop lateness: %s", stats)
        runtime.shutdown()
        planner_pool.shutdown(wait=False, cancel_futures=True)
        with contextlib.suppress(queue.Full):
            snapshots.put_nowait(("lateness", stats))


class ProcessMachineLink:
    def __init__(
        self,
        process: multiprocessing.process.BaseProcess,
        commands: multiprocessing.queues.Queue[Any],
        snapshots: multiprocessing.queues.Queue[Any],
        plans: multiprocessing.queues.Queue[Any],
    ) -> None:
        self._process = process
        self._commands = commands
        self._snapshots = snapshots
        self._plans_queue = plans
        self._latest: MachineSnapshot | None = None
        self._plans: dict[int, PlanPreview] = {}
        self.lateness: dict[str, float] = {}
        self._closed = False

    @classmethod
    def start(
        cls, config: MachineConfig, db_path: Path, realtime_priority: bool = True
    ) -> ProcessMachineLink:
        context = multiprocessing.get_context("spawn")
        commands: multiprocessing.queues.Queue[Any] = context.Queue()
        snapshots: multiprocessing.queues.Queue[Any] = context.Queue(_SNAPSHOT_QUEUE_SIZE)
        plans: multiprocessing.queues.Queue[Any] = context.Queue(_PLAN_QUEUE_SIZE)
        process = context.Process(
            target=machine_process_main,
            name="machine",
            args=(config, str(db_path), commands, snapshots, plans, os.getpid(), realtime_priority),
            daemon=True,
        )
        process.start()
        return cls(process, commands, snapshots, plans)

    def send(self, command: Command) -> None:
        if not self._closed and self._process.is_alive():
            self._commands.put_nowait(command)

    def latest(self) -> MachineSnapshot | None:
        if self._closed:
            return self._latest
        while True:
            try:
                item = self._snapshots.get_nowait()
            except queue.Empty:
                break
            if isinstance(item, MachineSnapshot):
                self._latest = item
            elif isinstance(item, tuple) and item[0] == "lateness":
                self.lateness = item[1]
        while True:
            try:
                preview = self._plans_queue.get_nowait()
            except queue.Empty:
                break
            self._plans = {preview.plan_id: preview}
        return self._latest

    def plan(self, plan_id: int) -> PlanPreview | None:
        self.latest()
        return self._plans.get(plan_id)

    def alive(self) -> bool:
        return self._process.is_alive()

    def wait_for_snapshot(self, timeout_s: float) -> MachineSnapshot | None:
        """For tools and tests only (it waits): the first snapshot, or None on timeout."""
        end = time.monotonic() + timeout_s
        while time.monotonic() < end and self.alive():
            snapshot = self.latest()
            if snapshot is not None:
                return snapshot
            time.sleep(0.01)
        return self.latest()

    def close(self, timeout_s: float = 5.0) -> None:
        """Ask the machine to stop safely and wait for it; safe to call more than once."""
        if self._closed:
            return
        if self._process.is_alive():
            with contextlib.suppress(ValueError, OSError):
                self._commands.put_nowait(Shutdown())
            self._process.join(timeout_s)
            if self._process.is_alive():
                log.error("machine process did not stop in %.0f s: terminating", timeout_s)
                self._process.terminate()
                self._process.join(timeout_s)
        self.latest()
        self._closed = True
        for q in (self._commands, self._snapshots, self._plans_queue):
            q.close()
            q.cancel_join_thread()
