"""Backup (online, consistent, one self-contained file) and restore (checked first, the
previous database kept)."""

from __future__ import annotations

import sqlite3
from dataclasses import replace
from pathlib import Path

import pytest

from app.data.backup import BackupError, backup_database, inspect_backup, restore_database
from app.data.database import Database
from app.data.schema import SCHEMA_VERSION, apply_migrations
from app.data.users import Role, User

from .test_recipe import make_recipe


def test_a_backup_holds_every_commit_even_those_still_in_the_wal(
    db: Database, users: dict[Role, User], tmp_path: Path
) -> None:
    db.save_recipe(make_recipe(name="Only in the WAL"), users[Role.OPERATOR])
    assert Path(f"{db.path}-wal").stat().st_size > 0  # not checkpointed into the main file
    target = backup_database(db, tmp_path / "backups" / "copy.db")
    assert not Path(f"{target}-wal").exists()
    with sqlite3.connect(target) as conn:
        assert conn.execute("PRAGMA journal_mode").fetchone()[0] == "delete"
    with Database.open(target) as copy:
        assert copy.get_recipe_by_name("Only in the WAL") is not None
        assert copy.list_recipes() == db.list_recipes()


def test_a_backup_into_a_folder_gets_a_dated_name(db: Database, tmp_path: Path) -> None:
    target = backup_database(db.path, tmp_path)
    assert target.parent == tmp_path and target.name.startswith("stave-")
    assert inspect_backup(target).recipes == len(db.list_recipes())


def test_a_backup_does_not_overwrite_unless_asked(db: Database, tmp_path: Path) -> None:
    target = tmp_path / "b.db"
    target.write_text("an older backup")
    with pytest.raises(BackupError, match="exists"):
        backup_database(db, target)
    assert target.read_text() == "an older backup"
    backup_database(db, target, overwrite=True)
    assert inspect_backup(target).schema_version == SCHEMA_VERSION
    with pytest.raises(BackupError, match="itself"):
        backup_database(db, db.path, overwrite=True)
    with pytest.raises(BackupError, match="not found"):
        backup_database(tmp_path / "none.db", tmp_path / "x.db")


def test_restore_replaces_the_content_and_keeps_the_previous_database(
    db: Database, users: dict[Role, User], tmp_path: Path
) -> None:
    backup = backup_database(db, tmp_path / "before.db")
    original = db.list_recipes()
    db.save_recipe(make_recipe(name="Made after the backup"), users[Role.OPERATOR])
    db.close()

    report = restore_database(backup, db.path)
    assert report.previous_copy is not None and report.previous_copy.parent == db.path.parent
    assert report.restored.recipes == len(original)
    with Database.open(db.path) as restored:
        assert restored.list_recipes() == original
        assert restored.integrity_problems() == []
        assert restored._conn.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
    with Database.open(report.previous_copy) as previous:
        assert previous.get_recipe_by_name("Made after the backup") is not None


def test_an_open_database_sees_the_restored_content(
    db: Database, users: dict[Role, User], tmp_path: Path
) -> None:
    backup = backup_database(db, tmp_path / "before.db")
    db.save_recipe(make_recipe(name="Gone after the restore"), users[Role.OPERATOR])
    restore_database(backup, db.path)
    assert db.get_recipe_by_name("Gone after the restore") is None  # same connection, new data


def test_restoring_an_older_schema_migrates_it(tmp_path: Path, db_path: Path) -> None:
    old = tmp_path / "v1.db"
    conn = sqlite3.connect(old, isolation_level=None)
    conn.execute("BEGIN")
    apply_migrations(conn, 0, 1)
    conn.execute("COMMIT")
    conn.close()
    restore_database(old, db_path)
    with Database.open(db_path) as restored:
        assert restored.schema_version == SCHEMA_VERSION
        assert restored.recipe_history() == []


def corrupt(path: Path) -> None:
    data = bytearray(path.read_bytes())
    page = 4096
    for offset in range(page * 2, min(len(data), page * 4)):
        data[offset] = 0x5A  # flatten b-tree pages after the first
    path.write_bytes(bytes(data))


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda p: p.write_text("name,length_mm\n"), "not an SQLite database"),
        (lambda p: None, "not found"),
        (corrupt, "integrity|cannot be read|malformed"),
        ("newer", "schema version"),
        ("foreign", "tables missing"),
    ],
)
def test_restore_refuses_a_file_that_is_not_a_healthy_backup(
    db: Database, tmp_path: Path, make: object, message: str
) -> None:
    candidate = tmp_path / "candidate.db"
    if make == "newer":
        backup_database(db, candidate)
        with sqlite3.connect(candidate) as conn:
            conn.execute(f"PRAGMA user_version = {SCHEMA_VERSION + 1}")
    elif make == "foreign":
        with sqlite3.connect(candidate) as conn:
            conn.execute("CREATE TABLE invoices (id INTEGER PRIMARY KEY)")
            conn.execute("PRAGMA user_version = 1")
    elif make is corrupt:
        backup_database(db, candidate)
        corrupt(candidate)
    else:
        assert callable(make)
        make(candidate)
    before = db.list_recipes()
    files_before = sorted(p.name for p in db.path.parent.iterdir())
    with pytest.raises(BackupError, match=message):
        restore_database(candidate, db.path)
    assert db.list_recipes() == before
    assert sorted(p.name for p in db.path.parent.iterdir()) == files_before  # no copy made


def test_restore_into_a_new_place(db: Database, tmp_path: Path) -> None:
    backup = backup_database(db, tmp_path / "b.db")
    target = tmp_path / "new" / "stave.db"
    target.parent.mkdir()
    report = restore_database(backup, target)
    assert report.previous_copy is None
    with Database.open(target) as restored:
        assert [replace(r) for r in restored.list_recipes()] == db.list_recipes()
