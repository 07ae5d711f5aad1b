"""Point-to-point moves: at rest at both ends, exact target, X-Y on the straight line,
axes synchronised, limits kept."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from app.machine.planner.limits import AxisLimits, MotionLimits
from app.machine.planner.point_to_point import SAME_POSITION_MM, plan_point_to_point
from app.machine.planner.trajectory import Phase, PlannerError

from .support import LIMITS, PERIOD_S, assert_within_limits

positions = st.tuples(st.floats(-5.0, 3900.0), st.floats(-5.0, 800.0), st.floats(-15.0, 15.0))


@settings(max_examples=60, deadline=None)
@given(positions, positions)
@example((0.0, 0.0, 0.0), (1e-9, 1e-9, 0.0))  # per axis the same, 1.4e-9 apart in X-Y
def test_point_to_point_is_exact_synchronised_and_within_limits(start, target) -> None:
    if max(abs(a - b) for a, b in zip(start, target, strict=True)) <= SAME_POSITION_MM:
        with pytest.raises(PlannerError):
            plan_point_to_point(start, target, LIMITS)
        return
    move = plan_point_to_point(start, target, LIMITS)
    first, last = move.sample(0.0), move.sample(move.duration_s)
    assert first.xyz == pytest.approx(start, abs=1e-9)
    assert last.xyz == pytest.approx(target, abs=1e-9)
    assert (first.vx, first.vy, first.vz) == (0.0, 0.0, 0.0)
    assert (last.vx, last.vy, last.vz) == (0.0, 0.0, 0.0)
    assert first.phase is Phase.POINT_TO_POINT and not first.cutting
    rows = move.setpoints(PERIOD_S)
    assert_within_limits(rows[:, 1:])
    # X-Y on the straight line between the points
    d = np.array(target[:2]) - np.array(start[:2])
    if np.linalg.norm(d) > 1e-6:
        off = rows[:, 1:3] - np.array(start[:2])
        cross = (off[:, 0] * d[1] - off[:, 1] * d[0]) / np.linalg.norm(d)
        assert np.abs(cross).max() < 1e-6
        along = (off @ d) / np.linalg.norm(d) ** 2
        assert along.min() >= -1e-9 and along.max() <= 1 + 1e-9
    # synchronised: every axis that moves is still moving in the last few periods
    for axis in range(3):
        if abs(target[axis] - start[axis]) > 1e-3:
            moving = np.nonzero(np.abs(np.diff(rows[:, 1 + axis])) > 0.0)[0]
            assert moving[-1] * PERIOD_S >= move.duration_s - 3 * PERIOD_S


def test_a_long_move_reaches_the_limiting_axis_velocity() -> None:
    move = plan_point_to_point((0.0, 0.0, 0.0), (2000.0, 10.0, 0.0), LIMITS)
    speeds = [abs(move.sample(t).vx) for t in np.linspace(0, move.duration_s, 500)]
    assert max(speeds) == pytest.approx(LIMITS.x.velocity, rel=1e-6)


def test_a_tilt_only_move_keeps_x_y_still() -> None:
    move = plan_point_to_point((100.0, 200.0, 0.0), (100.0, 200.0, 12.0), LIMITS)
    rows = move.setpoints(PERIOD_S)
    assert np.all(rows[:, 1] == 100.0) and np.all(rows[:, 2] == 200.0)
    assert rows[-1, 3] == 12.0
    assert_within_limits(rows[:, 1:])


@pytest.mark.parametrize("bad", [(0.0, 0.0), (0.0, math.nan, 0.0), (0.0, 0.0, math.inf)])
def test_bad_positions_are_named(bad) -> None:
    with pytest.raises(PlannerError, match="start_xyz"):
        plan_point_to_point(bad, (1.0, 1.0, 1.0), LIMITS)


@pytest.mark.parametrize("start", [(-5.0, -5.0, -12.0), (-5.0, -5.0, 0.0)])
def test_a_move_exactly_on_a_ruckig_profile_boundary_is_planned(start) -> None:
    # 5*sqrt(2) mm at a = 1000*sqrt(2), j = 20000*sqrt(2) along the diagonal: the distance at
    # which the acceleration limit is just reached, where ruckig alone raises.
    limits = MotionLimits(
        AxisLimits(300.0, 1000.0, 20000.0), AxisLimits(300.0, 1000.0, 20000.0), LIMITS.z, 100.0
    )
    move = plan_point_to_point(start, (0.0, 0.0, 0.0), limits)
    assert move.sample(move.duration_s).xyz == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)
    assert_within_limits(move.setpoints(PERIOD_S)[:, 1:], limits)
