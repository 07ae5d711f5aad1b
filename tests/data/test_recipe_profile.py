"""The side profile of a recipe: stored, migrated, exported, imported, and cut the same."""

from __future__ import annotations

import sqlite3
from dataclasses import replace
from pathlib import Path

import pytest

from app.data.database import Database
from app.data.dxf_profile import read_dxf_profile
from app.data.errors import RecipeValidationError
from app.data.exchange import export_recipes, import_recipes
from app.data.recipe import recipe_from_mapping, recipe_to_mapping
from app.data.recipe_files import load_recipe_file
from app.data.recipe_profile import LINE_ARC_LINE, RecipeProfile, parse_recipe_profile
from app.data.schema import apply_migrations
from app.data.users import Role
from app.geometry.limits import DEFAULT_LIMITS
from app.geometry.profile_kinds import ProfileKind
from app.geometry.stave_cut import cut_stave
from tests.data import dxf_drawings as drawings
from tests.data.test_recipe import make_recipe

PARAMS = {
    "tool_radius_mm": 40.0,
    "machine_height_mm": 150.0,
    "start_x_mm": 200.0,
    "start_y_mm": 500.0,
    "lead_mm": 60.0,
    "home_x_mm": 0.0,
    "home_y_mm": 0.0,
    "home_z_deg": 0.0,
    "tilt_clearance_mm": 20.0,
}


def drawn_profile(tmp_path: Path) -> tuple[RecipeProfile, Path]:
    path = tmp_path / "house style.dxf"
    path.write_bytes(drawings.spline())
    drawing = read_dxf_profile(path.name, path.read_bytes())
    profile = RecipeProfile(
        ProfileKind.DRAWN,
        drawing=drawing.shape,
        file_name=drawing.file_name,
        file_sha256=drawing.sha256,
    )
    return profile, path


SUPERELLIPSE = RecipeProfile(
    ProfileKind.SUPERELLIPSE, (("exponent", 4.0), ("semi_axis_ratio", 1.3))
)


def test_family_and_drawn_profiles_are_stored_and_read_back(db: Database, users, tmp_path):
    drawn, _ = drawn_profile(tmp_path)
    editor = users[Role.OPERATOR]
    family = db.save_recipe(make_recipe(name="Fuller", profile=SUPERELLIPSE), editor)
    drawing = db.save_recipe(make_recipe(name="House", profile=drawn), editor)
    assert db.get_recipe(family.id).profile == SUPERELLIPSE
    stored = db.get_recipe(drawing.id).profile
    assert stored == drawn
    assert stored.file_name == "house style.dxf" and len(stored.file_sha256 or "") == 64


def test_a_drawn_recipe_cuts_the_same_after_the_file_is_gone(db: Database, users, tmp_path):
    drawn, path = drawn_profile(tmp_path)
    recipe = db.save_recipe(make_recipe(name="House", profile=drawn), users[Role.OPERATOR])
    before = cut_stave(recipe.stave, 150.0, PARAMS, DEFAULT_LIMITS).toolpath.segments
    path.unlink()
    again = db.get_recipe(recipe.id)
    assert cut_stave(again.stave, 150.0, PARAMS, DEFAULT_LIMITS).toolpath.segments == before


def test_bad_profiles_are_not_stored_and_say_why(db: Database, users):
    editor = users[Role.OPERATOR]
    bad_family = RecipeProfile(ProfileKind.ELLIPSE, (("semi_axis_ratio", 0.5),))
    with pytest.raises(RecipeValidationError, match=r"semi_axis_ratio = 0\.5 is out of range"):
        db.save_recipe(make_recipe(profile=bad_family), editor)
    no_drawing = RecipeProfile(ProfileKind.DRAWN)
    with pytest.raises(RecipeValidationError, match="needs a drawing: import a DXF file"):
        db.save_recipe(make_recipe(profile=no_drawing), editor)


def test_migration_keeps_old_recipes_as_line_arc_line(tmp_path: Path, clock):
    path = tmp_path / "old.db"
    conn = sqlite3.connect(path)
    apply_migrations(conn, 0, 3)  # the version before side profiles
    conn.execute(
        "INSERT INTO recipes (name, length_mm, thickness_mm, length_ratio_num, length_ratio_den, "
        "width_ratio_num, width_ratio_den, tilt_mode, tilt_deg, created_at, created_by, "
        "updated_at, updated_by) VALUES ('Old', 950, 27, 1, 4, 4, 5, 'fixed', 9, 't', 'u', "
        "'t', 'u')"
    )
    conn.commit()
    conn.close()
    with Database.open(path, clock=clock) as db:
        (old,) = db.list_recipes()
        assert old.profile == LINE_ARC_LINE


@pytest.mark.parametrize("suffix", [".json", ".csv"])
def test_export_and_import_carry_the_profile(db: Database, users, tmp_path, suffix):
    drawn, _ = drawn_profile(tmp_path)
    editor = users[Role.TECHNICIAN]
    db.save_recipe(make_recipe(name="Fuller", profile=SUPERELLIPSE), editor)
    db.save_recipe(make_recipe(name="House", profile=drawn), editor)
    out = tmp_path / f"recipes{suffix}"
    export_recipes(db, out)
    by_name = {r.name: r.profile for r in load_recipe_file(out)}
    assert by_name["Fuller"] == SUPERELLIPSE
    assert by_name["House"] == drawn
    for recipe in db.list_recipes():
        db.delete_recipe(recipe.id, editor)
    report = import_recipes(db, out, editor)
    assert {"Fuller", "House"} <= set(report.created)
    assert {r.name: r.profile for r in db.list_recipes()}["House"] == drawn


def test_rows_without_profile_keys_are_line_arc_line_and_bad_ones_are_named():
    row = recipe_to_mapping(make_recipe())
    del row["profile_kind"], row["profile"]
    assert recipe_from_mapping(row).profile == LINE_ARC_LINE
    with pytest.raises(ValueError, match="profile_kind = 'cycloid' is not known"):
        recipe_from_mapping({**row, "profile_kind": "cycloid"})
    with pytest.raises(ValueError, match="profile: is not a JSON object"):
        recipe_from_mapping({**row, "profile_kind": "ellipse", "profile": "{oops"})
    tampered = {"drawing": {"primitives": []}, "file_name": "x.dxf", "file_sha256": "0" * 64}
    with pytest.raises(ValueError, match="no usable curve"):
        parse_recipe_profile("drawn", tampered)


def test_a_family_recipe_cuts_its_own_shape_not_line_arc_line():
    family = make_recipe(profile=replace(SUPERELLIPSE))
    plain = make_recipe()
    width = 150.0
    family_cut = cut_stave(family.stave, width, PARAMS, DEFAULT_LIMITS)
    plain_cut = cut_stave(plain.stave, width, PARAMS, DEFAULT_LIMITS)
    assert family_cut.profile.edge("A") != plain_cut.profile.edge("A")
    assert family_cut.profile.head_width_mm == plain_cut.profile.head_width_mm
