"""Database backup and restore with SQLite's online backup API.

Backup copies a consistent snapshot page by page through SQLite itself, so it is safe while
the machine is running and writing (a plain file copy of a WAL database can miss the
committed transactions still in the -wal file, or catch a half-written page). The copy is
written beside its destination and renamed into place once complete and checked, and it is a
single self-contained file (journal mode DELETE, no -wal to forget).

Restore refuses a file that is not a healthy database of this application (not SQLite,
``PRAGMA integrity_check`` not ok, a schema version this software does not know, tables
missing), keeps a backup of the current database beside it before touching anything, and then
copies the backup into the live database through the same API - one transaction, so a crash
during the restore leaves the old database - and migrates it if it came from older software.
"""

from __future__ import annotations

import sqlite3
from contextlib import closing
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path

from app.data.database import Database
from app.data.errors import DataError
from app.data.files import fsync_directory, temporary_sibling
from app.data.schema import REQUIRED_TABLES, SCHEMA_VERSION, read_schema_version, user_table_names

_SQLITE_HEADER = b"SQLite format 3\x00"


class BackupError(DataError):
    """A backup could not be made, or a file is not fit to restore (message says why)."""


@dataclass(frozen=True)
class BackupInfo:
    """What a checked backup file holds."""

    path: Path
    schema_version: int
    recipes: int
    production_records: int


@dataclass(frozen=True)
class RestoreReport:
    """What a restore did: the file restored and where the replaced database was kept."""

    restored: BackupInfo
    previous_copy: Path | None


def _connect_existing(path: Path, read_only: bool) -> sqlite3.Connection:
    """Connect without ever creating a file (a plain connect creates an empty database)."""
    mode = "ro" if read_only else "rw"
    return sqlite3.connect(f"{path.resolve().as_uri()}?mode={mode}", uri=True, timeout=10.0)


def _stamp(now: datetime | None) -> str:
    return (now or datetime.now(UTC)).astimezone().strftime("%Y%m%d-%H%M%S")


def default_backup_name(now: datetime | None = None) -> str:
    """``stave-YYYYmmdd-HHMMSS.db`` in local time."""
    return f"stave-{_stamp(now)}.db"


def backup_database(source: Database | Path, destination: Path, *, overwrite: bool = False) -> Path:
    """Copy the database to ``destination`` (a file, or a directory to put a dated file in).

    Returns the path written. An existing file is replaced only with ``overwrite``.
    """
    source_path = source.path if isinstance(source, Database) else Path(source)
    if not source_path.is_file():
        raise BackupError(f"{source_path}: no database to back up (file not found)")
    target = destination / default_backup_name() if destination.is_dir() else destination
    if target.resolve() == source_path.resolve():
        raise BackupError(f"{target}: a backup cannot replace the database itself")
    if target.exists() and not overwrite:
        raise BackupError(f"{target}: file exists (choose another name or allow overwriting)")
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise BackupError(f"{target}: cannot create the folder ({exc.strerror})") from None
    partial = temporary_sibling(target)
    partial.unlink(missing_ok=True)
    try:
        with (
            closing(_connect_existing(source_path, read_only=False)) as src,
            closing(sqlite3.connect(partial)) as dst,
        ):
            src.backup(dst)
            dst.execute("PRAGMA journal_mode = DELETE")
            problems = [str(row[0]) for row in dst.execute("PRAGMA integrity_check")]
            if problems != ["ok"]:
                raise BackupError(
                    f"{source_path}: the copy fails the integrity check: {problems[0]}"
                )
        partial.replace(target)
    except sqlite3.Error as exc:
        partial.unlink(missing_ok=True)
        raise BackupError(f"{source_path}: backup to {target} failed ({exc})") from None
    except BaseException:
        partial.unlink(missing_ok=True)
        raise
    fsync_directory(target.parent)
    return target


def inspect_backup(path: Path) -> BackupInfo:
    """Check that ``path`` is a healthy database of this application; BackupError if not."""
    if not path.is_file():
        raise BackupError(f"{path}: backup file not found")
    with path.open("rb") as stream:
        if stream.read(len(_SQLITE_HEADER)) != _SQLITE_HEADER:
            raise BackupError(f"{path}: not an SQLite database file")
    try:
        with closing(_connect_existing(path, read_only=True)) as conn:
            problems = [str(row[0]) for row in conn.execute("PRAGMA integrity_check")]
            if problems != ["ok"]:
                raise BackupError(f"{path}: fails the integrity check: {problems[0]}")
            version = read_schema_version(conn)
            if not 1 <= version <= SCHEMA_VERSION:
                raise BackupError(
                    f"{path}: schema version {version} is not restorable: this software knows "
                    f"versions 1 to {SCHEMA_VERSION}"
                )
            missing = REQUIRED_TABLES - user_table_names(conn)
            if missing:
                raise BackupError(
                    f"{path}: not a stave-jointer database (tables missing: "
                    f"{', '.join(sorted(missing))})"
                )
            if conn.execute("PRAGMA foreign_key_check").fetchone() is not None:
                raise BackupError(f"{path}: fails the foreign key check")
            recipes = int(conn.execute("SELECT count(*) FROM recipes").fetchone()[0])
            records = int(conn.execute("SELECT count(*) FROM production").fetchone()[0])
    except sqlite3.Error as exc:
        raise BackupError(f"{path}: cannot be read as a database ({exc})") from None
    return BackupInfo(path, version, recipes, records)


def restore_database(backup_path: Path, database_path: Path) -> RestoreReport:
    """Replace the database at ``database_path`` by the backup at ``backup_path``.

    The backup is checked first (:func:`inspect_backup`); the current database, if any, is
    kept as ``<name>.before-restore-<time>.db`` beside it. Other processes using the database
    see the restored content at their next read. Returns what was restored and the copy kept.
    """
    info = inspect_backup(backup_path)
    if backup_path.resolve() == database_path.resolve():
        raise BackupError(f"{backup_path}: this is the database itself")
    previous: Path | None = None
    if database_path.exists():
        stem = f"{database_path.stem}.before-restore-{_stamp(None)}"
        suffix = database_path.suffix or ".db"
        previous = database_path.with_name(f"{stem}{suffix}")
        number = 1
        while previous.exists():  # two restores within one second
            number += 1
            previous = database_path.with_name(f"{stem}-{number}{suffix}")
        backup_database(database_path, previous)
    try:
        with (
            closing(_connect_existing(backup_path, read_only=True)) as src,
            closing(sqlite3.connect(database_path, timeout=10.0)) as dst,
        ):
            src.backup(dst)
    except sqlite3.Error as exc:
        raise BackupError(
            f"{database_path}: restore from {backup_path} failed, database unchanged ({exc})"
        ) from None
    Database.open(database_path, load_samples=False).close()  # WAL mode, migrations, parameters
    return RestoreReport(info, previous)
