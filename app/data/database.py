"""The embedded database: recipes, system parameters, users, production and alarm history.

One SQLite file (standard library) holds everything an operator or a technician must never
lose. How that promise is kept:

* WAL journal with ``synchronous=FULL``: a commit is on disk before the call returns, so neither
  a killed process nor a power cut loses it, and readers (the screens, a backup) never block the
  machine's writes.
* Every public write is exactly one transaction (``BEGIN IMMEDIATE`` ... ``COMMIT``): a batch of
  recipes, a set of parameters with their change log, a piece - all or nothing.
* Nothing invalid is stored: recipes pass the geometry's validation plus the recipe rules,
  parameters the catalogue, records their own checks, all before the transaction; STRICT tables
  and CHECK constraints catch anything that slips past.
* The schema has a version and forward migrations (``app.data.schema``); creating a database
  (tables, default users, parameters, sample recipes) is itself one transaction, so a crash
  during creation leaves an empty file that the next start creates again.

Permissions are checked here, against the role stored for the user (not the one a caller
claims): editing recipes needs :data:`RECIPE_EDIT_ROLE`, deleting them
:data:`RECIPE_DELETE_ROLE`, each parameter its catalogue role, adding users
:data:`USER_ADMIN_ROLE`.

One connection per Database object, used from one thread (the machine process writes from its
own thread; the GUI process opens its own Database). Times come from ``clock`` so tests and
simulations run on simulated time.
"""

from __future__ import annotations

import contextlib
import json
import logging
import os
import sqlite3
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import replace
from datetime import UTC, datetime
from pathlib import Path
from types import TracebackType

from app.data.barrel_records import (
    BarrelRecord,
    BarrelStaveRecord,
    last_barrel_number,
    read_barrel,
    read_barrel_staves,
    read_barrels,
    store_barrel,
    store_barrel_stave,
)
from app.data.errors import (
    DatabaseOpenError,
    NotFoundError,
    ParameterError,
    PermissionDeniedError,
    PinEntryRefused,
    PinError,
    RecipeValidationError,
    RecordError,
    SchemaVersionError,
    StorageError,
)
from app.data.files import create_private_file, ensure_private_directory
from app.data.parameters import (
    DEFAULT_PARAMETERS,
    PARAMETER_BY_NAME,
    PARAMETERS,
    check_parameter_set,
    check_parameter_value,
    parameter_spec,
    unknown_parameter,
)
from app.data.paths import default_database_path
from app.data.pin_guard import (
    LOCKOUT_ALARM_CODE,
    LOCKOUT_ALARM_SOURCE,
    LOCKOUT_ALARM_TEXT,
    LOCKOUT_FAILURES,
    PinGuardState,
    after_claim,
    after_wrong,
    refusal_text,
    wait_s,
)
from app.data.recipe import BarrelType, Recipe, recipe_to_mapping
from app.data.recipe_files import load_recipe_file
from app.data.recipe_profile import parse_recipe_profile
from app.data.records import (
    AlarmEvent,
    AlarmEventFilter,
    AlarmState,
    ParameterChange,
    ProductionRecord,
    RecipeChange,
    alarm_fields,
    alarm_from_fields,
    format_utc,
    optional_float,
    optional_int,
    parse_utc,
    production_fields,
    production_from_fields,
    to_utc,
)
from app.data.schema import SCHEMA_VERSION, apply_migrations, read_schema_version, user_table_names
from app.data.users import DEFAULT_USERS, Role, User, check_pin_format, hash_pin, verify_pin
from app.geometry.errors import FieldError
from app.geometry.limits import DEFAULT_LIMITS, StaveLimits
from app.geometry.ratio import Ratio
from app.resources import resource_path

__all__ = [
    "Database",
    "default_database_path",
    "sample_recipes_path",
]

_log = logging.getLogger(__name__)


def sample_recipes_path() -> Path:
    """The recipes a brand-new database starts with (``resources/recipes``, see app.resources)."""
    return resource_path("recipes", "sample_recipes.json")


RECIPE_EDIT_ROLE = Role.OPERATOR
"""Creating, changing and copying recipes: production work, every operator may do it."""
RECIPE_DELETE_ROLE = Role.TECHNICIAN
"""Deleting a recipe (its last version stays in the recipe history)."""
RECIPE_IMPORT_ROLE = Role.TECHNICIAN
"""Importing recipe files (may change many recipes at once)."""
USER_ADMIN_ROLE = Role.SERVICE
"""Adding users."""

SIMULATION_APPLICATION_ID = 0x53494D55
"""SQLite's header field ``application_id`` ("SIMU") of a database made by ``stave simulate``:
in the file itself, so a copy keeps it, and no table or migration is needed for it."""

SYSTEM_USER = "system"
"""Name logged for changes the software makes by itself (defaults of a new database)."""
PAGE_CACHE_KIB = 2048
"""SQLite's page cache per connection unless the opener asks for another bound, set
explicitly: a long-running process's database grows by every board, and a connection's cache
keeps every page it touches until this bound is reached (then it reuses the least recent)."""

_RECIPE_COLUMNS = (
    "id, name, length_mm, thickness_mm, length_ratio_num, length_ratio_den, width_ratio_num, "
    "width_ratio_den, tilt_mode, tilt_deg, barrel_diameter_mm, barrel_perimeter_mm, note, "
    "profile_kind, profile_json, barrel_minor_diameter_mm, target_width_mm, barrel_type"
)
_PRODUCTION_COLUMNS = (
    "id, time, recipe_id, recipe_name, width_mm, d_mm, r_mm, tilt_deg, cycle_time_s, result, "
    "alarm_code, resumed, step_times_json, barrel_number, stave_number, operator_name"
)
_ALARM_COLUMNS = "id, time, code, text, source, from_state, to_state, user_name, detail_json"


def _recipe_from_row(row: sqlite3.Row) -> Recipe:
    return Recipe(
        id=int(row["id"]),
        name=str(row["name"]),
        length_mm=float(row["length_mm"]),
        thickness_mm=float(row["thickness_mm"]),
        length_ratio=Ratio(int(row["length_ratio_num"]), int(row["length_ratio_den"])),
        width_ratio=Ratio(int(row["width_ratio_num"]), int(row["width_ratio_den"])),
        barrel_type=BarrelType(row["barrel_type"]),
        tilt_deg=float(row["tilt_deg"]),
        barrel_diameter_mm=_opt_float(row["barrel_diameter_mm"]),
        barrel_perimeter_mm=_opt_float(row["barrel_perimeter_mm"]),
        note=str(row["note"]),
        profile=parse_recipe_profile(row["profile_kind"], row["profile_json"]),
        barrel_minor_diameter_mm=_opt_float(row["barrel_minor_diameter_mm"]),
        target_width_mm=_opt_float(row["target_width_mm"]),
    )


_opt_float = optional_float
_opt_int = optional_int
_production_from_row = production_from_fields
_alarm_from_row = alarm_from_fields


def _recipe_json(recipe: Recipe) -> str:
    return json.dumps({"id": recipe.id, **recipe_to_mapping(recipe)}, ensure_ascii=False)


def _create_private(path: Path) -> None:
    """A new database file is created 0600 (SQLite gives its -wal and -shm the same mode)."""
    if path.exists():
        return
    with contextlib.suppress(FileExistsError):  # another process made it meanwhile: fine
        os.close(create_private_file(path))


def _same_content(a: Recipe, b: Recipe) -> bool:
    return replace(a, id=None) == replace(b, id=None)


class Database:
    """The application's database; create with :meth:`open`, use as a context manager."""

    def __init__(
        self,
        connection: sqlite3.Connection,
        path: Path,
        limits: StaveLimits,
        clock: Callable[[], datetime],
    ) -> None:
        """Use :meth:`open`; this only wires an already configured connection."""
        self._conn = connection
        self._path = path
        self.limits = limits
        self._clock = clock

    # ------------------------------------------------------------------ lifecycle

    @classmethod
    def open(
        cls,
        path: Path | str,
        *,
        limits: StaveLimits | None = None,
        clock: Callable[[], datetime] | None = None,
        busy_timeout_s: float = 10.0,
        load_samples: bool = True,
        samples_path: Path | None = None,
        page_cache_kib: int = PAGE_CACHE_KIB,
    ) -> Database:
        """Open (creating or migrating as needed) the database at ``path``.

        A brand-new database gets the schema, the default users, the default parameters and
        (``load_samples``) the sample recipes of ``samples_path`` (None: the shipped ones), all
        in one transaction.
        ``limits`` are the machine limits recipes are validated against; ``clock`` gives the
        time stamps (UTC now by default); ``page_cache_kib`` bounds this connection's page
        cache. Raises DatabaseOpenError (SchemaVersionError for a
        file from newer software) with the path and the reason.
        """
        db_path = Path(path)
        try:
            ensure_private_directory(db_path.parent)
            _create_private(db_path)
            connection = sqlite3.connect(db_path, timeout=busy_timeout_s, isolation_level=None)
        except (OSError, sqlite3.Error) as exc:
            raise DatabaseOpenError(f"{db_path}: cannot open the database ({exc})") from None
        connection.row_factory = sqlite3.Row
        try:
            mode = str(connection.execute("PRAGMA journal_mode = WAL").fetchone()[0])
            if mode.lower() != "wal":
                raise DatabaseOpenError(
                    f"{db_path}: the file system does not support SQLite's WAL journal "
                    f"(journal mode {mode!r}); use a local disk"
                )
            connection.execute("PRAGMA synchronous = FULL")
            connection.execute("PRAGMA foreign_keys = ON")
            connection.execute(f"PRAGMA cache_size = -{int(page_cache_kib)}")  # negative: KiB
            database = cls(
                connection,
                db_path,
                DEFAULT_LIMITS if limits is None else limits,
                clock if clock is not None else (lambda: datetime.now(UTC)),
            )
            database._prepare((samples_path or sample_recipes_path()) if load_samples else None)
        except (sqlite3.DatabaseError, StorageError) as exc:
            connection.close()
            raise DatabaseOpenError(
                f"{db_path}: not a usable stave-jointer database ({exc})"
            ) from None
        except BaseException:
            connection.close()
            raise
        return database

    def _prepare(self, samples_path: Path | None) -> None:
        """Create, migrate and complete the database as needed (one transaction, if any)."""
        version = read_schema_version(self._conn)
        self._check_version(version)
        if version == SCHEMA_VERSION and not self._missing_parameters():
            return
        sample_recipes: list[Recipe] = []
        if version == 0 and samples_path is not None:
            sample_recipes = self._read_samples(samples_path)
        default_hashes = [hash_pin(pin) for _, _, pin in DEFAULT_USERS] if version == 0 else []
        with self._write() as conn:
            version = read_schema_version(conn)  # again, now under the write lock
            self._check_version(version)
            if version == 0:
                tables = user_table_names(conn)
                if tables:
                    raise DatabaseOpenError(
                        f"{self._path}: not a stave-jointer database (it has the tables "
                        f"{', '.join(sorted(tables))} but no schema version)"
                    )
            if version < SCHEMA_VERSION:
                apply_migrations(conn, version)
                _log.info("%s: schema v%d -> v%d", self._path, version, SCHEMA_VERSION)
            if version == 0:
                self._seed(conn, sample_recipes, default_hashes)
            self._insert_missing_parameters(conn)

    def _check_version(self, version: int) -> None:
        if version > SCHEMA_VERSION:
            raise SchemaVersionError(
                f"{self._path}: schema version {version} was written by newer software; "
                f"this version knows up to {SCHEMA_VERSION}"
            )

    def _read_samples(self, samples_path: Path) -> list[Recipe]:
        if not samples_path.exists():
            _log.warning("sample recipes %s not found: new database starts empty", samples_path)
            return []
        recipes = load_recipe_file(samples_path)
        for recipe in recipes:
            errors = recipe.validate(self.limits)
            if errors:
                raise RecipeValidationError(f"sample recipe {recipe.name!r}", errors)
        return recipes

    def _seed(
        self, conn: sqlite3.Connection, recipes: Sequence[Recipe], pin_hashes: Sequence[str]
    ) -> None:
        now = format_utc(self._clock())
        for (name, role, _), pin_hash in zip(DEFAULT_USERS, pin_hashes, strict=True):
            conn.execute(
                "INSERT INTO users (name, role, pin_hash, updated_at) VALUES (?, ?, ?, ?)",
                (name, role.label, pin_hash, now),
            )
        for recipe in recipes:
            self._insert_recipe(conn, recipe, SYSTEM_USER, now)

    def _missing_parameters(self) -> list[str]:
        stored = {str(row[0]) for row in self._conn.execute("SELECT name FROM parameters")}
        return [spec.name for spec in PARAMETERS if spec.name not in stored]

    def _insert_missing_parameters(self, conn: sqlite3.Connection) -> None:
        """Store the default of every catalogue parameter the file lacks.

        Not logged as a change: nobody changed anything, and "no change logged yet" is how the
        machine layer recognises a database nobody has tuned (it then applies the machine
        configuration's factory values, which are logged).
        """
        now = format_utc(self._clock())
        for name in self._missing_parameters():
            conn.execute(
                "INSERT INTO parameters (name, value, updated_at, updated_by) VALUES (?, ?, ?, ?)",
                (name, DEFAULT_PARAMETERS[name], now, SYSTEM_USER),
            )

    def close(self) -> None:
        """Close the connection (the last one to close also checkpoints the WAL)."""
        self._conn.close()

    def __enter__(self) -> Database:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.close()

    @property
    def for_simulation(self) -> bool:
        """True for a database ``stave simulate`` created for itself (never the panel's)."""
        row = self._conn.execute("PRAGMA application_id").fetchone()
        return int(row[0]) == SIMULATION_APPLICATION_ID

    def mark_for_simulation(self) -> None:
        """Mark a database as a simulation's own (only a new one: production stays production)."""
        if self._conn.execute("SELECT 1 FROM production LIMIT 1").fetchone() is not None:
            raise PermissionDeniedError(f"{self._path}: has production records: not a simulation's")
        self._conn.execute(f"PRAGMA application_id = {SIMULATION_APPLICATION_ID}")

    @property
    def path(self) -> Path:
        """The database file."""
        return self._path

    @property
    def schema_version(self) -> int:
        """The schema version of the file (always the current one once open)."""
        return read_schema_version(self._conn)

    @contextmanager
    def _write(self) -> Iterator[sqlite3.Connection]:
        """One write transaction: committed if the block ends, rolled back if it raises.

        A failure of SQLite itself (disk full, I/O error, another writer holding the lock for
        longer than the busy timeout) becomes StorageError, so callers handle one family of
        exceptions; refusals raised inside the block pass through unchanged.
        """
        try:
            self._conn.execute("BEGIN IMMEDIATE")
        except sqlite3.Error as exc:
            raise StorageError(f"{self._path}: cannot start a write ({exc})") from exc
        try:
            yield self._conn
            self._conn.execute("COMMIT")
        except BaseException as exc:
            if self._conn.in_transaction:
                self._conn.execute("ROLLBACK")
            if isinstance(exc, sqlite3.Error) and not isinstance(exc, sqlite3.ProgrammingError):
                raise StorageError(f"{self._path}: write not stored ({exc})") from exc
            raise

    def _now(self) -> str:
        return format_utc(self._clock())

    def integrity_problems(self) -> list[str]:
        """What ``PRAGMA integrity_check`` and ``foreign_key_check`` find (empty: healthy)."""
        rows = [str(row[0]) for row in self._conn.execute("PRAGMA integrity_check")]
        problems = [] if rows == ["ok"] else rows
        for row in self._conn.execute("PRAGMA foreign_key_check"):
            problems.append(f"foreign key: table {row[0]} row {row[1]} -> {row[2]}")
        return problems

    def check_stored_parameters(self) -> None:
        """ParameterError unless every stored parameter is known and within the catalogue and
        its cross rules (restore runs this on a candidate)."""
        errors: list[FieldError] = []
        for row in self._conn.execute("SELECT name, value FROM parameters"):
            name, value = str(row["name"]), row["value"]
            if name not in PARAMETER_BY_NAME:
                errors.append(unknown_parameter(name, value))
                continue
            error = check_parameter_value(PARAMETER_BY_NAME[name], value)
            if error is not None:
                errors.append(error)
        errors.extend(check_parameter_set(self.get_parameters()) if not errors else [])
        if errors:
            raise ParameterError("parameters", errors)

    def check_stored_records(self) -> None:
        """RecordError unless every production record and alarm event passes its own checks."""
        for row in self._conn.execute(f"SELECT {_PRODUCTION_COLUMNS} FROM production"):
            problems = _production_from_row(row).problems()
            if problems:
                raise RecordError(f"production record {row['id']}: {problems[0]}")
        for row in self._conn.execute(f"SELECT {_ALARM_COLUMNS} FROM alarm_events"):
            problems = _alarm_from_row(row).problems()
            if problems:
                raise RecordError(f"alarm event {row['id']}: {problems[0]}")

    def export_users(self) -> list[tuple[int, str, str, str, str]]:
        """(id, name, role, PIN hash, updated_at) of every user: only for a restore that keeps
        the current users. The hashes never leave the data layer otherwise."""
        rows = self._conn.execute("SELECT id, name, role, pin_hash, updated_at FROM users")
        return [
            (int(r["id"]), str(r["name"]), str(r["role"]), str(r["pin_hash"]), str(r["updated_at"]))
            for r in rows
        ]

    # ------------------------------------------------------------------ users and roles

    def _stored_user(self, user: User) -> User:
        row = self._conn.execute("SELECT id, name, role FROM users WHERE id = ?", (user.id,))
        found = row.fetchone()
        if found is None or str(found["name"]).casefold() != user.name.casefold():
            raise PermissionDeniedError(f"user {user.name!r} is not a user of this database")
        return User(int(found["id"]), str(found["name"]), Role.from_label(found["role"]))

    def check_role(self, user: User, required: Role, action: str) -> User:
        """The stored user if its role allows ``action``; else PermissionDeniedError."""
        stored = self._stored_user(user)
        if stored.role < required:
            raise PermissionDeniedError(
                f"{action} needs the role {required.label} or higher; "
                f"user {stored.name!r} is {stored.role.label}"
            )
        return stored

    def list_users(self) -> list[User]:
        """All users, by id."""
        rows = self._conn.execute("SELECT id, name, role FROM users ORDER BY id")
        return [User(int(r["id"]), str(r["name"]), Role.from_label(r["role"])) for r in rows]

    def authenticate(self, pin: str) -> User | None:
        """The user whose PIN this is, or None (a malformed PIN is simply no match).

        Raises PinEntryRefused, without looking at the PIN, while the wrong-PIN delay or the
        lockout of :mod:`app.data.pin_guard` runs. The attempt is counted before the hashes
        are checked (so parallel attempts cannot share one gap) and forgiven if it matches.
        """
        try:
            check_pin_format(pin)
        except ValueError:
            return None
        with self._write() as conn:
            state = self._pin_guard(conn)
            seconds, locked = wait_s(state, self._clock())
            if seconds > 0:
                raise PinEntryRefused(refusal_text(seconds, locked), seconds, locked)
            self._store_pin_guard(conn, after_claim(state, self._clock()))
        rows = self._conn.execute("SELECT id, name, role, pin_hash FROM users ORDER BY id")
        for row in rows.fetchall():
            if verify_pin(pin, str(row["pin_hash"])):
                user = User(int(row["id"]), str(row["name"]), Role.from_label(row["role"]))
                with self._write() as conn:
                    self._store_pin_guard(conn, PinGuardState())
                return user
        with self._write() as conn:
            now = self._clock()
            state = self._pin_guard(conn)
            wrong = after_wrong(state, now)
            self._store_pin_guard(conn, wrong)
            if wrong.locked_until != state.locked_until and wrong.locked_until is not None:
                seconds = (wrong.locked_until - now).total_seconds()
                _log.warning("%s", refusal_text(seconds, locked=True))
                self._record_lockout_alarm(conn, AlarmState.NORMAL, AlarmState.ACTIVE_UNACKED)
        return None

    def pin_guard_state(self) -> PinGuardState:
        """The wrong-PIN counter and lockout as stored (for the screens and the tests)."""
        return self._pin_guard(self._conn)

    def unlock_pin_entry(self, by_user: User) -> None:
        """End a lockout and reset the wrong-PIN counter (a logged-in service user)."""
        actor = self.check_role(by_user, USER_ADMIN_ROLE, "unlocking PIN entry")
        self.reset_pin_guard(actor.name)

    def reset_pin_guard(self, by: str) -> None:
        """End a lockout and reset the counter; ``by`` is logged with the alarm's return to
        normal. For :meth:`unlock_pin_entry` and for the owner of the database file (who could
        change anything in it anyway)."""
        with self._write() as conn:
            state = self._pin_guard(conn)
            self._store_pin_guard(conn, PinGuardState())
            if state.locked_until is not None:
                self._record_lockout_alarm(conn, AlarmState.ACTIVE_UNACKED, AlarmState.NORMAL, by)
        _log.warning("PIN entry unlocked by %s", by)

    def _record_lockout_alarm(
        self,
        conn: sqlite3.Connection,
        from_state: AlarmState,
        to_state: AlarmState,
        user_name: str | None = None,
    ) -> None:
        self._insert_alarm(
            conn,
            AlarmEvent(
                time=self._clock(),
                code=LOCKOUT_ALARM_CODE,
                text=f"{LOCKOUT_ALARM_TEXT} ({LOCKOUT_FAILURES})",
                source=LOCKOUT_ALARM_SOURCE,
                from_state=from_state,
                to_state=to_state,
                user_name=user_name,
            ),
        )

    @staticmethod
    def _pin_guard(conn: sqlite3.Connection) -> PinGuardState:
        row = conn.execute(
            "SELECT failures, last_failure_at, locked_until FROM pin_guard WHERE id = 1"
        ).fetchone()
        if row is None:
            return PinGuardState()
        last, until = row["last_failure_at"], row["locked_until"]
        return PinGuardState(
            int(row["failures"]),
            None if last is None else parse_utc(last),
            None if until is None else parse_utc(until),
        )

    @staticmethod
    def _store_pin_guard(conn: sqlite3.Connection, state: PinGuardState) -> None:
        conn.execute(
            "INSERT INTO pin_guard (id, failures, last_failure_at, locked_until) "
            "VALUES (1, ?, ?, ?) ON CONFLICT (id) DO UPDATE SET failures = excluded.failures, "
            "last_failure_at = excluded.last_failure_at, locked_until = excluded.locked_until",
            (
                state.failures,
                None if state.last_failure_at is None else format_utc(state.last_failure_at),
                None if state.locked_until is None else format_utc(state.locked_until),
            ),
        )

    def users_with_default_pins(self) -> list[str]:
        """Names of the users whose PIN is still the one a new database gives them (the real
        machine does not start while there is one: the defaults are printed in the README)."""
        defaults = [pin for _, _, pin in DEFAULT_USERS]
        rows = self._conn.execute("SELECT name, pin_hash FROM users ORDER BY id").fetchall()
        return [
            str(row["name"])
            for row in rows
            if any(verify_pin(pin, str(row["pin_hash"])) for pin in defaults)
        ]

    def _pin_taken(self, pin: str, except_user_id: int | None) -> bool:
        rows = self._conn.execute("SELECT id, pin_hash FROM users").fetchall()
        return any(
            int(row["id"]) != except_user_id and verify_pin(pin, str(row["pin_hash"]))
            for row in rows
        )

    def set_pin(self, user: User, new_pin: str, by_user: User) -> None:
        """Change ``user``'s PIN. Allowed to the user itself, to a higher role, and to service.

        PINs identify users, so one already used by another user is refused (PinError).
        """
        try:
            check_pin_format(new_pin)
        except ValueError as exc:
            raise PinError(str(exc)) from None
        self._check_pin_permission(user, by_user)
        if self._pin_taken(new_pin, user.id):
            raise PinError("pin: this PIN is already used by another user; choose another")
        pin_hash = hash_pin(new_pin)
        with self._write() as conn:
            self._check_pin_permission(user, by_user)
            conn.execute(
                "UPDATE users SET pin_hash = ?, updated_at = ? WHERE id = ?",
                (pin_hash, self._now(), user.id),
            )

    def _check_pin_permission(self, user: User, by_user: User) -> None:
        target = self._stored_user(user)
        actor = self._stored_user(by_user)
        if actor.id != target.id and actor.role <= target.role and actor.role < Role.SERVICE:
            raise PermissionDeniedError(
                f"changing the PIN of {target.name!r} ({target.role.label}) needs a higher role "
                f"than {target.role.label}; user {actor.name!r} is {actor.role.label}"
            )

    def add_user(self, name: str, role: Role, pin: str, by_user: User) -> User:
        """Add a user (needs USER_ADMIN_ROLE); name 1..40 characters, unique; PIN unused."""
        clean = name.strip() if isinstance(name, str) else ""
        if not 1 <= len(clean) <= 40:
            raise PinError(f"name: {name!r} is not allowed: 1 to 40 characters")
        if not isinstance(role, Role):
            raise PinError(f"role: {role!r} is not allowed: one of operator, technician, service")
        try:
            check_pin_format(pin)
        except ValueError as exc:
            raise PinError(str(exc)) from None
        self.check_role(by_user, USER_ADMIN_ROLE, "adding a user")
        if self._pin_taken(pin, None):
            raise PinError("pin: this PIN is already used by another user; choose another")
        pin_hash = hash_pin(pin)
        with self._write() as conn:
            self.check_role(by_user, USER_ADMIN_ROLE, "adding a user")
            if conn.execute("SELECT 1 FROM users WHERE name = ?", (clean,)).fetchone():
                raise PinError(f"name: {clean!r} is already a user")
            cursor = conn.execute(
                "INSERT INTO users (name, role, pin_hash, updated_at) VALUES (?, ?, ?, ?)",
                (clean, role.label, pin_hash, self._now()),
            )
        return User(int(cursor.lastrowid or 0), clean, role)

    # ------------------------------------------------------------------ recipes

    def list_recipes(self) -> list[Recipe]:
        """All recipes, by id (the order the Main screen steps through)."""
        rows = self._conn.execute(f"SELECT {_RECIPE_COLUMNS} FROM recipes ORDER BY id")
        return [_recipe_from_row(row) for row in rows]

    def get_recipe(self, recipe_id: int) -> Recipe:
        """The recipe with this id; NotFoundError if there is none."""
        row = self._conn.execute(
            f"SELECT {_RECIPE_COLUMNS} FROM recipes WHERE id = ?", (recipe_id,)
        ).fetchone()
        if row is None:
            raise NotFoundError(f"recipe id {recipe_id!r} does not exist")
        return _recipe_from_row(row)

    def get_recipe_by_name(self, name: str) -> Recipe | None:
        """The recipe with this name (letter case ignored, accented letters too), or None."""
        recipe_id = self._id_of_name(self._conn, name)
        return None if recipe_id is None else self.get_recipe(recipe_id)

    @staticmethod
    def _id_of_name(conn: sqlite3.Connection, name: str) -> int | None:
        """Names compare with str.casefold ("PIÈCE" is "pièce"); SQLite's NOCASE knows ASCII
        only, so the comparison is done here."""
        return Database._name_index(conn).get(name.strip().casefold())

    @staticmethod
    def _name_index(conn: sqlite3.Connection) -> dict[str, int]:
        """Every stored name (casefolded) -> id, read once: a batch of thousands of recipes
        checks its names in one pass instead of one table scan per recipe."""
        return {
            str(row["name"]).casefold(): int(row["id"])
            for row in conn.execute("SELECT id, name FROM recipes")
        }

    def recipe_ids_by_name(self) -> dict[str, int]:
        """Casefolded name -> id of every recipe (one read; for imports)."""
        return self._name_index(self._conn)

    def save_recipe(self, recipe: Recipe, user: User, *, logged_as: str | None = None) -> Recipe:
        """Insert (``id`` None) or update a recipe; returns it as stored, with its id.

        ``logged_as``: the name the change log shows instead of the user's, for a change the
        machine makes on that user's authority (:data:`~app.data.users.SIMULATION_ACTOR`).
        Raises RecipeValidationError listing every invalid field (nothing is stored),
        NotFoundError for an update of a recipe that no longer exists, PermissionDeniedError.
        """
        return self.save_recipes([recipe], user, logged_as=logged_as)[0]

    def save_recipes(
        self, recipes: Sequence[Recipe], user: User, *, logged_as: str | None = None
    ) -> list[Recipe]:
        """Insert or update several recipes in one transaction: all of them or none."""
        for recipe in recipes:
            errors = recipe.validate(self.limits)
            if errors:
                raise RecipeValidationError(f"recipe {recipe.name!r}", errors)
        with self._write() as conn:
            actor = self.check_role(user, RECIPE_EDIT_ROLE, "changing recipes")
            return self._store_recipes(conn, recipes, logged_as or actor.name)

    def save_plant_recipe(self, recipe: Recipe, plant_user: str) -> Recipe:
        """Store a recipe downloaded over the plant connection (OPC UA role ``plant``); the
        change log names the sender as ``opcua:<user>``. Validated like every other save."""
        errors = recipe.validate(self.limits)
        if errors:
            raise RecipeValidationError(f"recipe {recipe.name!r}", errors)
        existing = self.get_recipe_by_name(recipe.name)
        to_store = replace(recipe, id=None if existing is None else existing.id)
        with self._write() as conn:
            return self._store_recipes(conn, [to_store], f"opcua:{plant_user}")[0]

    def _store_recipes(
        self, conn: sqlite3.Connection, recipes: Sequence[Recipe], actor_name: str
    ) -> list[Recipe]:
        saved: list[Recipe] = []
        now = self._now()
        names = self._name_index(conn)
        key_of_id = {recipe_id: key for key, recipe_id in names.items()}
        for recipe in recipes:
            clash = names.get(recipe.name.strip().casefold())
            if clash is not None and clash != recipe.id:
                allowed = "a name no other recipe has"
                message = (
                    f"name = {recipe.name!r} is already used by recipe {clash}: allowed {allowed}"
                )
                error = FieldError("name", recipe.name, allowed, message)
                raise RecipeValidationError(f"recipe {recipe.name!r}", [error])
            if recipe.id is None:
                stored = self._insert_recipe(conn, recipe, actor_name, now)
            else:
                stored = self._update_recipe(conn, recipe, actor_name, now)
                names.pop(key_of_id.get(int(stored.id or 0), ""), None)
            stored_id = int(stored.id or 0)
            key = stored.name.strip().casefold()
            names[key] = stored_id
            key_of_id[stored_id] = key
            saved.append(stored)
        return saved

    def _insert_recipe(
        self, conn: sqlite3.Connection, recipe: Recipe, user_name: str, now: str
    ) -> Recipe:
        cursor = conn.execute(
            "INSERT INTO recipes (name, length_mm, thickness_mm, length_ratio_num, "
            "length_ratio_den, width_ratio_num, width_ratio_den, tilt_mode, tilt_deg, "
            "barrel_diameter_mm, barrel_perimeter_mm, note, profile_kind, profile_json, "
            "barrel_minor_diameter_mm, target_width_mm, barrel_type, "
            "created_at, created_by, updated_at, updated_by) "
            "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
            (
                *self._recipe_values(recipe),
                now,
                user_name,
                now,
                user_name,
            ),
        )
        stored = replace(recipe, id=int(cursor.lastrowid or 0))
        self._log_recipe(conn, now, stored.id, stored.name, "create", user_name, None, stored)
        return stored

    def _update_recipe(
        self, conn: sqlite3.Connection, recipe: Recipe, user_name: str, now: str
    ) -> Recipe:
        row = conn.execute(
            f"SELECT {_RECIPE_COLUMNS} FROM recipes WHERE id = ?", (recipe.id,)
        ).fetchone()
        if row is None:
            raise NotFoundError(f"recipe id {recipe.id!r} does not exist (deleted meanwhile?)")
        before = _recipe_from_row(row)
        if before == recipe:
            return before
        conn.execute(
            "UPDATE recipes SET name = ?, length_mm = ?, thickness_mm = ?, length_ratio_num = ?, "
            "length_ratio_den = ?, width_ratio_num = ?, width_ratio_den = ?, tilt_mode = ?, "
            "tilt_deg = ?, barrel_diameter_mm = ?, barrel_perimeter_mm = ?, note = ?, "
            "profile_kind = ?, profile_json = ?, barrel_minor_diameter_mm = ?, "
            "target_width_mm = ?, barrel_type = ?, updated_at = ?, updated_by = ? WHERE id = ?",
            (*self._recipe_values(recipe), now, user_name, recipe.id),
        )
        self._log_recipe(conn, now, recipe.id, recipe.name, "update", user_name, before, recipe)
        return recipe

    @staticmethod
    def _recipe_values(recipe: Recipe) -> tuple[object, ...]:
        return (
            recipe.name,
            float(recipe.length_mm),
            float(recipe.thickness_mm),
            recipe.length_ratio.numerator,
            recipe.length_ratio.denominator,
            recipe.width_ratio.numerator,
            recipe.width_ratio.denominator,
            recipe.tilt_mode.value,
            float(recipe.tilt_deg),
            _opt_float(recipe.barrel_diameter_mm),
            _opt_float(recipe.barrel_perimeter_mm),
            recipe.note,
            recipe.profile.kind.value,
            recipe.profile.data_json(),
            _opt_float(recipe.barrel_minor_diameter_mm),
            _opt_float(recipe.target_width_mm),
            recipe.barrel_type.value,
        )

    @staticmethod
    def _log_recipe(
        conn: sqlite3.Connection,
        now: str,
        recipe_id: int | None,
        name: str,
        action: str,
        user_name: str,
        before: Recipe | None,
        after: Recipe | None,
    ) -> None:
        conn.execute(
            "INSERT INTO recipe_changes (time, recipe_id, recipe_name, action, user_name, "
            "before_json, after_json) VALUES (?, ?, ?, ?, ?, ?, ?)",
            (
                now,
                recipe_id,
                name,
                action,
                user_name,
                None if before is None else _recipe_json(before),
                None if after is None else _recipe_json(after),
            ),
        )

    def delete_recipe(self, recipe_id: int, user: User) -> Recipe:
        """Delete a recipe; returns it. Its last version stays in :meth:`recipe_history`.

        Production records keep the recipe's name (their recipe id becomes None).
        """
        with self._write() as conn:
            actor = self.check_role(user, RECIPE_DELETE_ROLE, "deleting recipes")
            row = conn.execute(
                f"SELECT {_RECIPE_COLUMNS} FROM recipes WHERE id = ?", (recipe_id,)
            ).fetchone()
            if row is None:
                raise NotFoundError(f"recipe id {recipe_id!r} does not exist")
            before = _recipe_from_row(row)
            conn.execute("DELETE FROM recipes WHERE id = ?", (recipe_id,))
            self._log_recipe(
                conn, self._now(), recipe_id, before.name, "delete", actor.name, before, None
            )
        return before

    def copy_recipe(self, recipe_id: int, new_name: str, user: User) -> Recipe:
        """A new recipe like ``recipe_id`` under ``new_name`` (validated like any recipe)."""
        source = self.get_recipe(recipe_id)
        return self.save_recipe(replace(source, id=None, name=new_name), user)

    def recipe_history(self, recipe_id: int | None = None, limit: int = 1000) -> list[RecipeChange]:
        """Logged recipe changes, last logged first (all recipes, or one id, deleted ones too)."""
        where, params = ("WHERE recipe_id = ?", [recipe_id]) if recipe_id is not None else ("", [])
        rows = self._conn.execute(
            "SELECT id, time, recipe_id, recipe_name, action, user_name, before_json, after_json "
            f"FROM recipe_changes {where} ORDER BY id DESC LIMIT ?",
            (*params, int(limit)),
        )
        return [
            RecipeChange(
                id=int(row["id"]),
                time=parse_utc(row["time"]),
                recipe_id=_opt_int(row["recipe_id"]),
                recipe_name=str(row["recipe_name"]),
                action=str(row["action"]),
                user_name=str(row["user_name"]),
                before_json=row["before_json"],
                after_json=row["after_json"],
            )
            for row in rows
        ]

    # ------------------------------------------------------------------ system parameters

    def get_parameters(self) -> dict[str, float]:
        """Every catalogue parameter's current value, in catalogue order."""
        stored = {
            str(row["name"]): float(row["value"])
            for row in self._conn.execute("SELECT name, value FROM parameters")
        }
        return {spec.name: float(stored.get(spec.name, spec.default)) for spec in PARAMETERS}

    def get_parameter(self, name: str) -> float:
        """One parameter's value (KeyError naming close matches for an unknown name)."""
        spec = parameter_spec(name)
        return self.get_parameters()[spec.name]

    def set_parameter(self, name: str, value: float, user: User) -> None:
        """Change one parameter (validated, role-checked, logged); see :meth:`set_parameters`."""
        self.set_parameters({name: value}, user)

    def set_parameters(
        self, values: Mapping[str, float], user: User, *, logged_as: str | None = None
    ) -> None:
        """Change several parameters in one transaction, each change logged with user and time
        (``logged_as``: the name logged instead of the user's, as in :meth:`save_recipe`).

        Every value is checked against the catalogue and the whole set against the rules
        between parameters before anything is stored: ParameterError lists all problems.
        An unchanged value is not logged.
        """
        errors: list[FieldError] = []
        for name, value in values.items():
            if name not in PARAMETER_BY_NAME:
                errors.append(unknown_parameter(name, value))
                continue
            error = check_parameter_value(PARAMETER_BY_NAME[name], value)
            if error is not None:
                errors.append(error)
        if errors:
            raise ParameterError("parameters", errors)
        with self._write() as conn:
            actor = self._stored_user(user)
            for name in values:
                spec = PARAMETER_BY_NAME[name]
                self.check_role(user, spec.required_role, f"changing {name}")
            current = self.get_parameters()
            proposed = {**current, **{name: float(value) for name, value in values.items()}}
            cross = check_parameter_set(proposed)
            if cross:
                raise ParameterError("parameters", cross)
            now = self._now()
            logged_name = logged_as or actor.name
            for name, value in proposed.items():
                if name not in values or value == current[name]:
                    continue
                conn.execute(
                    "UPDATE parameters SET value = ?, updated_at = ?, updated_by = ? "
                    "WHERE name = ?",
                    (value, now, logged_name, name),
                )
                conn.execute(
                    "INSERT INTO parameter_changes (time, name, old_value, new_value, user_name, "
                    "user_role) VALUES (?, ?, ?, ?, ?, ?)",
                    (now, name, current[name], value, logged_name, actor.role.label),
                )

    def parameter_history(
        self,
        name: str | None = None,
        start: datetime | None = None,
        end: datetime | None = None,
        limit: int = 1000,
    ) -> list[ParameterChange]:
        """Logged parameter changes, last logged first; optionally one parameter, [start, end)."""
        conditions: list[str] = []
        params: list[object] = []
        if name is not None:
            conditions.append("name = ?")
            params.append(name)
        if start is not None:
            conditions.append("time >= ?")
            params.append(format_utc(start))
        if end is not None:
            conditions.append("time < ?")
            params.append(format_utc(end))
        where = f"WHERE {' AND '.join(conditions)}" if conditions else ""
        rows = self._conn.execute(
            "SELECT id, time, name, old_value, new_value, user_name, user_role FROM "
            f"parameter_changes {where} ORDER BY id DESC LIMIT ?",
            (*params, int(limit)),
        )
        return [
            ParameterChange(
                id=int(row["id"]),
                time=parse_utc(row["time"]),
                name=str(row["name"]),
                old_value=_opt_float(row["old_value"]),
                new_value=float(row["new_value"]),
                user_name=str(row["user_name"]),
                user_role=str(row["user_role"]),
            )
            for row in rows
        ]

    # ------------------------------------------------------------------ production

    def record_piece(
        self, record: ProductionRecord, *, skip_if_stored: bool = False
    ) -> ProductionRecord:
        """Store one board's record; returns it as stored (id set, time in UTC).

        A recipe deleted meanwhile does not lose the count: the record keeps the recipe's
        name and its recipe id becomes None. ``skip_if_stored``: a record with the same time,
        recipe name, result and cycle time is already there (a journalled write stored before
        a crash), so nothing is added and that one is returned.
        """
        problems = record.problems()
        if problems:
            raise RecordError("production record not saved: " + "; ".join(problems))
        stored = replace(record, time=to_utc(record.time))
        with self._write() as conn:
            if skip_if_stored:
                row = conn.execute(
                    f"SELECT {_PRODUCTION_COLUMNS} FROM production WHERE time = ? AND "
                    "recipe_name = ? AND result = ? AND cycle_time_s = ?",
                    (
                        format_utc(stored.time),
                        stored.recipe_name,
                        stored.result.value,
                        float(stored.cycle_time_s),
                    ),
                ).fetchone()
                if row is not None:
                    return _production_from_row(row)
            recipe_id: int | None = None
            if record.recipe_id is not None:
                found = conn.execute(
                    "SELECT id FROM recipes WHERE id = ?", (record.recipe_id,)
                ).fetchone()
                recipe_id = None if found is None else int(found["id"])
            fields = production_fields(replace(stored, recipe_id=recipe_id))
            cursor = conn.execute(
                f"INSERT INTO production ({', '.join(fields)}) "
                f"VALUES ({', '.join('?' for _ in fields)})",
                tuple(fields.values()),
            )
        return replace(stored, id=int(cursor.lastrowid or 0), recipe_id=recipe_id)

    def list_production(self, start: datetime, end: datetime) -> list[ProductionRecord]:
        """Records with ``start <= time < end``, oldest first."""
        rows = self._conn.execute(
            f"SELECT {_PRODUCTION_COLUMNS} FROM production WHERE time >= ? AND time < ? "
            "ORDER BY time, id",
            (format_utc(start), format_utc(end)),
        )
        return [_production_from_row(row) for row in rows]

    def piece_counts(self, shift_start: datetime) -> tuple[int, int]:
        """(finished staves since ``shift_start``, finished staves ever); one consistent read."""
        row = self._conn.execute(
            "SELECT (SELECT count(*) FROM production WHERE result = 'ok' AND time >= ?), "
            "(SELECT count(*) FROM production WHERE result = 'ok')",
            (format_utc(shift_start),),
        ).fetchone()
        return int(row[0]), int(row[1])

    # ------------------------------------------------------------------ barrels

    def record_barrel(self, record: BarrelRecord) -> None:
        """Store a barrel set, or its new state (RecordError: the record is invalid)."""
        with self._write() as conn:
            store_barrel(conn, record)

    def record_barrel_stave(self, record: BarrelStaveRecord) -> None:
        """Store one stave of a stored barrel, linked to its production record."""
        with self._write() as conn:
            store_barrel_stave(conn, record)

    def get_barrel(self, number: int) -> BarrelRecord | None:
        return read_barrel(self._conn, number)

    def list_barrels(self, limit: int = 100) -> list[BarrelRecord]:
        """The newest barrels first."""
        return read_barrels(self._conn, limit)

    def barrel_staves(self, number: int) -> list[BarrelStaveRecord]:
        """A barrel's staves in order around it (empty for an unknown barrel)."""
        return read_barrel_staves(self._conn, number)

    def last_barrel_number(self) -> int:
        """The highest barrel number stored (0: none yet); the machine counts on from it."""
        return last_barrel_number(self._conn)

    # ------------------------------------------------------------------ machine state

    def machine_state(self, key: str) -> str | None:
        """A value the machine keeps across a restart (e.g. the interrupted board), or None."""
        row = self._conn.execute("SELECT value FROM machine_state WHERE key = ?", (key,)).fetchone()
        return None if row is None else str(row["value"])

    def set_machine_state(self, key: str, value: str | None) -> None:
        """Store (or with None forget) a value the machine keeps across a restart."""
        with self._write() as conn:
            if value is None:
                conn.execute("DELETE FROM machine_state WHERE key = ?", (key,))
            else:
                conn.execute(
                    "INSERT INTO machine_state (key, value, updated_at) VALUES (?, ?, ?) "
                    "ON CONFLICT (key) DO UPDATE SET value = excluded.value, "
                    "updated_at = excluded.updated_at",
                    (key, value, self._now()),
                )

    # ------------------------------------------------------------------ alarms

    def record_alarm_event(self, event: AlarmEvent, *, skip_if_stored: bool = False) -> AlarmEvent:
        """Store one alarm state transition; returns it as stored (id set, time in UTC).

        ``skip_if_stored``: the same transition (time, code, source, states) is already there,
        so nothing is added and that one is returned.
        """
        problems = event.problems()
        if problems:
            raise RecordError("alarm event not saved: " + "; ".join(problems))
        stored = replace(event, time=to_utc(event.time))
        with self._write() as conn:
            if skip_if_stored:
                row = conn.execute(
                    f"SELECT {_ALARM_COLUMNS} FROM alarm_events WHERE time = ? AND code = ? "
                    "AND source = ? AND from_state = ? AND to_state = ?",
                    (
                        format_utc(stored.time),
                        stored.code,
                        stored.source,
                        stored.from_state.value,
                        stored.to_state.value,
                    ),
                ).fetchone()
                if row is not None:
                    return _alarm_from_row(row)
            new_id = self._insert_alarm(conn, stored)
        return replace(stored, id=new_id)

    @staticmethod
    def _insert_alarm(conn: sqlite3.Connection, event: AlarmEvent) -> int:
        fields = alarm_fields(event)
        cursor = conn.execute(
            f"INSERT INTO alarm_events ({', '.join(fields)}) "
            f"VALUES ({', '.join('?' for _ in fields)})",
            tuple(fields.values()),
        )
        return int(cursor.lastrowid or 0)

    def list_alarm_events(self, filters: AlarmEventFilter | None = None) -> list[AlarmEvent]:
        """Alarm transitions matching ``filters`` (all of them if None), newest first."""
        chosen = AlarmEventFilter() if filters is None else filters
        conditions: list[str] = []
        params: list[object] = []
        if chosen.start is not None:
            conditions.append("time >= ?")
            params.append(format_utc(chosen.start))
        if chosen.end is not None:
            conditions.append("time < ?")
            params.append(format_utc(chosen.end))
        if chosen.code is not None:
            conditions.append("code = ?")
            params.append(chosen.code)
        if chosen.source is not None:
            conditions.append("source = ?")
            params.append(chosen.source)
        where = f"WHERE {' AND '.join(conditions)}" if conditions else ""
        rows = self._conn.execute(
            f"SELECT {_ALARM_COLUMNS} FROM alarm_events {where} ORDER BY time DESC, id DESC "
            "LIMIT ?",
            (*params, int(chosen.limit)),
        )
        return [_alarm_from_row(row) for row in rows]
