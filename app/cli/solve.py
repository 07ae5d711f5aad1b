"""`stave solve`: the profile and tool path of one board, from the command line.

    stave solve --length MM --width MM [--length-ratio N/D] --width-ratio N/D
                [--thickness MM] [--tilt DEG [--tilt-b DEG]
                 | --barrel-diameter-mm D | --barrel-axes-mm AxB [--barrel-start-deg T]]
                [--tool-radius MM] [--machine-height MM]
                [--profile KIND] [--exponent N] [--semi-axis-ratio S]
                [--dxf FILE [--dxf-layer NAME]] [--config FILE] [--json]

Human-readable by default; `--json` prints one JSON object (keys A, B, C, D, R, W1, points,
arc_center_a, arc_center_b, toolpath; for the other profile kinds "profile_kind", W1, "edge"
(side A's fitted lines and arcs) and toolpath). --length-ratio is needed by line-arc-line
only; the profile options are those of `app.cli.profile_args`. The bevels: `--tilt` for
side A (and side B unless `--tilt-b` gives its own), or from a barrel: round
(`--barrel-diameter-mm`, both sides asin(W/D)) or oval (`--barrel-axes-mm` a x b, the
semi-axes, with `--barrel-start-deg` the ellipse parameter t of the stave's first joint,
docs/MACHINE.md section 7); both tilts are printed ("tilt_a_deg", "tilt_b_deg" in the
JSON). Invalid input exits with
code 2 and one line on stderr naming the field(s) and the allowed range(s); never a traceback.

`app.cli` wires `stave solve` to `add_arguments` and `run`; `main(argv)` runs it standalone
(`python -m app.cli.solve ...`). Numbers are read as text and converted here, so that
a bad number is reported with the field's name and range like every other invalid input.

Process parameters (tool radius, machine height, start position P0, lead, tilt clearance)
and the axis travel and home position come from `--config FILE` (the machine TOML read by
`app.config.load_config`) through `load_machine_settings`, the one function that knows where
they come from; --tool-radius and --machine-height override them; without a config file the
documented defaults below apply.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

from app.cli.console import (
    EXIT_INVALID_INPUT,
    EXIT_OK,
    CliInputError,
    OneLineParser,
    emit,
    run_parsed,
)
from app.cli.profile_args import ProfileOptionError, add_profile_arguments, profile_from_args
from app.data.recipe_profile import LINE_ARC_LINE
from app.geometry.barrel import RoundBarrelTilt
from app.geometry.barrel_section import BarrelSection, PlacedBarrelTilt, validate_section
from app.geometry.bevel import FixedSideTilts, FixedTilt, SideTilts, TiltRule
from app.geometry.biarc import FIT_TOLERANCE_MM
from app.geometry.curved_profile import CurvedProfile, SideProfile
from app.geometry.errors import FieldError, GeometryError, not_a_number, out_of_range
from app.geometry.limits import StaveLimits, validate_stave
from app.geometry.ratio import Ratio
from app.geometry.stave_cut import StaveSpec, cut_stave
from app.geometry.toolpath import ArcSegment, ToolPath

if TYPE_CHECKING:
    from app.config import MachineConfig

# Defaults when neither a flag nor the config gives a value. They describe a typical
# jointer: an 80 mm diameter cutter, the tilt pivot 250 mm above the table, the stave's left
# end at X = 100 mm on a centre line at Y = 400 mm, home at the origin, untilted.
DEFAULT_TILT_DEG = 4.0
"""4 deg: every width from 60 to 280 mm then gives a barrel of 860..4014 mm (limits 240..4500)."""

PROCESS_DEFAULTS: Mapping[str, float] = {
    "tool_radius_mm": 40.0,
    "machine_height_mm": 250.0,
    "start_x_mm": 100.0,
    "start_y_mm": 400.0,
    "lead_mm": 60.0,
    "tilt_clearance_mm": 50.0,
    "home_x_mm": 0.0,
    "home_y_mm": 0.0,
    "home_z_deg": 0.0,
}

_AXIS_KEYS = (
    ("X", "x_min_mm", "x_max_mm", "home_x_mm"),
    ("Y", "y_min_mm", "y_max_mm", "home_y_mm"),
    ("Z", "z_min_deg", "z_max_deg", "home_z_deg"),
)


@dataclass(frozen=True)
class MachineSettings:
    """Process parameters and limits for one solve."""

    process: Mapping[str, float]
    limits: StaveLimits


def load_machine_settings(config_path: str | None) -> MachineSettings:
    """The process parameters and limits: the one place that knows where they come from.

    Without a path: the shipped default configuration. With one: that file, read by
    `app.config.load_config` and converted by `settings_from_config`; a file that cannot be
    read or is invalid is a CliInputError.
    """
    from app.config import default_config_path, load_config

    if config_path is None:
        config_path = str(default_config_path())  # the shipped machine.toml

    try:
        config = load_config(config_path)
    except Exception as exc:  # any failure to read the file is the user's input error
        raise CliInputError(str(exc).replace("\n", " ")) from exc
    return settings_from_config(config)


def settings_from_config(config: MachineConfig) -> MachineSettings:
    """Process parameters and axis travel from a loaded machine configuration.

    Takes the factory process values of `[process]` (the database may hold newer ones; the
    machine layer passes those), the home position and the soft limits of `[axes.X/Y/Z]`.
    Values the configuration lacks keep this module's defaults.
    """
    process = dict(PROCESS_DEFAULTS)
    for key in process:
        value = getattr(config.process, key, None)
        if isinstance(value, int | float) and not isinstance(value, bool):
            process[key] = float(value)
    travel: dict[str, float] = {}
    for axis_name, min_key, max_key, home_key in _AXIS_KEYS:
        axis = config.axes.get(axis_name)
        if axis is None:
            continue
        travel[min_key] = float(axis.min_position)
        travel[max_key] = float(axis.max_position)
        process[home_key] = float(axis.home_position)
    return MachineSettings(process=process, limits=replace(StaveLimits(), **travel))


def _argument_text(value: object) -> str:
    """The text of an option's value. ``--length=--`` reaches us as an empty list (argparse
    takes ``--`` for its end-of-options marker even after ``=``): it is the text "--"."""
    if isinstance(value, list):
        return " ".join(str(v) for v in value) or "--"
    return str(value)


def _parse_float(field: str, text: str, allowed: str) -> float:
    text = _argument_text(text)
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise CliInputError(f"{field} = {text!r} is not a finite number: allowed {allowed}")
    return value


def _number_or_text(text: str | None) -> object:
    """A float if the text is one; otherwise the text itself, for the validators to report."""
    if text is None:
        return None
    text = _argument_text(text)
    try:
        return float(text)
    except ValueError:
        return text


def _ratio_or_text(text: str) -> tuple[Ratio | None, object]:
    text = _argument_text(text)
    try:
        ratio = Ratio.parse(text)
    except ValueError:
        return None, text
    return ratio, ratio.value


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The options of `stave solve` (values are read as text and checked by `run`)."""
    parser.add_argument("--length", required=True, metavar="MM", help="stave length L")
    parser.add_argument("--width", required=True, metavar="MM", help="measured board width W")
    parser.add_argument(
        "--length-ratio",
        metavar="N/D",
        help="lambda = L1 : L, e.g. 1/4 or 0.25 (line-arc-line only)",
    )
    parser.add_argument(
        "--width-ratio", required=True, metavar="N/D", help="k = W1 : W, e.g. 3/4 or 0.75"
    )
    parser.add_argument("--thickness", metavar="MM", help="stave thickness H (checked only)")
    parser.add_argument(
        "--tilt",
        metavar="DEG",
        help=f"bevel alpha of side A, and of B (default {format(DEFAULT_TILT_DEG, 'g')})",
    )
    parser.add_argument("--tilt-b", metavar="DEG", help="side B's own bevel (with --tilt)")
    parser.add_argument(
        "--barrel-diameter-mm", metavar="D", help="bevels from a round barrel: asin(W / D)"
    )
    parser.add_argument(
        "--barrel-axes-mm", metavar="AxB", help="bevels from an oval barrel: semi-axes a x b"
    )
    parser.add_argument(
        "--barrel-start-deg",
        metavar="T",
        help="oval: the ellipse parameter t of the stave's first joint (default 0)",
    )
    parser.add_argument(
        "--tool-radius",
        metavar="MM",
        help=f"cutter radius r (default {PROCESS_DEFAULTS['tool_radius_mm']:g})",
    )
    parser.add_argument(
        "--machine-height",
        metavar="MM",
        help=f"table to tilt pivot Hm (default {PROCESS_DEFAULTS['machine_height_mm']:g})",
    )
    add_profile_arguments(parser)
    parser.add_argument("--config", metavar="FILE", help="machine configuration file")
    parser.add_argument("--json", action="store_true", help="print one JSON object")


def _solve(args: argparse.Namespace) -> tuple[SideProfile, ToolPath, tuple[str, str]]:
    settings = load_machine_settings(args.config)
    try:
        profile_choice = profile_from_args(args) or LINE_ARC_LINE
    except ProfileOptionError as exc:
        raise CliInputError(str(exc)) from exc
    if not profile_choice.spec.uses_length_ratio():
        args.length_ratio = "0"  # the other kinds have no straight sections: the report says so
    elif args.length_ratio is None:
        raise CliInputError(
            "--length-ratio is required for the line_arc_line profile: "
            "allowed a fraction like 1/4 or a decimal"
        )
    process = dict(settings.process)
    if args.tool_radius is not None:
        process["tool_radius_mm"] = _parse_float(
            "tool_radius_mm", args.tool_radius, "tool radius > 0 mm"
        )
    if args.machine_height is not None:
        process["machine_height_mm"] = _parse_float(
            "machine_height_mm", args.machine_height, "machine height >= 0 mm"
        )
    length = _number_or_text(args.length)
    width = _number_or_text(args.width)
    thickness = _number_or_text(args.thickness)
    tilt = _number_or_text(args.tilt) if args.tilt is not None else DEFAULT_TILT_DEG
    length_ratio, lam = _ratio_or_text(args.length_ratio)
    width_ratio, k = _ratio_or_text(args.width_ratio)

    # Text that is not a number is reported here, with every other problem of the input;
    # numbers go on to the one composition of the cut the machine uses.
    if not all(isinstance(v, float) for v in (length, width, tilt, lam, k)) or not (
        thickness is None or isinstance(thickness, float)
    ):
        raise GeometryError(validate_stave(length, width, lam, k, settings.limits, thickness, tilt))
    assert isinstance(length, float) and isinstance(width, float) and isinstance(tilt, float)
    assert length_ratio is not None and width_ratio is not None
    assert thickness is None or isinstance(thickness, float)
    stave = StaveSpec(
        length,
        thickness,
        length_ratio.value,
        width_ratio.value,
        _tilt_rule(args, tilt),
        profile_choice.spec,
    )
    cut = cut_stave(stave, width, process, settings.limits)
    profile, toolpath = cut.profile, cut.toolpath
    return profile, toolpath, (str(length_ratio), str(width_ratio))


def _tilt_rule(args: argparse.Namespace, tilt_deg: float) -> TiltRule:
    """The bevels the options ask for (GeometryError/CliInputError naming the option)."""
    barrel = args.barrel_diameter_mm is not None or args.barrel_axes_mm is not None
    if barrel and (args.tilt is not None or args.tilt_b is not None):
        raise CliInputError(
            "--tilt/--tilt-b and --barrel-...: give the bevels or the barrel, not both"
        )
    if args.barrel_start_deg is not None and args.barrel_axes_mm is None:
        raise CliInputError("--barrel-start-deg is for an oval barrel: give --barrel-axes-mm")
    if args.tilt_b is not None:
        tilt_b = _number_or_text(args.tilt_b)
        allowed = "0 <= tilt of side B < 90 deg"
        if not isinstance(tilt_b, float):
            raise GeometryError([not_a_number("tilt_b_deg", tilt_b, allowed)])
        if not 0.0 <= tilt_b < 90.0:
            raise GeometryError([out_of_range("tilt_b_deg", tilt_b, allowed)])
        return FixedSideTilts(SideTilts(tilt_deg, tilt_b))
    if not barrel:
        return FixedTilt(tilt_deg)
    axes = None if args.barrel_axes_mm is None else args.barrel_axes_mm.lower().split("x")
    if axes is None:
        diameter = _number_or_text(args.barrel_diameter_mm)
        errors = validate_section(diameter_mm=diameter)
        if errors:
            raise GeometryError(errors)
        assert isinstance(diameter, float)
        return RoundBarrelTilt(diameter)
    if len(axes) != 2:
        raise CliInputError(
            f"barrel_axes_mm = {args.barrel_axes_mm!r} is not AxB: allowed two semi-axes in mm "
            "joined by x, a >= b, e.g. 350x250"
        )
    a, b = _number_or_text(axes[0]), _number_or_text(axes[1])
    errors = validate_section(a_mm=a, b_mm=b)
    start = 0.0 if args.barrel_start_deg is None else _number_or_text(args.barrel_start_deg)
    if not isinstance(start, float) or not 0.0 <= start < 360.0:
        errors.append(out_of_range("barrel_start_deg", start, "0 <= t < 360 deg"))
    if errors:
        raise GeometryError(errors)
    assert isinstance(a, float) and isinstance(b, float) and isinstance(start, float)
    return PlacedBarrelTilt(BarrelSection(a, b), math.radians(start))


_SIDE_OPTIONS = {"tilt_a_deg": ("--tilt", "A"), "tilt_b_deg": ("--tilt-b", "B")}
"""The options that give each side's bevel when the two sides differ."""


def _option_message(error: FieldError) -> str:
    """One refusal as the command line says it: a side's bevel is named by its option and
    in words ("--tilt-b: tilt of side B = 30 is out of range ...")."""
    option = _SIDE_OPTIONS.get(error.field)
    if option is None:
        return error.message
    flag, side = option
    return f"{flag}: " + error.message.replace(error.field, f"tilt of side {side}", 1)


def _pair(point: tuple[float, float]) -> list[float]:
    return [point[0], point[1]]


def _edge_json(profile: CurvedProfile) -> list[dict[str, object]]:
    items: list[dict[str, object]] = []
    for segment in profile.edge("A"):
        item: dict[str, object] = {
            "type": "arc" if isinstance(segment, ArcSegment) else "line",
            "start": _pair(segment.start),
            "end": _pair(segment.end),
        }
        if isinstance(segment, ArcSegment):
            item["center"] = _pair(segment.center)
            item["direction"] = "cw" if segment.clockwise else "ccw"
        items.append(item)
    return items


def to_json_object(profile: SideProfile, toolpath: ToolPath) -> dict[str, object]:
    """The `--json` object."""
    tilts = {
        "tilt_a_deg": toolpath.params.side_tilt_deg("A"),
        "tilt_b_deg": toolpath.params.side_tilt_deg("B"),
    }
    if isinstance(profile, CurvedProfile):
        return {
            "profile_kind": profile.kind.value,
            "W1": profile.W1,
            "edge": _edge_json(profile),
            **tilts,
            "toolpath": toolpath.to_json_list(),
        }
    return {
        "A": profile.A,
        "B": profile.B,
        "C": profile.C,
        "D": profile.D,
        "R": profile.R,
        "W1": profile.W1,
        "points": {name: _pair(point) for name, point in profile.points.items()},
        "arc_center_a": _pair(profile.arc_center_a),
        "arc_center_b": _pair(profile.arc_center_b),
        **tilts,
        "toolpath": toolpath.to_json_list(),
    }


def _curved_lines(profile: CurvedProfile) -> list[str]:
    arcs = [s for s in profile.edge("A") if isinstance(s, ArcSegment)]
    tightest = min((s.radius_mm for s in arcs), default=math.inf)
    return [
        f"stave: L = {profile.length_mm:g} mm, W = {profile.width_mm:g} mm, "
        f"profile {profile.kind.value}, width ratio {profile.width_ratio:g}",
        f"  W1 = {profile.W1:12.6f} mm  head width",
        f"  side A fitted as {len(profile.edge_a)} tangent lines and arcs "
        f"(within {FIT_TOLERANCE_MM:g} mm), tightest radius {tightest:.3f} mm",
    ]


def format_report(profile: SideProfile, toolpath: ToolPath, ratios: tuple[str, str]) -> str:
    """The human-readable output."""
    if isinstance(profile, CurvedProfile):
        return "\n".join([*_curved_lines(profile), *_toolpath_lines(toolpath)])
    lines = [
        f"stave: L = {profile.length_mm:g} mm, W = {profile.width_mm:g} mm, "
        f"length ratio {ratios[0]}, width ratio {ratios[1]}",
        f"  A  = {profile.A:12.6f} mm  straight section",
        f"  B  = {profile.B:12.6f} mm  half length of the arc",
        f"  C  = {profile.C:12.6f} mm  narrowing per side at the heads",
        f"  D  = {profile.D:12.6f} mm  rise of the straight section",
        f"  R  = {profile.R:12.6f} mm  arc radius",
        f"  W1 = {profile.W1:12.6f} mm  head width",
        "points (profile frame, mm):",
    ]
    names = list(profile.points)
    for left, right in zip(names[:4], names[4:], strict=True):
        (lx, ly), (rx, ry) = profile.points[left], profile.points[right]
        lines.append(f"  {left} ({lx:12.6f}, {ly:12.6f})    {right} ({rx:12.6f}, {ry:12.6f})")
    (ax, ay), (bx, by) = profile.arc_center_a, profile.arc_center_b
    lines.append(f"  arc centre A ({ax:.6f}, {ay:.6f})    arc centre B ({bx:.6f}, {by:.6f})")
    return "\n".join([*lines, *_toolpath_lines(toolpath)])


def _toolpath_lines(toolpath: ToolPath) -> list[str]:
    p = toolpath.params
    lines: list[str] = []
    lines.append(
        f"tool path (machine X, Y mm; tilt deg): r = {p.tool_radius_mm:g} mm, "
        f"Hm = {p.machine_height_mm:g} mm, tilt A = {p.side_tilt_deg('A'):.4f} deg, "
        f"tilt B = {p.side_tilt_deg('B'):.4f} deg, "
        f"P0 = ({p.start_x_mm:g}, {p.start_y_mm:g})"
    )
    lines.append("   #  move  side      start X    start Y        end X      end Y    tilt")
    for number, segment in enumerate(toolpath.segments, start=1):
        if isinstance(segment, ArcSegment):
            kind = "arc " + ("cw " if segment.clockwise else "ccw")
        else:
            kind = "line   "
        tilt_text = (
            f"{segment.z_end_deg:g}"
            if segment.z_start_deg == segment.z_end_deg
            else f"{segment.z_start_deg:g} -> {segment.z_end_deg:g}"
        )
        side = segment.side if segment.cutting else "-"
        lines.append(
            f"  {number:2d}  {kind} {side:>2}  {segment.start[0]:11.3f} {segment.start[1]:10.3f}"
            f"  {segment.end[0]:11.3f} {segment.end[1]:10.3f}    {tilt_text}"
            + ("" if segment.cutting else "  (travel)")
        )
    lines.append(
        f"cutting length: side A {toolpath.cutting_length_mm('A'):.3f} mm, "
        f"side B {toolpath.cutting_length_mm('B'):.3f} mm (leads included)"
    )
    return lines


def run(args: argparse.Namespace) -> int:
    """Run `stave solve` with parsed arguments; returns the exit code."""
    try:
        profile, toolpath, ratios = _solve(args)
    except GeometryError as exc:
        print("stave solve: " + "; ".join(_option_message(e) for e in exc.errors), file=sys.stderr)
        return EXIT_INVALID_INPUT
    except CliInputError as exc:
        print(f"stave solve: {exc}", file=sys.stderr)
        return EXIT_INVALID_INPUT
    if args.json:
        emit(json.dumps(to_json_object(profile, toolpath)))
    else:
        emit(format_report(profile, toolpath, ratios))
    return EXIT_OK


def build_parser() -> argparse.ArgumentParser:
    parser = OneLineParser(
        prog="stave solve", description="Solve the stave profile and its tool path."
    )
    add_arguments(parser)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Standalone entry point; returns the exit code instead of exiting."""
    return run_parsed(build_parser(), run, argv)


if __name__ == "__main__":
    sys.exit(main())
