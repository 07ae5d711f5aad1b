"""`stave barrel`: the JSON shape, the worked examples, overrun and invalid input."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from app.cli.barrel import main

REPO = Path(__file__).resolve().parents[2]


def barrel_json(capsys, *args: str) -> dict:
    assert main([*args, "--json"]) == 0
    out, err = capsys.readouterr()
    assert err == "" and out.count("\n") == 1
    return json.loads(out)


def widths(width: str, count: int) -> list[str]:
    return [arg for _ in range(count) for arg in ("--width", width)]


def test_oval_json_shape_and_values(capsys):
    data = barrel_json(capsys, "--axes-mm", "350x250", *widths("100", 18))
    assert list(data) == ["staves", "closing", "perimeter_mm"]
    assert len(data["staves"]) == 18
    first = data["staves"][0]
    assert list(first) == [
        "number", "width_mm", "start_angle_deg", "bevel_start_deg", "bevel_end_deg",
    ]  # fmt: skip
    assert first["number"] == 1 and first["start_angle_deg"] == 0.0
    assert first["width_mm"] == pytest.approx(100.0, abs=1e-9)
    assert first["bevel_start_deg"] == pytest.approx(15.6644, abs=5e-5)
    assert first["bevel_end_deg"] == pytest.approx(14.6323, abs=5e-5)
    assert data["staves"][2]["start_angle_deg"] == pytest.approx(42.999860, abs=5e-7)
    assert list(data["closing"]) == ["width_mm", "bevel_start_deg", "bevel_end_deg"]
    assert data["closing"]["width_mm"] == pytest.approx(88.3871, abs=5e-5)
    assert data["closing"]["bevel_start_deg"] == pytest.approx(13.1755, abs=5e-5)
    assert data["closing"]["bevel_end_deg"] == pytest.approx(13.9145, abs=5e-5)
    assert data["perimeter_mm"] == pytest.approx(1898.07, abs=5e-3)


def test_round_text_report(capsys):
    assert main(["--diameter-mm", "600", *widths("100", 18)]) == 0
    out = capsys.readouterr().out
    assert "round barrel, belly diameter 600 mm" in out
    assert "9.5941" in out
    assert "closing stave 19: width 76.3091 mm" in out and "7.3068 deg (start)" in out


def test_overrun_lists_the_staves_that_fit(capsys):
    data = barrel_json(capsys, "--diameter-mm", "600", *widths("100", 19))
    assert len(data["staves"]) == 18 and data["closing"] is None
    assert main(["--diameter-mm", "600", *widths("100", 19)]) == 0
    assert "overrun the perimeter: stave 19 (100 mm)" in capsys.readouterr().out


def test_a_long_gap_says_how_many_staves_are_missing(capsys):
    assert barrel_json(capsys, "--diameter-mm", "600", "--width", "100")["closing"] is None
    assert main(["--diameter-mm", "600", "--width", "100"]) == 0
    assert "about 18 more staves of the mean width 100.0 mm" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (["--width", "100"], "exactly one of --diameter-mm D (round) or --axes-mm AxB"),
        (["--diameter-mm", "600", "--axes-mm", "350x250", "--width", "1"], "exactly one of"),
        (["--diameter-mm", "600"], "width_mm is missing"),
        (["--diameter-mm", "100", "--width", "90"], "barrel_diameter_mm = 100 is out of range"),
        (["--diameter-mm", "x", "--width", "90"], "barrel_diameter_mm = 'x' is not a finite"),
        (["--axes-mm", "350", "--width", "90"], "axes_mm = '350' is not AxB"),
        (["--axes-mm", "250x350", "--width", "90"], "barrel_b_mm = 350 is out of range"),
        (["--axes-mm", "350x250", "--width", "300"], "width_mm = 300 is out of range"),
        (["--axes-mm", "350x250", "--width", "nan"], "width_mm = nan is not a finite number"),
        (["--diameter-mm", "600", "--width", "100", "--bogus"], "unrecognized arguments"),
    ],
)
def test_invalid_input_is_exit_2_and_one_line(capsys, args, expected):
    code = main(args)
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("stave barrel: ")
    assert expected in err


def test_a_width_wider_than_the_barrel_is_exit_2(capsys):
    assert main(["--diameter-mm", "240", "--width", "250"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "width_mm = 250 is out of range" in err


def test_the_stave_command_runs_it():
    result = subprocess.run(
        [sys.executable, "-m", "app.cli", "barrel", "--axes-mm", "350x250", "--width", "100",
         "--json"],
        cwd=REPO, capture_output=True, text=True, check=False, timeout=60,
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["staves"][0]["bevel_end_deg"] == pytest.approx(
        14.6323, abs=5e-5
    )
