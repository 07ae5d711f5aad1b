"""Backup (online, consistent, one self-contained file with its checksum) and restore (a
service operation; every check on a copy first; the live database byte-identical when refused;
the current users kept)."""

from __future__ import annotations

import hashlib
import sqlite3
import stat
from collections.abc import Callable
from contextlib import closing
from dataclasses import replace
from datetime import UTC, datetime
from pathlib import Path

import pytest

from app.data.backup import (
    BackupError,
    backup_database,
    checksum_path,
    file_sha256,
    inspect_backup,
    restore_database,
    service_pin_check,
)
from app.data.database import Database
from app.data.errors import DataError, PinEntryRefused
from app.data.records import PieceResult, ProductionRecord
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


SERVICE = service_pin_check("9999")


def sign(path: Path) -> None:
    """A checksum file for a file made by hand (as a backup of ours would have)."""
    checksum_path(path).write_text(f"{file_sha256(path)}  {path.name}\n")


def live_bytes(path: Path) -> str:
    """The database file and its WAL: what must not change when a restore is refused."""
    digest = hashlib.sha256()
    for part in (path, Path(f"{path}-wal")):
        if part.exists():
            digest.update(part.read_bytes())
    return digest.hexdigest()


def assert_refused_untouched(db: Database, candidate: Path, message: str) -> None:
    """Refused with ``message``; the live database byte-identical and no copy left behind."""
    before = live_bytes(db.path)
    files_before = sorted(p.name for p in db.path.parent.iterdir())
    with pytest.raises(BackupError, match=message):
        restore_database(candidate, db.path, authorize=SERVICE)
    assert live_bytes(db.path) == before
    assert sorted(p.name for p in db.path.parent.iterdir()) == files_before


def test_a_backup_is_private_and_carries_its_checksum(db: Database, tmp_path: Path) -> None:
    target = backup_database(db, tmp_path / "b.db")
    assert stat.S_IMODE(target.stat().st_mode) == 0o600
    line = checksum_path(target).read_text()
    assert line == f"{hashlib.sha256(target.read_bytes()).hexdigest()}  b.db\n"
    with Database.open(tmp_path / "data" / "new.db", load_samples=False) as new:
        assert stat.S_IMODE(new.path.stat().st_mode) == 0o600
        assert stat.S_IMODE(new.path.parent.stat().st_mode) == 0o700


def test_restore_replaces_the_content_and_keeps_the_previous_database(
    db: Database, users: dict[Role, User], tmp_path: Path
) -> None:
    backup = backup_database(db, tmp_path / "before.db")
    original = db.list_recipes()
    db.save_recipe(make_recipe(name="Made after the backup"), users[Role.OPERATOR])
    db.close()

    report = restore_database(backup, db.path, authorize=SERVICE)
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
    restore_database(backup, db.path, authorize=SERVICE)
    assert db.get_recipe_by_name("Gone after the restore") is None  # same connection, new data


def test_restore_keeps_the_current_users_unless_asked(
    db: Database, users: dict[Role, User], tmp_path: Path
) -> None:
    backup = backup_database(db, tmp_path / "fresh.db")  # default PINs in the backup
    db.set_pin(users[Role.SERVICE], "86420975", users[Role.SERVICE])
    restore_database(backup, db.path, authorize=service_pin_check("86420975"))
    assert db.authenticate("9999") is None  # the default service PIN did not come back
    assert db.authenticate("86420975") == users[Role.SERVICE]
    restore_database(backup, db.path, authorize=service_pin_check("86420975"), restore_users=True)
    assert db.authenticate("9999") == users[Role.SERVICE]


@pytest.mark.parametrize(
    ("authorize", "message"),
    [
        (None, "service PIN"),
        (service_pin_check("1234"), "needs the role service"),
        (service_pin_check("5555"), "belongs to no user"),
    ],
)
def test_restore_needs_the_service_pin_of_the_current_database(
    db: Database, tmp_path: Path, authorize: Callable[[Database], None] | None, message: str
) -> None:
    backup = backup_database(db, tmp_path / "b.db")
    recipes = db.list_recipes()
    with pytest.raises(DataError, match=message):
        restore_database(backup, db.path, authorize=authorize)
    assert db.list_recipes() == recipes


def test_wrong_service_pins_on_restore_lock_pin_entry(db: Database, tmp_path: Path) -> None:
    backup = backup_database(db, tmp_path / "b.db")
    refused = 0
    for _ in range(12):
        try:
            restore_database(backup, db.path, authorize=service_pin_check("5555"))
        except PinEntryRefused:
            refused += 1
        except BackupError:
            pass
    assert refused > 0  # the delay applies here as everywhere


def test_restoring_an_older_schema_migrates_it(
    tmp_path: Path, db: Database, users: dict[Role, User]
) -> None:
    old = tmp_path / "v1.db"
    conn = sqlite3.connect(old, isolation_level=None)
    conn.execute("BEGIN")
    apply_migrations(conn, 0, 1)
    conn.execute(
        "INSERT INTO users (name, role, pin_hash, updated_at) VALUES ('svc', 'service', "
        "'scrypt$1$1$1$00$00', '2024-01-01T00:00:00.000000Z')"
    )
    conn.execute("COMMIT")
    conn.close()
    sign(old)
    restore_database(old, db.path, authorize=SERVICE)
    assert db.schema_version == SCHEMA_VERSION
    assert db.recipe_history() == []
    assert db.list_users() == list(users.values())  # kept


def corrupt(path: Path) -> None:
    data = bytearray(path.read_bytes())
    page = 4096
    for offset in range(page * 2, min(len(data), page * 4)):
        data[offset] = 0x5A  # flatten b-tree pages after the first
    path.write_bytes(bytes(data))


def _sql(*statements: str) -> Callable[[Path], None]:
    def change(path: Path) -> None:
        with closing_connection(path) as conn:
            for statement in statements:
                conn.execute(statement)

    return change


def closing_connection(path: Path) -> closing[sqlite3.Connection]:
    return closing(sqlite3.connect(path, isolation_level=None))


def _v1_with_a_v2_table(path: Path) -> None:
    path.unlink()
    with closing_connection(path) as conn:
        apply_migrations(conn, 0, 1)
        conn.execute("CREATE TABLE recipe_changes (id INTEGER PRIMARY KEY)")


def _recipes_without_checks(path: Path) -> None:
    with closing_connection(path) as conn:
        conn.execute("PRAGMA foreign_keys = OFF")
        conn.execute("PRAGMA legacy_alter_table = ON")
        conn.execute("ALTER TABLE recipes RENAME TO old_recipes")
        conn.execute(
            "CREATE TABLE recipes (id INTEGER PRIMARY KEY, name TEXT, length_mm REAL, "
            "thickness_mm REAL, length_ratio_num INTEGER, length_ratio_den INTEGER, "
            "width_ratio_num INTEGER, width_ratio_den INTEGER, tilt_mode TEXT, tilt_deg REAL, "
            "barrel_diameter_mm REAL, barrel_perimeter_mm REAL, note TEXT, created_at TEXT, "
            "created_by TEXT, updated_at TEXT, updated_by TEXT)"
        )
        conn.execute(
            "INSERT INTO recipes SELECT id, name, length_mm, thickness_mm, length_ratio_num, "
            "0, width_ratio_num, width_ratio_den, tilt_mode, tilt_deg, barrel_diameter_mm, "
            "barrel_perimeter_mm, note, created_at, created_by, updated_at, updated_by "
            "FROM old_recipes"
        )
        conn.execute("DROP TABLE old_recipes")


BAD_CANDIDATES: list[tuple[str, Callable[[Path], None], str]] = [
    ("no service user", _sql("DELETE FROM users WHERE role = 'service'"), "no service user"),
    (
        "unknown role",
        _sql(
            "PRAGMA writable_schema = ON",
            "UPDATE sqlite_master SET sql = replace(sql, \"'operator', 'technician', "
            "'service'\", \"'operator', 'technician', 'service', 'root'\") WHERE name = 'users'",
        ),
        "schema differs",
    ),
    ("denominator 0 without CHECKs", _recipes_without_checks, "schema differs"),
    ("missing table", _sql("DROP TABLE alarm_events"), "schema differs|missing"),
    (
        "parameter out of range",
        _sql("UPDATE parameters SET value = 1e9 WHERE name = 'xy_speed_mm_s'"),
        "xy_speed_mm_s",
    ),
    ("unknown parameter", _sql("INSERT INTO parameters VALUES ('x', 1, 'a', 'b')"), "'x'"),
    (
        "hostile trigger",
        _sql("CREATE TRIGGER t AFTER INSERT ON production BEGIN DELETE FROM recipes; END"),
        "trigger t",
    ),
    ("view", _sql("CREATE VIEW v AS SELECT * FROM users"), "view v"),
    ("v1 file with a v2 table", _v1_with_a_v2_table, "schema differs"),
    (
        "recipe outside the machine's limits",
        _sql("UPDATE recipes SET length_mm = 99999 WHERE id = 1"),
        "length_mm",
    ),
    ("bad record", _sql("UPDATE production SET width_mm = 1e999"), "width_mm|production"),
]


@pytest.mark.parametrize(
    ("what", "change", "message"), BAD_CANDIDATES, ids=[b[0] for b in BAD_CANDIDATES]
)
def test_restore_refuses_a_candidate_that_would_break_the_application(
    db: Database,
    users: dict[Role, User],
    tmp_path: Path,
    what: str,
    change: Callable[[Path], None],
    message: str,
) -> None:
    candidate = backup_database(db, tmp_path / "candidate.db")
    if what == "bad record":
        db.record_piece(
            ProductionRecord(
                datetime(2024, 5, 2, tzinfo=UTC), None, "x", 150.0, 1, 2, 3.0, PieceResult.OK
            )
        )
        candidate.unlink()
        candidate = backup_database(db, tmp_path / "candidate.db", overwrite=True)
    change(candidate)
    sign(candidate)
    assert_refused_untouched(db, candidate, message)


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda p: p.write_text("name,length_mm\n"), "not an SQLite database"),
        (lambda p: None, "not found"),
        (corrupt, "integrity|cannot be read|malformed"),
        ("newer", "schema version"),
        ("foreign", "schema differs"),
        ("unsigned", "no checksum"),
        ("changed after signing", "does not match its checksum"),
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
    elif make == "unsigned":
        backup_database(db, candidate)
        checksum_path(candidate).unlink()
    elif make == "changed after signing":
        backup_database(db, candidate)
        with sqlite3.connect(candidate) as conn:
            conn.execute("DELETE FROM recipes")
    else:
        assert callable(make)
        make(candidate)
    if make not in ("unsigned", "changed after signing") and candidate.exists():
        sign(candidate)
    assert_refused_untouched(db, candidate, message)


def test_restore_into_a_new_place(db: Database, tmp_path: Path) -> None:
    backup = backup_database(db, tmp_path / "b.db")
    target = tmp_path / "new" / "stave.db"
    target.parent.mkdir()
    report = restore_database(backup, target)
    assert report.previous_copy is None
    with Database.open(target) as restored:
        assert [replace(r) for r in restored.list_recipes()] == db.list_recipes()
