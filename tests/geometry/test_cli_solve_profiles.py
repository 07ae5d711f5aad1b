"""`stave solve` with the profile kinds: families by option, drawings from a DXF file."""

from __future__ import annotations

import json

import pytest

from app.cli.solve import main
from tests.data import dxf_drawings as drawings
from tests.geometry.chain_checks import worst_tangent_break_rad

BOARD = ["--length", "1000", "--width", "150", "--width-ratio", "3/4"]


def solve_json(capsys, *extra: str) -> dict:
    assert main([*BOARD, *extra, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.parametrize(
    "options",
    [
        ["--profile", "parabola"],
        ["--profile", "ellipse", "--semi-axis-ratio", "2"],
        ["--profile", "superellipse", "--exponent", "4", "--semi-axis-ratio", "1.2"],
    ],
)
def test_families_print_their_fitted_edge_and_tool_path(capsys, options):
    result = solve_json(capsys, *options)
    assert result["profile_kind"] == options[1]
    assert result["W1"] == 112.5
    edge = result["edge"]
    assert edge[0]["start"] == [0.0, 56.25] and edge[-1]["end"][0] == 1000.0
    assert {item["type"] for item in edge} <= {"line", "arc"}
    assert any(item["cutting"] for item in result["toolpath"])


def test_a_dxf_drawing_is_read_and_cut(capsys, tmp_path):
    path = tmp_path / "side.dxf"
    path.write_bytes(drawings.bulged_polyline_belly_down())
    result = solve_json(capsys, "--dxf", str(path))
    assert result["profile_kind"] == "drawn"
    assert main([*BOARD, "--dxf", str(path)]) == 0
    text = capsys.readouterr().out
    assert "profile drawn" in text and "tangent lines and arcs" in text


def test_single_arc_needs_no_length_ratio_and_line_arc_line_does(capsys):
    assert main([*BOARD, "--profile", "single_arc", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["A"] == 0.0
    assert main([*BOARD, "--profile", "single_arc", "--length-ratio", "1/4"]) == 0
    assert "length ratio 0/1, width ratio 3/4" in capsys.readouterr().out  # a given one is unused
    assert main(BOARD) == 2
    assert "--length-ratio is required for the line_arc_line profile" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("options", "message"),
    [
        (["--profile", "cycloid"], "profile_kind = 'cycloid' is not known"),
        (
            ["--profile", "ellipse", "--semi-axis-ratio", "x"],
            "--semi-axis-ratio 'x' is not a number",
        ),
        (["--profile", "superellipse", "--exponent", "1"], "exponent = 1 is out of range"),
        (["--profile", "drawn"], "--profile drawn needs --dxf FILE"),
        (["--dxf", "/nonexistent/side.dxf"], "--dxf /nonexistent/side.dxf: No such file"),
        (["--dxf", "TWO_LAYERS"], "2 candidate curves (curve 1: LINE #"),
        (["--dxf", "TWO_LAYERS"], "choose its layer (--dxf-layer: one of SIDE, FRAME)"),
    ],
)
def test_bad_profile_options_are_one_line(capsys, tmp_path, options, message):
    if "TWO_LAYERS" in options:  # the side on SIDE, a frame line on FRAME
        path = tmp_path / "two layers.dxf"
        path.write_bytes(
            drawings.with_entities(
                lambda space: (
                    space.add_line((0, 0), (500, 0), dxfattribs={"layer": "SIDE"}),
                    space.add_line((0, 100), (500, 100), dxfattribs={"layer": "FRAME"}),
                )
            )
        )
        options = [str(path) if o == "TWO_LAYERS" else o for o in options]
    assert main([*BOARD, *options]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err


def test_a_concave_part_tighter_than_the_cutter_is_refused(capsys, tmp_path):
    """Two narrow dips between heads and belly, concave with a radius of about 53 mm: a 40 mm
    cutter follows them, a 56 mm cutter cannot."""
    path = tmp_path / "dips.dxf"
    path.write_bytes(drawings.spline(drawings.DIPS_POINTS))
    assert main([*BOARD, "--dxf", str(path), "--tool-radius", "40", "--json"]) == 0
    capsys.readouterr()
    assert main([*BOARD, "--dxf", str(path), "--tool-radius", "56"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert "side A is concave with a radius of" in err
    assert "tighter than the cutter's" in err


def test_fitted_edge_from_json_is_tangent_continuous(capsys):
    from app.geometry.segments import ArcSegment, LineSegment

    result = solve_json(capsys, "--profile", "ellipse", "--semi-axis-ratio", "1.1")
    chain = []
    for item in result["edge"]:
        start, end = tuple(item["start"]), tuple(item["end"])
        if item["type"] == "arc":
            chain.append(
                ArcSegment(
                    start, end, tuple(item["center"]), item["direction"] == "cw", 0, 0, False, "A"
                )
            )
        else:
            chain.append(LineSegment(start, end, 0, 0, False, "A"))
    assert worst_tangent_break_rad(chain) < 1e-9
