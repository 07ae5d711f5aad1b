"""``stave db``: each action end to end on real files; bad input exits 2 with one line."""

from __future__ import annotations

import json
import subprocess
import sys
from datetime import UTC, datetime
from pathlib import Path

import pytest

from app.cli import main as stave_main
from app.cli.db import main
from app.data.database import Database
from app.data.records import PieceResult, ProductionRecord

HEADER = "name,length_mm,thickness_mm,length_ratio,width_ratio,tilt_deg"


@pytest.fixture(autouse=True)
def no_pin_in_the_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("STAVE_PIN", raising=False)


def run(capsys: pytest.CaptureFixture[str], *argv: str, pin: str = "") -> tuple[int, str, str]:
    """Run ``stave db``; a PIN is given the way a script gives it, in $STAVE_PIN."""
    with pytest.MonkeyPatch.context() as env:
        if pin:
            env.setenv("STAVE_PIN", pin)
        code = main(list(argv))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_list_recipes_parameters_users(db_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "list", "--db", str(db_path))
    assert (code, err) == (0, "")
    assert "Barrique 225 l Bordeaux" in out and "Foudre" in out
    barrique = next(line for line in out.splitlines() if "Barrique" in line)
    assert barrique.endswith("round barrel D 690 mm")  # the recipe's barrel type
    code, out, _ = run(capsys, "list", "parameters", "--db", str(db_path))
    assert code == 0 and "xy_speed_mm_s" in out and "mm/s" in out
    code, out, _ = run(capsys, "list", "users", "--db", str(db_path))
    assert code == 0 and "technician" in out and "1234" not in out


def test_export_and_import(
    db_path: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    exported = tmp_path / "all.json"
    code, out, _ = run(capsys, "export", str(exported), "--db", str(db_path))
    assert code == 0 and out.startswith("7 recipes written")
    assert len(json.loads(exported.read_text(encoding="utf-8"))["recipes"]) == 7

    other = tmp_path / "other.db"
    code, out, err = run(capsys, "import", str(exported), "--db", str(other), pin="1234")
    assert (code, err) == (0, "")
    assert "7 accepted" in out  # new database: samples already there, all unchanged


def test_import_with_rejected_rows_exits_1_and_reports_them(
    db_path: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = tmp_path / "in.csv"
    source.write_text(f"{HEADER}\nFine,1000,28,1/5,4/5,8\nShort,500,28,1/5,4/5,8\n")
    code, out, _ = run(capsys, "import", str(source), "--db", str(db_path), pin="9999")
    assert code == 1
    assert "1 accepted (1 new" in out
    assert "row 3 (Short): length_mm = 500 is out of range" in out
    with Database.open(db_path) as db:
        assert db.get_recipe_by_name("Fine") is not None
        assert db.recipe_history()[0].user_name == "service"


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["import", "{csv}", "PIN=0000"], "needs the role technician"),
        (["import", "{csv}", "PIN=5555"], "belongs to no user"),
        (["import", "{csv}"], "needs the PIN of a technician"),
        (["import", "{missing}", "PIN=1234"], "not found"),
        (["import", "{txt}", "PIN=1234"], "not supported"),
        (["export", "{out_txt}"], "not supported"),
        (["export-production", "{out_csv}"], "--day, --shift or --from/--to"),
        (["export-production", "{out_csv}", "--from", "2024-05-02T06:00"], "go together"),
        (
            [
                "export-production",
                "{out_csv}",
                "--day",
                "2024-05-02",
                "--from",
                "2024-05-02",
                "--to",
                "2024-05-03",
            ],
            "cannot be combined",
        ),
        (["export-production", "{out_csv}", "--day", "2024-05-02", "--shift", "9"], "shift = 9"),
        (["restore", "{csv}"], "no checksum file"),
        (["backup", "{csv}"], "exists"),
    ],
)
def test_bad_input_exits_2_with_one_clear_line(
    db_path: Path,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    argv: list[str],
    expected: str,
) -> None:
    csv_file = tmp_path / "in.csv"
    csv_file.write_text(f"{HEADER}\nFine,1000,28,1/5,4/5,8\n")
    (tmp_path / "in.txt").write_text("x")
    names = {
        "csv": csv_file,
        "missing": tmp_path / "missing.csv",
        "txt": tmp_path / "in.txt",
        "out_txt": tmp_path / "out.txt",
        "out_csv": tmp_path / "out.csv",
    }
    args = [a.format(**{k: str(v) for k, v in names.items()}) for a in argv]
    pins = [a.removeprefix("PIN=") for a in args if a.startswith("PIN=")]
    args = [a for a in args if not a.startswith("PIN=")]
    code, _, err = run(capsys, *args, "--db", str(db_path), pin=pins[0] if pins else "")
    assert code == 2
    assert err.count("\n") == 1 and err.startswith(f"stave db {argv[0]}: ")
    assert expected in err


def test_a_missing_database_is_not_created_by_a_listing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = run(capsys, "list", "--db", str(tmp_path / "none.db"))
    assert code == 2 and "no database there" in err
    assert not (tmp_path / "none.db").exists()


def test_export_production_for_a_day_and_a_range(
    db_path: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    with Database.open(db_path) as db:
        db.record_piece(
            ProductionRecord(
                datetime(2024, 5, 2, 9, tzinfo=UTC),
                1,
                "Barrique",
                120.0,
                12.0,
                5000.0,
                88.0,
                PieceResult.OK,
            )
        )
    out_csv = tmp_path / "day.csv"
    code, out, _ = run(
        capsys,
        "export-production",
        str(out_csv),
        "--day",
        "2024-05-02",
        "--utc",
        "--db",
        str(db_path),
    )
    assert code == 0 and out.startswith("1 production records (2024-05-02)")
    assert "2024-05-02T09:00:00+00:00" in out_csv.read_text(encoding="utf-8")
    code, out, _ = run(
        capsys,
        "export-production",
        str(out_csv),
        "--from",
        "2024-05-02T09:00:01+00:00",
        "--to",
        "2024-05-03T00:00+00:00",
        "--db",
        str(db_path),
    )
    assert code == 0 and out.startswith("0 production records")
    code, out, _ = run(
        capsys,
        "export-production",
        str(out_csv),
        "--day",
        "2024-05-02",
        "--shift",
        "1",
        "--utc",
        "--db",
        str(db_path),
    )
    assert code == 0 and out.startswith("1 production records (shift 1 of 2024-05-02)")


def test_backup_and_restore(
    db_path: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    copy = tmp_path / "copy.db"
    code, out, _ = run(capsys, "backup", str(copy), "--db", str(db_path))
    assert code == 0 and str(copy) in out
    code, _, err = run(capsys, "restore", str(copy), "--db", str(db_path))
    assert code == 2 and "needs the PIN of a service user" in err
    code, _, err = run(capsys, "restore", str(copy), "--db", str(db_path), pin="1234")
    assert code == 2 and "needs the role service" in err
    code, out, _ = run(capsys, "restore", str(copy), "--db", str(db_path), pin="9999")
    assert code == 0 and "7 recipes" in out and "kept as" in out


def test_the_stave_command_dispatches_to_db(
    db_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert stave_main(["db", "list", "users", "--db", str(db_path)]) == 0
    assert "service" in capsys.readouterr().out


def test_as_a_separate_process(db_path: Path) -> None:
    done = subprocess.run(
        [sys.executable, "-m", "app.cli.db", "list", "--db", str(db_path)],
        capture_output=True,
        text=True,
        check=False,
        timeout=60,
    )
    assert done.returncode == 0, done.stderr
    assert "Hogshead 300 l" in done.stdout
