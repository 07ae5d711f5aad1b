"""The side-profile options shared by `stave solve` and `stave simulate`.

    --profile KIND          line_arc_line (default), single_arc, parabola, ellipse,
                            superellipse or drawn
    --exponent N            superellipse exponent (2 to 10)
    --semi-axis-ratio S     ellipse / superellipse: semi-axis along the stave over L/2 (1.05 to 10)
    --dxf FILE [--dxf-layer NAME]   a drawn profile from a DXF file (implies --profile drawn)

The file is read here (the command line's I/O) and handed to `app.data.dxf_profile` as bytes.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from app.data.dxf_profile import DxfProfileError, read_dxf_profile
from app.data.recipe_profile import RecipeProfile
from app.geometry.profile_kinds import EXPONENT, SEMI_AXIS_RATIO, ProfileKind, default_parameters

KINDS = ", ".join(kind.value for kind in ProfileKind)


class ProfileOptionError(ValueError):
    """An option names a kind, a number or a file that cannot be used (one line, why)."""


def add_profile_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--profile", metavar="KIND", help=f"side profile kind: {KINDS}")
    parser.add_argument(
        "--exponent", metavar="N", help=f"superellipse exponent ({EXPONENT.allowed})"
    )
    parser.add_argument(
        "--semi-axis-ratio",
        metavar="S",
        help=f"ellipse/superellipse semi-axis over L/2 ({SEMI_AXIS_RATIO.allowed})",
    )
    parser.add_argument("--dxf", type=Path, metavar="FILE", help="drawn profile (DXF file)")
    parser.add_argument("--dxf-layer", metavar="NAME", help="the DXF layer holding the curve")


def _number(option: str, text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise ProfileOptionError(f"{option} {text!r} is not a number") from None


def profile_from_args(args: argparse.Namespace) -> RecipeProfile | None:
    """The profile the options ask for, or None when none of them is given.

    Raises ProfileOptionError naming the option, the value and what is allowed.
    """
    given = (args.profile, args.exponent, args.semi_axis_ratio, args.dxf)
    if all(value is None for value in given):
        return None
    if args.dxf is not None:
        if args.profile not in (None, ProfileKind.DRAWN.value):
            raise ProfileOptionError(f"--dxf is a drawn profile, not --profile {args.profile}")
        try:
            data = args.dxf.read_bytes()
        except OSError as exc:
            raise ProfileOptionError(f"--dxf {args.dxf}: {exc.strerror or exc}") from None
        try:
            drawing = read_dxf_profile(args.dxf.name, data, args.dxf_layer)
        except DxfProfileError as exc:
            layers = ", ".join(exc.curve_layers)
            hint = f" (--dxf-layer: one of {layers})" if layers else ""
            raise ProfileOptionError(f"--dxf {exc}{hint}") from None
        return RecipeProfile(
            ProfileKind.DRAWN,
            drawing=drawing.shape,
            file_name=drawing.file_name,
            file_sha256=drawing.sha256,
        )
    try:
        kind = ProfileKind.parse(args.profile or ProfileKind.LINE_ARC_LINE.value)
    except ValueError as exc:
        raise ProfileOptionError(f"--profile: {exc}") from None
    if kind is ProfileKind.DRAWN:
        raise ProfileOptionError("--profile drawn needs --dxf FILE")
    params: dict[str, float] = {}
    if args.exponent is not None:
        params[EXPONENT.name] = _number("--exponent", args.exponent)
    if args.semi_axis_ratio is not None:
        params[SEMI_AXIS_RATIO.name] = _number("--semi-axis-ratio", args.semi_axis_ratio)
    if kind.is_family:
        params = {**default_parameters(kind), **params}
    profile = RecipeProfile(kind, tuple(sorted(params.items())))
    errors = profile.validate()
    if errors:
        raise ProfileOptionError("; ".join(e.message for e in errors))
    return profile
