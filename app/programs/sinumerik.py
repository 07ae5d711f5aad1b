"""The fixed program of one stave in SINUMERIK's dialect (802D sl / 840D sl, ISO mode off).

Words, as the SINUMERIK programming manuals define them: G17 X-Y plane, G71 mm, G90 absolute,
G94 feed in mm/min, G40 no cutter radius compensation (the path is the tool centre's), G500
no settable zero offset (machine coordinates), G64 continuous-path mode; G0/G1/G2/G3 with
the arc centre as I, J incremental from the arc's start (the default), `M3 S..` spindle,
`G4 F..` dwell in seconds, `M30` end of program, comments after `;`. The tilt is the rotary
axis A in degrees. Not checked by a Siemens interpreter (none is freely available): the tests
read the blocks back and run the program through a third-party Sinumerik-flavoured one; the
motion is the same `StaveMoves` the LinuxCNC program (checked by rs274) is written from.
"""

from __future__ import annotations

from app.programs.header import ProgramInfo, format_number, plain_text
from app.programs.moves import StaveMoves, motion_blocks


def comment(text: str) -> str:
    return f"; {plain_text(text, '')}"


def write_program(moves: StaveMoves, info: ProgramInfo) -> str:
    """The complete program text (ends with a newline)."""
    lines = [
        comment(f"stave jointer program, recipe {info.recipe_name}, {info.describe_width()}"),
        comment(info.stamp()),
        comment("machine coordinates in mm (G500); the tilt is the rotary axis A in degrees"),
        comment(
            f"side A at A = {format_number(moves.tilt_a_deg)}, "
            f"side B at A = {format_number(moves.tilt_b_deg)} deg"
        ),
        comment(info.describe_arcs()),
        "G17 G71 G90 G94 G40 G500 G64",
        comment("start at home"),
        f"G0 X{format_number(moves.start[0])} Y{format_number(moves.start[1])} "
        f"A{format_number(moves.start_tilt_deg)}",
        f"M3 S{format_number(info.spindle_rpm, 0)}",
        f"G4 F{format_number(info.spindle_runup_s, 1)} ; spindle run-up, s",
        f"F{format_number(info.feed_mm_min, 1)} ; cutting feed, mm/min",
    ]
    lines += motion_blocks(moves, comment)
    lines += ["M5", "M30"]
    return "\n".join(lines) + "\n"
