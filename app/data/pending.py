"""Records the machine could not store yet, kept in a journal file until the database takes them.

Why a journal and not only a retry: a production record or an alarm transition is made once,
by the machine, and nobody can make it again. While the database is busy (a large import, a
backup, a slow disk) the record waits; if the process is killed or the panel loses power while
it waits, the journal file still holds it and the next start stores it. Each write is appended
as one JSON line and flushed to disk before the database is even tried, so there is no moment
at which a record exists only in memory beyond the call that made it.

Storing a journalled write twice is harmless: :meth:`Database.record_piece` and
:meth:`Database.record_alarm_event` with ``skip_if_stored`` find an identical row and keep it,
so a crash between the database's commit and the journal's truncation duplicates nothing.
A torn last line (the crash came while appending) is the one write that never reached the
disk completely; it is skipped with a log line, the lines before it are kept.
"""

from __future__ import annotations

import json
import logging
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from app.data.barrel_records import (
    BarrelRecord,
    BarrelStaveRecord,
    barrel_fields,
    barrel_from_fields,
    barrel_stave_fields,
    barrel_stave_from_fields,
)
from app.data.files import PRIVATE_FILE_MODE
from app.data.records import (
    AlarmEvent,
    ProductionRecord,
    alarm_fields,
    alarm_from_fields,
    production_fields,
    production_from_fields,
)

_log = logging.getLogger(__name__)

JOURNAL_SUFFIX = ".pending"
"""The journal lives beside the database: ``stave.db.pending``."""


@dataclass(frozen=True)
class PieceWrite:
    """A production record to store."""

    record: ProductionRecord


@dataclass(frozen=True)
class AlarmWrite:
    """An alarm transition to store."""

    event: AlarmEvent


@dataclass(frozen=True)
class SeedParametersWrite:
    """The configuration's factory values for a database nobody has tuned yet."""

    values: dict[str, float]


@dataclass(frozen=True)
class MachineStateWrite:
    """A value the machine keeps across a restart (None: forget it), e.g. the board it was
    cutting; journalled like the records, so a crash right after the write keeps it."""

    key: str
    value: str | None


@dataclass(frozen=True)
class BarrelWrite:
    """A barrel set started, closed or abandoned."""

    record: BarrelRecord


@dataclass(frozen=True)
class BarrelStaveWrite:
    """A stave cut for a barrel (after the production record of its board)."""

    record: BarrelStaveRecord


PendingWrite = (
    PieceWrite
    | AlarmWrite
    | SeedParametersWrite
    | MachineStateWrite
    | BarrelWrite
    | BarrelStaveWrite
)


def journal_path(database_path: Path) -> Path:
    """Where the journal of ``database_path`` lives."""
    return database_path.with_name(database_path.name + JOURNAL_SUFFIX)


def encode_write(write: PendingWrite) -> dict[str, Any]:
    """The JSON object of one journal line (a record in the columns the database stores)."""
    if isinstance(write, PieceWrite):
        return {"kind": "piece", **production_fields(write.record)}
    if isinstance(write, AlarmWrite):
        return {"kind": "alarm", **alarm_fields(write.event)}
    if isinstance(write, MachineStateWrite):
        return {"kind": "machine_state", "key": write.key, "value": write.value}
    if isinstance(write, BarrelWrite):
        return {"kind": "barrel", **barrel_fields(write.record)}
    if isinstance(write, BarrelStaveWrite):
        return {"kind": "barrel_stave", **barrel_stave_fields(write.record)}
    return {"kind": "seed_parameters", "values": dict(write.values)}


def decode_write(data: dict[str, Any]) -> PendingWrite:
    """Inverse of :func:`encode_write`; ValueError/KeyError/TypeError for a damaged line."""
    kind = data["kind"]
    if kind == "piece":
        return PieceWrite(production_from_fields(data))
    if kind == "alarm":
        return AlarmWrite(alarm_from_fields(data))
    if kind == "seed_parameters":
        return SeedParametersWrite({str(k): float(v) for k, v in data["values"].items()})
    if kind == "machine_state":
        value = data["value"]
        return MachineStateWrite(str(data["key"]), None if value is None else str(value))
    if kind == "barrel":
        return BarrelWrite(barrel_from_fields(data))
    if kind == "barrel_stave":
        return BarrelStaveWrite(barrel_stave_from_fields(data))
    raise ValueError(
        f"kind = {kind!r} is not allowed: one of piece, alarm, seed_parameters, machine_state, "
        "barrel, barrel_stave"
    )


class WriteJournal:
    """An append-only file of pending writes (one JSON line each), emptied once all are stored."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def append(self, write: PendingWrite) -> None:
        """Add one write and flush it to disk (OSError if the disk refuses)."""
        line = json.dumps(encode_write(write), ensure_ascii=False, allow_nan=False) + "\n"
        fd = os.open(
            self.path,
            os.O_WRONLY | os.O_APPEND | os.O_CREAT | os.O_NOFOLLOW | getattr(os, "O_CLOEXEC", 0),
            PRIVATE_FILE_MODE,
        )
        try:
            os.write(fd, line.encode("utf-8"))
            os.fsync(fd)
        finally:
            os.close(fd)

    def entries(self) -> list[PendingWrite]:
        """Every complete write in the file, oldest first (none if there is no file)."""
        try:
            raw = self.path.read_bytes()
        except FileNotFoundError:
            return []
        writes: list[PendingWrite] = []
        for number, line in enumerate(raw.split(b"\n"), start=1):
            if not line.strip():
                continue
            try:
                writes.append(decode_write(json.loads(line.decode("utf-8"))))
            except (ValueError, KeyError, TypeError, AttributeError) as exc:
                _log.error("%s line %d: not a complete write, skipped (%s)", self.path, number, exc)
        return writes

    def clear(self) -> None:
        """Everything in it is stored: empty the file (it stays, with its permissions)."""
        try:
            fd = os.open(self.path, os.O_WRONLY | os.O_NOFOLLOW | getattr(os, "O_CLOEXEC", 0))
        except FileNotFoundError:
            return
        try:
            os.ftruncate(fd, 0)
            os.fsync(fd)
        finally:
            os.close(fd)
