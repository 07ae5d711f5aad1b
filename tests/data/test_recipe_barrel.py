"""Barrel types in the recipe: round, oval and fixed tilt, the fixed belly width; their checks,
their bevels, the row format and the database."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from app.data.database import Database
from app.data.errors import RecipeFormatError
from app.data.recipe import BarrelType, recipe_from_mapping, recipe_to_mapping
from app.data.users import Role, User
from app.geometry.barrel_section import BarrelSection, PlacedBarrelTilt
from app.geometry.bevel import SideTilts
from app.geometry.errors import GeometryError
from app.geometry.limits import DEFAULT_LIMITS

from .test_recipe import make_recipe

OVAL = make_recipe(
    name="Oval 700 x 500",
    barrel_type=BarrelType.OVAL,
    barrel_diameter_mm=700.0,
    barrel_minor_diameter_mm=500.0,
)


@pytest.mark.parametrize(
    ("row", "barrel_type"),
    [
        ({"tilt_mode": "fixed"}, BarrelType.FIXED_TILT),
        ({"tilt_mode": "barrel", "barrel_diameter_mm": "600"}, BarrelType.ROUND),
        (
            {"tilt_mode": "barrel", "barrel_diameter_mm": "700", "barrel_minor_diameter_mm": "500"},
            BarrelType.OVAL,
        ),
        ({"barrel_type": "round", "tilt_mode": "barrel", "barrel_diameter_mm": "600"}, None),
    ],
)
def test_a_file_written_before_the_barrel_type_still_reads(row, barrel_type) -> None:
    """Older files gave only tilt_mode; "barrel" with a short axis was an oval barrel."""
    base = recipe_to_mapping(make_recipe())
    del base["barrel_type"]
    recipe = recipe_from_mapping({**base, **row})
    assert recipe.barrel_type is (barrel_type or BarrelType.ROUND)
    assert recipe.validate() == []
    assert "tilt_mode" not in recipe_to_mapping(recipe)  # written as barrel_type only


def test_an_unknown_barrel_type_names_the_field_the_value_and_the_choices() -> None:
    base = recipe_to_mapping(make_recipe())
    with pytest.raises(RecipeFormatError) as caught:
        recipe_from_mapping({**base, "barrel_type": "square"})
    assert str(caught.value) == ("barrel_type = 'square' is unknown: allowed fixed, round or oval")


def test_a_round_barrel_is_never_made_oval_by_a_stray_short_axis() -> None:
    stray = replace(OVAL, barrel_type=BarrelType.ROUND)
    assert [e.field for e in stray.validate()] == ["barrel_minor_diameter_mm"]
    assert stray.barrel_section == BarrelSection(350.0, 350.0)


def test_barrel_types() -> None:
    assert make_recipe().barrel_type is BarrelType.FIXED_TILT
    round_recipe = make_recipe(barrel_type=BarrelType.ROUND, barrel_diameter_mm=600.0)
    assert round_recipe.barrel_type is BarrelType.ROUND
    assert round_recipe.barrel_section == BarrelSection(300.0, 300.0)
    assert OVAL.barrel_type is BarrelType.OVAL
    assert OVAL.barrel_section == BarrelSection(350.0, 250.0)
    assert make_recipe().barrel_section is None
    assert OVAL.validate() == []


def test_an_oval_recipe_bevels_the_first_stave_at_its_place() -> None:
    """The worked example's first stave: 100 mm from the end of the long axis."""
    assert OVAL.tilt_rule == PlacedBarrelTilt(BarrelSection(350.0, 250.0), 0.0)
    tilts = OVAL.tilt_rule.tilts_for_width(100.0, DEFAULT_LIMITS)
    assert tilts.a_deg == pytest.approx(15.6644, abs=5e-5)
    assert tilts.b_deg == pytest.approx(14.6323, abs=5e-5)


def test_a_placed_tilt_refuses_a_bevel_beyond_the_tilt_limits() -> None:
    rule = PlacedBarrelTilt(BarrelSection(350.0, 250.0), 0.0)
    with pytest.raises(GeometryError) as caught:
        rule.tilts_for_width(100.0, replace(DEFAULT_LIMITS, max_tilt_deg=15.0))
    assert caught.value.fields == ("tilt_a_deg",)
    assert "0 <= tilt <= 15 deg" in str(caught.value)
    with pytest.raises(GeometryError) as caught:
        rule.tilts_for_width(math.nan, DEFAULT_LIMITS)
    assert caught.value.fields == ("width_mm",)
    assert rule.tilts_for_width(100.0, DEFAULT_LIMITS) != SideTilts.both(15.6644)


@pytest.mark.parametrize(
    ("changes", "field", "text"),
    [
        ({"barrel_minor_diameter_mm": 800.0}, "barrel_minor_diameter_mm", "350 <= barrel_minor"),
        ({"barrel_minor_diameter_mm": 300.0}, "barrel_minor_diameter_mm", "<= barrel_diameter_mm"),
        ({"barrel_minor_diameter_mm": 100.0}, "barrel_minor_diameter_mm", "240 <="),
        ({"barrel_minor_diameter_mm": math.nan}, "barrel_minor_diameter_mm", "not a finite"),
        ({"barrel_type": BarrelType.FIXED_TILT}, "barrel_minor_diameter_mm", "fixed tilt"),
        ({"barrel_type": BarrelType.ROUND}, "barrel_minor_diameter_mm", "a round barrel"),
        ({"barrel_minor_diameter_mm": None}, "barrel_minor_diameter_mm", "oval barrel needs it"),
        ({"target_width_mm": 300.0}, "target_width_mm", "300 is out of range"),
        ({"target_width_mm": 70.0}, "target_width_mm", "the head would be 56.0 mm wide"),
    ],
)
def test_bad_barrel_values_name_the_field_value_and_range(changes, field, text) -> None:
    errors = replace(OVAL, **changes).validate()
    assert [e.field for e in errors] == [field]
    assert text in errors[0].message


def test_row_format_round_trip_and_unreadable_values() -> None:
    recipe = replace(OVAL, target_width_mm=120.0)
    row = recipe_to_mapping(recipe)
    assert row["barrel_minor_diameter_mm"] == 500.0 and row["target_width_mm"] == 120.0
    assert recipe_from_mapping(row) == recipe
    text_row = {key: ("" if value is None else str(value)) for key, value in row.items()}
    assert recipe_from_mapping(text_row) == recipe
    with pytest.raises(RecipeFormatError) as caught:
        recipe_from_mapping({**row, "barrel_minor_diameter_mm": "wide"})
    assert "barrel_minor_diameter_mm = 'wide' is not a finite number" in str(caught.value)


def test_the_database_keeps_the_barrel_fields(db: Database, users: dict[Role, User]) -> None:
    saved = db.save_recipe(replace(OVAL, target_width_mm=120.0), users[Role.OPERATOR])
    assert saved.id is not None
    assert db.get_recipe(saved.id) == saved
    assert saved.barrel_minor_diameter_mm == 500.0 and saved.target_width_mm == 120.0
    assert db.get_recipe(saved.id).barrel_type is BarrelType.OVAL
    round_again = replace(saved, barrel_type=BarrelType.ROUND, barrel_minor_diameter_mm=None)
    changed = db.save_recipe(round_again, users[Role.OPERATOR])
    assert db.get_recipe(saved.id).barrel_type is BarrelType.ROUND == changed.barrel_type
