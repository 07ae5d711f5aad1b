"""The Database: creation, migrations, recipes, production, alarms, users, and that nothing
invalid is ever stored."""

from __future__ import annotations

import json
import math
import sqlite3
from dataclasses import replace
from datetime import UTC, datetime, timedelta
from pathlib import Path

import pytest

from app.data.database import PAGE_CACHE_KIB, Database, default_database_path
from app.data.errors import (
    DatabaseOpenError,
    NotFoundError,
    PermissionDeniedError,
    PinError,
    RecipeValidationError,
    RecordError,
    SchemaVersionError,
    StorageError,
)
from app.data.paths import DATABASE_PATH_ENV
from app.data.pending import AlarmWrite, decode_write, encode_write
from app.data.recipe import BarrelType, Recipe, recipe_from_mapping
from app.data.recipe_files import load_recipe_file
from app.data.records import (
    AlarmEvent,
    AlarmEventFilter,
    AlarmState,
    PieceResult,
    ProductionRecord,
)
from app.data.schema import MIGRATIONS, SCHEMA_VERSION, apply_migrations
from app.data.users import DEFAULT_USERS, Role, User
from app.geometry.ratio import Ratio

from .conftest import SimClock
from .test_recipe import make_recipe

T0 = datetime(2024, 5, 2, 6, 0, tzinfo=UTC)


def piece(minutes: float, **changes: object) -> ProductionRecord:
    record = ProductionRecord(
        time=T0 + timedelta(minutes=minutes),
        recipe_id=1,
        recipe_name="Barrique 225 l Bordeaux",
        width_mm=120.0,
        d_mm=12.5,
        r_mm=5005.2,
        cycle_time_s=88.5,
        result=PieceResult.OK,
        tilt_deg=9.2,
    )
    return replace(record, **changes)  # type: ignore[arg-type]


def count(db_path: Path, table: str) -> int:
    with sqlite3.connect(db_path) as conn:
        return int(conn.execute(f"SELECT count(*) FROM {table}").fetchone()[0])


# ----------------------------------------------------------------------------- opening


def test_default_path_is_in_the_user_data_directory(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(DATABASE_PATH_ENV, raising=False)
    path = default_database_path()
    assert path.name == "stave.db" and path.parent.name == "stave-jointer"
    monkeypatch.setenv(DATABASE_PATH_ENV, "/srv/stave/custom.db")
    assert default_database_path() == Path("/srv/stave/custom.db")


def test_a_new_database_is_complete(db: Database, db_path: Path) -> None:
    assert db.schema_version == SCHEMA_VERSION
    samples = load_recipe_file(Path("resources/recipes/sample_recipes.json"))
    assert [r.name for r in db.list_recipes()] == [r.name for r in samples]
    assert [replace(r, id=None) for r in db.list_recipes()] == samples
    assert [(u.name, u.role) for u in db.list_users()] == [(n, r) for n, r, _ in DEFAULT_USERS]
    assert db.integrity_problems() == []


def test_the_connection_is_wal_synchronous_full_with_foreign_keys(db_path: Path) -> None:
    with Database.open(db_path) as database:
        conn = database._conn
        assert conn.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
        assert conn.execute("PRAGMA synchronous").fetchone()[0] == 2  # FULL
        assert conn.execute("PRAGMA foreign_keys").fetchone()[0] == 1
        # the page cache, the one memory that grows with the file, is bounded
        assert conn.execute("PRAGMA cache_size").fetchone()[0] == -PAGE_CACHE_KIB
    with Database.open(db_path, page_cache_kib=256) as small:  # the machine's record writer
        assert small._conn.execute("PRAGMA cache_size").fetchone()[0] == -256


def test_reopening_adds_nothing(db_path: Path) -> None:
    before = count(db_path, "recipes"), count(db_path, "users"), count(db_path, "parameters")
    Database.open(db_path).close()
    Database.open(db_path).close()
    after = count(db_path, "recipes"), count(db_path, "users"), count(db_path, "parameters")
    assert after == before


def test_a_new_database_without_samples(tmp_path: Path) -> None:
    with Database.open(tmp_path / "deep" / "er" / "empty.db", load_samples=False) as database:
        assert database.list_recipes() == []
        assert len(database.list_users()) == 3


def test_invalid_sample_recipes_are_refused_and_nothing_is_created(tmp_path: Path) -> None:
    samples = tmp_path / "samples.json"
    samples.write_text(
        json.dumps(
            [
                {
                    "name": "short",
                    "length_mm": 500,
                    "thickness_mm": 27,
                    "length_ratio": "1/4",
                    "width_ratio": "4/5",
                    "tilt_deg": 9,
                }
            ]
        )
    )
    path = tmp_path / "new.db"
    with pytest.raises(RecipeValidationError, match="length_mm"):
        Database.open(path, samples_path=samples)
    with sqlite3.connect(path) as conn:  # the creation transaction was rolled back
        assert conn.execute("PRAGMA user_version").fetchone()[0] == 0
        assert conn.execute("SELECT count(*) FROM sqlite_master").fetchone()[0] == 0
    with Database.open(path) as database:  # and the next start creates it properly
        assert len(database.list_recipes()) >= 6


def test_a_file_that_is_not_a_database_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "notes.db"
    path.write_bytes(b"these are not the pages you are looking for" * 100)
    with pytest.raises(DatabaseOpenError, match="not a usable"):
        Database.open(path)


def test_another_applications_database_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "other.db"
    with sqlite3.connect(path) as conn:
        conn.execute("CREATE TABLE invoices (id INTEGER PRIMARY KEY)")
    with pytest.raises(DatabaseOpenError, match="invoices"):
        Database.open(path)


def test_a_database_from_newer_software_is_refused(db_path: Path) -> None:
    with sqlite3.connect(db_path) as conn:
        conn.execute(f"PRAGMA user_version = {SCHEMA_VERSION + 1}")
    with pytest.raises(SchemaVersionError, match="newer software"):
        Database.open(db_path)


def test_forward_migration_keeps_the_data(tmp_path: Path) -> None:
    """A version-1 database (older software) is migrated on open and keeps its recipes."""
    assert [m.version for m in MIGRATIONS] == list(range(1, SCHEMA_VERSION + 1))
    path = tmp_path / "v1.db"
    conn = sqlite3.connect(path, isolation_level=None)
    conn.execute("BEGIN")
    apply_migrations(conn, 0, 1)
    conn.execute(
        "INSERT INTO recipes (name, length_mm, thickness_mm, length_ratio_num, length_ratio_den, "
        "width_ratio_num, width_ratio_den, tilt_mode, tilt_deg, created_at, created_by, "
        "updated_at, updated_by) VALUES ('Old', 1000, 30, 1, 4, 3, 4, 'fixed', 8, 't', 'u', "
        "'t', 'u')"
    )
    conn.execute("COMMIT")
    conn.close()
    with Database.open(path) as database:
        assert database.schema_version == SCHEMA_VERSION
        [old] = database.list_recipes()  # not a new database: no samples added
        assert (old.name, old.width_ratio) == ("Old", Ratio(3, 4))
        assert (old.barrel_minor_diameter_mm, old.target_width_mm) == (None, None)  # v5
        database.record_piece(piece(0))
        [record] = database.list_production(T0, T0 + timedelta(hours=1))
        assert record.step_times_s == {}  # v8: a record without step times
        assert record.operator_name is None  # v10: a record naming no operator
        users = {u.role: u for u in database.list_users()}
        assert users == {}  # v1 files made by older software had their own users
        assert database.recipe_history() == []  # the v2 table exists and works


def test_migration_10_states_the_barrel_type_each_recipe_meant(tmp_path: Path) -> None:
    """Before version 12 round or oval was guessed from the short axis; the migration writes
    down what each recipe meant, and the type is then the recipe's own choice."""
    path = tmp_path / "v9.db"
    conn = sqlite3.connect(path, isolation_level=None)
    conn.execute("BEGIN")
    apply_migrations(conn, 0, 9)
    for name, mode, major, minor in (
        ("Fixed", "fixed", None, None),
        ("Round", "barrel", 700.0, None),
        ("Oval", "barrel", 700.0, 500.0),
    ):
        conn.execute(
            "INSERT INTO recipes (name, length_mm, thickness_mm, length_ratio_num, "
            "length_ratio_den, width_ratio_num, width_ratio_den, tilt_mode, tilt_deg, "
            "barrel_diameter_mm, barrel_minor_diameter_mm, created_at, created_by, updated_at, "
            "updated_by) VALUES (?, 1000, 30, 1, 4, 3, 4, ?, 8, ?, ?, 't', 'u', 't', 'u')",
            (name, mode, major, minor),
        )
    conn.execute("COMMIT")
    conn.close()
    with Database.open(path) as database:
        types = {r.name: r.barrel_type for r in database.list_recipes()}
    assert types == {
        "Fixed": BarrelType.FIXED_TILT,
        "Round": BarrelType.ROUND,
        "Oval": BarrelType.OVAL,
    }
    with sqlite3.connect(path) as conn, pytest.raises(sqlite3.IntegrityError):
        conn.execute("UPDATE recipes SET barrel_type = 'egg'")


# ----------------------------------------------------------------------------- recipes


def test_save_get_update_copy_delete(db: Database, users: dict[Role, User]) -> None:
    operator, technician = users[Role.OPERATOR], users[Role.TECHNICIAN]
    saved = db.save_recipe(make_recipe(name="New barrel"), operator)
    assert saved.id is not None
    assert db.get_recipe(saved.id) == saved
    assert db.get_recipe_by_name("NEW BARREL") == saved  # letter case ignored

    changed = db.save_recipe(replace(saved, thickness_mm=30.0, note="thicker"), operator)
    assert db.get_recipe(saved.id) == changed
    assert changed.id == saved.id

    copy = db.copy_recipe(saved.id, "New barrel 2", operator)
    assert copy.id != saved.id and replace(copy, id=None, name="") == replace(
        changed, id=None, name=""
    )

    with pytest.raises(PermissionDeniedError, match="technician"):
        db.delete_recipe(saved.id, operator)
    assert db.delete_recipe(saved.id, technician) == changed
    with pytest.raises(NotFoundError):
        db.get_recipe(saved.id)
    assert db.get_recipe_by_name("New barrel") is None


def test_the_ratio_decimals_are_derived_in_the_table(db: Database, db_path: Path) -> None:
    with sqlite3.connect(db_path) as conn:
        rows = conn.execute(
            "SELECT length_ratio_num, length_ratio_den, length_ratio, width_ratio_num, "
            "width_ratio_den, width_ratio FROM recipes"
        ).fetchall()
    assert rows
    for ln, ld, lv, wn, wd, wv in rows:
        assert (lv, wv) == (ln / ld, wn / wd)


def test_an_invalid_recipe_stores_nothing(db: Database, users: dict[Role, User]) -> None:
    before = db.list_recipes()
    history = db.recipe_history()
    with pytest.raises(RecipeValidationError) as caught:
        db.save_recipe(make_recipe(length_mm=5000.0, thickness_mm=10.0), users[Role.SERVICE])
    assert {e.field for e in caught.value.errors} == {"length_mm", "thickness_mm"}
    existing = before[0]
    with pytest.raises(RecipeValidationError, match="width_ratio"):
        db.save_recipe(replace(existing, width_ratio=Ratio(1, 1)), users[Role.SERVICE])
    assert db.list_recipes() == before
    assert db.recipe_history() == history


def test_names_are_unique_ignoring_letter_case(db: Database, users: dict[Role, User]) -> None:
    taken = db.list_recipes()[0].name
    with pytest.raises(RecipeValidationError, match="already used") as caught:
        db.save_recipe(make_recipe(name=taken.upper()), users[Role.OPERATOR])
    accented = db.get_recipe_by_name("PIÈCE 228 L BOURGOGNE")  # not only ASCII letters
    assert accented is not None and accented.name == "Pièce 228 l Bourgogne"
    with pytest.raises(RecipeValidationError, match="already used"):
        db.save_recipe(make_recipe(name="PIÈCE 228 l Bourgogne"), users[Role.OPERATOR])
    assert caught.value.errors[0].field == "name"
    with pytest.raises(RecipeValidationError, match="already used"):
        db.copy_recipe(db.list_recipes()[1].id or 0, taken, users[Role.OPERATOR])


def test_a_batch_is_all_or_nothing(db: Database, users: dict[Role, User]) -> None:
    before = db.list_recipes()
    batch = [make_recipe(name="A"), make_recipe(name="B"), make_recipe(name="a")]  # clash
    with pytest.raises(RecipeValidationError, match="already used"):
        db.save_recipes(batch, users[Role.OPERATOR])
    assert db.list_recipes() == before


def test_updating_a_deleted_recipe_is_refused(db: Database, users: dict[Role, User]) -> None:
    recipe = db.list_recipes()[0]
    db.delete_recipe(recipe.id or 0, users[Role.TECHNICIAN])
    with pytest.raises(NotFoundError, match="does not exist"):
        db.save_recipe(replace(recipe, note="edited on a stale screen"), users[Role.OPERATOR])
    with pytest.raises(NotFoundError):
        db.delete_recipe(recipe.id or 0, users[Role.TECHNICIAN])


def test_a_deleted_recipe_can_be_recovered_from_the_history(
    db: Database, users: dict[Role, User], clock: SimClock
) -> None:
    recipe = db.list_recipes()[2]
    clock.advance(10)
    db.delete_recipe(recipe.id or 0, users[Role.TECHNICIAN])
    change, created = db.recipe_history(recipe.id)
    assert (created.action, created.user_name) == ("create", "system")  # loaded as a sample
    assert (change.action, change.user_name, change.time) == ("delete", "technician", clock.now)
    assert change.after_json is None and change.before_json is not None
    recovered = recipe_from_mapping(json.loads(change.before_json))
    assert recovered == replace(recipe, id=None)
    assert db.save_recipe(recovered, users[Role.OPERATOR]).name == recipe.name


def test_the_history_records_create_and_update(db: Database, users: dict[Role, User]) -> None:
    created = db.save_recipe(make_recipe(name="Logged"), users[Role.OPERATOR])
    db.save_recipe(replace(created, tilt_deg=8.0), users[Role.TECHNICIAN])
    db.save_recipe(replace(created, tilt_deg=8.0), users[Role.TECHNICIAN])  # no change: no log
    update, create = db.recipe_history(created.id)
    assert (create.action, create.user_name, create.before_json) == ("create", "operator", None)
    assert (update.action, update.user_name) == ("update", "technician")
    assert json.loads(update.before_json or "")["tilt_deg"] == 9.0
    assert json.loads(update.after_json or "")["tilt_deg"] == 8.0


def test_the_tables_refuse_what_the_code_would_never_write(db_path: Path) -> None:
    """CHECK constraints and STRICT types: the last line of defence against other writers."""
    bad_rows = [
        "INSERT INTO recipes (name, length_mm, thickness_mm, length_ratio_num, length_ratio_den,"
        " width_ratio_num, width_ratio_den, tilt_mode, tilt_deg, created_at, created_by,"
        " updated_at, updated_by) VALUES ('x', 1000, 30, 1, 0, 3, 4, 'fixed', 8, 't','u','t','u')",
        "INSERT INTO recipes (name, length_mm, thickness_mm, length_ratio_num, length_ratio_den,"
        " width_ratio_num, width_ratio_den, tilt_mode, tilt_deg, created_at, created_by,"
        " updated_at, updated_by) VALUES ('x', 1000, 30, 1, 4, 3, 4, 'barrel', 8, 't','u','t','u')",
        "INSERT INTO recipes (name, length_mm, thickness_mm, length_ratio_num, length_ratio_den,"
        " width_ratio_num, width_ratio_den, tilt_mode, tilt_deg, created_at, created_by,"
        " updated_at, updated_by)"
        " VALUES ('x', 'long', 30, 1, 4, 3, 4, 'fixed', 8, 't','u','t','u')",
        "INSERT INTO production (time, recipe_name, cycle_time_s, result) VALUES"
        " ('t', 'r', -1, 'ok')",
        "INSERT INTO production (time, recipe_name, cycle_time_s, result) VALUES"
        " ('t', 'r', 1, 'good')",
        "INSERT INTO alarm_events (time, code, text, source, from_state, to_state) VALUES"
        " ('t', 'c', 'x', 's', 'normal', 'normal')",
    ]
    with sqlite3.connect(db_path) as conn:
        for statement in bad_rows:
            with pytest.raises(sqlite3.IntegrityError):
                conn.execute(statement)


# ----------------------------------------------------------------------------- production


def test_pieces_are_recorded_listed_and_counted(db: Database) -> None:
    stored = [db.record_piece(piece(m)) for m in (0, 90, 180)]
    db.record_piece(
        piece(
            200,
            result=PieceResult.REJECTED,
            width_mm=None,
            d_mm=None,
            r_mm=None,
            alarm_code="W_RANGE",
        )
    )
    db.record_piece(piece(300, result=PieceResult.ABORTED, alarm_code="ESTOP"))
    assert [r.id for r in stored] == [1, 2, 3]
    listed = db.list_production(T0, T0 + timedelta(days=1))
    assert listed[:3] == stored
    assert [r.result for r in listed] == [PieceResult.OK] * 3 + [
        PieceResult.REJECTED,
        PieceResult.ABORTED,
    ]
    assert listed[3].width_mm is None and listed[3].alarm_code == "W_RANGE"
    # [start, end): the piece at exactly T0+90 min belongs to the later window.
    assert [r.id for r in db.list_production(T0, T0 + timedelta(minutes=90))] == [1]
    assert db.piece_counts(T0 + timedelta(minutes=90)) == (2, 3)  # ok pieces: shift, total
    assert db.piece_counts(T0 + timedelta(days=1)) == (0, 3)


def test_the_step_times_are_kept_with_the_record(db: Database) -> None:
    steps = {"centering": 0.8, "side_a": 9.12, "waiting": 0.0}
    stored = db.record_piece(piece(0, step_times_s=steps))
    [listed] = db.list_production(T0, T0 + timedelta(hours=1))
    assert listed == stored and listed.step_times_s == steps
    assert db.integrity_problems() == []


def test_the_operator_of_the_shift_is_kept_with_the_record(db: Database) -> None:
    stored = db.record_piece(piece(0, operator_name="Marko Novak"))
    unnamed = db.record_piece(piece(1))  # a record from before operators were named
    listed = db.list_production(T0, T0 + timedelta(hours=1))
    assert listed == [stored, unnamed]
    assert [r.operator_name for r in listed] == ["Marko Novak", None]
    for name in ("", " ", "x" * 41):
        with pytest.raises(RecordError, match="operator_name"):
            db.record_piece(piece(2, operator_name=name))


def test_a_naive_time_is_local_time(db: Database) -> None:
    local = datetime(2024, 5, 2, 10, 30)
    stored = db.record_piece(piece(0, time=local))
    assert stored.time == local.astimezone(UTC)
    assert db.list_production(stored.time, stored.time + timedelta(seconds=1)) == [stored]


def test_a_count_survives_the_deletion_of_its_recipe(db: Database, users: dict[Role, User]) -> None:
    recipe = db.save_recipe(make_recipe(name="Short-lived"), users[Role.OPERATOR])
    first = db.record_piece(piece(0, recipe_id=recipe.id, recipe_name=recipe.name))
    db.delete_recipe(recipe.id or 0, users[Role.TECHNICIAN])
    # ... and a piece finished after the deletion (the machine had the recipe loaded).
    late = db.record_piece(piece(2, recipe_id=recipe.id, recipe_name=recipe.name))
    assert late.recipe_id is None
    records = db.list_production(T0, T0 + timedelta(hours=1))
    assert [(r.id, r.recipe_id, r.recipe_name) for r in records] == [
        (first.id, None, "Short-lived"),
        (late.id, None, "Short-lived"),
    ]
    assert db.integrity_problems() == []


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"width_mm": math.nan}, "width_mm"),
        ({"d_mm": math.inf}, "d_mm"),
        ({"cycle_time_s": -1.0}, "cycle_time_s"),
        ({"recipe_name": " "}, "recipe_name"),
        ({"result": "ok"}, "result"),
        ({"width_mm": None}, "width_mm"),  # a finished piece has a width
        ({"alarm_code": ""}, "alarm_code"),
        ({"time": "yesterday"}, "time"),
        ({"step_times_s": {"side_a": -1.0}}, "step_times_s"),
        ({"step_times_s": {"": 1.0}}, "step_times_s"),
        ({"step_times_s": [1.0]}, "step_times_s"),
    ],
)
def test_an_invalid_record_is_refused(db: Database, changes: dict[str, object], field: str) -> None:
    with pytest.raises(RecordError, match=field):
        db.record_piece(piece(0, **changes))
    assert db.list_production(T0 - timedelta(days=1), T0 + timedelta(days=1)) == []


# ----------------------------------------------------------------------------- alarms


def alarm(minutes: float, code: str, source: str, a: AlarmState, b: AlarmState) -> AlarmEvent:
    return AlarmEvent(T0 + timedelta(minutes=minutes), code, f"{code} text", source, a, b)


def test_alarm_history_with_filters(db: Database) -> None:
    n, au, aa = AlarmState.NORMAL, AlarmState.ACTIVE_UNACKED, AlarmState.ACTIVE_ACKED
    events = [
        alarm(0, "FOLLOWING_ERROR", "X", n, au),
        alarm(1, "FOLLOWING_ERROR", "X", au, aa),
        alarm(2, "ESTOP", "estop", n, au),
        alarm(3, "FOLLOWING_ERROR", "X", aa, n),
    ]
    stored = [db.record_alarm_event(e) for e in events]
    assert all(s.id is not None for s in stored)
    assert db.list_alarm_events() == stored[::-1]  # newest first
    assert [e.id for e in db.list_alarm_events(AlarmEventFilter(code="ESTOP"))] == [3]
    assert len(db.list_alarm_events(AlarmEventFilter(source="X"))) == 3
    window = AlarmEventFilter(start=T0 + timedelta(minutes=1), end=T0 + timedelta(minutes=3))
    assert [e.id for e in db.list_alarm_events(window)] == [3, 2]
    assert len(db.list_alarm_events(AlarmEventFilter(limit=2))) == 2


def test_an_alarm_event_keeps_its_coded_message(db: Database) -> None:
    coded = '{"reason": "LATCHED_ERROR", "args": [], "causes": []}'
    event = alarm(0, "E011", "X", AlarmState.NORMAL, AlarmState.ACTIVE_UNACKED)
    stored = db.record_alarm_event(replace(event, detail_json=coded))
    plain = db.record_alarm_event(replace(event, time=event.time + timedelta(minutes=1)))
    assert db.list_alarm_events() == [plain, stored]
    assert (stored.detail_json, plain.detail_json) == (coded, None)
    journalled = replace(stored, id=None)  # a journal line has no id yet
    line = encode_write(AlarmWrite(journalled))
    assert decode_write(line) == AlarmWrite(journalled)
    del line["detail_json"]  # a journal line written before the column
    assert decode_write(line) == AlarmWrite(replace(journalled, detail_json=None))
    for damaged in ("[1]", "{", ""):
        with pytest.raises(RecordError, match="detail_json"):
            db.record_alarm_event(replace(event, detail_json=damaged))


def test_an_invalid_alarm_event_is_refused(db: Database) -> None:
    same = alarm(0, "E", "X", AlarmState.NORMAL, AlarmState.NORMAL)
    with pytest.raises(RecordError, match="to_state"):
        db.record_alarm_event(same)
    with pytest.raises(RecordError, match="code"):
        db.record_alarm_event(replace(same, code="", to_state=AlarmState.ACTIVE_UNACKED))
    assert db.list_alarm_events() == []


# ----------------------------------------------------------------------------- users


def test_the_default_pins_log_in(db: Database) -> None:
    for name, role, pin in DEFAULT_USERS:
        user = db.authenticate(pin)
        assert user is not None and (user.name, user.role) == (name, role)
    assert db.authenticate("5555") is None
    assert db.authenticate("12") is None  # malformed: simply no match
    assert db.authenticate("abcd") is None


def test_pins_are_stored_only_hashed(db: Database, db_path: Path) -> None:
    with sqlite3.connect(db_path) as conn:
        hashes = [row[0] for row in conn.execute("SELECT pin_hash FROM users")]
    assert len(set(hashes)) == 3
    for stored, (_, _, pin) in zip(hashes, DEFAULT_USERS, strict=True):
        assert stored.startswith("scrypt$") and pin not in stored.split("$")


def test_roles_are_ordered() -> None:
    assert Role.OPERATOR < Role.TECHNICIAN < Role.SERVICE


def test_changing_pins(db: Database, users: dict[Role, User]) -> None:
    op, tech, svc = users[Role.OPERATOR], users[Role.TECHNICIAN], users[Role.SERVICE]
    db.set_pin(op, "4711", op)  # one's own
    assert db.authenticate("4711") == op
    assert db.authenticate("0000") is None
    db.set_pin(op, "4712", tech)  # a higher role
    with pytest.raises(PermissionDeniedError, match="higher role"):
        db.set_pin(tech, "2468", op)
    db.set_pin(tech, "2468", svc)
    with pytest.raises(PinError, match="already used"):
        db.set_pin(op, "2468", op)
    with pytest.raises(PinError, match="4 to 8 digits"):
        db.set_pin(op, "12a4", op)
    assert db.authenticate("2468") == tech


def test_adding_users(db: Database, users: dict[Role, User]) -> None:
    with pytest.raises(PermissionDeniedError, match="service"):
        db.add_user("Ana", Role.OPERATOR, "13579", users[Role.TECHNICIAN])
    ana = db.add_user("Ana", Role.OPERATOR, "13579", users[Role.SERVICE])
    assert db.authenticate("13579") == ana
    with pytest.raises(PinError, match="already a user"):
        db.add_user("ana", Role.OPERATOR, "97531", users[Role.SERVICE])
    with pytest.raises(PinError, match="already used"):
        db.add_user("Bo", Role.OPERATOR, "13579", users[Role.SERVICE])


def test_recipe_edit_roles(db: Database, users: dict[Role, User]) -> None:
    stranger = User(42, "mallory", Role.SERVICE)
    with pytest.raises(PermissionDeniedError):
        db.save_recipe(make_recipe(name="Sneaky"), stranger)
    assert db.get_recipe_by_name("Sneaky") is None


def test_barrel_mode_recipes_round_trip(db: Database, users: dict[Role, User]) -> None:
    recipe = make_recipe(
        name="Oval-ish",
        barrel_type=BarrelType.ROUND,
        barrel_diameter_mm=850.0,
        barrel_perimeter_mm=2700.0,
        note="für Export, «spécial»",
    )
    stored = db.save_recipe(recipe, users[Role.OPERATOR])
    assert db.get_recipe(stored.id or 0) == replace(recipe, id=stored.id)
    assert isinstance(db.get_recipe(stored.id or 0), Recipe)


def test_a_write_that_sqlite_cannot_complete_is_a_storage_error(
    db_path: Path, users: dict[Role, User]
) -> None:
    """Another writer holding the lock past the busy timeout: refused, nothing half-stored."""
    blocker = sqlite3.connect(db_path, isolation_level=None)
    blocker.execute("BEGIN IMMEDIATE")
    try:
        with Database.open(db_path, busy_timeout_s=0.05) as database:
            before = database.list_recipes()
            with pytest.raises(StorageError, match="cannot start a write"):
                database.save_recipe(make_recipe(name="Blocked"), users[Role.OPERATOR])
            blocker.execute("ROLLBACK")
            assert database.list_recipes() == before
            database.save_recipe(make_recipe(name="Blocked"), users[Role.OPERATOR])  # now fine
    finally:
        blocker.close()
