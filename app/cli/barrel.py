"""`stave barrel`: place boards around a round or oval barrel, without the machine.

    stave barrel (--diameter-mm D | --axes-mm AxB) --width W [--width W ...] [--json]
                 [--card FILE.csv]

AxB are the oval's semi-axes a >= b (a 700 x 500 mm belly is --axes-mm 350x250). Prints, per
stave, its number, width and the bevels at its first and second joint (counter-clockwise),
then the closing stave's width and bevels, or that the widths already overrun the perimeter.
`--json` prints one object: {"staves": [{"number", "width_mm", "start_angle_deg",
"bevel_start_deg", "bevel_end_deg"}], "closing": {"width_mm", "bevel_start_deg",
"bevel_end_deg"} | null, "perimeter_mm"}; start_angle_deg is the ellipse parameter t of the
stave's first joint. "closing" is null when the widths overrun the perimeter (the staves that
fit are listed), close it exactly, or leave a gap no single stave can close. `--card` also
writes the cooper's card of the plan (``app.data.barrel_card``; the closing stave marked).
Invalid input exits with 2 and one line on stderr.

Why the values are read as text here: a bad number is then reported with the field's name and
what is allowed, like every other invalid input, instead of argparse's usage dump.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence
from pathlib import Path

from app.cli.console import (
    EXIT_INVALID_INPUT,
    EXIT_OK,
    CliInputError,
    OneLineParser,
    emit,
    run_parsed,
)
from app.data.barrel_card import CardStave, barrel_card_csv
from app.data.files import atomic_write_text
from app.geometry.barrel_section import (
    CLOSED_GAP_MM,
    FULL_TURN_RAD,
    BarrelPlan,
    BarrelSection,
    PlacedStave,
    plan_barrel,
    staves_to_close,
    validate_section,
    validate_widths,
)
from app.geometry.errors import GeometryError


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The options of `stave barrel` (checked by `run`, so errors are one line)."""
    parser.add_argument("--diameter-mm", metavar="D", help="round barrel: belly diameter")
    parser.add_argument(
        "--axes-mm", metavar="AxB", help="oval barrel: belly semi-axes a >= b, e.g. 350x250"
    )
    parser.add_argument(
        "--width",
        action="append",
        default=[],
        metavar="W",
        help="a board's belly width in mm, in placing order (repeat the option)",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument(
        "--card", metavar="FILE", help="also write the cooper's card (.csv): staves in order"
    )


def _number(field: str, text: str) -> object:
    """A float if the text is one; otherwise the text, for the validators to name."""
    try:
        return float(text)
    except ValueError:
        return text


def section_from_args(args: argparse.Namespace) -> tuple[BarrelSection, list[float]]:
    """The barrel section and the widths, or GeometryError / CliInputError naming the field."""
    if (args.diameter_mm is None) == (args.axes_mm is None):
        raise CliInputError(
            "barrel: give exactly one of --diameter-mm D (round) or --axes-mm AxB (oval)"
        )
    if not args.width:
        raise CliInputError("width_mm is missing: allowed one or more --width W (mm)")
    widths = [_number("width_mm", text) for text in args.width]
    errors = validate_widths(widths)
    if args.diameter_mm is not None:
        diameter = _number("barrel_diameter_mm", args.diameter_mm)
        errors = validate_section(diameter_mm=diameter) + errors
        if errors:
            raise GeometryError(errors)
        assert isinstance(diameter, float)
        section = BarrelSection.circle(diameter)
    else:
        parts = args.axes_mm.lower().split("x")
        if len(parts) != 2:
            raise CliInputError(
                f"axes_mm = {args.axes_mm!r} is not AxB: allowed two semi-axes in mm "
                "joined by x, a >= b, e.g. 350x250"
            )
        a, b = _number("barrel_a_mm", parts[0]), _number("barrel_b_mm", parts[1])
        errors = validate_section(a_mm=a, b_mm=b) + errors
        if errors:
            raise GeometryError(errors)
        assert isinstance(a, float) and isinstance(b, float)
        section = BarrelSection(a, b)
    return section, [float(w) for w in widths]  # type: ignore[arg-type]  # checked above


def _stave_json(stave: PlacedStave) -> dict[str, object]:
    return {
        "number": stave.number,
        "width_mm": stave.width_mm,
        "start_angle_deg": stave.start_angle_deg,
        "bevel_start_deg": stave.bevel_start_deg,
        "bevel_end_deg": stave.bevel_end_deg,
    }


def to_json_object(plan: BarrelPlan) -> dict[str, object]:
    """The `--json` object."""
    closing = plan.closing
    return {
        "staves": [_stave_json(stave) for stave in plan.staves],
        "closing": None
        if closing is None
        else {
            "width_mm": closing.width_mm,
            "bevel_start_deg": closing.bevel_start_deg,
            "bevel_end_deg": closing.bevel_end_deg,
        },
        "perimeter_mm": plan.section.perimeter_mm,
    }


def format_report(plan: BarrelPlan, widths_mm: Sequence[float]) -> str:
    """The human-readable output."""
    section = plan.section
    mean = sum(widths_mm) / len(widths_mm)
    shape = (
        f"round barrel, belly diameter {2 * section.a_mm:g} mm"
        if section.is_round
        else f"oval barrel, belly {2 * section.a_mm:g} x {2 * section.b_mm:g} mm "
        f"(a = {section.a_mm:g}, b = {section.b_mm:g})"
    )
    lines = [
        f"{shape}, perimeter {section.perimeter_mm:.2f} mm",
        "stave   width mm   t start deg   bevel start deg   bevel end deg",
    ]
    for stave in plan.staves:
        lines.append(
            f"{stave.number:5d} {stave.width_mm:10.4f} {stave.start_angle_deg:13.6f}"
            f" {stave.bevel_start_deg:17.4f} {stave.bevel_end_deg:15.4f}"
        )
    if plan.overrun_number is not None:
        width = widths_mm[plan.overrun_number - 1]
        lines.append(
            f"the widths overrun the perimeter: stave {plan.overrun_number} ({width:g} mm) "
            f"does not fit after the {len(plan.staves)} before it"
        )
    elif (
        plan.closing is None
        and len(plan.staves)
        and section.chord_mm(plan.end_t_rad, FULL_TURN_RAD) < CLOSED_GAP_MM
    ):
        lines.append("the staves close the barrel exactly: no closing stave")
    elif plan.closing is None:
        lines.append(
            f"no closing stave yet: about {staves_to_close(section, plan.end_t_rad, mean)} more "
            f"staves of the mean width {mean:.1f} mm close the barrel"
        )
    else:
        c = plan.closing
        lines.append(
            f"closing stave {c.number}: width {c.width_mm:.4f} mm, t start "
            f"{c.start_angle_deg:.6f} deg, bevels {c.bevel_start_deg:.4f} deg (start) and "
            f"{c.bevel_end_deg:.4f} deg (end)"
        )
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    """Run `stave barrel` with parsed arguments; returns the exit code."""
    try:
        section, widths = section_from_args(args)
        plan = plan_barrel(section, widths)
    except GeometryError as exc:
        print("stave barrel: " + "; ".join(e.message for e in exc.errors), file=sys.stderr)
        return EXIT_INVALID_INPUT
    except CliInputError as exc:
        print(f"stave barrel: {exc}", file=sys.stderr)
        return EXIT_INVALID_INPUT
    if args.card is not None:
        try:
            write_plan_card(plan, Path(args.card))
        except (ValueError, OSError) as exc:
            print(f"stave barrel: --card: {exc}", file=sys.stderr)
            return EXIT_INVALID_INPUT
    emit(json.dumps(to_json_object(plan)) if args.json else format_report(plan, widths))
    return EXIT_OK


def write_plan_card(plan: BarrelPlan, path: Path) -> None:
    """The cooper's card of the planned staves and the closing stave (ValueError: not .csv)."""
    if path.suffix.lower() != ".csv":
        raise ValueError(f"{path}: the cooper's card is CSV: use a .csv file name")
    placed = [*plan.staves, *([] if plan.closing is None else [plan.closing])]
    closes = plan.overrun_number is None and (
        plan.closing is not None
        or (
            bool(plan.staves)
            and plan.section.chord_mm(plan.end_t_rad, FULL_TURN_RAD) < CLOSED_GAP_MM
        )
    )
    staves = [
        CardStave(
            s.number,
            s.width_mm,
            s.start_angle_deg,
            s.end_angle_deg,
            s.bevel_start_deg,
            s.bevel_end_deg,
            closing=s is plan.closing,
        )
        for s in placed
    ]
    text = barrel_card_csv(staves, closed=closes, barrel_number=None, recipe_name="")
    atomic_write_text(path, text)


def main(argv: Sequence[str] | None = None) -> int:
    """Standalone entry point; returns the exit code instead of exiting."""
    parser = OneLineParser(prog="stave barrel", description="Place staves around a barrel.")
    add_arguments(parser)
    return run_parsed(parser, run, argv)


if __name__ == "__main__":
    sys.exit(main())
