"""One LinuxCNC program for every board of a recipe: the width is a parameter at the top.

Why a parametric program: a control that has no width gauge link still cuts any board of the
recipe after the operator types the measured width into `#<width>`. The program computes what
the product computes, in the same order: the tilt of each side (fixed, or asin(W / Db) for a
barrel recipe), A, B, C, the rise D as the root of the cubic of docs/MACHINE.md section 2 by
bisection on [0, C] in an O-word loop (as the original PLC did; f(0) > 0 > f(C), 100 steps
at most, stopping below 1e-10 mm), R from relation (1), the points P1..P8, the tool
radius offset r / cos(tilt) along the normals of the straight sections and the arc, the pivot
shift Hm * tan(tilt), the keep-out box and the routes around it, and the tilt position. A
width the product refuses (outside the range found by the product's own function when the
program was written) stops the program with `(abort, ...)` before anything moves.

LinuxCNC's trigonometric functions take and give degrees; named parameters are
case-insensitive and some short global ones are taken (#<_a> is the A axis' position),
so every name here is spelt out. The width and its check come right after the header, then
the subroutines (LinuxCNC reads a definition before its call). Each side has its own tilt
(`#<_tilt_a>`, `#<_tilt_b>`): they are equal today and may differ for a barrel whose sides
are bevelled differently.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from decimal import Decimal

from app.geometry.toolpath import ToolPathParams
from app.programs.header import ProgramInfo, format_number
from app.programs.linuxcnc import comment, header_lines, spindle_on_lines

BISECTION_STEPS = 100
BISECTION_TOLERANCE_MM = 1e-10


@dataclass(frozen=True)
class ParametricStave:
    """A recipe as the parametric program needs it (mm, deg).

    ``barrel_diameter_mm`` set: the tilt of both sides is asin(W / Db) for each board;
    otherwise ``tilt_a_deg`` and ``tilt_b_deg`` (>= 0, side B is cut at -tilt_b_deg).
    ``machine`` holds the process parameters; its ``tilt_deg`` is not used (the program
    computes the tilt for its width). The width range is what the product accepts."""

    length_mm: float
    length_ratio: float
    width_ratio: float
    tilt_a_deg: float
    tilt_b_deg: float
    barrel_diameter_mm: float | None
    width_min_mm: float
    width_max_mm: float
    default_width_mm: float
    machine: ToolPathParams


def exact(value: float) -> str:
    """The float in plain decimal notation (no exponent, which G-code cannot read), with the
    digits that give back exactly this float."""
    if not math.isfinite(value):
        raise ValueError(f"a program cannot hold the number {value}")
    text = format(Decimal(repr(float(value))), "f")
    return "0" if text in ("-0", "-0.0") else text


class _Labels:
    """Unique O-word numbers for the program's if/while blocks."""

    def __init__(self) -> None:
        self._next = 100

    def take(self) -> str:
        self._next += 1
        return f"o{self._next}"


def _max_into(target: str, *candidates: str, labels: _Labels) -> list[str]:
    """#<target> = the largest of the candidate expressions (G-code has no MAX)."""
    lines = [f"#<{target}> = {candidates[0]}"]
    for candidate in candidates[1:]:
        label = labels.take()
        lines += [
            f"{label} if [{candidate} GT #<{target}>]",
            f"  #<{target}> = {candidate}",
            f"{label} endif",
        ]
    return lines


def _slab(axis: str, labels: _Labels) -> list[str]:
    """One axis of the keep-out box's segment test (as KeepOutBox.blocks), inside o<blocks>."""
    start, end = ("#1", "#3") if axis == "x" else ("#2", "#4")
    low, high = f"#<_keep_{axis}_min>", f"#<_keep_{axis}_max>"
    flat, flat_out, swap, raise_low, lower_high, empty = (labels.take() for _ in range(6))
    return [
        f"  #<delta> = [{end} - {start}]",
        f"  {flat} if [#<delta> EQ 0]",
        f"    {flat_out} if [[{start} LE {low}] OR [{start} GE {high}]]",
        "      #<_blocked> = 0",
        "      o<blocks> return",
        f"    {flat_out} endif",
        f"  {flat} else",
        f"    #<enter> = [[{low} - {start}] / #<delta>]",
        f"    #<leave> = [[{high} - {start}] / #<delta>]",
        f"    {swap} if [#<enter> GT #<leave>]",
        "      #<swapped> = #<enter>",
        "      #<enter> = #<leave>",
        "      #<leave> = #<swapped>",
        f"    {swap} endif",
        f"    {raise_low} if [#<enter> GT #<low>]",
        "      #<low> = #<enter>",
        f"    {raise_low} endif",
        f"    {lower_high} if [#<leave> LT #<high>]",
        "      #<high> = #<leave>",
        f"    {lower_high} endif",
        f"    {empty} if [#<low> GE #<high>]",
        "      #<_blocked> = 0",
        "      o<blocks> return",
        f"    {empty} endif",
        f"  {flat} endif",
    ]


WAY_COUNT = "#1000"
"""Numbered globals for the travel waypoints: #1000 the count, #1001.. X and #1011.. Y (named
parameters cannot be indexed; numbered ones can, as #[1001 + i])."""


def _subroutines(labels: _Labels) -> list[str]:
    """o<blocks>, o<route> and o<travel>: the product's keep-out routing and travel moves."""
    direct, level, above = labels.take(), labels.take(), labels.take()
    sum_loop, no_length, walk, last = (labels.take() for _ in range(4))
    step = (
        "SQRT[[#[1001 + #<index>] - #[1000 + #<index>]] ** 2"
        " + [#[1011 + #<index>] - #[1010 + #<index>]] ** 2]"
    )
    return [
        comment("o<blocks>: does the straight move #1,#2 -> #3,#4 cross the keep-out box?"),
        "o<blocks> sub",
        "  #<low> = 0",
        "  #<high> = 1",
        *_slab("x", labels),
        *_slab("y", labels),
        "  #<_blocked> = 1",
        "o<blocks> endsub",
        comment("o<route>: the corners between #1,#2 left of the box and #3,#4, around the box"),
        "o<route> sub",
        "  o<blocks> call [#1] [#2] [#3] [#4]",
        "  #<_route_points> = 0",
        f"  {direct} if [#<_blocked> EQ 1]",
        f"    {level} if [[#4 GE #<_keep_y_max>] OR [#4 LE #<_keep_y_min>]]",
        "      #<_route_points> = 1",
        "      #<_route_1_x> = #1",
        "      #<_route_1_y> = #4",
        f"    {level} else",
        "      #<_route_points> = 2",
        f"      {above} if [#2 GE [[#<_keep_y_min> + #<_keep_y_max>] / 2]]",
        "        #<side_y> = [#<_keep_y_max> + #<_tilt_clearance>]",
        f"      {above} else",
        "        #<side_y> = [#<_keep_y_min> - #<_tilt_clearance>]",
        f"      {above} endif",
        "      #<_route_1_x> = #1",
        "      #<_route_1_y> = #<side_y>",
        "      #<_route_2_x> = #3",
        "      #<_route_2_y> = #<side_y>",
        f"    {level} endif",
        f"  {direct} endif",
        "o<route> endsub",
        comment("o<travel>: rapid moves through the waypoints, the tilt #1 -> #2 by distance"),
        "o<travel> sub",
        "  #<total> = 0",
        "  #<index> = 1",
        f"  {sum_loop} while [#<index> LT {WAY_COUNT}]",
        f"    #<total> = [#<total> + {step}]",
        "    #<index> = [#<index> + 1]",
        f"  {sum_loop} endwhile",
        f"  {no_length} if [#<total> EQ 0]",
        "    G0 A#2",
        "    o<travel> return",
        f"  {no_length} endif",
        "  #<done> = 0",
        "  #<index> = 1",
        f"  {walk} while [#<index> LT {WAY_COUNT}]",
        f"    #<done> = [#<done> + {step}]",
        "    #<tilt> = [#1 + [#2 - #1] * [#<done> / #<total>]]",
        f"    {last} if [#<index> EQ [{WAY_COUNT} - 1]]",
        "      #<tilt> = #2",
        f"    {last} endif",
        "    G0 X#[1001 + #<index>] Y#[1011 + #<index>] A#<tilt>",
        "    #<index> = [#<index> + 1]",
        f"  {walk} endwhile",
        "o<travel> endsub",
    ]


def _push(x: str, y: str) -> list[str]:
    """Append a waypoint to the list o<travel> walks."""
    return [
        f"#[1001 + {WAY_COUNT}] = {x}",
        f"#[1011 + {WAY_COUNT}] = {y}",
        f"{WAY_COUNT} = [{WAY_COUNT} + 1]",
    ]


def _travel_around_the_board(labels: _Labels, side_point: str, to_side: bool) -> list[str]:
    """The waypoints between home and a side's lead-in start or lead-out end (left of the
    board): o<route> gives the corners from the side point towards home; the approach walks
    them backwards, the return forwards."""
    side = (f"#<_{side_point}_x>", f"#<_{side_point}_y>")
    home = ("#<_home_x>", "#<_home_y>")
    lines = [
        f"o<route> call [{side[0]}] [{side[1]}] [{home[0]}] [{home[1]}]",
        f"{WAY_COUNT} = 0",
        *_push(*(home if to_side else side)),
    ]
    for corner in (2, 1) if to_side else (1, 2):
        label = labels.take()
        lines += [
            f"{label} if [#<_route_points> GE {corner}]",
            *("  " + line for line in _push(f"#<_route_{corner}_x>", f"#<_route_{corner}_y>")),
            f"{label} endif",
        ]
    return lines + _push(*(side if to_side else home))


def _bisection(labels: _Labels) -> list[str]:
    """D by bisection of f(D) = D^3 - 2CD^2 + (C^2 - B^2 - 2AB)D + 2ABC on [0, C]."""
    straight, loop, sign = labels.take(), labels.take(), labels.take()
    return [
        comment("D: root of the cubic in (0, C) by bisection; R from R = A*B/D + C - D"),
        f"{straight} if [#<_len_a> GT 0]",
        "  #<_d_low> = 0",
        "  #<_d_high> = #<_len_c>",
        "  #<_steps> = 0",
        f"  {loop} while [[#<_steps> LT {BISECTION_STEPS}] AND "
        f"[[#<_d_high> - #<_d_low>] GT {exact(BISECTION_TOLERANCE_MM)}]]",
        "    #<_rise_d> = [[#<_d_low> + #<_d_high>] / 2]",
        "    #<_f> = [[[#<_rise_d> - 2 * #<_len_c>] * #<_rise_d>"
        " + [#<_len_c> * #<_len_c> - #<_len_b> * #<_len_b> - 2 * #<_len_a> * #<_len_b>]]"
        " * #<_rise_d> + 2 * #<_len_a> * #<_len_b> * #<_len_c>]",
        f"    {sign} if [#<_f> GT 0]",
        "      #<_d_low> = #<_rise_d>",
        f"    {sign} else",
        "      #<_d_high> = #<_rise_d>",
        f"    {sign} endif",
        "    #<_steps> = [#<_steps> + 1]",
        f"  {loop} endwhile",
        "  #<_rise_d> = [[#<_d_low> + #<_d_high>] / 2]",
        "  #<_radius_r> = [#<_len_a> * #<_len_b> / #<_rise_d> + [#<_len_c> - #<_rise_d>]]",
        "  #<_theta> = ATAN[#<_rise_d>]/[#<_len_a>]",
        f"{straight} else",
        comment("  no straight section: one arc, D = 0"),
        "  #<_rise_d> = 0",
        "  #<_radius_r> = [[#<_len_b> * #<_len_b> + #<_len_c> * #<_len_c>] / [2 * #<_len_c>]]",
        "  #<_theta> = [2 * ATAN[#<_len_c>]/[#<_len_b>]]",
        f"{straight} endif",
    ]


def _side_points() -> list[str]:
    """The compensated edges of both sides (docs/MACHINE.md section 3), machine coordinates."""
    lines = [
        comment("offsets along the normals by r / cos(tilt), pivot shift Hm * tan(tilt)"),
        "#<_cos_t> = COS[#<_theta>]",
        "#<_sin_t> = SIN[#<_theta>]",
        "#<_half_head> = [#<_head_width> / 2]",
        "#<_rise> = [#<_half_head> + #<_rise_d>]",
        "#<_centre_y> = [#<width> / 2 - #<_radius_r>]",
    ]
    for side, sign in (("a", "-"), ("b", "+")):
        lines += [
            f"#<_rc_{side}> = [#<_tool_radius> / COS[#<_tilt_{side}>]]",
            f"#<_nx_{side}> = [#<_sin_t> * #<_rc_{side}>]",
            f"#<_ny_{side}> = [#<_cos_t> * #<_rc_{side}>]",
            f"#<_dy_{side}> = [#<_start_y> {sign} #<_machine_height> * TAN[#<_tilt_{side}>]]",
        ]
    # (x, y) of each point in the profile frame, then moved by (P0x, P0y -/+ shift).
    points = {
        "q1": ("[0 - #<_nx_a>]", "[#<_half_head> + #<_ny_a>]", "a"),
        "q2": ("[#<_len_a> - #<_nx_a>]", "[#<_rise> + #<_ny_a>]", "a"),
        "q3": ("[#<_length> - #<_len_a> + #<_nx_a>]", "[#<_rise> + #<_ny_a>]", "a"),
        "q4": ("[#<_length> + #<_nx_a>]", "[#<_half_head> + #<_ny_a>]", "a"),
        "centre_a": ("[#<_length> / 2]", "#<_centre_y>", "a"),
        "q5": ("[#<_length> + #<_nx_b>]", "[0 - #<_half_head> - #<_ny_b>]", "b"),
        "q6": ("[#<_length> - #<_len_a> + #<_nx_b>]", "[0 - #<_rise> - #<_ny_b>]", "b"),
        "q7": ("[#<_len_a> - #<_nx_b>]", "[0 - #<_rise> - #<_ny_b>]", "b"),
        "q8": ("[0 - #<_nx_b>]", "[0 - #<_half_head> - #<_ny_b>]", "b"),
        "centre_b": ("[#<_length> / 2]", "[0 - #<_centre_y>]", "b"),
    }
    for name, (x, y, side) in points.items():
        lines += [
            f"#<_{name}_x> = [{x} + #<_start_x>]",
            f"#<_{name}_y> = [{y} + #<_dy_{side}>]",
        ]
    lines += [
        "#<_in_a_x> = [#<_q1_x> - #<_cos_t> * #<_lead>]",
        "#<_in_a_y> = [#<_q1_y> - #<_sin_t> * #<_lead>]",
        "#<_out_a_x> = [#<_q4_x> + #<_cos_t> * #<_lead>]",
        "#<_out_a_y> = [#<_q4_y> - #<_sin_t> * #<_lead>]",
        "#<_in_b_x> = [#<_q5_x> + #<_cos_t> * #<_lead>]",
        "#<_in_b_y> = [#<_q5_y> + #<_sin_t> * #<_lead>]",
        "#<_out_b_x> = [#<_q8_x> - #<_cos_t> * #<_lead>]",
        "#<_out_b_y> = [#<_q8_y> + #<_sin_t> * #<_lead>]",
    ]
    return lines


def _keep_out(labels: _Labels) -> list[str]:
    """The box around the raw board the travel keeps the pivot out of (keep_out_box)."""
    return [
        comment("keep-out box around the board, and the tilt position beyond its right end"),
        *_max_into("_box_tilt", "ABS[#<_home_z>]", "#<_tilt_a>", "#<_tilt_b>", labels=labels),
        "#<_across> = [#<_tool_radius> / COS[#<_box_tilt>]"
        " + #<_machine_height> * TAN[#<_box_tilt>]]",
        "#<_keep_x_min> = [0 - #<_tool_radius> + #<_start_x>]",
        "#<_keep_x_max> = [#<_length> + #<_tool_radius> + #<_start_x>]",
        "#<_keep_y_min> = [0 - #<width> / 2 - #<_across> + #<_start_y>]",
        "#<_keep_y_max> = [#<width> / 2 + #<_across> + #<_start_y>]",
        *_max_into(
            "_tilt_x",
            "[#<_start_x> + #<_length> + #<_tool_radius> + #<_tilt_clearance>]",
            "#<_out_a_x>",
            "#<_in_b_x>",
            labels=labels,
        ),
    ]


def _cut(side: str, first: str, arc_start: str, arc_end: str, last: str) -> list[str]:
    """One side's cutting moves from its lead-in start on: the edge, then the lead-out."""
    lead_out, centre = f"out_{side}", f"centre_{side}"

    def xy(name: str) -> str:
        return f"X#<_{name}_x> Y#<_{name}_y>"

    return [
        f"G1 {xy(first)}",
        f"G1 {xy(arc_start)}",
        f"G2 {xy(arc_end)} I[#<_{centre}_x> - #<_{arc_start}_x>]"
        f" J[#<_{centre}_y> - #<_{arc_start}_y>]",
        f"G1 {xy(last)}",
        f"G1 {xy(lead_out)}",
    ]


def write_parametric_program(stave: ParametricStave, info: ProgramInfo) -> str:
    """The parametric LinuxCNC program of the recipe (ends with a newline)."""
    labels = _Labels()
    m = stave.machine
    low, high = format_number(stave.width_min_mm, 3), format_number(stave.width_max_mm, 3)
    if stave.barrel_diameter_mm is None:
        tilt_line = (
            f"side A at A = {format_number(stave.tilt_a_deg)}, "
            f"side B at A = -{format_number(stave.tilt_b_deg)} deg"
        )
        tilt = [
            f"#<_tilt_a> = {exact(stave.tilt_a_deg)}",
            f"#<_tilt_b> = {exact(stave.tilt_b_deg)}",
        ]
    else:
        tilt_line = (
            # No parentheses: they would end a LinuxCNC comment (they came out as "_").
            "both sides at A = asin of width / barrel diameter "
            f"{format_number(stave.barrel_diameter_mm, 1)} mm, side B negative"
        )
        tilt = [
            f"#<_tilt_a> = ASIN[#<width> / {exact(stave.barrel_diameter_mm)}]",
            "#<_tilt_b> = #<_tilt_a>",
        ]
    refuse = labels.take()
    lines = [
        *header_lines(info, tilt_line),
        comment(f"the board's width at the belly in mm: set it for each board, {low} to {high}"),
        f"#<width> = {format_number(stave.default_width_mm, 3)}",
        f"{refuse} if [[#<width> LT {low}] OR [#<width> GT {high}]]",
        f"  (abort, width outside what this recipe accepts: {low} to {high} mm)",
        f"{refuse} endif",
        *_subroutines(labels),
        comment("recipe"),
        f"#<_length> = {exact(stave.length_mm)}",
        f"#<_length_ratio> = {exact(stave.length_ratio)}",
        f"#<_width_ratio> = {exact(stave.width_ratio)}",
        *tilt,
        comment("machine: tool radius, pivot height, P0, lead, home, tilt clearance"),
        f"#<_tool_radius> = {exact(m.tool_radius_mm)}",
        f"#<_machine_height> = {exact(m.machine_height_mm)}",
        f"#<_start_x> = {exact(m.start_x_mm)}",
        f"#<_start_y> = {exact(m.start_y_mm)}",
        f"#<_lead> = {exact(m.lead_mm)}",
        f"#<_home_x> = {exact(m.home_x_mm)}",
        f"#<_home_y> = {exact(m.home_y_mm)}",
        f"#<_home_z> = {exact(m.home_z_deg)}",
        f"#<_tilt_clearance> = {exact(m.tilt_clearance_mm)}",
        comment("profile: A, B, C, head width"),
        "#<_len_a> = [#<_length_ratio> * #<_length>]",
        "#<_len_b> = [#<_length> / 2 - #<_len_a>]",
        "#<_head_width> = [#<_width_ratio> * #<width>]",
        "#<_len_c> = [[#<width> - #<_head_width>] / 2]",
        *_bisection(labels),
        *_side_points(),
        *_keep_out(labels),
        comment("start at home"),
        "G0 X#<_home_x> Y#<_home_y> A#<_home_z>",
        *spindle_on_lines(info),
        comment("approach: from home to the side A lead-in, tilting to side A"),
    ]
    lines += _travel_around_the_board(labels, "in_a", to_side=True)
    lines += [
        "o<travel> call [#<_home_z>] [#<_tilt_a>]",
        comment("side A: lead-in, P1 to P4, lead-out"),
        *_cut("a", "q1", "q2", "q3", "q4"),
        comment("reposition: out to the tilt position, tilt change, in to side B"),
        "G0 X#<_tilt_x> Y#<_out_a_y> A#<_tilt_a>",
        "G0 X#<_tilt_x> Y#<_in_b_y> A[0 - #<_tilt_b>]",
        "G0 X#<_in_b_x> Y#<_in_b_y> A[0 - #<_tilt_b>]",
        comment("side B: lead-in, P5 to P8, lead-out"),
        *_cut("b", "q5", "q6", "q7", "q8"),
        comment("return: home, tilting back"),
    ]
    lines += _travel_around_the_board(labels, "out_b", to_side=False)
    lines += [
        "o<travel> call [0 - #<_tilt_b>] [#<_home_z>]",
        "M5",
        "M2",
        "%",
    ]
    return "\n".join(lines) + "\n"
