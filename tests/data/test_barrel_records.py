"""Barrel sets and their staves in the database: stored, read back, linked to the production
record of each board, idempotent for the journal, and nothing invalid stored."""

from __future__ import annotations

import sqlite3
from dataclasses import replace
from datetime import UTC, datetime, timedelta
from pathlib import Path

import pytest

from app.data.barrel_records import BarrelRecord, BarrelState, BarrelStaveRecord
from app.data.database import Database
from app.data.errors import RecordError
from app.data.pending import (
    BarrelStaveWrite,
    BarrelWrite,
    PieceWrite,
    decode_write,
    encode_write,
)
from app.data.recipe import BarrelType
from app.data.records import PieceResult, ProductionRecord

T0 = datetime(2024, 5, 2, 8, 0, tzinfo=UTC)

BARREL = BarrelRecord(
    number=1,
    recipe_id=None,
    recipe_name="Oval 700 x 500",
    barrel_type=BarrelType.OVAL,
    belly_major_mm=700.0,
    belly_minor_mm=500.0,
    started_at=T0,
)
# Staves 1 and 2 of docs/MACHINE.md section 7's oval example.
STAVE_1 = BarrelStaveRecord(1, 1, T0, 100.0, 100.0, 0.0, 22.652673, 15.6644, 14.6323, False)
STAVE_2 = BarrelStaveRecord(1, 2, T0, 100.0, 100.0, 22.652673, 42.99986, 11.79, 10.4619, False)


def piece(stave: int | None, result: PieceResult = PieceResult.OK) -> ProductionRecord:
    return ProductionRecord(
        time=T0 + timedelta(minutes=stave or 0),
        recipe_id=None,
        recipe_name=BARREL.recipe_name,
        width_mm=100.0,
        d_mm=None,
        r_mm=None,
        cycle_time_s=30.0,
        result=result,
        barrel_number=None if stave is None else 1,
        stave_number=stave,
    )


def test_a_barrel_its_staves_and_their_production_records(db: Database) -> None:
    assert db.last_barrel_number() == 0
    db.record_barrel(BARREL)
    aborted = db.record_piece(piece(1, PieceResult.ABORTED))
    cut = db.record_piece(piece(1))
    db.record_barrel_stave(STAVE_1)
    db.record_barrel_stave(STAVE_1)  # the journal's second try: kept once
    assert db.record_piece(piece(2)).stave_number == 2
    db.record_barrel_stave(STAVE_2)
    closed = replace(BARREL, state=BarrelState.CLOSED, finished_at=T0 + timedelta(hours=1))
    db.record_barrel(closed)
    db.record_barrel(closed)
    assert db.get_barrel(1) == closed and db.list_barrels() == [closed]
    assert db.last_barrel_number() == 1
    staves = db.barrel_staves(1)
    assert [s.number for s in staves] == [1, 2]
    assert staves[0] == replace(STAVE_1, production_id=cut.id) and cut.id != aborted.id
    stored = db.list_production(T0, T0 + timedelta(hours=1))
    assert [(p.barrel_number, p.stave_number) for p in stored] == [(1, 1), (1, 1), (1, 2)]
    assert db.barrel_staves(2) == [] and db.get_barrel(2) is None


def test_journal_lines_round_trip() -> None:
    for write in (BarrelWrite(BARREL), BarrelStaveWrite(STAVE_1)):
        assert decode_write(encode_write(write)) == write
    old_line = encode_write(PieceWrite(replace(piece(3), operator_name="ana")))
    assert decode_write(old_line) == PieceWrite(replace(piece(3), operator_name="ana"))
    # written before barrels and operators were recorded
    del old_line["barrel_number"], old_line["stave_number"], old_line["operator_name"]
    assert decode_write(old_line) == PieceWrite(
        replace(piece(3), barrel_number=None, stave_number=None)
    )


@pytest.mark.parametrize(
    ("record", "text"),
    [
        (replace(BARREL, number=0), "number: 0 is not allowed"),
        (replace(BARREL, belly_minor_mm=800.0), "belly_minor_mm: 800.0 is not allowed"),
        (replace(BARREL, barrel_type=BarrelType.FIXED_TILT), "barrel_type"),
        (replace(BARREL, state=BarrelState.CLOSED), "finished_at: None is not allowed"),
        (replace(STAVE_1, width_mm=float("nan")), "width_mm: nan is not allowed"),
        (replace(STAVE_1, bevel_b_deg=float("inf")), "bevel_b_deg: inf is not allowed"),
        (replace(STAVE_1, barrel_number=7), "barrel_number = 7 is not a stored barrel"),
    ],
)
def test_invalid_records_are_refused_naming_the_field(db: Database, record, text) -> None:
    db.record_barrel(BARREL)
    with pytest.raises(RecordError, match=text):
        if isinstance(record, BarrelRecord):
            db.record_barrel(record)
        else:
            db.record_barrel_stave(record)


def test_a_production_record_names_both_numbers_or_neither(db: Database) -> None:
    with pytest.raises(RecordError, match="stave_number: None is not allowed with barrel_number"):
        db.record_piece(replace(piece(1), stave_number=None))
    with pytest.raises(RecordError, match="stave_number: 0 is not allowed"):
        db.record_piece(replace(piece(1), stave_number=0))


def test_the_tables_refuse_a_stave_wider_than_its_board(db: Database, db_path: Path) -> None:
    db.record_barrel(BARREL)
    with sqlite3.connect(db_path) as conn, pytest.raises(sqlite3.IntegrityError):
        conn.execute(
            "INSERT INTO barrel_staves (barrel_number, number, time, board_width_mm, width_mm, "
            "start_angle_deg, end_angle_deg, bevel_a_deg, bevel_b_deg, closing) "
            "VALUES (1, 1, 'x', 90, 100, 0, 20, 1, 1, 0)"
        )
