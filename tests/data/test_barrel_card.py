"""The cooper's card: a barrel's staves in order with widths, bevels and neighbours, from the
database (`stave db export-barrel`) and from a plan (`stave barrel --card`)."""

from __future__ import annotations

import csv
import io
from dataclasses import replace
from datetime import timedelta
from pathlib import Path

import pytest

from app.cli import main
from app.data.barrel_card import CARD_COLUMNS, export_barrel_card
from app.data.barrel_records import BarrelState
from app.data.csv_cells import from_csv_text
from app.data.database import Database
from app.data.errors import NotFoundError

from .test_barrel_records import BARREL, STAVE_1, STAVE_2, T0


def rows(path: Path) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))


@pytest.fixture
def stored(db: Database) -> Database:
    db.record_barrel(replace(BARREL, recipe_name="=HYPERLINK(1)"))
    db.record_barrel_stave(STAVE_1)
    db.record_barrel_stave(STAVE_2)
    return db


def test_an_open_barrels_card(stored: Database, tmp_path: Path) -> None:
    path = tmp_path / "card.csv"
    assert export_barrel_card(stored, path).number == 1
    card = rows(path)
    assert tuple(card[0]) == CARD_COLUMNS
    assert [r["stave"] for r in card] == ["1", "2"]
    assert card[0]["recipe"] == "'=HYPERLINK(1)"  # escaped: a spreadsheet runs no formula
    assert from_csv_text(card[0]["recipe"]) == "=HYPERLINK(1)"
    assert (card[0]["bevel_a_deg"], card[0]["bevel_b_deg"]) == ("15.6644", "14.6323")
    assert (card[1]["start_angle_deg"], card[1]["end_angle_deg"]) == ("22.652673", "42.999860")
    # Open: stave 1's side A meets nothing yet, the last stave's side B neither.
    neighbours = [(r["side_a_meets_stave"], r["side_b_meets_stave"]) for r in card]
    assert neighbours == [("", "2"), ("1", "")]


def test_a_closed_barrels_card_joins_the_last_stave_to_the_first(
    stored: Database, tmp_path: Path
) -> None:
    closed = replace(BARREL, state=BarrelState.CLOSED, finished_at=T0 + timedelta(hours=1))
    stored.record_barrel(closed)
    path = tmp_path / "card.csv"
    export_barrel_card(stored, path, 1)
    card = rows(path)
    assert [(r["side_a_meets_stave"], r["side_b_meets_stave"]) for r in card] == [
        ("2", "2"),
        ("1", "1"),
    ]


def test_an_unknown_barrel_or_a_wrong_name_is_refused(stored: Database, tmp_path: Path) -> None:
    with pytest.raises(NotFoundError, match=r"barrel = 9 is not stored: allowed 1\.\.1"):
        export_barrel_card(stored, tmp_path / "card.csv", 9)
    with pytest.raises(ValueError, match=r"use a \.csv file name"):
        export_barrel_card(stored, tmp_path / "card.txt")


def test_stave_db_export_barrel_and_list(stored: Database, tmp_path: Path, capsys) -> None:
    path = tmp_path / "card.csv"
    db_file = str(stored.path)
    assert main(["db", "export-barrel", "--db", db_file, str(path), "--barrel", "1"]) == 0
    assert "barrel 1 (open, 2 staves)" in capsys.readouterr().out
    assert len(rows(path)) == 2
    assert main(["db", "list", "barrels", "--db", db_file]) == 0
    assert "open" in capsys.readouterr().out
    with pytest.raises(SystemExit) as exited:
        main(["db", "export-barrel", "--db", db_file, str(path), "--barrel", "0"])
    assert exited.value.code == 2
    _, err = capsys.readouterr()
    assert err.count("\n") == 1 and "'0' is not allowed" in err


def test_stave_barrel_writes_the_plans_card(tmp_path: Path, capsys) -> None:
    """docs/MACHINE.md section 7: 18 staves of 100 mm round the 700 x 500 oval, then the
    closing stave of 88.3871 mm meeting stave 18 and stave 1."""
    path = tmp_path / "plan.csv"
    widths = [arg for _ in range(18) for arg in ("--width", "100")]
    assert main(["barrel", "--axes-mm", "350x250", *widths, "--card", str(path)]) == 0
    card = rows(path)
    assert len(card) == 19 and [r["closing"] for r in card] == [""] * 18 + ["yes"]
    last = card[-1]
    assert (last["width_mm"], last["bevel_a_deg"], last["bevel_b_deg"]) == (
        "88.387",
        "13.1755",
        "13.9145",
    )
    assert (last["side_a_meets_stave"], last["side_b_meets_stave"]) == ("18", "1")
    assert card[0]["side_a_meets_stave"] == "19" and card[0]["board_width_mm"] == ""
    capsys.readouterr()
    assert main(["barrel", "--diameter-mm", "600", "--width", "100", "--card", "x.txt"]) == 2
    _, err = capsys.readouterr()
    assert err.count("\n") == 1 and "use a .csv file name" in err
