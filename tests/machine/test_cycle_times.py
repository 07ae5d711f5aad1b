"""Booking a cycle's periods to its timed steps."""

from __future__ import annotations

import pytest

from app.machine.cycle_times import StepClock, timed_step
from app.machine.planner.trajectory import Phase
from app.machine.states import CycleStep, TimedStep


@pytest.mark.parametrize(
    ("step", "phase", "waiting", "expected"),
    [
        (CycleStep.WAIT_FOR_PART, None, False, TimedStep.WAITING),
        (CycleStep.CENTERING, None, False, TimedStep.CENTERING),
        (CycleStep.STARTING_SPINDLE, None, False, TimedStep.SPINDLE),
        # "cutting side A" on the screen from the approach on; the approach is timed apart.
        (CycleStep.CUTTING_A, Phase.APPROACH, False, TimedStep.APPROACH),
        (CycleStep.CUTTING_A, Phase.CUT_A, False, TimedStep.SIDE_A),
        (CycleStep.CUTTING_A, Phase.APPROACH, True, TimedStep.WAITING),  # a hold at rest
        (CycleStep.REPOSITIONING, Phase.REPOSITION, False, TimedStep.REPOSITIONING),
        (CycleStep.RETURNING, Phase.RETURN, False, TimedStep.RETURN),
        (CycleStep.UNCLAMPING, None, False, TimedStep.UNCLAMPING),
    ],
)
def test_each_period_has_one_timed_step(
    step: CycleStep, phase: Phase | None, waiting: bool, expected: TimedStep
) -> None:
    assert timed_step(step, phase, waiting) is expected


def test_every_cycle_step_and_phase_has_a_timed_step() -> None:
    for step in CycleStep:
        timed_step(step, None, False)
    for phase in Phase:
        timed_step(CycleStep.CUTTING_A, phase, False)


def test_the_clock_adds_up_to_the_cycle_in_step_order() -> None:
    clock = StepClock(started_s=10.0)
    clock.book(10.8, TimedStep.CENTERING)
    clock.book(11.4, TimedStep.CLAMPING)
    clock.book(11.5, TimedStep.CENTERING)  # back to a step: added to it
    clock.book(11.5, TimedStep.SIDE_A)  # no time passed: booked as 0
    assert clock.seconds() == pytest.approx({"centering": 0.9, "clamping": 0.6, "side_a": 0.0})
    assert list(clock.seconds()) == ["centering", "clamping", "side_a"]
