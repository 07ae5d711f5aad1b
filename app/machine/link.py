"""How a screen talks to the machine: post commands, read the latest snapshot.

Why a protocol with two implementations: on the panel the machine runs in its own process
(:class:`app.machine.process_link.ProcessMachineLink`) so that no GUI work can delay a
setpoint; in tests and in the command-line tools the same machine runs in-process on a
simulated clock (:class:`app.machine.local_link.LocalMachineLink`). The screens cannot tell
the difference, and none of these calls ever blocks.
"""

from __future__ import annotations

from typing import Protocol

from app.machine.commands import Command
from app.machine.snapshot import MachineSnapshot, PlanPreview


class MachineLink(Protocol):
    def send(self, command: Command) -> None:
        """Queue a command; returns at once."""

    def latest(self) -> MachineSnapshot | None:
        """The newest snapshot received so far (None before the first); returns at once."""

    def plan(self, plan_id: int) -> PlanPreview | None:
        """The tool path preview with that id, once it has arrived."""

    def alive(self) -> bool:
        """False once the machine has ended (or died: then the GUI shows it)."""

    def close(self) -> None:
        """Ask the machine to stop safely and wait for it to end."""
