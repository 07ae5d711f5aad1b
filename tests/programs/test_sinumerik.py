"""The SINUMERIK program read back block by block: the words of the 802D/840D dialect, and
its motion (absolute X, Y, A; arc centres I, J relative to the start) against the tool path.
No SINUMERIK interpreter is available to run it; this reads the text as the manual defines it."""

from __future__ import annotations

import math
import re

import pytest

from app.data.recipe import Recipe
from app.geometry.segments import ArcSegment
from app.machine.program_export import Dialect, ExportOptions, export_program, stave_toolpath
from tests.programs.conftest import LIMITS, PARAMS

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
    width = 160.0
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
