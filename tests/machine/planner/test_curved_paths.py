"""The planner on fitted curves: every axis's velocity, acceleration and jerk limit kept.

The only declared exceptions to the jerk limit are where a line meets an arc (the lead-in and
lead-out meeting the curve, as at line-arc-line's tangent points); between the arcs of a fitted
curve the path box keeps the curvature steps within the jerk limit.
"""

from __future__ import annotations

import numpy as np
import pytest

from app.data.dxf_profile import read_dxf_profile
from app.geometry.curved_profile import solve_side_profile
from app.geometry.profile_kinds import ProfileKind
from app.geometry.toolpath import build_toolpath
from app.machine.planner.chunk import CURVATURE_STEP_WINDOW_S, path_box
from app.machine.planner.limits import AxisLimits
from app.machine.planner.path import ArcPiece, Path
from app.machine.planner.stave_plan import plan_stave
from tests.data import dxf_drawings as drawings
from tests.machine.planner.support import LIMITS, PERIOD_S, assert_within_limits, params

CASES = {
    "parabola": (ProfileKind.PARABOLA, {}, None),
    "ellipse": (ProfileKind.ELLIPSE, {"semi_axis_ratio": 1.05}, None),
    "superellipse": (ProfileKind.SUPERELLIPSE, {"exponent": 10.0, "semi_axis_ratio": 1.05}, None),
    "drawn-spline": (ProfileKind.DRAWN, {}, drawings.spline),
    "drawn-lines-arcs": (ProfileKind.DRAWN, {}, drawings.lines_and_arc),
}


@pytest.fixture(scope="module", params=list(CASES), ids=list(CASES))
def curved(request):
    kind, values, drawing = CASES[request.param]
    shape = None if drawing is None else read_dxf_profile("side.dxf", drawing()).shape
    profile = solve_side_profile(kind, 1000.0, 150.0, 0.75, 0.25, values, shape)
    toolpath = build_toolpath(profile, params())
    start = (toolpath.params.home_x_mm, toolpath.params.home_y_mm, toolpath.params.home_z_deg)
    result = plan_stave(toolpath, start, LIMITS)
    return result, result.setpoints(PERIOD_S)


def test_setpoints_stay_within_every_axis_limit_on_curves(curved):
    result, rows = curved
    assert_within_limits(rows[:, 1:], step_times=result.curvature_step_times())


def test_setpoints_never_leave_the_fitted_tool_path(curved):
    result, rows = curved
    assert result.distances_to_path(rows[:, 1], rows[:, 2]).max() < 1e-6


def test_only_line_arc_meetings_are_declared_steps(curved):
    result, _ = curved
    lines_meeting_arcs = 4  # each lead-in and lead-out meets the curve
    if result.toolpath.profile.kind is ProfileKind.DRAWN:
        drawn_lines = sum(1 for s in result.toolpath.profile.edge("A") if not hasattr(s, "center"))
        lines_meeting_arcs += 4 * drawn_lines
    assert len(result.curvature_step_times()) <= lines_meeting_arcs


def test_a_curvature_step_between_arcs_caps_the_path_speed():
    axis = AxisLimits(velocity=400.0, acceleration=2000.0, jerk=20000.0)
    # A quarter turn left (radius 100) and then right (radius 50), tangent at (100, 100).
    first = ArcPiece.through((0.0, 0.0), (100.0, 100.0), (0.0, 100.0), False)
    second = ArcPiece.through((100.0, 100.0), (150.0, 150.0), (150.0, 100.0), True)
    joined = Path((first, second))
    step = joined.bounds().step
    assert max(step) == pytest.approx(1 / 100 + 1 / 50)
    box = path_box(joined.bounds(), axis, axis, 300.0, 300.0)
    expected = np.sqrt(axis.jerk * CURVATURE_STEP_WINDOW_S / (2 * max(step)))
    assert box.velocity_cap == pytest.approx(min(expected, box.velocity_cap))
    assert box.velocity_cap <= expected * (1 + 1e-12)
    alone = path_box(Path((first,)).bounds(), axis, axis, 300.0, 300.0)
    assert alone.velocity_cap > box.velocity_cap
