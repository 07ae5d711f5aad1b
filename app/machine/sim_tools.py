"""The technician's simulation menu: inject and clear faults, put a board on the table, take
it off.

Why apart from the controller: these act on the simulated world only (through the objects
the sim backend offers in ``MachineBackend.extras``), never on a real machine; the
permission rules refuse them on any other backend, and here they do nothing if the world is
not there.
"""

from __future__ import annotations

from app.drivers.contracts import FaultInjector, MachineBackend
from app.machine import commands as cmd
from app.machine.refusals import Reason, Refusal, refusal


class SimulationTools:
    def __init__(self, backend: MachineBackend) -> None:
        self._backend = backend
        self._pending_board: tuple[float | None] | None = None

    def inject(self, kind: str, target: str) -> Refusal | None:
        """Inject a fault; returns why it was refused, or None."""
        injector = self._backend.extras.get("faults")
        if isinstance(injector, FaultInjector):
            try:
                injector.inject(kind, target)
            except ValueError as exc:
                return refusal(Reason.SIMULATION_REFUSED, exc)
        return None

    def clear(self) -> None:
        injector = self._backend.extras.get("faults")
        if isinstance(injector, FaultInjector):
            injector.clear_injections()

    def remove_board(self) -> None:
        """Take the board off (a finished piece, or one the operator does not want cut)."""
        remove = getattr(self._backend.extras.get("world"), "remove_board", None)
        if callable(remove):
            remove()
            self._pending_board = None

    def replace_board(self, width_mm: float | None) -> None:
        """Take the board off now and put a new one on once the part sensor has seen the
        table empty (see :meth:`tick`), as an operator would."""
        remove = getattr(self._backend.extras.get("world"), "remove_board", None)
        if callable(remove):
            remove()
            self._pending_board = (width_mm,)

    def handwheel(
        self, command: cmd.SelectHandwheel | cmd.TurnHandwheel | cmd.HoldJogEnable
    ) -> Refusal | None:
        """Work the simulated handwheel: its selector, a turn, its enable button."""
        wheel = getattr(self._backend.extras.get("world"), "handwheel", None)
        if wheel is None:
            return None
        try:
            match command:
                case cmd.SelectHandwheel(axis=axis, multiplier=multiplier):
                    wheel.select(axis, multiplier)
                case cmd.TurnHandwheel(counts=counts, rate_counts_s=rate):
                    wheel.turn(counts, rate)
                case cmd.HoldJogEnable(held=held):
                    wheel.enable = held
        except (ValueError, TypeError) as exc:
            return refusal(Reason.SIMULATION_REFUSED, exc)
        return None

    def push_joystick(self, x: float, y: float, z: float) -> Refusal | None:
        stick = getattr(self._backend.extras.get("world"), "joystick", None)
        if stick is None:
            return None
        try:
            stick.push(x, y, z)
        except (ValueError, TypeError) as exc:
            return refusal(Reason.SIMULATION_REFUSED, exc)
        return None

    def tick(self, part_present: bool) -> None:
        if self._pending_board is not None and not part_present:
            load = getattr(self._backend.extras.get("world"), "load_board", None)
            if callable(load):
                load(self._pending_board[0])
            self._pending_board = None
