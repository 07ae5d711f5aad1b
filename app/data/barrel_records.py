"""Barrel sets and their staves as stored: which barrel a stave went into, where, at what bevels.

Why the database keeps them (and not only the production records): a cooper raises a barrel
from its staves in order, and on an oval barrel each stave has its own two bevels; the card
he works from (``app.data.barrel_card``) is read back from here, long after the machine has
forgotten the barrel. A barrel is identified by its number, counted up by the machine; each
stave row names the production record of the board it was cut from.

The writes are idempotent (a barrel row is updated by its number, a stave row that is already
there is kept), so a journalled write stored twice after a crash changes nothing.
"""

from __future__ import annotations

import math
import sqlite3
from dataclasses import dataclass
from datetime import datetime
from enum import Enum
from typing import Any

from app.data.errors import RecordError
from app.data.recipe import BarrelType
from app.data.records import Fields, format_utc, optional_int, parse_utc


class BarrelState(Enum):
    OPEN = "open"  # staves are being cut for it
    CLOSED = "closed"  # its last stave closed the gap
    ABANDONED = "abandoned"  # another barrel or recipe was started before it closed


@dataclass(frozen=True)
class BarrelRecord:
    """One barrel set: its recipe, belly section (axes as diameters, mm) and life."""

    number: int
    recipe_id: int | None
    recipe_name: str
    barrel_type: BarrelType
    belly_major_mm: float
    belly_minor_mm: float
    started_at: datetime
    state: BarrelState = BarrelState.OPEN
    finished_at: datetime | None = None

    def problems(self) -> list[str]:
        found = _whole_number_problems(("number", self.number))
        if self.barrel_type not in (BarrelType.ROUND, BarrelType.OVAL):
            found.append(f"barrel_type: {self.barrel_type!r} is not allowed; round or oval")
        if not isinstance(self.recipe_name, str) or not self.recipe_name.strip():
            found.append(f"recipe_name: {self.recipe_name!r} is not allowed; expected a name")
        found.extend(
            _positive_problems(
                ("belly_major_mm", self.belly_major_mm), ("belly_minor_mm", self.belly_minor_mm)
            )
        )
        if not found and self.belly_minor_mm > self.belly_major_mm:
            found.append(
                f"belly_minor_mm: {self.belly_minor_mm!r} is not allowed; at most "
                f"belly_major_mm = {self.belly_major_mm!r}"
            )
        if (self.state is BarrelState.OPEN) != (self.finished_at is None):
            found.append(
                f"finished_at: {self.finished_at!r} is not allowed in state "
                f"{self.state.value}: an open barrel has none, a finished one has one"
            )
        return found


@dataclass(frozen=True)
class BarrelStaveRecord:
    """One stave of a barrel: its place (ellipse parameter of its joints) and bevels.

    Side A is the joint with the stave before it (for stave 1: with the closing stave),
    side B the joint with the stave after it. ``board_width_mm`` is the board's measured
    width; ``width_mm`` the stave's belly width after the cut (narrower for the closing
    stave, cut to the gap).
    """

    barrel_number: int
    number: int
    time: datetime
    board_width_mm: float
    width_mm: float
    start_angle_deg: float
    end_angle_deg: float
    bevel_a_deg: float
    bevel_b_deg: float
    closing: bool
    production_id: int | None = None

    def problems(self) -> list[str]:
        found = _whole_number_problems(
            ("barrel_number", self.barrel_number), ("number", self.number)
        )
        found.extend(
            _positive_problems(("board_width_mm", self.board_width_mm), ("width_mm", self.width_mm))
        )
        for field, value in (
            ("start_angle_deg", self.start_angle_deg),
            ("end_angle_deg", self.end_angle_deg),
            ("bevel_a_deg", self.bevel_a_deg),
            ("bevel_b_deg", self.bevel_b_deg),
        ):
            if not _is_finite(value):
                found.append(f"{field}: {value!r} is not allowed; expected a finite number")
        return found


def _is_finite(value: object) -> bool:
    return not isinstance(value, bool) and isinstance(value, int | float) and math.isfinite(value)


def _whole_number_problems(*fields: tuple[str, object]) -> list[str]:
    return [
        f"{name}: {value!r} is not allowed; expected a whole number >= 1"
        for name, value in fields
        if isinstance(value, bool) or not isinstance(value, int) or value < 1
    ]


def _positive_problems(*fields: tuple[str, object]) -> list[str]:
    return [
        f"{name}: {value!r} is not allowed; expected a finite number > 0"
        for name, value in fields
        if not _is_finite(value) or float(value) <= 0  # type: ignore[arg-type]
    ]


def _check(problems: list[str], what: str) -> None:
    if problems:
        raise RecordError(f"{what} not saved: " + "; ".join(problems))


def barrel_fields(record: BarrelRecord) -> dict[str, Any]:
    """The stored columns of a barrel (times in the stored text form)."""
    return {
        "number": record.number,
        "recipe_id": record.recipe_id,
        "recipe_name": record.recipe_name,
        "barrel_type": record.barrel_type.value,
        "belly_major_mm": float(record.belly_major_mm),
        "belly_minor_mm": float(record.belly_minor_mm),
        "started_at": format_utc(record.started_at),
        "finished_at": None if record.finished_at is None else format_utc(record.finished_at),
        "state": record.state.value,
    }


def barrel_from_fields(fields: Fields) -> BarrelRecord:
    """Inverse of :func:`barrel_fields` (a stored row, or a journal line)."""
    return BarrelRecord(
        number=int(fields["number"]),
        recipe_id=optional_int(fields["recipe_id"]),
        recipe_name=str(fields["recipe_name"]),
        barrel_type=BarrelType(fields["barrel_type"]),
        belly_major_mm=float(fields["belly_major_mm"]),
        belly_minor_mm=float(fields["belly_minor_mm"]),
        started_at=parse_utc(fields["started_at"]),
        state=BarrelState(fields["state"]),
        finished_at=None if fields["finished_at"] is None else parse_utc(fields["finished_at"]),
    )


_STAVE_FLOATS = (
    "board_width_mm",
    "width_mm",
    "start_angle_deg",
    "end_angle_deg",
    "bevel_a_deg",
    "bevel_b_deg",
)


def barrel_stave_fields(record: BarrelStaveRecord) -> dict[str, Any]:
    """The stored columns of a stave, without the production record it is linked to."""
    return {
        "barrel_number": record.barrel_number,
        "number": record.number,
        "time": format_utc(record.time),
        **{name: float(getattr(record, name)) for name in _STAVE_FLOATS},
        "closing": int(bool(record.closing)),
    }


def barrel_stave_from_fields(fields: Fields) -> BarrelStaveRecord:
    """Inverse of :func:`barrel_stave_fields` (with ``production_id`` where the row has it)."""
    keys = set(fields.keys())
    return BarrelStaveRecord(
        barrel_number=int(fields["barrel_number"]),
        number=int(fields["number"]),
        time=parse_utc(fields["time"]),
        board_width_mm=float(fields["board_width_mm"]),
        width_mm=float(fields["width_mm"]),
        start_angle_deg=float(fields["start_angle_deg"]),
        end_angle_deg=float(fields["end_angle_deg"]),
        bevel_a_deg=float(fields["bevel_a_deg"]),
        bevel_b_deg=float(fields["bevel_b_deg"]),
        closing=bool(fields["closing"]),
        production_id=optional_int(fields["production_id"]) if "production_id" in keys else None,
    )


def _insert(conn: sqlite3.Connection, table: str, fields: dict[str, Any], tail: str) -> None:
    conn.execute(
        f"INSERT INTO {table} ({', '.join(fields)}) "
        f"VALUES ({', '.join('?' for _ in fields)}) {tail}",
        tuple(fields.values()),
    )


def store_barrel(conn: sqlite3.Connection, record: BarrelRecord) -> None:
    """Insert the barrel, or update its state and end (RecordError: an invalid record)."""
    _check(record.problems(), f"barrel {record.number!r}")
    fields = barrel_fields(record)
    if record.recipe_id is not None:  # a recipe deleted meanwhile: the name stays
        found = conn.execute("SELECT id FROM recipes WHERE id = ?", (record.recipe_id,))
        fields["recipe_id"] = None if found.fetchone() is None else record.recipe_id
    tail = (
        "ON CONFLICT (number) DO UPDATE SET finished_at = excluded.finished_at, "
        "state = excluded.state"
    )
    _insert(conn, "barrels", fields, tail)


def store_barrel_stave(conn: sqlite3.Connection, record: BarrelStaveRecord) -> None:
    """Insert the stave (kept if already there), linked to the last finished production
    record of its barrel and number (RecordError: invalid, or its barrel is not stored)."""
    _check(record.problems(), f"stave {record.number!r} of barrel {record.barrel_number!r}")
    if not conn.execute(
        "SELECT 1 FROM barrels WHERE number = ?", (record.barrel_number,)
    ).fetchone():
        raise RecordError(
            f"stave {record.number} not saved: barrel_number = {record.barrel_number} "
            "is not a stored barrel"
        )
    produced = conn.execute(
        "SELECT id FROM production WHERE barrel_number = ? AND stave_number = ? "
        "AND result = 'ok' ORDER BY id DESC LIMIT 1",
        (record.barrel_number, record.number),
    ).fetchone()
    fields = barrel_stave_fields(record)
    fields["production_id"] = None if produced is None else int(produced[0])
    _insert(conn, "barrel_staves", fields, "ON CONFLICT DO NOTHING")


_BARREL_COLUMNS = ", ".join(
    (
        "number",
        "recipe_id",
        "recipe_name",
        "barrel_type",
        "belly_major_mm",
        "belly_minor_mm",
        "started_at",
        "finished_at",
        "state",
    )
)


def read_barrel(conn: sqlite3.Connection, number: int) -> BarrelRecord | None:
    row = conn.execute(f"SELECT {_BARREL_COLUMNS} FROM barrels WHERE number = ?", (number,))
    found = row.fetchone()
    return None if found is None else barrel_from_fields(found)


def read_barrels(conn: sqlite3.Connection, limit: int) -> list[BarrelRecord]:
    """The newest ``limit`` barrels, newest first."""
    rows = conn.execute(
        f"SELECT {_BARREL_COLUMNS} FROM barrels ORDER BY number DESC LIMIT ?", (int(limit),)
    )
    return [barrel_from_fields(row) for row in rows]


def read_barrel_staves(conn: sqlite3.Connection, barrel_number: int) -> list[BarrelStaveRecord]:
    """The barrel's staves in order around it."""
    rows = conn.execute(
        "SELECT * FROM barrel_staves WHERE barrel_number = ? ORDER BY number", (barrel_number,)
    )
    return [barrel_stave_from_fields(row) for row in rows]


def last_barrel_number(conn: sqlite3.Connection) -> int:
    """The highest barrel number stored (0: none yet)."""
    row = conn.execute("SELECT max(number) FROM barrels").fetchone()
    return 0 if row is None or row[0] is None else int(row[0])
