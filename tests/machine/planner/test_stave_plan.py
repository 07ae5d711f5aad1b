"""The whole-stave plan: limits never exceeded, path never left, the cut at the feed without
a stop at the tangent points, tilt overlapped with travel, at rest at both ends."""

from __future__ import annotations

import itertools
import math
import pickle

import numpy as np
import pytest
from hypothesis import given, settings

from app.geometry.segments import ArcSegment, LineSegment
from app.geometry.toolpath import ToolPath, build_toolpath
from app.machine.planner.stave_plan import StavePlan, plan_stave
from app.machine.planner.trajectory import Phase, PlannerError, Trajectory
from tests.geometry.strategies import stave_inputs, toolpath_params

from .support import HOME, LIMITS, PERIOD_S, assert_within_limits, plan, toolpath

STAVES = {
    "short": (900.0, 100.0, 0.25, 0.7, 10.0),
    "medium": (2000.0, 200.0, 1 / 3, 0.6, 15.0),
    "long-wide": (3500.0, 280.0, 0.2, 0.5, 5.0),
    "all-arc": (1000.0, 150.0, 0.0, 0.75, 10.0),
    "short-arc": (900.0, 280.0, 0.45, 60 / 280, 30.0),
    "no-tilt": (1200.0, 150.0, 0.25, 0.75, 0.0),
}


@pytest.fixture(scope="module", params=list(STAVES), ids=list(STAVES))
def stave(request: pytest.FixtureRequest) -> tuple[StavePlan, np.ndarray]:
    length, width, lam, k, tilt = STAVES[request.param]
    result = plan(length, width, lam, k, tilt)
    return result, result.setpoints(PERIOD_S)


def test_the_plan_is_a_trajectory(stave: tuple[StavePlan, np.ndarray]) -> None:
    assert isinstance(stave[0], Trajectory)


def test_setpoint_stream_stays_within_every_axis_limit(stave) -> None:
    result, rows = stave
    assert_within_limits(rows[:, 1:], step_times=result.curvature_step_times())


def test_setpoints_and_chords_never_leave_the_tool_path(stave) -> None:
    result, rows = stave
    assert result.distances_to_path(rows[:, 1], rows[:, 2]).max() < 1e-6
    midpoints = (rows[1:, 1:3] + rows[:-1, 1:3]) / 2.0
    assert result.distances_to_path(midpoints[:, 0], midpoints[:, 1]).max() < 1e-3


def test_each_side_is_cut_at_the_feed_on_the_board_without_stopping(stave) -> None:
    result, _ = stave
    for side, phase in (("A", Phase.CUT_A), ("B", Phase.CUT_B)):
        segments = result.toolpath.side_segments(side)
        on_board = segments[1:-1]  # P1 .. P4 (lead-in and lead-out excluded)
        interval = result.phase_interval(phase)
        assert interval is not None
        speeds = []
        for t in np.arange(interval[0], interval[1], PERIOD_S / 2):
            sample = result.sample(float(t))
            assert sample.phase is phase
            if min(s.distance_to((sample.x, sample.y)) for s in on_board) < 1e-6:
                speeds.append(math.hypot(sample.vx, sample.vy))
        assert len(speeds) > 100
        assert np.allclose(speeds, LIMITS.feed_mm_s, rtol=1e-9)


def test_no_stop_at_the_tangent_points_p2_p3_p6_p7(stave) -> None:
    result, _ = stave
    steps = result.curvature_step_times()
    assert len(steps) == 4  # both ends of each side's arc (P2, P3, P6, P7)
    arc_ends = [
        p for s in result.toolpath.segments if isinstance(s, ArcSegment) for p in (s.start, s.end)
    ]
    for t in steps:
        sample = result.sample(t)
        assert min(math.dist(sample.xyz[:2], p) for p in arc_ends) < 1e-6
        assert math.hypot(sample.vx, sample.vy) == pytest.approx(LIMITS.feed_mm_s, rel=1e-9)


def test_tilt_is_constant_while_cutting(stave) -> None:
    result, rows = stave
    alpha = result.toolpath.params.tilt_deg
    for phase, tilt in ((Phase.CUT_A, alpha), (Phase.CUT_B, -alpha)):
        interval = result.phase_interval(phase)
        assert interval is not None
        inside = (rows[:, 0] >= interval[0]) & (rows[:, 0] <= interval[1])
        assert np.all(rows[inside, 3] == tilt)


def test_tilt_changes_while_travelling(stave) -> None:
    result, rows = stave
    if result.toolpath.params.tilt_deg == 0.0:
        assert np.all(rows[:, 3] == 0.0)  # nothing to tilt: Z never moves
        return
    interval = result.phase_interval(Phase.REPOSITION)
    assert interval is not None
    overlap = [
        s
        for s in (result.sample(float(t)) for t in np.arange(*interval, PERIOD_S))
        if abs(s.vz) > 1.0 and abs(s.vy) > 10.0
    ]
    assert overlap


def test_starts_and_ends_at_rest(stave) -> None:
    result, _ = stave
    first, last = result.sample(0.0), result.sample(result.duration_s)
    assert first.xyz == HOME and (first.vx, first.vy, first.vz) == (0.0, 0.0, 0.0)
    assert last.xyz == pytest.approx(HOME, abs=1e-12)
    assert (last.vx, last.vy, last.vz) == (0.0, 0.0, 0.0)
    assert result.sample(result.duration_s + 5.0).xyz == last.xyz
    assert result.sample(-1.0).xyz == first.xyz


def test_phases_follow_each_other(stave) -> None:
    result, _ = stave
    order = [Phase.APPROACH, Phase.CUT_A, Phase.REPOSITION, Phase.CUT_B, Phase.RETURN]
    intervals = [result.phase_interval(p) for p in order]
    spans = [i for i in intervals if i is not None]
    assert len(spans) == len(order)
    assert spans[0][0] == 0.0
    for before, after in itertools.pairwise(spans):
        assert before[1] == pytest.approx(after[0])
    assert spans[-1][1] == result.duration_s
    assert result.phase_interval(Phase.POINT_TO_POINT) is None


def test_cut_length_and_time(stave) -> None:
    result, _ = stave
    for side in ("A", "B"):
        length = result.cut_length_mm(side)
        assert length == pytest.approx(result.toolpath.cutting_length_mm(side), rel=1e-12)
        assert result.cut_time_s(side) > length / LIMITS.feed_mm_s
    with pytest.raises(ValueError, match="side = 'C'"):
        result.cut_time_s("C")


def test_a_start_away_from_home_prepends_a_move() -> None:
    start = (300.0, 50.0, -4.0)
    result = plan(start=start)
    assert result.chunks[0].chunk.phase is Phase.APPROACH
    assert result.sample(0.0).xyz == start
    rows = result.setpoints(PERIOD_S)
    assert_within_limits(rows[:, 1:], step_times=result.curvature_step_times())
    first_leg = result.chunks[0]
    t = np.arange(0.0, first_leg.t_end_s, PERIOD_S)
    xy = np.array([result.sample(float(x)).xyz[:2] for x in t])
    # the prepended move is the straight line from the start to the tool path's first point
    direction = np.array(HOME[:2]) - np.array(start[:2])
    offsets = xy - np.array(start[:2])
    cross = offsets[:, 0] * direction[1] - offsets[:, 1] * direction[0]
    assert np.abs(cross / np.linalg.norm(direction)).max() < 1e-9


def test_the_plan_survives_pickling() -> None:
    result = plan()
    copy = pickle.loads(pickle.dumps(result))
    for t in (0.0, 1.234, 7.5, result.duration_s):
        assert copy.sample(t) == result.sample(t)


def test_distance_to_path() -> None:
    result = plan()
    segment = result.toolpath.side_segments("A")[1]  # P1 -> P2
    mid = segment.point_at(segment.length_mm / 2)
    tx, ty = segment.tangent_at(0.0)
    assert result.distance_to_path(mid[0] - ty, mid[1] + tx) == pytest.approx(1.0, abs=1e-9)


def test_a_tool_path_with_a_gap_is_refused() -> None:
    path = toolpath()
    segments = list(path.segments)
    broken = segments[3]
    segments[3] = LineSegment(
        broken.start,
        (broken.end[0], broken.end[1] + 0.5),
        broken.z_start_deg,
        broken.z_end_deg,
        False,
        "",
    )
    with pytest.raises(PlannerError, match="does not start where"):
        plan_stave(ToolPath(tuple(segments), path.params, path.profile), HOME, LIMITS)


@settings(max_examples=12, deadline=None)
@given(stave_inputs(), toolpath_params())
def test_any_valid_stave_keeps_limits_and_path(stave_input, params) -> None:
    path = build_toolpath(stave_input.solve(), params)
    result = plan_stave(path, HOME, LIMITS)
    rows = result.setpoints(PERIOD_S)
    assert_within_limits(rows[:, 1:], step_times=result.curvature_step_times())
    assert result.distances_to_path(rows[:, 1], rows[:, 2]).max() < 1e-6
    for side in ("A", "B"):
        interval = result.phase_interval(Phase.CUT_A if side == "A" else Phase.CUT_B)
        assert interval is not None
        inside = (rows[:, 0] >= interval[0]) & (rows[:, 0] <= interval[1])
        tilt = params.tilt_deg if side == "A" else -params.tilt_deg
        assert np.all(rows[inside, 3] == tilt)
    assert rows[-1, 1:] == pytest.approx(HOME, abs=1e-9)


def test_the_axes_dwell_at_rest_at_each_lead_in_start() -> None:
    result = plan()
    for phase, side in ((Phase.CUT_A, "A"), (Phase.CUT_B, "B")):
        interval = result.phase_interval(phase)
        assert interval is not None
        start = result.toolpath.side_segments(side)[0].start
        for t in np.linspace(interval[0] - result.settle_s, interval[0], 11)[:-1]:
            sample = result.sample(float(t))
            assert sample.xyz[:2] == pytest.approx(start, abs=1e-12)
            assert (sample.vx, sample.vy, sample.vz) == (0.0, 0.0, 0.0)
            assert not sample.cutting
    without = plan_stave(toolpath(), HOME, LIMITS, settle_s=0.0)
    assert without.duration_s == pytest.approx(result.duration_s - 2 * result.settle_s)
    with pytest.raises(PlannerError, match="settle_s = -1"):
        plan_stave(toolpath(), HOME, LIMITS, settle_s=-1.0)
