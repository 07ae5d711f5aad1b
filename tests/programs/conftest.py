"""Recipes across the machine's range and the parameters the program tests use."""

from __future__ import annotations

from dataclasses import replace

import pytest

from app.cli.solve import PROCESS_DEFAULTS
from app.data.dxf_profile import read_dxf_profile
from app.data.recipe import Recipe, recipe_from_mapping
from app.data.recipe_profile import RecipeProfile
from app.geometry.limits import StaveLimits
from app.geometry.profile_kinds import ProfileKind
from tests.data import dxf_drawings as drawings

# Lengths 900..3500 mm, length ratios 0..0.45, tilts 3..20 deg, and one barrel recipe.
RECIPE_ROWS = (
    {"name": "one arc 900", "length_mm": 900, "length_ratio": "0", "width_ratio": "3/4",
     "tilt_deg": 3},
    {"name": "worked example 1000", "length_mm": 1000, "length_ratio": "1/4",
     "width_ratio": "3/4", "tilt_deg": 4},
    {"name": "mid 1800", "length_mm": 1800, "length_ratio": "3/10", "width_ratio": "3/5",
     "tilt_deg": 8},
    {"name": "long straights 2500", "length_mm": 2500, "length_ratio": "9/20",
     "width_ratio": "4/5", "tilt_deg": 12},
    {"name": "vat 3500 (steep)", "length_mm": 3500, "length_ratio": "1/10",
     "width_ratio": "1/2", "tilt_deg": 20},
    {"name": "barrique barrel mode", "length_mm": 950, "length_ratio": "1/4",
     "width_ratio": "4/5", "tilt_mode": "barrel", "tilt_deg": 9.2,
     "barrel_diameter_mm": 690},
)  # fmt: skip

RECIPES: tuple[Recipe, ...] = tuple(
    recipe_from_mapping({"thickness_mm": 27, **row}) for row in RECIPE_ROWS
)

PARAMS: dict[str, float] = {**PROCESS_DEFAULTS, "xy_speed_mm_s": 120.0}

LIMITS = replace(
    StaveLimits(),
    x_min_mm=-10.0,
    x_max_mm=3900.0,
    y_min_mm=-10.0,
    y_max_mm=800.0,
    z_min_deg=-25.0,
    z_max_deg=25.0,
)


def curved_recipes() -> list[Recipe]:
    """A parabola and a drawn spline (with concave dips) on the worked example's recipe."""
    drawn = read_dxf_profile("dips.dxf", drawings.spline(drawings.DIPS_POINTS))
    profiles = (
        RecipeProfile(ProfileKind.PARABOLA),
        RecipeProfile(ProfileKind.DRAWN, (), drawn.shape, drawn.file_name, drawn.sha256),
    )
    return [replace(RECIPES[1], profile=profile) for profile in profiles]


@pytest.fixture(params=RECIPES, ids=[r.name for r in RECIPES])
def recipe(request: pytest.FixtureRequest) -> Recipe:
    value: Recipe = request.param
    return value
