import math
from dataclasses import replace

import pytest
from hypothesis import given

from app.geometry.compare import (
    edge_deviation,
    profile_edge,
    slope_overcut_formula_mm,
    tangent_point_shift_mm,
)
from app.geometry.profile import solve_profile
from app.geometry.toolpath import build_original_toolpath, build_toolpath
from tests.geometry.strategies import DEFAULT_PARAMS, PROPERTY, stave_inputs

EXAMPLE = solve_profile(1000.0, 150.0, 0.25, 0.75)


def test_our_path_cuts_the_profile_exactly():
    path = build_toolpath(EXAMPLE, DEFAULT_PARAMS)
    for side in ("A", "B"):
        assert edge_deviation(path, side).max_abs_mm < 1e-9


def test_original_method_overcuts_the_slanted_sections_as_the_spec_says():
    original = build_original_toolpath(EXAMPLE, DEFAULT_PARAMS)
    ours = build_toolpath(EXAMPLE, DEFAULT_PARAMS)
    rc = DEFAULT_PARAMS.effective_radius_mm
    theta = EXAMPLE.slope_rad
    for side in ("A", "B"):
        deviation = edge_deviation(original, side)
        # Normal to the edge: rc * (1 - cos theta); across (in y): rc * (1/cos theta - 1).
        assert deviation.max_overcut_mm == pytest.approx(rc * (1 - math.cos(theta)), rel=1e-6)
        assert deviation.max_undercut_mm < 1e-9
    assert slope_overcut_formula_mm(EXAMPLE, rc) == pytest.approx(0.05008, abs=1e-5)
    # The tangent points move along X by rc * sin(theta), about 2 mm here.
    assert tangent_point_shift_mm(original, ours) == pytest.approx(rc * math.sin(theta), rel=1e-9)


@PROPERTY
@given(stave_inputs())
def test_our_edge_error_is_nil_over_the_range(stave):
    path = build_toolpath(stave.solve(), DEFAULT_PARAMS)
    assert edge_deviation(path, "A", samples_per_piece=40).max_abs_mm < 1e-6


def test_profile_edge_and_bad_arguments():
    assert [type(p).__name__ for p in profile_edge(EXAMPLE, "B")] == [
        "LineSegment",
        "ArcSegment",
        "LineSegment",
    ]
    with pytest.raises(ValueError, match="side must be"):
        profile_edge(EXAMPLE, "C")
    with pytest.raises(ValueError, match="samples_per_piece = 1 is out of range"):
        edge_deviation(build_toolpath(EXAMPLE, DEFAULT_PARAMS), "A", samples_per_piece=1)


def test_no_tilt_no_pivot_shift_still_compares():
    flat = replace(DEFAULT_PARAMS, tilt_deg=0.0)
    original = build_original_toolpath(EXAMPLE, flat)
    assert edge_deviation(original, "A").max_overcut_mm == pytest.approx(
        40 * (1 - math.cos(EXAMPLE.slope_rad)), rel=1e-6
    )
