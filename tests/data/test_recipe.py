"""The recipe model: validation (the geometry's and the recipe's own), the computed tilt, the
row format, and the shipped sample recipes."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.data.database import sample_recipes_path
from app.data.errors import RecipeFormatError
from app.data.recipe import (
    NAME_MAX_CHARS,
    ROW_KEYS,
    BarrelType,
    Recipe,
    TiltMode,
    recipe_from_mapping,
    recipe_to_mapping,
)
from app.data.recipe_files import load_recipe_file
from app.geometry.barrel import RoundBarrelTilt, barrel_tilt_deg
from app.geometry.bevel import FixedTilt
from app.geometry.errors import GeometryError
from app.geometry.limits import DEFAULT_LIMITS, StaveLimits
from app.geometry.ratio import Ratio
from app.geometry.stave_cut import StaveSpec


def make_recipe(**changes: object) -> Recipe:
    base = Recipe(
        id=None,
        name="Barrique test",
        length_mm=950.0,
        thickness_mm=27.0,
        length_ratio=Ratio(1, 4),
        width_ratio=Ratio(4, 5),
        barrel_type=BarrelType.FIXED_TILT,
        tilt_deg=9.0,
        barrel_diameter_mm=None,
        barrel_perimeter_mm=None,
    )
    return replace(base, **changes)  # type: ignore[arg-type]


def tilt_for_width(recipe: Recipe, width_mm: float) -> float:
    tilts = recipe.tilt_rule.tilts_for_width(width_mm, DEFAULT_LIMITS)
    assert tilts.symmetric
    return tilts.a_deg


def fields(recipe: Recipe, limits: StaveLimits | None = None) -> set[str]:
    return {error.field for error in recipe.validate(limits)}


def test_a_valid_recipe_has_no_errors() -> None:
    assert make_recipe().validate() == []
    assert make_recipe(barrel_type=BarrelType.ROUND, barrel_diameter_mm=690.0).validate() == []


def test_ratio_decimals_are_derived_from_the_fractions() -> None:
    recipe = make_recipe(length_ratio=Ratio(2, 8), width_ratio=Ratio(3, 4))
    assert recipe.length_ratio_decimal == 0.25
    assert recipe.width_ratio_decimal == 0.75
    assert str(recipe.length_ratio) == "2/8"  # kept as entered


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"length_mm": 899.0}, "length_mm"),
        ({"length_mm": 3501.0}, "length_mm"),
        ({"length_mm": math.nan}, "length_mm"),
        ({"thickness_mm": 24.0}, "thickness_mm"),
        ({"thickness_mm": 91.0}, "thickness_mm"),
        ({"length_ratio": Ratio(1, 2)}, "length_ratio"),
        ({"width_ratio": Ratio(1, 1)}, "width_ratio"),
        ({"width_ratio": Ratio(1, 5)}, "width_ratio"),  # head < 60 mm even on a 280 mm board
        ({"tilt_deg": 46.0}, "tilt_deg"),
        ({"tilt_deg": 0.0}, "tilt_deg"),  # fits no barrel diameter within 240..4500 mm
        ({"name": ""}, "name"),
        ({"name": "   "}, "name"),
        ({"name": " padded"}, "name"),
        ({"name": "x" * (NAME_MAX_CHARS + 1)}, "name"),
        ({"name": "line\nbreak"}, "name"),
        ({"note": "n" * 501}, "note"),
        ({"barrel_type": BarrelType.ROUND}, "barrel_diameter_mm"),  # a barrel needs it
        ({"barrel_type": "square"}, "barrel_type"),
        ({"barrel_diameter_mm": 239.0}, "barrel_diameter_mm"),
        ({"barrel_diameter_mm": 4501.0}, "barrel_diameter_mm"),
        ({"barrel_perimeter_mm": 100.0}, "barrel_perimeter_mm"),
        ({"barrel_perimeter_mm": math.inf}, "barrel_perimeter_mm"),
    ],
)
def test_each_invalid_field_is_named(changes: dict[str, object], field: str) -> None:
    recipe = make_recipe(**changes)
    errors = recipe.validate()
    assert field in {error.field for error in errors}
    for error in errors:
        assert error.field in error.message  # each message names its field ...
        assert error.allowed  # ... and what is allowed


def test_every_problem_is_reported_at_once() -> None:
    recipe = make_recipe(name="", length_mm=10.0, thickness_mm=200.0, width_ratio=Ratio(1, 1))
    assert {"name", "length_mm", "thickness_mm", "width_ratio"} <= fields(recipe)


def test_the_name_limit_is_inclusive() -> None:
    assert make_recipe(name="x" * NAME_MAX_CHARS).validate() == []


def test_a_barrel_too_small_for_any_board_of_the_recipe_is_refused() -> None:
    # k = 4/5: boards from 75 mm; with tilt at most 10 deg, W <= 240 * sin 10 = 41.7 mm.
    limits = replace(DEFAULT_LIMITS, max_tilt_deg=10.0)
    recipe = make_recipe(barrel_type=BarrelType.ROUND, barrel_diameter_mm=240.0, tilt_deg=9.0)
    assert "barrel_diameter_mm" in fields(recipe, limits)
    assert "barrel_diameter_mm" not in fields(replace(recipe, barrel_diameter_mm=690.0), limits)


# ----------------------------------------------------------------------------- computed tilt


def test_fixed_mode_uses_the_recipe_tilt_for_every_width() -> None:
    recipe = make_recipe(tilt_deg=7.5, barrel_diameter_mm=690.0)
    assert recipe.tilt_rule == FixedTilt(7.5)
    assert tilt_for_width(recipe, 90.0) == tilt_for_width(recipe, 150.0) == 7.5


def test_barrel_mode_bevels_each_board_for_the_barrel() -> None:
    recipe = make_recipe(barrel_type=BarrelType.ROUND, barrel_diameter_mm=690.0)
    assert recipe.tilt_rule == RoundBarrelTilt(690.0)
    assert tilt_for_width(recipe, 110.0) == barrel_tilt_deg(110.0, 690.0, DEFAULT_LIMITS)


def test_the_stave_the_geometry_cuts_carries_the_recipe() -> None:
    recipe = make_recipe(barrel_type=BarrelType.ROUND, barrel_diameter_mm=690.0)
    assert recipe.stave == StaveSpec(950.0, 27.0, 0.25, 0.8, RoundBarrelTilt(690.0))


def test_a_barrel_recipe_without_its_diameter_names_the_field_for_every_width() -> None:
    recipe = make_recipe(barrel_type=BarrelType.ROUND, barrel_diameter_mm=None)
    with pytest.raises(GeometryError) as caught:
        tilt_for_width(recipe, 150.0)
    assert caught.value.fields == ("barrel_diameter_mm",)


# ----------------------------------------------------------------------------- row format


def good_row(**changes: object) -> dict[str, object]:
    row: dict[str, object] = {
        "name": "Barrique",
        "length_mm": "950",
        "thickness_mm": "27",
        "length_ratio": "1/4",
        "width_ratio": "0.8",
        "tilt_deg": "9",
    }
    row.update(changes)
    return row


def test_a_row_of_text_is_read() -> None:
    recipe = recipe_from_mapping(good_row(barrel_type=" Round ", barrel_diameter_mm="690"))
    assert recipe.id is None
    assert recipe.length_mm == 950.0
    assert recipe.width_ratio == Ratio(4, 5)  # the decimal became the nearest fraction
    assert recipe.barrel_type is BarrelType.ROUND
    assert recipe.tilt_mode is TiltMode.BARREL
    assert recipe.barrel_diameter_mm == 690.0
    assert recipe.barrel_perimeter_mm is None  # optional, absent
    assert recipe.note == ""


def test_a_json_row_with_numbers_is_read() -> None:
    row = good_row(length_mm=950, thickness_mm=27.5, length_ratio=0.25, width_ratio=0.75)
    recipe = recipe_from_mapping(row)
    assert (recipe.thickness_mm, recipe.length_ratio, recipe.width_ratio) == (
        27.5,
        Ratio(1, 4),
        Ratio(3, 4),
    )
    assert recipe.barrel_type is BarrelType.FIXED_TILT  # the default
    assert recipe.tilt_mode is TiltMode.FIXED


@pytest.mark.parametrize(
    ("changes", "key"),
    [
        ({"name": None}, "name"),
        ({"length_mm": ""}, "length_mm"),
        ({"length_mm": "nine hundred"}, "length_mm"),
        ({"thickness_mm": True}, "thickness_mm"),
        ({"tilt_deg": "nan"}, "tilt_deg"),
        ({"length_ratio": "3/0"}, "length_ratio"),
        ({"width_ratio": "-1/2"}, "width_ratio"),
        ({"width_ratio": [3, 4]}, "width_ratio"),
        ({"tilt_mode": "round"}, "tilt_mode"),
        ({"barrel_type": "square"}, "barrel_type"),
        ({"barrel_type": 3}, "barrel_type"),
        ({"barrel_type": "oval", "tilt_mode": "fixed"}, "tilt_mode"),  # contradicting
        ({"barrel_diameter_mm": "wide"}, "barrel_diameter_mm"),
        ({"lenght_mm": "950"}, "lenght_mm"),  # a typo is an unknown key, not silently ignored
        ({"note": 5}, "note"),
    ],
)
def test_a_bad_row_names_the_key(changes: dict[str, object], key: str) -> None:
    with pytest.raises(RecipeFormatError) as caught:
        recipe_from_mapping(good_row(**changes))
    assert key in {error.field for error in caught.value.errors}
    assert key in str(caught.value)


def test_a_missing_key_is_named() -> None:
    row = good_row()
    del row["width_ratio"]
    with pytest.raises(RecipeFormatError, match="width_ratio is missing"):
        recipe_from_mapping(row)


def test_an_id_in_a_row_is_ignored() -> None:
    assert recipe_from_mapping(good_row(id=42)).id is None


def test_to_mapping_writes_the_row_keys_in_order() -> None:
    mapping = recipe_to_mapping(make_recipe(id=7, length_ratio=Ratio(2, 8)))
    assert tuple(mapping) == ROW_KEYS
    assert mapping["length_ratio"] == "2/8"
    assert "id" not in mapping


finite = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, allow_infinity=False)


@given(
    name=st.text(min_size=1, max_size=40).map(str.strip).filter(bool),
    numbers=st.tuples(finite, finite, finite),
    lam=st.tuples(st.integers(0, 10_000), st.integers(1, 10_000)),
    k=st.tuples(st.integers(0, 10_000), st.integers(1, 10_000)),
    mode=st.sampled_from(BarrelType),
    diameter=st.none() | finite,
    note=st.text(max_size=50).map(str.strip),
)
def test_mapping_round_trip(
    name: str,
    numbers: tuple[float, float, float],
    lam: tuple[int, int],
    k: tuple[int, int],
    mode: BarrelType,
    diameter: float | None,
    note: str,
) -> None:
    recipe = Recipe(
        id=None,
        name=name,
        length_mm=numbers[0],
        thickness_mm=numbers[1],
        length_ratio=Ratio(*lam),
        width_ratio=Ratio(*k),
        barrel_type=mode,
        tilt_deg=numbers[2],
        barrel_diameter_mm=diameter,
        barrel_perimeter_mm=None,
        note=note,
    )
    assert recipe_from_mapping(recipe_to_mapping(recipe)) == recipe


# ----------------------------------------------------------------------------- samples


def test_the_sample_recipes_are_valid_and_inside_the_machine_limits() -> None:
    recipes = load_recipe_file(sample_recipes_path())
    assert len(recipes) >= 6
    names = [recipe.name for recipe in recipes]
    assert len({name.casefold() for name in names}) == len(names)
    for recipe in recipes:
        assert recipe.validate() == [], recipe.name
        # Typical boards of 90..160 mm must keep heads of at least 60 mm.
        assert recipe.width_ratio.value * 90.0 >= DEFAULT_LIMITS.min_head_width_mm, recipe.name
        assert recipe.barrel_diameter_mm is not None
        for width in (90.0, 160.0):
            tilt = tilt_for_width(recipe, width)
            assert DEFAULT_LIMITS.min_tilt_deg < tilt < DEFAULT_LIMITS.max_tilt_deg
    lengths = sorted(recipe.length_mm for recipe in recipes)
    assert lengths[0] < 1000.0 and lengths[-1] >= 3000.0  # barriques to a big foudre
    assert {BarrelType.FIXED_TILT, BarrelType.ROUND} <= {recipe.barrel_type for recipe in recipes}


def test_sample_fixed_tilts_match_their_barrel() -> None:
    """Every sample's tilt_deg is the bevel of a typical board of its barrel: it must lie within
    the tilts the barrel-mode computation gives for boards of 90..200 mm (foudre staves are the
    wide ones)."""
    for recipe in load_recipe_file(sample_recipes_path()):
        barrel = replace(recipe, barrel_type=BarrelType.ROUND)
        low, high = tilt_for_width(barrel, 90.0), tilt_for_width(barrel, 200.0)
        assert low <= recipe.tilt_deg <= high, recipe.name
