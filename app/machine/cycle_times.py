"""Where the seconds of a cycle went: the time of each step, from Start to the clamps open.

Why finer than :class:`~app.machine.states.CycleStep`: the screen's step says what the
operator must know ("cutting side A" from the approach on), but finding the seconds to save
needs the approach apart from the cut, and the waits (for a board, for the axes to settle)
apart from the motion. Each period of the cycle is booked to exactly one timed step, so the
step times add up to the cycle time.

The steps (:class:`~app.machine.states.TimedStep`) live beside the cycle steps, a vocabulary
the screens may use too. The names are stable text: they are the keys of ``step_times_s`` in
``stave simulate --json`` and of the step times kept with each production record.
"""

from __future__ import annotations

from app.machine.planner.trajectory import Phase
from app.machine.states import CycleStep, TimedStep

_BY_CYCLE_STEP: dict[CycleStep, TimedStep] = {
    CycleStep.WAIT_FOR_PART: TimedStep.WAITING,
    CycleStep.CENTERING: TimedStep.CENTERING,
    CycleStep.CLAMPING: TimedStep.CLAMPING,
    CycleStep.MEASURING: TimedStep.MEASURING,
    CycleStep.STARTING_SPINDLE: TimedStep.SPINDLE,
    CycleStep.RETRACTING: TimedStep.RETRACTING,
    CycleStep.CUTTING_A: TimedStep.SIDE_A,
    CycleStep.REPOSITIONING: TimedStep.REPOSITIONING,
    CycleStep.CUTTING_B: TimedStep.SIDE_B,
    CycleStep.RETURNING: TimedStep.RETURN,
    CycleStep.UNCLAMPING: TimedStep.UNCLAMPING,
}

_BY_PHASE: dict[Phase, TimedStep] = {
    Phase.APPROACH: TimedStep.APPROACH,
    Phase.POINT_TO_POINT: TimedStep.APPROACH,
    Phase.CUT_A: TimedStep.SIDE_A,
    Phase.REPOSITION: TimedStep.REPOSITIONING,
    Phase.CUT_B: TimedStep.SIDE_B,
    Phase.RETURN: TimedStep.RETURN,
    Phase.RETRACT: TimedStep.RETRACTING,
}


def timed_step(step: CycleStep, phase: Phase | None, waiting: bool) -> TimedStep:
    """The timed step of one period: ``phase`` is the path's while the axes follow a plan,
    ``waiting`` True while they stand at rest on purpose (a dwell, a hold for a condition)."""
    if waiting:
        return TimedStep.WAITING
    if phase is not None:
        return _BY_PHASE[phase]
    return _BY_CYCLE_STEP[step]


class StepClock:
    """Adds up the periods of one cycle per timed step."""

    def __init__(self, started_s: float) -> None:
        self._last_s = started_s
        self._seconds: dict[TimedStep, float] = {}

    def book(self, now_s: float, step: TimedStep) -> None:
        """The time since the last call was spent in ``step``."""
        elapsed_s = max(now_s - self._last_s, 0.0)
        self._last_s = now_s
        self._seconds[step] = self._seconds.get(step, 0.0) + elapsed_s

    def seconds(self) -> dict[str, float]:
        """Step name -> seconds, in the order of :class:`TimedStep`, steps never entered left
        out."""
        return {s.value: self._seconds[s] for s in TimedStep if s in self._seconds}
