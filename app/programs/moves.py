"""The tool path as the moves of a program, before any dialect's words are chosen.

Why this step: both dialects need the same decisions (which moves are rapid, where the tilt
changes, which arcs become chords and how many), and each decision must be taken once. A
cutting line is a feed move, a cutting arc a circular move (or its chords), a travel move a
rapid move with the tilt interpolated along it by the machine (the product changes the tilt
linearly with the distance travelled; G0 with an A word does the same on a coordinated
control). Sections carry the comment that names them in the program.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from enum import Enum

from app.geometry.polyline import segment_points
from app.geometry.segments import ArcSegment, Segment
from app.geometry.toolpath import ToolPath
from app.programs.header import format_number

Point = tuple[float, float]

MIN_CHORD_ERROR_MM = 0.001
MAX_CHORD_ERROR_MM = 5.0
"""Chord errors allowed: below 1 um the program's 4 decimals could not show the difference;
above 5 mm a stave is no longer the recipe's stave."""


class MoveKind(Enum):
    RAPID = "rapid"  # G0: travel, not cutting
    FEED = "feed"  # G1 at the cutting feed
    ARC_CW = "arc_cw"  # G2 at the cutting feed, centre (I, J) relative to the start
    ARC_CCW = "arc_ccw"  # G3


@dataclass(frozen=True)
class Move:
    """One block: where it ends (machine X, Y mm; tilt A deg) and, for arcs, the centre."""

    kind: MoveKind
    end: Point
    tilt_deg: float
    center: Point | None = None


class Section(Enum):
    """The parts of one stave's program, in order; each opens with its comment."""

    APPROACH = "approach: from home to the side A lead-in, tilting to side A"
    SIDE_A = "side A: lead-in, P1 to P4, lead-out"
    REPOSITION = "reposition: out to the tilt position, tilt change, in to side B"
    SIDE_B = "side B: lead-in, P5 to P8, lead-out"
    RETURN = "return: home, tilting back"


@dataclass(frozen=True)
class ProgramSection:
    section: Section
    moves: tuple[Move, ...]


@dataclass(frozen=True)
class StaveMoves:
    """The whole program's motion: where it starts (home) and its sections in order."""

    start: Point
    start_tilt_deg: float
    sections: tuple[ProgramSection, ...]
    tilt_a_deg: float
    tilt_b_deg: float


def check_chord_error(chord_error_mm: float) -> None:
    """Raise ValueError naming the option and the allowed range for a chord error outside it."""
    if not (
        math.isfinite(chord_error_mm) and MIN_CHORD_ERROR_MM <= chord_error_mm <= MAX_CHORD_ERROR_MM
    ):
        raise ValueError(
            f"chords = {chord_error_mm:g} is out of range: allowed "
            f"{MIN_CHORD_ERROR_MM:g} <= chords <= {MAX_CHORD_ERROR_MM:g} mm"
        )


def _section_of(segment: Segment, cut_a_seen: bool, cut_b_seen: bool) -> Section:
    if segment.cutting:
        return Section.SIDE_A if segment.side == "A" else Section.SIDE_B
    if cut_b_seen:
        return Section.RETURN
    if cut_a_seen:
        return Section.REPOSITION
    return Section.APPROACH


def _segment_moves(segment: Segment, chord_error_mm: float | None) -> list[Move]:
    if not segment.cutting:
        return [Move(MoveKind.RAPID, segment.end, segment.z_end_deg)]
    if not isinstance(segment, ArcSegment):
        return [Move(MoveKind.FEED, segment.end, segment.z_end_deg)]
    if chord_error_mm is None:
        kind = MoveKind.ARC_CW if segment.clockwise else MoveKind.ARC_CCW
        return [Move(kind, segment.end, segment.z_end_deg, segment.center)]
    # segment_points takes the fewest equal chords whose sagitta stays within the bound.
    return [
        Move(MoveKind.FEED, (x, y), z)
        for x, y, z, _cutting in segment_points(segment, chord_error_mm)
    ]


def side_tilt_deg(toolpath: ToolPath, side: str) -> float:
    """The one tilt a side is cut at, read from the tool path itself (sides may differ)."""
    tilts = {segment.z_start_deg for segment in toolpath.side_segments(side)}
    if len(tilts) != 1:
        raise ValueError(f"side {side} is cut at more than one tilt: {sorted(tilts)}")
    return tilts.pop()


def stave_moves(toolpath: ToolPath, chord_error_mm: float | None = None) -> StaveMoves:
    """The program's moves for exactly this tool path; arcs as chords when a bound is given."""
    if chord_error_mm is not None:
        check_chord_error(chord_error_mm)
    sections: list[ProgramSection] = []
    current: Section | None = None
    moves: list[Move] = []
    cut_a_seen = cut_b_seen = False
    for segment in toolpath.segments:
        section = _section_of(segment, cut_a_seen, cut_b_seen)
        cut_a_seen = cut_a_seen or section is Section.SIDE_A
        cut_b_seen = cut_b_seen or section is Section.SIDE_B
        if section is not current:
            if current is not None:
                sections.append(ProgramSection(current, tuple(moves)))
            current, moves = section, []
        moves.extend(_segment_moves(segment, chord_error_mm))
    if current is not None:
        sections.append(ProgramSection(current, tuple(moves)))
    first = toolpath.segments[0]
    return StaveMoves(
        start=first.start,
        start_tilt_deg=first.z_start_deg,
        sections=tuple(sections),
        tilt_a_deg=side_tilt_deg(toolpath, "A"),
        tilt_b_deg=side_tilt_deg(toolpath, "B"),
    )


def motion_block(move: Move, start: Point) -> str:
    """The move's words, the same in both dialects: G0/G1 X Y (A on rapid moves, where the
    tilt changes), G2/G3 X Y I J with the centre relative to the start as written (rounded),
    so the control's radius check sees one circle through both written ends."""
    x, y = format_number(move.end[0]), format_number(move.end[1])
    if move.kind is MoveKind.RAPID:
        return f"G0 X{x} Y{y} A{format_number(move.tilt_deg)}"
    if move.kind is MoveKind.FEED:
        return f"G1 X{x} Y{y}"
    assert move.center is not None
    word = "G2" if move.kind is MoveKind.ARC_CW else "G3"
    i = move.center[0] - float(format_number(start[0]))
    j = move.center[1] - float(format_number(start[1]))
    return f"{word} X{x} Y{y} I{format_number(i)} J{format_number(j)}"


def motion_blocks(moves: StaveMoves, section_comment: Callable[[str], str]) -> list[str]:
    """Every section's comment and blocks, in order."""
    lines: list[str] = []
    position = moves.start
    for section in moves.sections:
        lines.append(section_comment(section.section.value))
        for move in section.moves:
            lines.append(motion_block(move, position))
            position = move.end
    return lines
