"""What the machine records of its production: one piece record per board (cut, rejected
or aborted), the shift and total counters, the last width and cycle time.

Why apart from the controller: counting and recording is bookkeeping, not control; it reads
the finished cycle and writes to the store, and nothing in it decides what moves.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from datetime import datetime

from app.data.shifts import ShiftPlan, current_shift
from app.machine.cycle import AutomaticCycle
from app.machine.states import CycleStep
from app.machine.store import MachineStore, PieceRecord

KEPT_CYCLES = 10  # the last cycles kept for `stave simulate` and the tests to inspect
SHIFT_CHECK_S = 1.0  # how often (machine time) the counter looks whether a new shift began


def shift_start_s(params: Mapping[str, float], now_s: float) -> float:
    """The start (epoch seconds) of the shift of the plan (the ``production`` parameters)
    running at ``now_s`` in the machine's local time, or of the last one begun if none runs."""
    _number, start = current_shift(
        datetime.fromtimestamp(now_s).astimezone(), ShiftPlan.from_parameters(params)
    )
    return start.timestamp()


class Production:
    def __init__(self, store: MachineStore, wall_clock: Callable[[], float]) -> None:
        self._store = store
        self._wall_clock = wall_clock
        self.shift_start = wall_clock()
        self.pieces_shift, self.pieces_total = store.piece_counts(self.shift_start)
        self.last_width_mm: float | None = None
        self.last_cycle_time_s: float | None = None  # from Start, the wait for the board in
        self.last_wait_s: float | None = None  # of that, the wait for the board
        self.last_step_times_s: dict[str, float] = {}
        self.finished_cycles: list[tuple[PieceRecord, AutomaticCycle]] = []
        self._shift_params: dict[str, float] | None = None  # None: counting since power-up
        self.operator_name = ""  # who each record names (SetUser): the shift's operator
        # Shifts of the plan begun while the machine ran: the panel asks the new operator's
        # name at each one.
        self.plan_shifts_begun = 0

    def follow_shifts(self, params: Mapping[str, float]) -> None:
        """Count the pieces of the shift the plan says is running (those stored before a
        restart too), and start again at each new shift's start."""
        self._shift_params = dict(params)
        self._plan_start_s: float | None = None
        self._next_check_s = 0.0
        self._check_shift(recount_total=True)

    def tick(self, now_s: float) -> None:
        if self._shift_params is not None and now_s >= self._next_check_s:
            self._next_check_s = now_s + SHIFT_CHECK_S
            self._check_shift(recount_total=False)

    def _check_shift(self, *, recount_total: bool) -> None:
        assert self._shift_params is not None
        start = shift_start_s(self._shift_params, self._wall_clock())
        if start == self._plan_start_s:
            return
        if self._plan_start_s is not None:
            # The plan's next shift began: the last shift's operator no longer cuts here, so
            # no record of the new shift names him (the panel asks the new one's name).
            self.plan_shifts_begun += 1
            self.operator_name = ""
        self._plan_start_s = self.shift_start = start
        shift, total = self._store.piece_counts(start)
        self.pieces_shift = shift
        if recount_total:
            self.pieces_total = total

    def reset_shift(self) -> None:
        """The operator's New shift: counts from now until the plan's next shift begins."""
        self.shift_start = self._wall_clock()
        self.pieces_shift = 0

    def finished(self, cycle: AutomaticCycle, now_s: float) -> None:
        """A board cut (a resumed one too): counted, recorded, its width shown until the
        next one."""
        cycle_time_s = now_s - cycle.started_s
        self._record(cycle, cycle_time_s, "ok", None, resumed=cycle.is_continuation)
        self.pieces_shift += 1
        self.pieces_total += 1
        self.last_width_mm = cycle.outcome.width_mm
        self.last_cycle_time_s = cycle_time_s
        self.last_wait_s = cycle.waited_s(now_s)
        self.last_step_times_s = cycle.step_times_s()

    def aborted(self, cycle: AutomaticCycle, now_s: float, alarm: str | None) -> None:
        """A cycle ended before its board was cut: "rejected" if it was never planned (the
        width was refused), else "aborted"; nothing is recorded while no board was there."""
        if cycle.step is CycleStep.WAIT_FOR_PART:
            return
        result = "rejected" if cycle.planned is None else "aborted"
        self._record(cycle, now_s - cycle.started_s, result, alarm)

    def abandoned(self, cycle: AutomaticCycle, now_s: float, alarm: str | None) -> None:
        """A partly cut board taken clear of the cutter and given up."""
        self._record(cycle, now_s - cycle.started_s, "aborted", alarm)

    def _record(
        self,
        cycle: AutomaticCycle,
        cycle_time_s: float,
        result: str,
        alarm: str | None,
        resumed: bool = False,
    ) -> None:
        o = cycle.outcome
        placed = cycle.planned.barrel_stave if cycle.planned is not None else None
        piece = PieceRecord(
            self._wall_clock(),
            cycle.recipe.id,
            cycle.recipe.name,
            o.width_mm,
            o.d_mm,
            o.r_mm,
            o.tilt_deg,
            cycle_time_s,
            result,
            alarm,
            resumed,
            cycle.step_times_s(),
            None if placed is None else placed.barrel_number,
            None if placed is None else placed.number,
            self.operator_name,
        )
        self._store.record_piece(piece)
        self.finished_cycles.append((piece, cycle))
        del self.finished_cycles[:-KEPT_CYCLES]
