"""Restore of damaged backups, fuzzed: any truncation, any changed bytes, with or without a
checksum made afterwards (as a careless hand would). Each one is refused with one line naming
the file, and the live database is byte-identical afterwards; a change that happens to leave
a healthy database (a byte in a text value, in unused space) may be restored, and then the
result opens and passes SQLite's integrity check. Never another exception, never a half
replaced database.

The examples are bounded (each restore copies and checks a whole database file)."""

from __future__ import annotations

import hashlib
import shutil
import sqlite3
from collections.abc import Iterator
from contextlib import closing
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from app.data.backup import (
    BackupError,
    backup_database,
    checksum_path,
    restore_database,
    service_pin_check,
)
from app.data.database import Database

from .test_backup import live_bytes, sign

FUZZ = settings(
    max_examples=25,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
SERVICE = service_pin_check("9999")


class Workshop:
    """A pristine live database and a backup of it (both closed, one file each); every example
    works on fresh copies, so one example's restore cannot change the next one's start."""

    def __init__(self, root: Path, template: Path) -> None:
        self.root = root
        self.live = root / "pristine-live.db"
        shutil.copyfile(template, self.live)
        self.backup_bytes = backup_database(self.live, root / "pristine-backup.db").read_bytes()
        self._count = 0

    def fresh(self) -> tuple[Path, Path]:
        """A live database to restore into and the path a candidate backup goes to."""
        self._count += 1
        place = self.root / f"example-{self._count}"
        place.mkdir()
        live = place / "stave.db"
        shutil.copyfile(self.live, live)
        return live, place / "candidate.db"


@pytest.fixture(scope="module")
def workshop(tmp_path_factory: pytest.TempPathFactory, template_db: Path) -> Iterator[Workshop]:
    yield Workshop(tmp_path_factory.mktemp("backup-fuzz"), template_db)


def restore_refused_or_healthy(live: Path, candidate: Path) -> bool:
    """Restore ``candidate`` into ``live``: True when it was refused (live untouched, one
    line naming the file), False when it was restored (the result healthy)."""
    before = live_bytes(live)
    files_before = sorted(p.name for p in live.parent.iterdir())
    try:
        restore_database(candidate, live, authorize=SERVICE)
    except BackupError as exc:
        message = str(exc)
        assert "\n" not in message and candidate.name in message, message
        assert live_bytes(live) == before
        assert sorted(p.name for p in live.parent.iterdir()) == files_before
        return True
    with closing(sqlite3.connect(live)) as conn:
        assert conn.execute("PRAGMA integrity_check").fetchone()[0] == "ok"
    Database.open(live).close()
    return False


@FUZZ
@given(keep=st.floats(min_value=0.0, max_value=0.999), signed=st.booleans())
def test_a_truncated_backup_is_refused(workshop: Workshop, keep: float, signed: bool) -> None:
    live, candidate = workshop.fresh()
    data = workshop.backup_bytes
    candidate.write_bytes(data[: int(len(data) * keep)])
    if signed:
        sign(candidate)
    else:  # the checksum of the whole backup, as it was made
        checksum_path(candidate).write_text(
            f"{hashlib.sha256(data).hexdigest()}  {candidate.name}\n"
        )
    assert restore_refused_or_healthy(live, candidate)


@settings(FUZZ, max_examples=15)  # a healthy result is restored: a whole restore each
@given(
    changes=st.lists(
        st.tuples(st.floats(min_value=0.0, max_value=0.999), st.integers(1, 255)),
        min_size=1,
        max_size=8,
    ),
    signed=st.booleans(),
)
def test_a_backup_with_changed_bytes_is_refused_or_restored_healthy(
    workshop: Workshop, changes: list[tuple[float, int]], signed: bool
) -> None:
    live, candidate = workshop.fresh()
    data = bytearray(workshop.backup_bytes)
    original = bytes(data)
    for where, flip in changes:
        data[int(len(data) * where)] ^= flip
    assume(bytes(data) != original)  # two changes of one byte may cancel out
    candidate.write_bytes(bytes(data))
    if signed:
        sign(candidate)
    else:
        checksum_path(candidate).write_text(
            f"{hashlib.sha256(original).hexdigest()}  {candidate.name}\n"
        )
    refused = restore_refused_or_healthy(live, candidate)
    assert refused or signed  # an unsigned change never gets past the checksum
