"""Database backup and restore with SQLite's online backup API.

Backup copies a consistent snapshot page by page through SQLite itself, so it is safe while
the machine is running and writing (a plain file copy of a WAL database can miss the
committed transactions still in the -wal file, or catch a half-written page). The copy is
written to a private temporary file beside its destination and renamed into place once
complete and checked; it is one self-contained file (journal mode DELETE, no -wal to forget)
with a SHA-256 checksum beside it (``<backup>.sha256``, the format ``sha256sum -c`` reads).

Restore is a service operation and changes nothing until the candidate has passed every
check, in this order: the checksum; the file's length against the page count its SQLite
header records (a cut-off copy whose missing pages happened to be free ones passes SQLite's
own integrity check); the file opened read-only (SQLite header, integrity,
foreign keys, a known schema version); a private copy made of it and checked against the
exact schema of its version (tables, columns, constraints, indexes; no trigger or view of its
own, which would run inside the application); the copy migrated to the current version; every
row read back through the application's own rules (recipes validated against the machine's
limits, parameters against the catalogue and its cross rules, users with known roles and a
service user among them, records with their own checks). Only then is the service PIN of the
current database checked, the current database kept as ``<name>.before-restore-<time>.db``,
and the prepared copy written into the live database in one SQLite transaction. That is the
atomic swap that suits a database other processes have open: they see the restored content at
their next read, whereas renaming a file over it would leave the running machine process
writing its records into the old, unlinked file. The users (and their PINs) of the current
database are kept unless the restore is asked to bring back the backup's users too.
"""

from __future__ import annotations

import hashlib
import os
import re
import sqlite3
from collections.abc import Callable
from contextlib import closing
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path

from app.data.database import USER_ADMIN_ROLE, Database
from app.data.errors import DataError
from app.data.files import atomic_write_text, create_temporary_sibling, fsync_directory
from app.data.schema import SCHEMA_VERSION, apply_migrations, read_schema_version
from app.data.users import Role
from app.geometry.limits import StaveLimits

_SQLITE_HEADER = b"SQLite format 3\x00"
_HEADER_BYTES = 100
CHECKSUM_SUFFIX = ".sha256"
MAX_BACKUP_BYTES = 2 * 1024**3
"""A backup larger than this is refused before it is read (the panel's database is megabytes)."""


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


def _one_line(reason: object) -> str:
    """A reason as one line: SQLite quotes the damaged schema text it failed on, newlines
    and all, and a message on the panel or the terminal must stay one line."""
    return " ".join(str(reason).split())


def _connect_existing(path: Path, read_only: bool) -> sqlite3.Connection:
    """Connect without ever creating a file (a plain connect creates an empty database)."""
    mode = "ro" if read_only else "rw"
    return sqlite3.connect(f"{path.resolve().as_uri()}?mode={mode}", uri=True, timeout=10.0)


def _stamp(now: datetime | None) -> str:
    return (now or datetime.now(UTC)).astimezone().strftime("%Y%m%d-%H%M%S")


def default_backup_name(now: datetime | None = None) -> str:
    """``stave-YYYYmmdd-HHMMSS.db`` in local time."""
    return f"stave-{_stamp(now)}.db"


def checksum_path(backup: Path) -> Path:
    """The checksum file of a backup: ``<backup>.sha256``."""
    return backup.with_name(backup.name + CHECKSUM_SUFFIX)


def file_sha256(path: Path) -> str:
    """Hex SHA-256 of a file's content."""
    digest = hashlib.sha256()
    with path.open("rb") as stream:
        for block in iter(lambda: stream.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def backup_database(source: Database | Path, destination: Path, *, overwrite: bool = False) -> Path:
    """Copy the database to ``destination`` (a file, or a directory to put a dated file in).

    Returns the path written (0600, with its checksum file). An existing file is replaced only
    with ``overwrite``.
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
        partial, fd = create_temporary_sibling(target)
    except OSError as exc:
        raise BackupError(f"{target}: cannot create the file ({exc.strerror})") from None
    os.close(fd)
    try:
        _copy_database(source_path, partial)
        with closing(sqlite3.connect(partial)) as dst:
            problems = [str(row[0]) for row in dst.execute("PRAGMA integrity_check")]
            if problems != ["ok"]:
                raise BackupError(
                    f"{source_path}: the copy fails the integrity check: {_one_line(problems[0])}"
                )
        digest = file_sha256(partial)
        partial.replace(target)
    except sqlite3.Error as exc:
        partial.unlink(missing_ok=True)
        raise BackupError(f"{source_path}: backup to {target} failed ({_one_line(exc)})") from None
    except BaseException:
        partial.unlink(missing_ok=True)
        raise
    fsync_directory(target.parent)
    atomic_write_text(checksum_path(target), f"{digest}  {target.name}\n")
    return target


def _copy_database(source: Path, empty_target: Path) -> None:
    """SQLite's online backup of ``source`` into the (existing, empty) ``empty_target``."""
    with (
        closing(_connect_existing(source, read_only=False)) as src,
        closing(sqlite3.connect(empty_target)) as dst,
    ):
        src.backup(dst)
        dst.execute("PRAGMA journal_mode = DELETE")


def _check_checksum(path: Path) -> None:
    sums = checksum_path(path)
    if not sums.is_file():
        raise BackupError(
            f"{path}: no checksum file {sums.name} beside it (every backup made by "
            "`stave db backup` has one): not restored"
        )
    text = sums.read_text(encoding="utf-8", errors="replace").strip()
    match = re.fullmatch(r"([0-9a-f]{64})\s+\*?(.+)", text)
    if match is None:
        raise BackupError(f"{sums}: not a SHA-256 checksum line ('<64 hex digits>  <file name>')")
    if match.group(1) != file_sha256(path):
        raise BackupError(f"{path}: content does not match its checksum {sums.name}: not restored")


def _check_length(path: Path, header: bytes) -> None:
    """The file holds exactly the pages its header counts (file format section 1.3: the page
    size at offset 16, 1 meaning 65536; the page count at 28, valid while the number at 92
    equals the change counter at 24, as in every file SQLite's backup API writes)."""
    size = path.stat().st_size
    if len(header) < _HEADER_BYTES:
        raise BackupError(f"{path}: {size} bytes is shorter than an SQLite header")
    page_size = int.from_bytes(header[16:18], "big")
    page_size = 65536 if page_size == 1 else page_size
    pages = int.from_bytes(header[28:32], "big")
    counted = header[24:28] == header[92:96] and pages > 0
    if page_size < 512 or page_size & (page_size - 1):
        raise BackupError(f"{path}: page size {page_size} in its header is not a power of two")
    if counted and size != pages * page_size:
        raise BackupError(
            f"{path}: {size} bytes, but its header counts {pages} pages of {page_size} bytes "
            f"({pages * page_size} bytes): the file is cut off or extended, not restored"
        )
    if not counted and size % page_size:
        raise BackupError(f"{path}: {size} bytes is not a whole number of {page_size}-byte pages")


def inspect_backup(path: Path) -> BackupInfo:
    """Check that ``path`` is a healthy database file of a known schema version, opened
    read-only; BackupError if not. (Restore checks much more, on a copy.)"""
    if not path.is_file():
        raise BackupError(f"{path}: backup file not found")
    if path.stat().st_size > MAX_BACKUP_BYTES:
        raise BackupError(
            f"{path}: {path.stat().st_size} bytes is too large: at most {MAX_BACKUP_BYTES}"
        )
    with path.open("rb") as stream:
        header = stream.read(_HEADER_BYTES)
    if header[: len(_SQLITE_HEADER)] != _SQLITE_HEADER:
        raise BackupError(f"{path}: not an SQLite database file")
    _check_length(path, header)
    try:
        with closing(_connect_existing(path, read_only=True)) as conn:
            problems = [str(row[0]) for row in conn.execute("PRAGMA integrity_check")]
            if problems != ["ok"]:
                raise BackupError(f"{path}: fails the integrity check: {_one_line(problems[0])}")
            version = read_schema_version(conn)
            if not 1 <= version <= SCHEMA_VERSION:
                raise BackupError(
                    f"{path}: schema version {version} is not restorable: this software knows "
                    f"versions 1 to {SCHEMA_VERSION}"
                )
            _check_exact_schema(path, conn, version)
            if conn.execute("PRAGMA foreign_key_check").fetchone() is not None:
                raise BackupError(f"{path}: fails the foreign key check")
            recipes = int(conn.execute("SELECT count(*) FROM recipes").fetchone()[0])
            records = int(conn.execute("SELECT count(*) FROM production").fetchone()[0])
    except (sqlite3.Error, UnicodeDecodeError) as exc:  # damaged text is not UTF-8
        raise BackupError(f"{path}: cannot be read as a database ({_one_line(exc)})") from None
    return BackupInfo(path, version, recipes, records)


def _schema_objects(conn: sqlite3.Connection) -> set[tuple[str, str, str, str]]:
    rows = conn.execute(
        "SELECT type, name, tbl_name, coalesce(sql, '') FROM sqlite_master "
        "WHERE name NOT LIKE 'sqlite_%'"
    ).fetchall()
    return {(str(t), str(n), str(tb), " ".join(str(sql).split())) for t, n, tb, sql in rows}


def expected_schema(version: int) -> set[tuple[str, str, str, str]]:
    """Every table, index, trigger and view a database of ``version`` has, as SQLite keeps them."""
    with closing(sqlite3.connect(":memory:")) as conn:
        apply_migrations(conn, 0, version)
        return _schema_objects(conn)


def _check_exact_schema(path: Path, conn: sqlite3.Connection, version: int) -> None:
    found = _schema_objects(conn)
    wanted = expected_schema(version)
    extra = sorted(f"{kind} {name}" for kind, name, _, _ in found - wanted)
    missing = sorted(f"{kind} {name}" for kind, name, _, _ in wanted - found)
    if extra or missing:
        parts = []
        if missing:
            parts.append("missing or changed: " + ", ".join(missing))
        if extra:
            parts.append("not ours or changed: " + ", ".join(extra))
        raise BackupError(
            f"{path}: schema differs from version {version} of this software ({'; '.join(parts)})"
        )


def _check_content(path: Path, candidate: Database) -> None:
    """Every row through the application's own rules (the copy is already migrated)."""
    try:
        problems = candidate.integrity_problems()
        if problems:
            raise BackupError(f"{path}: {_one_line(problems[0])}")
        users = candidate.list_users()
        if not any(user.role is Role.SERVICE for user in users):
            raise BackupError(f"{path}: has no service user (at least one is required)")
        for recipe in candidate.list_recipes():
            errors = recipe.validate(candidate.limits)
            if errors:
                raise BackupError(f"{path}: recipe {recipe.name!r}: {_one_line(errors[0].message)}")
        candidate.check_stored_parameters()
        candidate.check_stored_records()
    except BackupError:
        raise
    except (DataError, ValueError, TypeError, ZeroDivisionError, OverflowError) as exc:
        raise BackupError(f"{path}: a stored value breaks the rules: {_one_line(exc)}") from None


def restore_database(
    backup_path: Path,
    database_path: Path,
    *,
    authorize: Callable[[Database], None] | None = None,
    restore_users: bool = False,
    limits: StaveLimits | None = None,
) -> RestoreReport:
    """Replace the database at ``database_path`` by the backup at ``backup_path``.

    Every check of the module docstring runs on a private copy first; ``authorize(current)``
    (the service PIN check, see :func:`service_pin_check`) runs after them and before anything
    is changed, and is required whenever a current database exists. Returns what was restored
    and where the previous database was kept. BackupError (or the authorizer's DataError) says
    why not; then the current database is untouched.
    """
    if not backup_path.is_file():
        raise BackupError(f"{backup_path}: backup file not found")
    _check_checksum(backup_path)
    info = inspect_backup(backup_path)
    if backup_path.resolve() == database_path.resolve():
        raise BackupError(f"{backup_path}: this is the database itself")
    current_exists = database_path.exists()
    if current_exists and authorize is None:
        raise BackupError("restore needs the service PIN of the current database")
    try:
        prepared, fd = create_temporary_sibling(database_path)
    except OSError as exc:
        raise BackupError(
            f"{database_path.parent}: cannot prepare the restore ({_one_line(exc)})"
        ) from None
    os.close(fd)
    previous: Path | None = None
    try:
        try:
            _copy_database(backup_path, prepared)
            with closing(sqlite3.connect(prepared)) as conn:
                _check_exact_schema(backup_path, conn, info.schema_version)
        except (sqlite3.Error, UnicodeDecodeError) as exc:
            raise BackupError(f"{backup_path}: cannot be copied ({_one_line(exc)})") from None
        try:
            candidate = Database.open(prepared, load_samples=False, limits=limits)
        except (DataError, UnicodeDecodeError) as exc:
            raise BackupError(
                f"{backup_path}: cannot be brought to the current schema ({_one_line(exc)})"
            ) from None
        with candidate:
            _check_content(backup_path, candidate)
        if current_exists:
            with Database.open(database_path, load_samples=False, limits=limits) as current:
                assert authorize is not None
                authorize(current)
                if not restore_users:
                    _keep_current_users(current, prepared)
            previous = _previous_copy_name(database_path)
            backup_database(database_path, previous)
        with (
            closing(_connect_existing(prepared, read_only=True)) as src,
            closing(sqlite3.connect(database_path, timeout=10.0)) as dst,
        ):
            src.backup(dst)
    except sqlite3.Error as exc:
        raise BackupError(
            f"{database_path}: restore from {backup_path} failed, database unchanged "
            f"({_one_line(exc)})"
        ) from None
    finally:
        for leftover in (prepared, Path(f"{prepared}-wal"), Path(f"{prepared}-shm")):
            leftover.unlink(missing_ok=True)
    Database.open(database_path, load_samples=False, limits=limits).close()  # WAL mode again
    return RestoreReport(info, previous)


def _previous_copy_name(database_path: Path) -> Path:
    stem = f"{database_path.stem}.before-restore-{_stamp(None)}"
    suffix = database_path.suffix or ".db"
    previous = database_path.with_name(f"{stem}{suffix}")
    number = 1
    while previous.exists():  # two restores within one second
        number += 1
        previous = database_path.with_name(f"{stem}-{number}{suffix}")
    return previous


def _keep_current_users(current: Database, prepared: Path) -> None:
    """The prepared copy takes the current database's users and PINs (and PIN lockout)."""
    rows = current.export_users()
    with closing(sqlite3.connect(prepared, isolation_level=None)) as conn:
        conn.execute("BEGIN IMMEDIATE")
        conn.execute("DELETE FROM users")
        conn.executemany(
            "INSERT INTO users (id, name, role, pin_hash, updated_at) VALUES (?, ?, ?, ?, ?)",
            rows,
        )
        conn.execute("COMMIT")


def service_pin_check(pin: str) -> Callable[[Database], None]:
    """An authorizer for :func:`restore_database`: ``pin`` must be a service user's of the
    current database (throttled like every PIN; PinEntryRefused while locked)."""

    def authorize(current: Database) -> None:
        user = current.authenticate(pin)
        if user is None:
            raise BackupError("pin: this PIN belongs to no user of the current database")
        current.check_role(user, USER_ADMIN_ROLE, "restoring a backup")

    return authorize
