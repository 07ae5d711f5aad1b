"""Recipe import/export (JSON, CSV) with the report of rejected rows; production exports for a
day, a shift or a range; shift windows."""

from __future__ import annotations

import csv
import io
import json
from dataclasses import replace
from datetime import UTC, date, datetime, timedelta, timezone
from pathlib import Path

import pytest

from app.data.database import Database
from app.data.errors import PermissionDeniedError
from app.data.exchange import (
    PRODUCTION_COLUMNS,
    export_production_csv,
    export_production_day,
    export_production_shift,
    export_recipes,
    import_recipes,
    read_recipes,
)
from app.data.recipe import ROW_KEYS, BarrelType, TiltMode
from app.data.recipe_files import RecipeFileError
from app.data.records import PieceResult, ProductionRecord
from app.data.shifts import ShiftPlan, current_shift, day_window, shift_window
from app.data.users import Role, User
from app.geometry.ratio import Ratio

HEADER = "name,length_mm,thickness_mm,length_ratio,width_ratio,tilt_deg"


def write(path: Path, text: str, encoding: str = "utf-8") -> Path:
    path.write_text(text, encoding=encoding)
    return path


@pytest.fixture
def empty_db(tmp_path: Path) -> Database:
    return Database.open(tmp_path / "empty.db", load_samples=False)


@pytest.mark.parametrize("suffix", [".json", ".csv"])
def test_export_then_import_gives_the_same_recipes(
    db: Database, users: dict[Role, User], tmp_path: Path, suffix: str
) -> None:
    # Values that a lossy format would change: long decimals, unreduced fractions, text.
    db.save_recipe(
        replace(
            db.list_recipes()[0],
            id=None,
            name='Tricky, "quoted"; name',
            length_mm=1234.5678901234,
            length_ratio=Ratio(2, 8),
            note="line one; ünïcode, comma",
        ),
        users[Role.OPERATOR],
    )
    path = tmp_path / f"recipes{suffix}"
    assert export_recipes(db, path) == len(db.list_recipes())
    with Database.open(tmp_path / "other.db", load_samples=False) as other:
        report = import_recipes(other, path, {u.role: u for u in other.list_users()}[Role.SERVICE])
        assert report.rejected == ()
        assert len(report.created) == len(db.list_recipes())
        assert [replace(r, id=None) for r in other.list_recipes()] == [
            replace(r, id=None) for r in db.list_recipes()
        ]
        # Importing the same file again changes nothing.
        again = import_recipes(other, path, {u.role: u for u in other.list_users()}[Role.SERVICE])
        assert (again.created, again.updated, len(again.unchanged)) == ((), (), again.accepted)


def test_the_json_export_format(db: Database, tmp_path: Path) -> None:
    path = tmp_path / "out.json"
    export_recipes(db, path)
    document = json.loads(path.read_text(encoding="utf-8"))
    assert (document["format"], document["version"]) == ("stave-jointer-recipes", 1)
    assert tuple(document["recipes"][0]) == ROW_KEYS
    assert document["recipes"][0]["length_ratio"] == "1/4"


def test_the_csv_export_format(db: Database, tmp_path: Path) -> None:
    path = tmp_path / "out.csv"
    export_recipes(db, path)
    rows = list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))
    assert tuple(rows[0]) == ROW_KEYS
    assert (rows[0]["length_mm"], rows[0]["width_ratio"], rows[0]["barrel_type"]) == (
        "950",
        "4/5",
        "round",
    )


def test_an_older_file_with_tilt_mode_imports_round_and_oval_barrels(
    empty_db: Database, tmp_path: Path
) -> None:
    """Files written before the barrel type: a barrel with a short axis was an oval one."""
    service = {u.role: u for u in empty_db.list_users()}[Role.SERVICE]
    path = write(
        tmp_path / "old.csv",
        f"{HEADER},tilt_mode,barrel_diameter_mm,barrel_minor_diameter_mm\n"
        "Round,1000,28,1/5,4/5,8,barrel,700,\n"
        "Oval,1000,28,1/5,4/5,8,barrel,700,500\n"
        "Fixed,1000,28,1/5,4/5,8,fixed,,\n",
    )
    report = import_recipes(empty_db, path, service)
    assert report.created == ("Round", "Oval", "Fixed")
    types = {r.name: r.barrel_type for r in empty_db.list_recipes()}
    assert types == {
        "Round": BarrelType.ROUND,
        "Oval": BarrelType.OVAL,
        "Fixed": BarrelType.FIXED_TILT,
    }
    out = tmp_path / "new.json"
    export_recipes(empty_db, out)
    again = write(tmp_path / "again.json", out.read_text(encoding="utf-8"))
    fresh = tmp_path / "fresh.db"
    with Database.open(fresh, load_samples=False) as other:
        import_recipes(other, again, {u.role: u for u in other.list_users()}[Role.SERVICE])
        assert {r.name: r.barrel_type for r in other.list_recipes()} == types


def test_a_bad_barrel_type_is_refused_naming_the_choices(
    empty_db: Database, tmp_path: Path
) -> None:
    service = {u.role: u for u in empty_db.list_users()}[Role.SERVICE]
    path = write(
        tmp_path / "bad.csv",
        f"{HEADER},barrel_type,barrel_diameter_mm\nX,1000,28,1/5,4/5,8,egg,700\n",
    )
    report = import_recipes(empty_db, path, service)
    [row] = report.rejected
    assert [e.message for e in row.errors] == [
        "barrel_type = 'egg' is unknown: allowed fixed, round or oval"
    ]


def test_a_report_names_each_rejected_row_field_and_reason(
    empty_db: Database, tmp_path: Path
) -> None:
    service = {u.role: u for u in empty_db.list_users()}[Role.SERVICE]
    path = write(
        tmp_path / "mixed.csv",
        f"{HEADER},tilt_mode,barrel_diameter_mm\n"
        "Good one,1000,28,1/5,4/5,8,,\n"
        "Too short,500,28,1/5,4/5,8,,\n"
        "Bad ratio,1000,28,1/0,4/5,8,,\n"
        ",1000,28,1/5,4/5,8,,\n"
        "No barrel,1000,28,1/5,4/5,8,barrel,\n"
        "Two problems,1000,95,1/2,4/5,8,,\n"
        "\n"
        "good one,1000,30,1/5,4/5,8,,\n"
        "Extra,1000,28,1/5,4/5,8,,,surplus\n",
    )
    report = import_recipes(empty_db, path, service)
    assert report.created == ("Good one",)
    rejected = {row.row: row for row in report.rejected}
    assert sorted(rejected) == [3, 4, 5, 6, 7, 9, 10]  # spreadsheet rows (header = 1)
    assert [e.field for e in rejected[3].errors] == ["length_mm"]
    assert [e.field for e in rejected[4].errors] == ["length_ratio"]
    assert [e.field for e in rejected[5].errors] == ["name"]
    assert [e.field for e in rejected[6].errors] == ["barrel_diameter_mm"]
    assert {e.field for e in rejected[7].errors} == {"thickness_mm", "length_ratio"}
    assert "already on row 2" in rejected[9].errors[0].message
    assert rejected[10].errors[0].field == "row"
    lines = report.lines()
    assert lines[0] == "mixed.csv: 1 accepted (1 new, 0 updated, 0 unchanged), 7 rejected"
    assert any(line.startswith("row 3 (Too short): length_mm = 500") for line in lines)
    assert [r.name for r in empty_db.list_recipes()] == ["Good one"]


def test_an_existing_name_is_updated_only_by_a_valid_row(
    db: Database, users: dict[Role, User], tmp_path: Path
) -> None:
    barrique = db.get_recipe_by_name("Barrique 225 l Bordeaux")
    assert barrique is not None
    invalid = write(tmp_path / "bad.csv", f"{HEADER}\nbarrique 225 L bordeaux,950,200,1/4,4/5,9\n")
    report = import_recipes(db, invalid, users[Role.TECHNICIAN])
    assert report.accepted == 0 and report.rejected[0].errors[0].field == "thickness_mm"
    assert db.get_recipe(barrique.id or 0) == barrique  # untouched

    valid = write(tmp_path / "good.csv", f"{HEADER}\nBarrique 225 l Bordeaux,950,28,1/4,4/5,9\n")
    report = import_recipes(db, valid, users[Role.TECHNICIAN])
    assert report.updated == ("Barrique 225 l Bordeaux",)
    updated = db.get_recipe(barrique.id or 0)
    assert (updated.thickness_mm, updated.tilt_mode) == (28.0, TiltMode.FIXED)


def test_importing_needs_a_technician(
    db: Database, users: dict[Role, User], tmp_path: Path
) -> None:
    path = write(tmp_path / "one.csv", f"{HEADER}\nNew,1000,28,1/5,4/5,8\n")
    with pytest.raises(PermissionDeniedError, match="technician"):
        import_recipes(db, path, users[Role.OPERATOR])
    assert db.get_recipe_by_name("New") is None


def test_a_spreadsheet_csv_with_semicolons_decimal_commas_and_a_bom(
    empty_db: Database, tmp_path: Path
) -> None:
    path = write(
        tmp_path / "excel.csv",
        "Name;Length_mm;thickness_mm;length_ratio;width_ratio;tilt_deg;note\r\n"
        "Barrique;950;27,5;1/4;0,8;9,2;fût, bordelais\r\n",
        encoding="utf-8-sig",
    )
    valid, rejected = read_recipes(path)
    assert rejected == []
    [(row, recipe)] = valid
    assert row == 2
    assert (recipe.thickness_mm, recipe.width_ratio, recipe.tilt_deg) == (27.5, Ratio(4, 5), 9.2)
    assert recipe.note == "fût, bordelais"  # text keeps its comma


@pytest.mark.parametrize(
    ("name", "text", "message"),
    [
        ("bad.json", '{"recipes": [ {"name": 1,} ]}', "not valid JSON"),
        ("other.json", '{"format": "cnc-programs", "recipes": []}', "not supported"),
        ("unknown.csv", f"{HEADER},colour\n", "column 'colour' is unknown"),
        ("missing.csv", "name,length_mm\n", "thickness_mm"),
        ("double.csv", f"{HEADER},name\n", "more than once"),
        ("empty.csv", "", "empty"),
        ("recipes.txt", "whatever", "not supported"),
    ],
)
def test_a_file_that_cannot_be_read_is_refused_with_one_line(
    empty_db: Database, tmp_path: Path, name: str, text: str, message: str
) -> None:
    service = {u.role: u for u in empty_db.list_users()}[Role.SERVICE]
    path = write(tmp_path / name, text)
    with pytest.raises(RecipeFileError, match=message) as caught:
        import_recipes(empty_db, path, service)
    assert "\n" not in str(caught.value) and name in str(caught.value)
    assert empty_db.list_recipes() == []


def test_a_missing_file_and_a_non_utf8_file(tmp_path: Path) -> None:
    with pytest.raises(RecipeFileError, match="not found"):
        read_recipes(tmp_path / "nope.json")
    latin = tmp_path / "latin.csv"
    latin.write_bytes(f"{HEADER}\nFût,950,27,1/4,4/5,9\n".encode("latin-1"))
    with pytest.raises(RecipeFileError, match="not UTF-8"):
        read_recipes(latin)


@pytest.mark.parametrize(
    "document",
    [
        {
            "name": "Solo",
            "length_mm": 950,
            "thickness_mm": 27,
            "length_ratio": "1/4",
            "width_ratio": "4/5",
            "tilt_deg": 9,
        },
        [
            {
                "name": "Solo",
                "length_mm": 950,
                "thickness_mm": 27,
                "length_ratio": 0.25,
                "width_ratio": 0.8,
                "tilt_deg": 9,
            }
        ],
    ],
)
def test_json_may_be_one_object_or_a_list(tmp_path: Path, document: object) -> None:
    path = write(tmp_path / "r.json", json.dumps(document))
    [(row, recipe)] = read_recipes(path)[0]
    assert (row, recipe.name, recipe.width_ratio) == (1, "Solo", Ratio(4, 5))


def test_a_json_item_that_is_not_an_object_is_a_rejected_row(tmp_path: Path) -> None:
    path = write(tmp_path / "r.json", json.dumps({"recipes": ["Barrique"]}))
    valid, [rejected] = read_recipes(path)
    assert valid == [] and rejected.row == 1 and rejected.errors[0].field == "row"


# ----------------------------------------------------------------------------- production

UTC_PLAN = ShiftPlan(first_start_h=6.0, length_h=8.0, count=3)
T = datetime(2024, 5, 2, tzinfo=UTC)


def record_at(db: Database, moment: datetime, result: PieceResult = PieceResult.OK) -> None:
    db.record_piece(
        ProductionRecord(
            time=moment,
            recipe_id=1,
            recipe_name="Barrique 225 l Bordeaux",
            width_mm=121.25,
            d_mm=12.502603,
            r_mm=5005.2066,
            cycle_time_s=87.4,
            result=result,
            tilt_deg=10.1234,
            alarm_code=None if result is PieceResult.OK else "W_RANGE",
            barrel_number=None if result is PieceResult.OK else 3,  # a barrel's board refused
            stave_number=None if result is PieceResult.OK else 5,
            operator_name="Marko Novak" if result is PieceResult.OK else None,
        )
    )


@pytest.fixture
def production(db: Database) -> Database:
    for hours in (1, 5.99, 6, 13.5, 14, 21.99, 22, 23.5, 29.99, 30):
        record_at(db, T + timedelta(hours=hours))
    record_at(db, T + timedelta(hours=7), PieceResult.REJECTED)
    return db


def exported(path: Path) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))


def test_export_a_range(production: Database, tmp_path: Path) -> None:
    path = tmp_path / "range.csv"
    count = export_production_csv(
        production, path, T + timedelta(hours=6), T + timedelta(hours=14), UTC
    )
    rows = exported(path)
    assert count == len(rows) == 3
    assert tuple(rows[0]) == PRODUCTION_COLUMNS
    assert [r["time"] for r in rows] == [
        "2024-05-02T06:00:00+00:00",
        "2024-05-02T07:00:00+00:00",
        "2024-05-02T13:30:00+00:00",
    ]
    assert rows[0]["width_mm"] == "121.25" and rows[0]["d_mm"] == "12.5026"
    assert (rows[1]["result"], rows[1]["alarm_code"]) == ("rejected", "W_RANGE")
    assert [(r["barrel_number"], r["stave_number"]) for r in rows] == [
        ("", ""),
        ("3", "5"),
        ("", ""),
    ]
    assert [r["operator_name"] for r in rows] == ["Marko Novak", "", "Marko Novak"]


def test_export_a_day_in_a_given_zone(production: Database, tmp_path: Path) -> None:
    path = tmp_path / "day.csv"
    assert export_production_day(production, path, date(2024, 5, 2), UTC) == 9
    plus2 = timezone(timedelta(hours=2))
    # At +02:00 the day is 22:00 UTC to 22:00 UTC: the two pieces after 22:00 UTC fall out.
    assert export_production_day(production, path, date(2024, 5, 2), plus2) == 7
    times = [r["time"] for r in exported(path)]
    assert times[0] == "2024-05-02T03:00:00+02:00"  # 01:00 UTC is 03:00 at +02:00
    assert times[-1] == "2024-05-02T23:59:24+02:00"  # 21:59:24 UTC


def test_export_a_shift_including_a_night_shift(production: Database, tmp_path: Path) -> None:
    path = tmp_path / "shift.csv"
    # Shift 3 of 2 May runs 22:00 - 06:00 of 3 May and belongs to 2 May.
    assert export_production_shift(production, path, date(2024, 5, 2), 3, UTC_PLAN, UTC) == 3
    assert export_production_shift(production, path, date(2024, 5, 2), 1, UTC_PLAN, UTC) == 3
    with pytest.raises(ValueError, match="shift = 4"):
        export_production_shift(production, path, date(2024, 5, 2), 4, UTC_PLAN, UTC)


def test_the_shift_plan_comes_from_the_parameters(
    production: Database, users: dict[Role, User], tmp_path: Path
) -> None:
    production.set_parameters(
        {"shift_first_start_h": 5.0, "shift_length_h": 12.0, "shifts_per_day": 2},
        users[Role.TECHNICIAN],
    )
    path = tmp_path / "shift.csv"
    assert export_production_shift(production, path, date(2024, 5, 2), 1, tz=UTC) == 5


def test_a_production_export_needs_csv_and_a_real_range(db: Database, tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"\.csv"):
        export_production_csv(db, tmp_path / "p.json", T, T + timedelta(hours=1))
    with pytest.raises(ValueError, match="not after"):
        export_production_csv(db, tmp_path / "p.csv", T, T)


def test_shift_windows() -> None:
    assert shift_window(date(2024, 5, 2), 3, UTC_PLAN, UTC) == (
        datetime(2024, 5, 2, 22, tzinfo=UTC),
        datetime(2024, 5, 3, 6, tzinfo=UTC),
    )
    assert day_window(date(2024, 5, 2), UTC) == (T, T + timedelta(days=1))
    # At 03:00 the night shift of the day before runs.
    assert current_shift(datetime(2024, 5, 3, 3, tzinfo=UTC), UTC_PLAN, UTC) == (
        3,
        datetime(2024, 5, 2, 22, tzinfo=UTC),
    )
    # Between two shifts the last one started counts.
    two = ShiftPlan(first_start_h=6.0, length_h=8.0, count=2)
    assert current_shift(datetime(2024, 5, 2, 23, tzinfo=UTC), two, UTC) == (
        2,
        datetime(2024, 5, 2, 14, tzinfo=UTC),
    )
    with pytest.raises(ValueError, match="more than a day"):
        ShiftPlan(first_start_h=6.0, length_h=9.0, count=3)


def test_shifts_follow_the_wall_clock_across_daylight_saving() -> None:
    from zoneinfo import ZoneInfo

    paris = ZoneInfo("Europe/Paris")
    start, end = shift_window(date(2024, 3, 31), 3, UTC_PLAN, paris)  # clocks go forward
    assert (start.hour, end.hour) == (22, 6)
    start, _ = shift_window(date(2024, 3, 31), 1, UTC_PLAN, paris)
    assert start.utcoffset() == timedelta(hours=2)
