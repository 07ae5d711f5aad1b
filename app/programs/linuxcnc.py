"""The fixed program of one stave in LinuxCNC's dialect (RS274/NGC as LinuxCNC 2.9 reads it).

Words: G21 mm, G17 X-Y plane, G90 absolute, G91.1 arc centres relative to the arc's start,
G94 feed in mm/min, G40/G49 no cutter or length compensation (the tool path is already the
tool centre's), G64 P0.001 so that blending never leaves the path by more than 1 um. The G54
offset is set to zero and not rotated (R0: G10 L2 without it keeps the rotation the control
held), and G92 cancelled, so the coordinates are the jointer's machine coordinates whatever
offsets the control held. The tilt is the rotary axis A in degrees.
Checked in the test suite by LinuxCNC's own interpreter, rs274.
"""

from __future__ import annotations

from app.programs.header import ProgramInfo, format_number, plain_text
from app.programs.moves import StaveMoves, motion_blocks

MODAL_SETUP = "G21 G17 G90 G91.1 G94 G40 G49 G80 G64 P0.001"
ZERO_OFFSETS = "G10 L2 P1 R0 X0 Y0 Z0 A0 (G54 = machine coordinates, not rotated)\nG54\nG92.1"


def comment(text: str) -> str:
    """A LinuxCNC comment; parentheses inside would end it early."""
    return f"({plain_text(text, '()')})"


def header_lines(info: ProgramInfo, tilt_line: str) -> list[str]:
    return [
        "%",
        comment(f"stave jointer program, recipe {info.recipe_name}, {info.describe_width()}"),
        comment(info.stamp()),
        comment("machine coordinates in mm; the tilt is the rotary axis A in degrees"),
        comment(tilt_line),
        comment(info.describe_arcs()),
        MODAL_SETUP,
        *ZERO_OFFSETS.splitlines(),
    ]


def spindle_on_lines(info: ProgramInfo) -> list[str]:
    return [
        f"M3 S{format_number(info.spindle_rpm, 0)}",
        f"G4 P{format_number(info.spindle_runup_s, 1)} (spindle run-up)",
        f"F{format_number(info.feed_mm_min, 1)} (cutting feed, mm/min)",
    ]


def write_program(moves: StaveMoves, info: ProgramInfo) -> str:
    """The complete program text (ends with a newline)."""
    tilt_line = (
        f"side A at A = {format_number(moves.tilt_a_deg)}, "
        f"side B at A = {format_number(moves.tilt_b_deg)} deg"
    )
    lines = header_lines(info, tilt_line)
    sx, sy = moves.start
    lines.append(comment("start at home"))
    lines.append(
        f"G0 X{format_number(sx)} Y{format_number(sy)} A{format_number(moves.start_tilt_deg)}"
    )
    lines.extend(spindle_on_lines(info))
    lines += motion_blocks(moves, comment)
    lines += ["M5", "M2", "%"]
    return "\n".join(lines) + "\n"
