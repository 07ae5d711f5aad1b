"""The machine in-process on a simulated clock, behind the same link the screens use.

Why: tests, ``--screenshots`` and demos on an office PC must drive the real machine layer
(state machine, cycle, planner, simulated drives) through the real screens, faster than real
time and reproducibly. Each ``latest()`` call advances the machine by ``advance_per_poll_s``
of machine time, so a screen polling at 25 Hz sees the machine run at that multiple.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from app.config import MachineConfig
from app.machine.commands import Command
from app.machine.controller import MachineController
from app.machine.runtime import MachineRuntime
from app.machine.snapshot import MachineSnapshot, PlanPreview


class LocalMachineLink:
    def __init__(self, runtime: MachineRuntime, advance_per_poll_s: float = 0.1) -> None:
        self.runtime = runtime
        self.advance_per_poll_s = advance_per_poll_s
        self._closed = False
        self._latest: MachineSnapshot | None = None

    @classmethod
    def create(
        cls, config: MachineConfig, db_path: Path, advance_per_poll_s: float = 0.1
    ) -> LocalMachineLink:
        runtime = MachineRuntime.create(config, db_path)
        runtime.start()
        return cls(runtime, advance_per_poll_s)

    @property
    def controller(self) -> MachineController:
        return self.runtime.controller

    def send(self, command: Command) -> None:
        if not self._closed:
            self.runtime.controller.post(command)

    def latest(self) -> MachineSnapshot | None:
        if not self._closed:
            if self.advance_per_poll_s > 0:
                self.runtime.run_for(self.advance_per_poll_s)
            self._latest = self.runtime.controller.snapshot()
        return self._latest

    def plan(self, plan_id: int) -> PlanPreview | None:
        return self.runtime.controller.plan_preview(plan_id)

    def alive(self) -> bool:
        return not self._closed

    def run_for(self, seconds: float) -> MachineSnapshot:
        self.runtime.run_for(seconds)
        self._latest = self.runtime.controller.snapshot()
        return self._latest

    def run_until(self, done: Callable[[MachineController], bool], timeout_s: float) -> bool:
        return self.runtime.run_until(done, timeout_s)

    def close(self) -> None:
        if not self._closed:
            self._closed = True
            self.runtime.shutdown()
