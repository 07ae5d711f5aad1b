"""The bevel from a round barrel: asin(W / Db), its inverse, and what it refuses."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from app.geometry.barrel import RoundBarrelTilt, barrel_tilt_deg, barrel_width_errors
from app.geometry.bevel import FixedTilt, SideTilts
from app.geometry.errors import GeometryError
from app.geometry.limits import DEFAULT_LIMITS, StaveLimits, barrel_diameter_mm


def test_tilt_is_half_the_central_angle_of_the_stave() -> None:
    width = 110.0
    tilt = barrel_tilt_deg(width, 690.0, DEFAULT_LIMITS)
    assert tilt == pytest.approx(math.degrees(math.asin(width / 690.0)), abs=1e-12)
    # The inverse of the limits' barrel diameter for a width and a bevel.
    assert barrel_diameter_mm(width, tilt) == pytest.approx(690.0, rel=1e-12)


@pytest.mark.parametrize("staves", [24, 30, 32, 60])
def test_n_equal_staves_close_the_circle(staves: int) -> None:
    """n staves of chord W = Db*sin(180/n) are bevelled 180/n each: 2n bevels make 360 deg."""
    diameter = 700.0
    width = diameter * math.sin(math.pi / staves)
    assert 2 * staves * barrel_tilt_deg(width, diameter, DEFAULT_LIMITS) == pytest.approx(
        360.0, abs=1e-9
    )


def test_wider_boards_of_one_barrel_get_a_larger_tilt() -> None:
    tilts = [barrel_tilt_deg(w, 900.0, DEFAULT_LIMITS) for w in (80.0, 120.0, 160.0, 200.0)]
    assert tilts == sorted(tilts)
    assert len(set(tilts)) == 4


@pytest.mark.parametrize(
    ("width", "diameter", "limits", "field"),
    [
        (math.nan, 690.0, DEFAULT_LIMITS, "width_mm"),
        (math.inf, 690.0, DEFAULT_LIMITS, "width_mm"),
        (0.0, 690.0, DEFAULT_LIMITS, "width_mm"),
        ("150", 690.0, DEFAULT_LIMITS, "width_mm"),
        (700.0, 690.0, DEFAULT_LIMITS, "width_mm"),  # wider than the barrel
        (200.0, 690.0, replace(DEFAULT_LIMITS, max_tilt_deg=10.0), "tilt_deg"),  # 16.9 deg
        (150.0, None, DEFAULT_LIMITS, "barrel_diameter_mm"),
        (150.0, -5.0, DEFAULT_LIMITS, "barrel_diameter_mm"),
    ],
)
def test_computed_tilt_refuses_what_cannot_be_cut(
    width: object, diameter: float | None, limits: StaveLimits, field: str
) -> None:
    with pytest.raises(GeometryError) as caught:
        barrel_tilt_deg(width, diameter, limits)
    assert caught.value.fields == (field,)
    assert field in str(caught.value)


def test_a_barrel_too_small_for_any_board_of_a_recipe() -> None:
    # k = 4/5: boards from 75 mm; with tilt at most 10 deg, W <= 240 * sin 10 = 41.7 mm.
    limits = replace(DEFAULT_LIMITS, max_tilt_deg=10.0)
    (error,) = barrel_width_errors(240.0, 0.8, limits)
    assert error.field == "barrel_diameter_mm"
    assert "fits no board" in error.message
    assert barrel_width_errors(690.0, 0.8, limits) == []


def test_the_rules_bevel_both_sides_alike() -> None:
    assert RoundBarrelTilt(690.0).tilts_for_width(110.0, DEFAULT_LIMITS) == SideTilts.both(
        barrel_tilt_deg(110.0, 690.0, DEFAULT_LIMITS)
    )
    fixed = FixedTilt(7.5).tilts_for_width(280.0, DEFAULT_LIMITS)
    assert fixed == SideTilts(7.5, 7.5) and fixed.symmetric
    assert not SideTilts(7.5, 6.0).symmetric
