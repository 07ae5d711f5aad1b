"""The executor's waits before a cut (spindle and settling) and its end before the return."""

from __future__ import annotations

from dataclasses import replace

import pytest

from app.geometry.profile import solve_profile
from app.geometry.toolpath import build_toolpath
from app.machine.executor import ExecutorState, PathExecutor
from app.machine.planner.stave_plan import plan_stave
from app.machine.planner.trajectory import Phase
from tests.machine.planner.support import HOME, LIMITS, PERIOD_S, params, plan

PLAN = plan()


def _step_until_waiting(executor: PathExecutor, limit: int = 100_000) -> int:
    for k in range(limit):
        if executor.waiting:
            return k
        executor.step()
    raise AssertionError("never waited")


def test_it_waits_at_each_cut_until_released_and_skips_the_planned_dwell() -> None:
    executor = PathExecutor(PLAN, PERIOD_S, wait_before_cuts=True)
    _step_until_waiting(executor)
    held = executor.last_output
    assert held.phase is Phase.CUT_A and not held.cutting  # at the lead-in, not cutting yet
    for _ in range(500):  # held as long as nobody releases, at rest
        out = executor.step()
        assert (out.x, out.y, out.z, out.vx, out.vy) == (held.x, held.y, held.z, 0.0, 0.0)
    assert executor.dwelling and executor.state is ExecutorState.WAITING
    executor.release()
    assert executor.step().cutting
    _step_until_waiting(executor)
    assert executor.last_output.phase is Phase.CUT_B
    executor.release()
    while not executor.done:
        executor.step()
    # Two waits released at once: the planned time less the two planned dwells.
    interval = PLAN.phase_interval(Phase.CUT_A)
    assert interval is not None
    dwells_s = sum(c.chunk.dwell_s for c in PLAN.chunks)
    assert dwells_s > 0.0
    assert executor.elapsed_s == pytest.approx(
        PLAN.duration_s - dwells_s + 500 * PERIOD_S, abs=3 * PERIOD_S
    )


def test_a_stop_while_waiting_stops_at_once_and_release_does_nothing_after() -> None:
    executor = PathExecutor(PLAN, PERIOD_S, wait_before_cuts=True)
    _step_until_waiting(executor)
    executor.request_stop()
    assert executor.stopped
    executor.release()
    assert executor.state is ExecutorState.STOPPED


def test_without_waits_the_stream_is_the_plan_and_it_can_end_before_the_return() -> None:
    plain = PathExecutor(PLAN, PERIOD_S)
    short = PathExecutor(PLAN, PERIOD_S, end_before=Phase.RETURN)
    while not plain.done:
        plain.step()
    while not short.done:
        short.step()
    interval = PLAN.phase_interval(Phase.RETURN)
    assert interval is not None
    assert plain.elapsed_s == pytest.approx(PLAN.duration_s, abs=PERIOD_S)
    assert short.elapsed_s == pytest.approx(interval[0], abs=PERIOD_S)
    side_b_end = [c.chunk.end_xyz() for c in PLAN.chunks if c.chunk.phase is Phase.CUT_B][-1]
    end = short.last_output
    assert (end.x, end.y, end.z) == pytest.approx(side_b_end)


def test_with_two_passes_only_the_second_pass_of_side_b_is_the_last_cut() -> None:
    """The clamps may open once the cutter leaves the board in the last cut, never between
    two passes: the executor says when no cut follows."""
    profile = solve_profile(1000.0, 150.0, 0.25, 0.75)
    path = build_toolpath(profile, replace(params(), roughing_allowances_mm=(10.0,)))
    executor = PathExecutor(plan_stave(path, HOME, LIMITS), PERIOD_S, wait_before_cuts=True)
    last_flags: list[bool] = []
    cutting_b_runs = 0
    was_cutting_b = False
    while not executor.done:
        if executor.waiting:
            executor.release()
        out = executor.step()
        cutting_b = out.cutting and out.phase is Phase.CUT_B
        if cutting_b and not was_cutting_b:
            cutting_b_runs += 1
            last_flags.append(executor.in_last_cut)
        was_cutting_b = cutting_b
    assert cutting_b_runs == 2 and last_flags == [False, True]
