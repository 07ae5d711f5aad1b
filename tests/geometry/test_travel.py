"""The tool path against the axis travel: every point counts, arcs included."""

import pytest

from app.geometry.limits import StaveLimits
from app.geometry.profile import solve_profile
from app.geometry.toolpath import build_toolpath
from app.geometry.travel import check_toolpath_travel
from tests.geometry.strategies import DEFAULT_PARAMS


def toolpath_extremes():
    profile = solve_profile(1000.0, 150.0, 0.25, 0.75)
    path = build_toolpath(profile, DEFAULT_PARAMS)
    apex_y = max(s.bounds()[3] for s in path.segments)
    return path, apex_y


def test_travel_within_limits():
    path, apex_y = toolpath_extremes()
    limits = StaveLimits(
        x_min_mm=-5.0,
        x_max_mm=3900.0,
        y_min_mm=-5.0,
        y_max_mm=apex_y + 1e-3,
        z_min_deg=-15.0,
        z_max_deg=15.0,
    )
    assert check_toolpath_travel(path, limits) == []
    assert check_toolpath_travel(path, StaveLimits()) == []


def test_travel_counts_the_bulge_of_arcs():
    path, apex_y = toolpath_extremes()
    # The highest Y of the path is the top of side A's arc, not any segment end.
    assert apex_y > max(max(s.start[1], s.end[1]) for s in path.segments) + 1.0
    (error,) = check_toolpath_travel(path, StaveLimits(y_max_mm=apex_y - 1e-3))
    assert error.field == "y_mm"
    assert error.value == pytest.approx(apex_y)
    assert error.message.startswith(f"y_mm = {apex_y:.3f} is out of range: allowed -inf <= Y <=")


def test_travel_each_axis_bound():
    path, _ = toolpath_extremes()
    limits = StaveLimits(
        x_min_mm=10.0,
        x_max_mm=1000.0,
        y_min_mm=10.0,
        y_max_mm=450.0,
        z_min_deg=-3.0,
        z_max_deg=3.0,
    )
    errors = check_toolpath_travel(path, limits)
    assert [e.field for e in errors] == ["x_mm", "x_mm", "y_mm", "y_mm", "z_deg", "z_deg"]
    assert [e.value for e in errors][:2] == [0.0, 1190.0]
    assert errors[4].value == -3.5 and errors[5].value == 3.5
    assert errors[5].allowed == "-3 <= Z <= 3 deg"
