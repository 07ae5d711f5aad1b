"""The SINUMERIK program read back block by block: the words of the 802D/840D dialect, and
its motion (absolute X, Y, A; arc centres I, J relative to the start) against the tool path;
and read by a Sinumerik-flavoured interpreter we did not write (nc-gcode-interpreter). No
Siemens control or its own interpreter runs it."""

from __future__ import annotations

import math
import re

import pytest

from app.data.recipe import Recipe
from app.geometry.polyline import segment_points
from app.geometry.segments import ArcSegment
from app.machine.program_export import Dialect, ExportOptions, export_program, stave_toolpath
from tests.programs.conftest import LIMITS, PARAMS, curved_recipes

_WORD = re.compile(r"([A-Z])(-?\d+(?:\.\d+)?)")


def _blocks(text: str) -> list[dict[str, float]]:
    blocks = []
    for line in text.splitlines():
        code = line.split(";", 1)[0].strip()
        if code:
            words: dict[str, float] = {}
            for letter, value in _WORD.findall(code):
                words.setdefault(letter, float(value))
            blocks.append({**words, "_text": code})  # type: ignore[dict-item]
    return blocks


def test_words_and_motion_match_the_tool_path(recipe: Recipe) -> None:
    _check_blocks(recipe, 160.0)


def test_a_drawn_side_turning_both_ways_has_g2_and_g3_blocks() -> None:
    drawn = curved_recipes()[1]
    text = _check_blocks(drawn, 150.0)
    assert {line[:3] for line in text.splitlines() if line.startswith("G")} >= {"G2 ", "G3 "}


def _check_blocks(recipe: Recipe, width: float) -> str:
    """The program's words and every motion block against the tool path; the text back."""
    toolpath = stave_toolpath(recipe, width, PARAMS, LIMITS)
    text = export_program(recipe, width, PARAMS, LIMITS, ExportOptions(dialect=Dialect.SINUMERIK))
    lines = text.splitlines()
    assert all(line.startswith("; ") for line in lines[:5])
    assert "G17 G71 G90 G94 G40 G500 G64" in lines
    assert lines[-2:] == ["M5", "M30"]
    assert "M3 S18000" in lines and "G4 F2.0 ; spindle run-up, s" in lines
    assert f"F{PARAMS['xy_speed_mm_s'] * 60:.1f} ; cutting feed, mm/min" in lines
    assert not [line for line in lines if "(" in line and not line.startswith(";")]

    motion = [b for b in _blocks(text) if str(b["_text"]).startswith(("G0 ", "G1 ", "G2 ", "G3 "))]
    home = motion.pop(0)
    position = (home["X"], home["Y"])
    assert position == pytest.approx(toolpath.segments[0].start, abs=1e-4)
    assert len(motion) == len(toolpath.segments)
    for block, segment in zip(motion, toolpath.segments, strict=True):
        assert (block["X"], block["Y"]) == pytest.approx(segment.end, abs=1e-4)
        word = str(block["_text"])[:2]
        if isinstance(segment, ArcSegment):
            assert word == ("G2" if segment.clockwise else "G3")
            centre = (position[0] + block["I"], position[1] + block["J"])
            assert math.dist(centre, segment.center) <= 1e-4
        elif segment.cutting:
            assert word == "G1"
        else:
            assert word == "G0" and block["A"] == pytest.approx(segment.z_end_deg, abs=1e-4)
        position = (block["X"], block["Y"])
    return text


@pytest.mark.parametrize("chords_mm", [None, 0.05])
def test_a_sinumerik_interpreter_reads_the_program_as_the_tool_path(
    recipe: Recipe, chords_mm: float | None
) -> None:
    """nc-gcode-interpreter (a Sinumerik-flavoured interpreter we did not write) reads the
    program: the modal groups are the ones meant (X-Y plane, no radius compensation, no
    settable offset, continuous path, mm, absolute, mm/min), every block ends where the tool
    path's move ends, at its tilt, with the feed and the spindle words; it does not check the
    arcs' centres (that is the block test above)."""
    import nc_gcode_interpreter as nc
    import polars as pl

    width = 175.0
    toolpath = stave_toolpath(recipe, width, PARAMS, LIMITS)
    options = ExportOptions(dialect=Dialect.SINUMERIK, chord_error_mm=chords_mm)
    text = export_program(recipe, width, PARAMS, LIMITS, options)
    frame, _state = nc.nc_to_dataframe(text, extra_axes=["A"])
    # Blocks without a comment: the motion, M3, M5 and M30 (the others carry one).
    rows = frame.filter(pl.col("gg01_motion").is_not_null() & pl.col("comment").is_null())
    rows = rows.to_dicts()
    modal = {key: rows[-1][key] for key in rows[-1] if key.startswith("gg") and key != "gg02_wait"}
    assert modal == {
        "gg01_motion": "G0",
        "gg06_plane_select": "G17",
        "gg07_tool_radius": "G40",
        "gg08_work_offset": "G500",
        "gg10_exact_stop_mode": "G64",
        "gg13_wp_measure": "G71",
        "gg14_wp_measure_mode": "G90",
        "gg15_feed_type": "G94",
    }
    assert rows[-2]["M"] == ["M5"] and rows[-1]["M"] == ["M30"]
    moves = [r for r in rows if r["M"] is None or r["M"] == ["M3"]]
    start = moves.pop(0)
    assert (start["X"], start["Y"], start["A"]) == pytest.approx((0.0, 0.0, 0.0))
    spindle = moves.pop(0)
    assert spindle["M"] == ["M3"] and spindle["S"] == 18000.0
    ends = []
    for segment in toolpath.segments:
        if chords_mm is not None and isinstance(segment, ArcSegment):
            count = len(segment_points(segment, chords_mm))
            ends += [("G1", segment)] * (count - 1)
        word = "G0" if not segment.cutting else "G2" if isinstance(segment, ArcSegment) else "G1"
        ends.append(("G1" if chords_mm is not None and word == "G2" else word, segment))
    assert len(moves) == len(ends)
    for row, (word, segment) in zip(moves, ends, strict=True):
        assert row["gg01_motion"] == word
        assert row["A"] == pytest.approx(segment.z_end_deg, abs=1e-3)
        if segment.cutting:
            assert row["F"] == PARAMS["xy_speed_mm_s"] * 60.0
            assert segment.distance_to((row["X"], row["Y"])) <= 1e-3
        else:
            assert math.dist((row["X"], row["Y"]), segment.end) <= 1e-3
    for row, (_word, segment) in zip(moves, ends, strict=True):
        if not (chords_mm is not None and isinstance(segment, ArcSegment)):
            assert math.dist((row["X"], row["Y"]), segment.end) <= 1e-3
