"""``stave gcode`` end to end through the command-line entry point: what it writes, where, and
the one-line refusals of bad input."""

from __future__ import annotations

import json
from pathlib import Path

import ezdxf
import pytest

from app import __version__
from app.cli import main
from app.data.database import Database
from app.data.recipe import recipe_to_mapping
from tests.programs.conftest import RECIPES

BARRIQUE = "Barrique 225 l Bordeaux"


def gcode(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    code = main(["gcode", *args])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture
def recipe_file(tmp_path: Path) -> Path:
    path = tmp_path / "recipe.json"
    path.write_text(json.dumps([recipe_to_mapping(RECIPES[1])]), encoding="utf-8")
    return path


def test_fixed_program_to_stdout_names_recipe_width_date_version(capsys, recipe_file):
    code, out, err = gcode(capsys, "--recipe-file", str(recipe_file), "--width", "150")
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0] == "%" and lines[-1] == "%"
    head = "\n".join(lines[:6])
    assert "recipe worked example 1000, width 150.0000 mm" in head
    assert f"by stave jointer {__version__}" in head and "written 20" in head
    assert "side A at A = 4.0000, side B at A = -4.0000 deg" in head
    assert "G21 G17 G90 G91.1 G94 G40 G49 G80 G64 P0.001" in lines
    assert sum(line.startswith("G2 ") for line in lines) == 2
    assert "M3 S18000" in lines and "M5" in lines and "M2" in lines
    # The configuration's factory feed (machine.toml: 120 mm/s) as mm/min.
    assert "F7200.0 (cutting feed, mm/min)" in lines


def test_chords_sinumerik_output_file_and_dxf(capsys, recipe_file, tmp_path):
    out_file = tmp_path / "stave.mpf"
    code, out, err = gcode(
        capsys, "--recipe-file", str(recipe_file), "--width", "150", "--dialect", "sinumerik",
        "--chords", "0.01", "-o", str(out_file),
    )  # fmt: skip
    assert (code, out, err) == (0, "", "")
    text = out_file.read_text(encoding="utf-8")
    blocks = [line for line in text.splitlines() if not line.startswith(";")]
    assert not [line for line in blocks if line.startswith(("G2", "G3")) or "(" in line]
    assert text.splitlines()[-1] == "M30"
    assert "chord error at most 0.0100 mm" in text
    drawing = tmp_path / "stave.dxf"
    code, _, err = gcode(
        capsys, "--recipe-file", str(recipe_file), "--width", "150", "--dxf", "-o", str(drawing)
    )
    assert code == 0, err
    assert {layer.dxf.name for layer in ezdxf.readfile(drawing).layers} >= {"OUTLINE", "POINTS"}


def test_parametric_program(capsys, recipe_file):
    code, out, err = gcode(capsys, "--recipe-file", str(recipe_file), "--parametric")
    assert code == 0, err
    assert "#<width> = 150.000" in out.splitlines()
    assert "(abort, width outside what this recipe accepts: 80.000 to 280.000 mm)" in out


def test_parametric_barrel_program_says_how_the_tilt_is_computed(capsys, tmp_path):
    path = tmp_path / "barrel.json"
    path.write_text(json.dumps([recipe_to_mapping(RECIPES[5])]), encoding="utf-8")
    code, out, err = gcode(capsys, "--recipe-file", str(path), "--parametric")
    assert code == 0, err
    assert (
        "(both sides at A = asin of width / barrel diameter 690.0 mm, side B negative)"
        in out.splitlines()
    )


def test_recipe_and_parameters_from_the_database(capsys, tmp_path):
    path = tmp_path / "stave.db"
    with Database.open(path) as db:
        service = next(u for u in db.list_users() if u.role.name == "SERVICE")
        db.set_parameters({"xy_speed_mm_s": 50.0}, service)
    code, out, err = gcode(capsys, "--recipe", BARRIQUE, "--width", "110", "--db", str(path))
    assert code == 0, err
    assert "F3000.0 (cutting feed, mm/min)" in out.splitlines()
    assert f"recipe {BARRIQUE}, width 110.0000 mm" in out
    code, _, err = gcode(capsys, "--recipe", "no such", "--width", "110", "--db", str(path))
    assert code == 2 and len(err.splitlines()) == 1
    assert "--recipe 'no such' is not in the database: allowed" in err and BARRIQUE in err


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (["--width", "abc"], "--width = 'abc' is not allowed: a width in mm"),
        (["--width", "300"], "width_mm = 300 is out of range"),
        (["--width", "60"], "head_width_mm = 45 is out of range: allowed head width >= 60 mm"),
        (["--width", "150", "--chords", "0"], "--chords = 0 is out of range: allowed 0.001"),
        (["--width", "150", "--chords", "x"], "--chords = 'x' is not allowed"),
        (["--width", "150", "--dialect", "fanuc"], "--dialect 'fanuc' is not allowed: one of"),
        (["--parametric", "--dialect", "sinumerik"], "not allowed with --parametric"),
        (["--parametric", "--chords", "0.1"], "--parametric is not allowed with --chords"),
        (["--width", "150", "--spindle-rpm", "0"], "--spindle-rpm = '0' is not allowed"),
        (["--width", "150", "--config", "/nonexistent.toml"], "--config"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(capsys, recipe_file, args, expected):
    code, out, err = gcode(capsys, "--recipe-file", str(recipe_file), *args)
    assert code == 2 and out == ""
    assert len(err.splitlines()) == 1 and err.startswith("stave gcode: ")
    assert expected in err


def test_missing_database_and_unwritable_output(capsys, recipe_file, tmp_path):
    code, _, err = gcode(capsys, "--recipe", "x", "--width", "150", "--db", str(tmp_path / "no"))
    assert code == 2 and "no database there" in err
    code, _, err = gcode(
        capsys, "--recipe-file", str(recipe_file), "--width", "150",
        "-o", str(tmp_path / "missing" / "dir" / "p.ngc"),
    )  # fmt: skip
    assert code == 2 and "cannot write" in err and len(err.splitlines()) == 1


def test_usage_errors_are_one_line_too(capsys):
    with pytest.raises(SystemExit) as exited:
        main(["gcode", "--width", "150"])
    out, err = capsys.readouterr()
    assert (exited.value.code, out) == (2, "")
    assert err == "stave gcode: one of the arguments --recipe --recipe-file is required\n"


@pytest.mark.parametrize(
    ("barrel", "expected"),
    [
        ({"barrel_type": "egg"}, "barrel_type = 'egg' is unknown: allowed fixed, round or oval"),
        ({"barrel_type": "oval", "barrel_diameter_mm": 700}, "barrel_minor_diameter_mm is missing"),
        (
            {"barrel_type": "round", "barrel_diameter_mm": 700, "barrel_minor_diameter_mm": 500},
            "barrel_minor_diameter_mm = 500 has no use with a round barrel",
        ),
    ],
)
def test_a_recipe_files_barrel_type_is_checked(capsys, tmp_path, barrel, expected) -> None:
    """The barrel type is the file's own choice: a bad or contradicting one is refused in
    one line naming the field, the value and what is allowed."""
    row = {**recipe_to_mapping(RECIPES[1]), **barrel}
    path = tmp_path / "barrel.json"
    path.write_text(json.dumps([row]), encoding="utf-8")
    code, out, err = gcode(capsys, "--recipe-file", str(path), "--width", "150")
    assert code == 2 and out == "" and len(err.splitlines()) == 1
    assert expected in err, err
