"""`stave solve` with two bevels: given (--tilt, --tilt-b) or from a round or oval barrel and
the stave's place on it; both tilts are printed and cut (side A at +alpha_A, B at -alpha_B)."""

from __future__ import annotations

import json

import pytest

from app.cli.solve import main

BOARD = ["--length", "900", "--width", "100", "--length-ratio", "1/4", "--width-ratio", "3/4"]


def solve(capsys, *extra: str) -> dict:
    assert main([*BOARD, "--json", *extra]) == 0
    return json.loads(capsys.readouterr().out)


def cut_tilts(data: dict) -> list[float]:
    """The tilts of the cutting moves in order, each once (side A's, then side B's)."""
    tilts: list[float] = []
    for segment in data["toolpath"]:
        if segment["cutting"] and segment["z_deg"] not in tilts:
            tilts.append(segment["z_deg"])
    return tilts


def test_two_given_bevels(capsys) -> None:
    data = solve(capsys, "--tilt", "5", "--tilt-b", "7.5")
    assert (data["tilt_a_deg"], data["tilt_b_deg"]) == (5.0, 7.5)
    assert cut_tilts(data) == [5.0, -7.5]


@pytest.mark.parametrize(
    ("start_deg", "bevel_a", "bevel_b"),
    [("22.652673", 11.7900, 10.4619), ("42.99986", 8.3781, 7.6402)],
)
def test_the_bevels_of_an_oval_staves_place(capsys, start_deg, bevel_a, bevel_b) -> None:
    """docs/MACHINE.md section 7: the 700 x 500 mm oval's staves 2 and 3 of 100 mm (stave 1's
    15.66 deg are beyond this machine's tilt travel: refused below)."""
    data = solve(capsys, "--barrel-axes-mm", "350x250", "--barrel-start-deg", start_deg)
    assert data["tilt_a_deg"] == pytest.approx(bevel_a, abs=5e-5)
    assert data["tilt_b_deg"] == pytest.approx(bevel_b, abs=5e-5)
    assert cut_tilts(data) == [data["tilt_a_deg"], -data["tilt_b_deg"]]


def test_a_round_barrel_bevels_both_sides_alike(capsys) -> None:
    data = solve(capsys, "--barrel-diameter-mm", "600")
    assert data["tilt_a_deg"] == data["tilt_b_deg"] == pytest.approx(9.594068, abs=1e-6)
    assert main([*BOARD, "--barrel-diameter-mm", "600"]) == 0
    assert "tilt A = 9.5941 deg, tilt B = 9.5941 deg" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("extra", "text"),
    [
        (["--tilt", "5", "--barrel-diameter-mm", "600"], "give the bevels or the barrel"),
        (["--barrel-start-deg", "10"], "--barrel-start-deg is for an oval barrel"),
        (["--barrel-axes-mm", "350"], "is not AxB"),
        (["--barrel-axes-mm", "250x350"], "barrel_b_mm = 350"),
        (["--barrel-axes-mm", "350x250", "--barrel-start-deg", "400"], "barrel_start_deg = 400"),
        (["--tilt", "5", "--tilt-b", "abc"], "--tilt-b: tilt of side B = 'abc' is not a"),
        (["--tilt", "5", "--tilt-b", "89"], "--tilt-b: tilt of side B = 89 is out of range"),
        (["--tilt", "5", "--tilt-b", "30"], "--tilt-b: tilt of side B = 30 is out of range"),
        (["--tilt", "30", "--tilt-b", "5"], "--tilt: tilt of side A = 30 is out of range"),
        (["--barrel-diameter-mm", "100"], "barrel_diameter_mm = 100"),
        (["--barrel-axes-mm", "350x250"], "z_deg = 15.664 is out of range"),
    ],
)
def test_bad_bevel_options_are_one_line(capsys, extra, text) -> None:
    assert main([*BOARD, *extra]) == 2
    _, err = capsys.readouterr()
    assert err.count("\n") == 1 and text in err
    assert "tilt_deg" not in err and "tilt_b_deg" not in err
