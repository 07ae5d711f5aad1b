"""The technician's simulation menu: inject and clear faults, put a board on the table, take
it off.

Why apart from the controller: these act on the simulated world only (through the objects
the sim backend offers in ``MachineBackend.extras``), never on a real machine; the
permission rules refuse them on any other backend, and here they do nothing if the world is
not there.
"""

from __future__ import annotations

from app.drivers.contracts import FaultInjector, MachineBackend
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

    def tick(self, part_present: bool) -> None:
        if self._pending_board is not None and not part_present:
            load = getattr(self._backend.extras.get("world"), "load_board", None)
            if callable(load):
                load(self._pending_board[0])
            self._pending_board = None
