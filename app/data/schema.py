"""The database schema as an ordered list of forward migrations.

The schema version lives in SQLite's ``PRAGMA user_version`` (in the file header, written in the
same transaction as the tables it describes), so a database is always at exactly one version:
a crash during a migration leaves it at the old version with the old tables. Migrations only go
forward; software that finds a newer version than it knows refuses to open the file rather than
guess. Tables are STRICT and carry CHECK constraints as a last line of defence: the Python layer
validates everything first, the constraints make sure nothing invalid gets in by another path.

To change the schema, append a Migration with the next version number; never edit a released
one (databases in the field are already at it).
"""

from __future__ import annotations

import sqlite3
from dataclasses import dataclass


@dataclass(frozen=True)
class Migration:
    """One step of the schema: the statements that take version - 1 to ``version``."""

    version: int
    description: str
    statements: tuple[str, ...]


_ALARM_STATES = "'normal', 'active_unacked', 'active_acked', 'returned_unacked', 'shelved'"
# Written out (not taken from ProfileKind): a released migration never changes.
_PROFILE_KINDS = "'line_arc_line', 'single_arc', 'parabola', 'ellipse', 'superellipse', 'drawn'"

MIGRATIONS: tuple[Migration, ...] = (
    Migration(
        1,
        "recipes, users, system parameters and their change log, production, alarm history",
        (
            """
            CREATE TABLE recipes (
                id INTEGER PRIMARY KEY,
                name TEXT NOT NULL COLLATE NOCASE UNIQUE
                    CHECK (length(name) BETWEEN 1 AND 40 AND name = trim(name)),
                length_mm REAL NOT NULL CHECK (length_mm > 0),
                thickness_mm REAL NOT NULL CHECK (thickness_mm > 0),
                length_ratio_num INTEGER NOT NULL CHECK (length_ratio_num >= 0),
                length_ratio_den INTEGER NOT NULL CHECK (length_ratio_den > 0),
                length_ratio REAL GENERATED ALWAYS AS
                    (CAST(length_ratio_num AS REAL) / length_ratio_den) VIRTUAL,
                width_ratio_num INTEGER NOT NULL CHECK (width_ratio_num > 0),
                width_ratio_den INTEGER NOT NULL CHECK (width_ratio_den > 0),
                width_ratio REAL GENERATED ALWAYS AS
                    (CAST(width_ratio_num AS REAL) / width_ratio_den) VIRTUAL,
                tilt_mode TEXT NOT NULL CHECK (tilt_mode IN ('fixed', 'barrel')),
                tilt_deg REAL NOT NULL,
                barrel_diameter_mm REAL
                    CHECK (barrel_diameter_mm IS NULL OR barrel_diameter_mm > 0),
                barrel_perimeter_mm REAL
                    CHECK (barrel_perimeter_mm IS NULL OR barrel_perimeter_mm > 0),
                note TEXT NOT NULL DEFAULT '',
                created_at TEXT NOT NULL,
                created_by TEXT NOT NULL,
                updated_at TEXT NOT NULL,
                updated_by TEXT NOT NULL,
                CHECK (tilt_mode = 'fixed' OR barrel_diameter_mm IS NOT NULL)
            ) STRICT
            """,
            """
            CREATE TABLE users (
                id INTEGER PRIMARY KEY,
                name TEXT NOT NULL COLLATE NOCASE UNIQUE CHECK (length(name) BETWEEN 1 AND 40),
                role TEXT NOT NULL CHECK (role IN ('operator', 'technician', 'service')),
                pin_hash TEXT NOT NULL CHECK (pin_hash LIKE 'scrypt$%'),
                updated_at TEXT NOT NULL
            ) STRICT
            """,
            """
            CREATE TABLE parameters (
                name TEXT PRIMARY KEY,
                value REAL NOT NULL,
                updated_at TEXT NOT NULL,
                updated_by TEXT NOT NULL
            ) STRICT
            """,
            """
            CREATE TABLE parameter_changes (
                id INTEGER PRIMARY KEY,
                time TEXT NOT NULL,
                name TEXT NOT NULL,
                old_value REAL,
                new_value REAL NOT NULL,
                user_name TEXT NOT NULL,
                user_role TEXT NOT NULL
            ) STRICT
            """,
            "CREATE INDEX parameter_changes_time ON parameter_changes (time)",
            """
            CREATE TABLE production (
                id INTEGER PRIMARY KEY,
                time TEXT NOT NULL,
                recipe_id INTEGER REFERENCES recipes (id) ON DELETE SET NULL,
                recipe_name TEXT NOT NULL,
                width_mm REAL,
                d_mm REAL,
                r_mm REAL,
                tilt_deg REAL,
                cycle_time_s REAL NOT NULL CHECK (cycle_time_s >= 0),
                result TEXT NOT NULL CHECK (result IN ('ok', 'rejected', 'aborted')),
                alarm_code TEXT
            ) STRICT
            """,
            "CREATE INDEX production_time ON production (time)",
            "CREATE INDEX production_result_time ON production (result, time)",
            f"""
            CREATE TABLE alarm_events (
                id INTEGER PRIMARY KEY,
                time TEXT NOT NULL,
                code TEXT NOT NULL,
                text TEXT NOT NULL,
                source TEXT NOT NULL,
                from_state TEXT NOT NULL CHECK (from_state IN ({_ALARM_STATES})),
                to_state TEXT NOT NULL CHECK (to_state IN ({_ALARM_STATES})),
                user_name TEXT,
                CHECK (from_state <> to_state)
            ) STRICT
            """,
            "CREATE INDEX alarm_events_time ON alarm_events (time)",
        ),
    ),
    Migration(
        2,
        "recipe change history (the last version of a deleted recipe is never lost)",
        (
            """
            CREATE TABLE recipe_changes (
                id INTEGER PRIMARY KEY,
                time TEXT NOT NULL,
                recipe_id INTEGER,
                recipe_name TEXT NOT NULL,
                action TEXT NOT NULL CHECK (action IN ('create', 'update', 'delete')),
                user_name TEXT NOT NULL,
                before_json TEXT,
                after_json TEXT
            ) STRICT
            """,
            "CREATE INDEX recipe_changes_recipe ON recipe_changes (recipe_id, time)",
        ),
    ),
    Migration(
        3,
        "wrong-PIN counter and lockout (one row, shared by the panel, the tools and the API)",
        (
            """
            CREATE TABLE pin_guard (
                id INTEGER PRIMARY KEY CHECK (id = 1),
                failures INTEGER NOT NULL CHECK (failures >= 0),
                last_failure_at TEXT,
                locked_until TEXT
            ) STRICT
            """,
            "INSERT INTO pin_guard (id, failures) VALUES (1, 0)",
        ),
    ),
    Migration(
        4,
        "side profiles of any shape: the kind, and its parameters or drawing as JSON",
        (
            f"""
            ALTER TABLE recipes ADD COLUMN profile_kind TEXT NOT NULL DEFAULT 'line_arc_line'
                CHECK (profile_kind IN ({_PROFILE_KINDS}))
            """,
            """
            ALTER TABLE recipes ADD COLUMN profile_json TEXT
                CHECK (profile_json IS NULL OR json_valid(profile_json))
            """,
        ),
    ),
    Migration(
        5,
        "oval barrels (the short belly axis) and fixed belly widths in recipes",
        (
            "ALTER TABLE recipes ADD COLUMN barrel_minor_diameter_mm REAL "
            "CHECK (barrel_minor_diameter_mm IS NULL OR barrel_minor_diameter_mm > 0)",
            "ALTER TABLE recipes ADD COLUMN target_width_mm REAL "
            "CHECK (target_width_mm IS NULL OR target_width_mm > 0)",
        ),
    ),
    Migration(
        6,
        "resumed boards in production; the machine's state that outlives a restart",
        (
            "ALTER TABLE production ADD COLUMN resumed INTEGER NOT NULL DEFAULT 0 "
            "CHECK (resumed IN (0, 1))",
            """
            CREATE TABLE machine_state (
                key TEXT PRIMARY KEY CHECK (length(key) BETWEEN 1 AND 40),
                value TEXT NOT NULL,
                updated_at TEXT NOT NULL
            ) STRICT
            """,
        ),
    ),
    Migration(
        7,
        "OPC UA users of the plant connection (user name, role, salted scrypt password hash)",
        (
            """
            CREATE TABLE opcua_users (
                id INTEGER PRIMARY KEY,
                name TEXT NOT NULL COLLATE NOCASE UNIQUE
                    CHECK (length(name) BETWEEN 1 AND 40 AND name = trim(name)),
                role TEXT NOT NULL CHECK (role IN ('read-only', 'plant')),
                password_hash TEXT NOT NULL CHECK (password_hash LIKE 'scrypt$%'),
                updated_at TEXT NOT NULL
            ) STRICT
            """,
        ),
    ),
    Migration(
        8,
        "the time of each cycle step in production (where the seconds of a board went)",
        (
            "ALTER TABLE production ADD COLUMN step_times_json TEXT "
            "CHECK (step_times_json IS NULL OR json_valid(step_times_json))",
        ),
    ),
    Migration(
        9,
        "barrel sets and their staves; each production record names its barrel and stave",
        (
            """
            CREATE TABLE barrels (
                number INTEGER PRIMARY KEY CHECK (number > 0),
                recipe_id INTEGER REFERENCES recipes (id) ON DELETE SET NULL,
                recipe_name TEXT NOT NULL,
                barrel_type TEXT NOT NULL CHECK (barrel_type IN ('round', 'oval')),
                belly_major_mm REAL NOT NULL CHECK (belly_major_mm > 0),
                belly_minor_mm REAL NOT NULL
                    CHECK (belly_minor_mm > 0 AND belly_minor_mm <= belly_major_mm),
                started_at TEXT NOT NULL,
                finished_at TEXT,
                state TEXT NOT NULL CHECK (state IN ('open', 'closed', 'abandoned')),
                CHECK ((state = 'open') = (finished_at IS NULL))
            ) STRICT
            """,
            """
            CREATE TABLE barrel_staves (
                barrel_number INTEGER NOT NULL REFERENCES barrels (number),
                number INTEGER NOT NULL CHECK (number > 0),
                time TEXT NOT NULL,
                board_width_mm REAL NOT NULL CHECK (board_width_mm > 0),
                width_mm REAL NOT NULL CHECK (width_mm > 0 AND width_mm <= board_width_mm),
                start_angle_deg REAL NOT NULL,
                end_angle_deg REAL NOT NULL CHECK (end_angle_deg > start_angle_deg),
                bevel_a_deg REAL NOT NULL,
                bevel_b_deg REAL NOT NULL,
                closing INTEGER NOT NULL CHECK (closing IN (0, 1)),
                production_id INTEGER REFERENCES production (id) ON DELETE SET NULL,
                PRIMARY KEY (barrel_number, number)
            ) STRICT
            """,
            "ALTER TABLE production ADD COLUMN barrel_number INTEGER "
            "CHECK (barrel_number IS NULL OR barrel_number > 0)",
            "ALTER TABLE production ADD COLUMN stave_number INTEGER "
            "CHECK ((stave_number IS NULL) = (barrel_number IS NULL) "
            "AND (stave_number IS NULL OR stave_number > 0))",
            "CREATE INDEX production_barrel ON production (barrel_number, stave_number)",
        ),
    ),
    Migration(
        10,
        "each production record names the operator of the shift (who named himself)",
        (
            "ALTER TABLE production ADD COLUMN operator_name TEXT "
            "CHECK (operator_name IS NULL OR length(operator_name) BETWEEN 1 AND 40)",
        ),
    ),
    Migration(
        11,
        "each alarm transition keeps its message as a reason and arguments, so the history is "
        "shown in the user's language",
        (
            "ALTER TABLE alarm_events ADD COLUMN detail_json TEXT "
            "CHECK (detail_json IS NULL OR json_valid(detail_json))",
        ),
    ),
    Migration(
        12,
        "the recipe's barrel type chosen, not guessed: fixed tilt, round or oval",
        (
            "ALTER TABLE recipes ADD COLUMN barrel_type TEXT NOT NULL DEFAULT 'fixed' "
            "CHECK (barrel_type IN ('fixed', 'round', 'oval'))",
            # What the recipe meant until now: a barrel with a short axis was oval.
            "UPDATE recipes SET barrel_type = CASE WHEN tilt_mode = 'fixed' THEN 'fixed' "
            "WHEN barrel_minor_diameter_mm IS NULL THEN 'round' ELSE 'oval' END",
        ),
    ),
)

SCHEMA_VERSION = MIGRATIONS[-1].version

# Tables a database must have at SCHEMA_VERSION (restore checks a file against this).
REQUIRED_TABLES = frozenset(
    {
        "recipes",
        "users",
        "parameters",
        "parameter_changes",
        "production",
        "alarm_events",
        "recipe_changes",
        "pin_guard",
        "barrels",
        "barrel_staves",
    }
)


def read_schema_version(conn: sqlite3.Connection) -> int:
    """The version stored in the file (0 for a new, empty database)."""
    row = conn.execute("PRAGMA user_version").fetchone()
    return int(row[0])


def user_table_names(conn: sqlite3.Connection) -> set[str]:
    """Names of the tables in the file, SQLite's own excluded."""
    rows = conn.execute(
        "SELECT name FROM sqlite_master WHERE type = 'table' AND name NOT LIKE 'sqlite_%'"
    ).fetchall()
    return {str(row[0]) for row in rows}


def apply_migrations(conn: sqlite3.Connection, current: int, target: int = SCHEMA_VERSION) -> None:
    """Run the migrations after ``current`` up to ``target`` and record the new version.

    The caller owns the transaction: this runs inside it, so all steps commit or none does.
    """
    if not 0 <= current <= target <= SCHEMA_VERSION:
        raise ValueError(f"cannot migrate from version {current} to {target}")
    for migration in MIGRATIONS:
        if current < migration.version <= target:
            for statement in migration.statements:
                conn.execute(statement)
    conn.execute(f"PRAGMA user_version = {int(target)}")
