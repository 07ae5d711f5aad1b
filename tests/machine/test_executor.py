"""The path executor: exactly the plan at 100 %, override changes without a velocity jump
and within the limits, controlled stops along the path within the braking distance, hold
at 0 %, abort freezes, and the feedback checks name the axis and the violation."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.machine.executor import (
    REMAINING_CACHE_SIZE,
    ExecutorOutput,
    ExecutorState,
    PathExecutor,
)
from app.machine.planner.point_to_point import plan_point_to_point
from app.machine.planner.stave_plan import StavePlan
from app.machine.planner.trajectory import Phase
from tests.machine.planner.support import (
    LIMITS,
    PERIOD_S,
    assert_within_limits,
    plan,
)

PLAN: StavePlan = plan()
CUT_A = PLAN.phase_interval(Phase.CUT_A)
assert CUT_A is not None


def xyz(outputs: list[ExecutorOutput]) -> np.ndarray:
    return np.array([(o.x, o.y, o.z) for o in outputs])


def run(
    executor: PathExecutor,
    actions: dict[int, object],
    limit: int = 100_000,
) -> list[ExecutorOutput]:
    """Step until done or stopped, calling actions[k](executor) before step k."""
    outputs = [executor.last_output]
    for k in range(1, limit):
        action = actions.get(k)
        if action is not None:
            action(executor)  # type: ignore[operator]
        outputs.append(executor.step())
        if executor.done or executor.stopped:
            break
    return outputs


def test_at_100_percent_the_stream_is_the_plan() -> None:
    outputs = run(PathExecutor(PLAN, PERIOD_S), {})
    rows = PLAN.setpoints(PERIOD_S)
    assert len(outputs) == len(rows)
    assert np.abs(xyz(outputs) - rows[:, 1:]).max() < 1e-9
    assert outputs[-1].done and outputs[-1].xyz if False else outputs[-1].done
    assert (outputs[-1].x, outputs[-1].y, outputs[-1].z) == PLAN.end_xyz


def test_phases_and_cutting_flags_follow_the_plan() -> None:
    executor = PathExecutor(PLAN, PERIOD_S)
    seen = []
    for out in run(executor, {}):
        if not seen or seen[-1] is not out.phase:
            seen.append(out.phase)
        if out.cutting:
            assert out.phase in (Phase.CUT_A, Phase.CUT_B)
    assert seen == [Phase.APPROACH, Phase.CUT_A, Phase.REPOSITION, Phase.CUT_B, Phase.RETURN]


def test_elapsed_remaining_and_progress() -> None:
    executor = PathExecutor(PLAN, PERIOD_S)
    assert executor.remaining_s == pytest.approx(PLAN.duration_s)
    last_progress = executor.progress
    for k in range(1, 3000):
        executor.step()
        assert executor.elapsed_s == pytest.approx(k * PERIOD_S)
        assert executor.remaining_s == pytest.approx(PLAN.duration_s - k * PERIOD_S, abs=1e-6)
        assert executor.progress >= last_progress
        last_progress = executor.progress
    executor.set_override(50.0)
    slow = executor.remaining_s
    executor.set_override(100.0)
    assert slow > executor.remaining_s
    while not executor.done:
        executor.step()
    assert executor.progress == 1.0 and executor.remaining_s == 0.0


def test_a_knob_turned_through_many_overrides_keeps_only_a_few_cached_durations() -> None:
    """The remaining time is cached per override value; a knob turned through 40 values in
    one cut keeps the newest few, and a value dropped from the cache is worked out again."""
    executor = PathExecutor(PLAN, PERIOD_S)
    for _ in range(50):
        executor.step()
    remaining = []
    for k in range(40):
        executor.set_override(60.0 + k * 0.5)
        remaining.append(executor.remaining_s)
        assert len(executor._remaining_cache) <= REMAINING_CACHE_SIZE
    assert remaining == sorted(remaining, reverse=True)  # faster: less time left
    executor.set_override(60.0)
    assert executor.remaining_s == pytest.approx(remaining[0], rel=1e-9)


@settings(max_examples=15, deadline=None)
@given(
    changes=st.lists(
        st.tuples(st.integers(1, int(CUT_A[1] / PERIOD_S)), st.floats(0.0, 120.0)),
        min_size=1,
        max_size=4,
    )
)
def test_override_changes_keep_limits_path_and_continuity(changes) -> None:
    actions = {k: (lambda e, p=percent: e.set_override(p)) for k, percent in changes}
    last = max(k for k, _ in changes)
    actions[last + 1] = lambda e: e.set_override(100.0)  # never stay held
    outputs = run(PathExecutor(PLAN, PERIOD_S), actions)
    assert outputs[-1].done
    stream = xyz(outputs)
    # FD acceleration within its limit implies no velocity jump between two periods
    assert_within_limits(stream, step_times=())
    assert PLAN.distances_to_path(stream[:, 0], stream[:, 1]).max() < 1e-6


def test_override_scales_the_cutting_feed() -> None:
    executor = PathExecutor(PLAN, PERIOD_S)
    start = int((CUT_A[0] + CUT_A[1]) / 2 / PERIOD_S)
    outputs = run(executor, {start: lambda e: e.set_override(120.0)}, limit=start + 400)
    speed = math.hypot(outputs[-1].vx, outputs[-1].vy)
    assert speed == pytest.approx(1.2 * LIMITS.feed_mm_s, rel=1e-9)
    executor.set_override(37.5)
    for _ in range(400):
        out = executor.step()
    assert math.hypot(out.vx, out.vy) == pytest.approx(0.375 * LIMITS.feed_mm_s, rel=1e-9)


def test_zero_override_holds_on_the_path_and_resumes() -> None:
    executor = PathExecutor(PLAN, PERIOD_S)
    k_hold = int((CUT_A[0] + 3.0) / PERIOD_S)
    outputs = run(executor, {k_hold: lambda e: e.set_override(0.0)}, limit=k_hold + 300)
    assert executor.state is ExecutorState.HOLDING and not executor.stopped
    assert executor.remaining_s == math.inf
    assert outputs[-1] == outputs[-2]  # at rest
    executor.set_override(100.0)
    outputs += run(executor, {})
    assert outputs[-1].done
    stream = xyz(outputs)
    assert_within_limits(stream)
    assert PLAN.distances_to_path(stream[:, 0], stream[:, 1]).max() < 1e-6


@pytest.mark.parametrize(
    "when_s",
    [0.3, CUT_A[0] + 0.05, CUT_A[0] + 4.0, CUT_A[1] - 0.05, CUT_A[1] + 0.5, PLAN.duration_s - 0.2],
)
def test_controlled_stop_stays_on_the_path_and_stops(when_s: float) -> None:
    k_stop = int(when_s / PERIOD_S)
    executor = PathExecutor(PLAN, PERIOD_S)
    outputs = run(executor, {k_stop: lambda e: e.request_stop()})
    assert executor.stopped and not executor.done
    assert executor.state is ExecutorState.STOPPED and executor.remaining_s == 0.0
    stream = xyz(outputs)
    assert_within_limits(stream)
    assert PLAN.distances_to_path(stream[:, 0], stream[:, 1]).max() < 1e-6
    frozen = executor.step()
    assert frozen == outputs[-1] and executor.step() == frozen
    assert (frozen.vx, frozen.vy, frozen.vz) == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)


def test_a_stop_while_cutting_at_the_feed_takes_exactly_the_braking_distance() -> None:
    k_stop = int((CUT_A[0] + 4.0) / PERIOD_S)
    executor = PathExecutor(PLAN, PERIOD_S)
    outputs = run(executor, {k_stop: lambda e: e.request_stop()})
    before = outputs[k_stop - 1]
    v = LIMITS.feed_mm_s
    assert math.hypot(before.vx, before.vy) == pytest.approx(v)
    box = next(c.chunk.s_dof for c in PLAN.chunks if c.chunk.phase is Phase.CUT_A)
    assert box is not None
    # jerk-limited stop from cruise: v < A^2/J, so a = J t up then down, time 2 sqrt(v/J)
    assert v < box.acceleration**2 / box.jerk
    braking_mm = v * math.sqrt(v / box.jerk)
    travelled = float(np.sum(np.hypot(*np.diff(xyz(outputs[k_stop - 1 :])[:, :2], axis=0).T)))
    assert travelled == pytest.approx(braking_mm, rel=1e-6)
    periods = len(outputs) - k_stop
    assert periods == math.ceil(2 * math.sqrt(v / box.jerk) / PERIOD_S - 1e-9)


def test_stop_during_a_tilting_travel_keeps_the_tilt_between_its_ends() -> None:
    interval = PLAN.phase_interval(Phase.REPOSITION)
    assert interval is not None
    cross = next(
        c for c in PLAN.chunks if c.chunk.z_dof is not None and c.chunk.phase is Phase.REPOSITION
    )
    k = int((cross.t_start_s + cross.duration_s / 2) / PERIOD_S)
    executor = PathExecutor(PLAN, PERIOD_S)
    outputs = run(executor, {k: lambda e: e.request_stop()})
    z = xyz(outputs)[k:, 2]
    lo, hi = sorted((cross.chunk.z_start, cross.chunk.z_end))
    assert z.min() >= lo and z.max() <= hi
    assert executor.stopped


def test_abort_freezes_the_setpoint() -> None:
    executor = PathExecutor(PLAN, PERIOD_S)
    outputs = run(executor, {1000: lambda e: e.abort()})
    assert executor.aborted and executor.stopped and not executor.done
    assert outputs[-1] == outputs[-2]  # the step after abort repeats the last setpoint
    for _ in range(10):
        assert executor.step() == outputs[-1]
    executor.set_override(50.0)
    executor.request_stop()
    assert executor.step() == outputs[-1]


def test_a_point_to_point_move_runs_too() -> None:
    move = plan_point_to_point((0.0, 0.0, 0.0), (500.0, 300.0, 5.0), LIMITS)
    outputs = run(PathExecutor(move, PERIOD_S), {50: lambda e: e.set_override(30.0)})
    assert outputs[-1].done and (outputs[-1].x, outputs[-1].y, outputs[-1].z) == pytest.approx(
        (500.0, 300.0, 5.0)
    )
    assert_within_limits(xyz(outputs))


@pytest.mark.parametrize("bad", [-1.0, 120.5, math.nan, True])
def test_bad_override_is_refused_with_its_value(bad) -> None:
    with pytest.raises(ValueError, match="override percent"):
        PathExecutor(PLAN, PERIOD_S).set_override(bad)


@pytest.mark.parametrize("bad", [0.0, -0.004, math.inf])
def test_bad_period_is_refused(bad) -> None:
    with pytest.raises(ValueError, match="period_s"):
        PathExecutor(PLAN, bad)


def _trace(executor: PathExecutor, actions: dict[int, object] | None = None) -> list[tuple]:
    """(phase, x, y, phase to go, move to go, path velocity) before and after every step."""
    rows = []
    actions = actions or {}
    k = 0
    while True:
        out = executor.last_output
        rows.append(
            (
                out.phase,
                out.x,
                out.y,
                executor.phase_distance_to_go_mm,
                executor.distance_to_go_mm,
                executor.path_velocity_mm_s,
            )
        )
        if executor.done or executor.stopped:
            return rows
        k += 1
        action = actions.get(k)
        if action is not None:
            action(executor)  # type: ignore[operator]
        executor.step()


def test_distance_to_go_is_the_path_still_run_in_the_phase() -> None:
    rows = _trace(PathExecutor(PLAN, PERIOD_S))
    assert rows[-1][3] == 0.0 and rows[-1][4] == 0.0
    checked = 0
    for k in range(0, len(rows) - 1, 25):
        phase = rows[k][0]
        travelled = 0.0
        for a, b in itertools.pairwise(rows[k:]):
            if b[0] is not phase:
                break
            travelled += math.hypot(b[1] - a[1], b[2] - a[2])
        # The rest of the phase is travelled (chords of a path with radii of metres).
        assert rows[k][3] == pytest.approx(travelled, abs=0.05), (k, phase)
        assert rows[k][4] <= rows[k][3] + 1e-9
        checked += 1
    assert checked > 100


def test_path_velocity_is_the_speed_along_the_path() -> None:
    rows = _trace(PathExecutor(PLAN, PERIOD_S))
    for a, b in itertools.pairwise(rows):
        if a[0] is not b[0]:
            continue
        step_mm_s = math.hypot(b[1] - a[1], b[2] - a[2]) / PERIOD_S
        assert (a[5] + b[5]) / 2 == pytest.approx(step_mm_s, abs=0.5)
    cutting = max(r[5] for r in rows if r[0] is Phase.CUT_A)
    assert cutting > 1.0


def test_while_stopping_the_distance_to_go_is_the_way_to_rest() -> None:
    k_stop = int((CUT_A[0] + CUT_A[1]) / 2 / PERIOD_S)
    rows = _trace(PathExecutor(PLAN, PERIOD_S), {k_stop: PathExecutor.request_stop})
    at_stop = rows[k_stop]
    travelled = sum(
        math.hypot(b[1] - a[1], b[2] - a[2]) for a, b in itertools.pairwise(rows[k_stop:])
    )
    assert at_stop[4] == pytest.approx(travelled, abs=0.01)
    assert at_stop[3] == at_stop[4]
    assert rows[-1][4] == 0.0 and rows[-1][5] == pytest.approx(0.0, abs=1e-6)
