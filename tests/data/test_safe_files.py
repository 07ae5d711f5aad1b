"""Exports safe in a spreadsheet (formula cells escaped, the import restores the text) and
temporary files that cannot be hijacked (exclusive, never through a link, private)."""

from __future__ import annotations

import csv
import io
import os
import stat
from datetime import UTC, datetime
from pathlib import Path

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from app.data.csv_cells import from_csv_text, to_csv_text
from app.data.database import Database
from app.data.exchange import export_production_day, export_recipes, import_recipes
from app.data.files import atomic_write_text, create_temporary_sibling
from app.data.records import PieceResult, ProductionRecord
from app.data.users import Role, User

from .test_recipe import make_recipe

HOSTILE = ["=cmd|' /C calc'!A0", "+1+1", "-2+3", "@SUM(A1)", "'=already quoted", "''", "'"]


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=30))
@example("=cmd|' /C calc'!A0")
@example("\t=1")
@example("\r=1")
@example("'")
def test_escaping_round_trips_and_never_starts_a_formula(text: str) -> None:
    cell = to_csv_text(text)
    assert from_csv_text(cell) == text
    assert not cell.startswith(("=", "+", "-", "@", "\t", "\r"))


def test_recipe_export_escapes_names_and_the_import_restores_them(
    db: Database, users: dict[Role, User], tmp_path: Path
) -> None:
    for number, name in enumerate(HOSTILE):
        db.save_recipe(make_recipe(name=name, note=f"-note {number}"), users[Role.OPERATOR])
    exported = tmp_path / "recipes.csv"
    export_recipes(db, exported)
    rows = list(csv.DictReader(io.StringIO(exported.read_text(encoding="utf-8"))))
    for row in rows:
        assert not row["name"].startswith(("=", "+", "-", "@"))
        assert not row["note"].startswith(("=", "+", "-", "@"))
    with Database.open(tmp_path / "other.db", load_samples=False) as other:
        technician = next(u for u in other.list_users() if u.role is Role.TECHNICIAN)
        report = import_recipes(other, exported, technician)
        assert not report.rejected
        names = {r.name for r in other.list_recipes()}
        assert set(HOSTILE) <= names
        notes = {r.note for r in other.list_recipes() if r.name in HOSTILE}
        assert notes == {f"-note {n}" for n in range(len(HOSTILE))}


def test_production_export_escapes_the_recipe_name(db: Database, tmp_path: Path) -> None:
    db.record_piece(
        ProductionRecord(
            datetime(2024, 5, 2, 9, tzinfo=UTC),
            None,
            HOSTILE[0],
            150.0,
            10.0,
            5000.0,
            28.0,
            PieceResult.OK,
        )
    )
    target = tmp_path / "day.csv"
    export_production_day(db, target, datetime(2024, 5, 2).date(), UTC)
    row = next(csv.DictReader(io.StringIO(target.read_text(encoding="utf-8"))))
    assert row["recipe_name"] == "'" + HOSTILE[0]
    assert stat.S_IMODE(target.stat().st_mode) == 0o600


def test_a_planted_link_is_never_written_through(tmp_path: Path) -> None:
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    target = tmp_path / "export.csv"
    # The old temporary name was predictable; plant links under every name it could take.
    os.symlink(victim, tmp_path / f".{target.name}.{os.getpid()}.partial")
    atomic_write_text(target, "new content")
    assert victim.read_text() == "precious"
    assert target.read_text() == "new content" and not target.is_symlink()
    assert stat.S_IMODE(target.stat().st_mode) == 0o600
    leftovers = [p.name for p in tmp_path.iterdir() if p.name.endswith(".partial")]
    assert leftovers == [f".{target.name}.{os.getpid()}.partial"]  # only the planted link


def test_the_exclusive_create_refuses_an_existing_name_and_a_link(tmp_path: Path) -> None:
    from app.data.files import create_private_file

    victim = tmp_path / "victim"
    victim.write_text("x")
    link = tmp_path / "link"
    os.symlink(victim, link)
    with pytest.raises(FileExistsError):
        create_private_file(link)
    with pytest.raises(FileExistsError):
        create_private_file(victim)
    partial, fd = create_temporary_sibling(tmp_path / "a.db")
    os.close(fd)
    assert partial.parent == tmp_path and stat.S_IMODE(partial.stat().st_mode) == 0o600


def test_a_failed_write_leaves_the_target_and_no_temporary_file(tmp_path: Path) -> None:
    target = tmp_path / "t.json"
    target.write_text("old")
    with pytest.raises(UnicodeEncodeError):
        atomic_write_text(target, "\udcff", encoding="utf-8")
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["t.json"]
