"""What the recipe screen previews for a chosen board width: the stave and its tool path.

Why computed in the GUI (and no Qt here): a preview is geometry only, solved in well under a
millisecond, and the operator wants it to follow every keypad entry; no motion is planned.
The numbers are the same functions the machine uses for the real cut (``solve_profile``,
``build_toolpath``), so the preview cannot disagree with the cut.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

from app.data.recipe import Recipe
from app.geometry.errors import GeometryError
from app.geometry.limits import StaveLimits, validate_stave
from app.geometry.profile import StaveProfile, solve_profile
from app.geometry.toolpath import ToolPathParams, build_toolpath

PREVIEW_CHORD_MM = 0.2
ARC_POINTS = 60

Point = tuple[float, float]


@dataclass(frozen=True)
class RecipePreview:
    """Outline and tool path in machine X/Y, the solved numbers, or why there are none."""

    width_mm: float
    outline: tuple[Point, ...] = ()
    toolpath: tuple[Point, ...] = ()
    cutting: tuple[bool, ...] = ()
    tilt_deg: float | None = None
    head_width_mm: float | None = None
    d_mm: float | None = None
    r_mm: float | None = None
    errors: tuple[str, ...] = field(default_factory=tuple)

    @property
    def ok(self) -> bool:
        return not self.errors


def _arc(center: Point, radius: float, start: Point, end: Point) -> list[Point]:
    a0 = math.atan2(start[1] - center[1], start[0] - center[0])
    a1 = math.atan2(end[1] - center[1], end[0] - center[0])
    if a1 - a0 > math.pi:
        a1 -= 2 * math.pi
    elif a0 - a1 > math.pi:
        a1 += 2 * math.pi
    return [
        (
            center[0] + radius * math.cos(a0 + (a1 - a0) * i / ARC_POINTS),
            center[1] + radius * math.sin(a0 + (a1 - a0) * i / ARC_POINTS),
        )
        for i in range(ARC_POINTS + 1)
    ]


def stave_outline(profile: StaveProfile, origin: Point) -> list[Point]:
    """The closed outline of the finished stave at table level, in machine coordinates."""
    p = profile.points
    side_a = [p["P1"], *_arc(profile.arc_center_a, profile.R, p["P2"], p["P3"]), p["P4"]]
    side_b = [p["P5"], *_arc(profile.arc_center_b, profile.R, p["P6"], p["P7"]), p["P8"]]
    return [(origin[0] + x, origin[1] + y) for x, y in (*side_a, *side_b, p["P1"])]


def toolpath_params(params: Mapping[str, float], tilt_deg: float) -> ToolPathParams:
    """The tool path's inputs from the system parameters (database names)."""
    return ToolPathParams(
        tool_radius_mm=params["tool_radius_mm"],
        machine_height_mm=params["machine_height_mm"],
        tilt_deg=tilt_deg,
        start_x_mm=params["start_x_mm"],
        start_y_mm=params["start_y_mm"],
        lead_mm=params["lead_mm"],
        home_x_mm=params["home_x_mm"],
        home_y_mm=params["home_y_mm"],
        home_z_deg=params["home_z_deg"],
        tilt_clearance_mm=params["tilt_clearance_mm"],
    )


def preview_recipe(
    recipe: Recipe, width_mm: float, params: Mapping[str, float], limits: StaveLimits
) -> RecipePreview:
    """Solve ``recipe`` for a board of ``width_mm``; never raises for bad input (the reasons
    are in ``errors``, one line each, naming the field, the value and what is allowed)."""
    try:
        tilt = recipe.tilt_for_width_deg(width_mm, limits)
    except (GeometryError, ValueError, ArithmeticError) as exc:
        return RecipePreview(width_mm, errors=tuple(str(exc).splitlines()))
    try:
        length_ratio = recipe.length_ratio.value
        width_ratio = recipe.width_ratio.value
    except (AttributeError, ZeroDivisionError) as exc:
        return RecipePreview(width_mm, errors=(str(exc),))
    problems = validate_stave(
        recipe.length_mm,
        width_mm,
        length_ratio,
        width_ratio,
        limits,
        thickness_mm=recipe.thickness_mm,
        tilt_deg=tilt,
    )
    if problems:
        return RecipePreview(width_mm, tilt_deg=tilt, errors=tuple(p.message for p in problems))
    try:
        profile = solve_profile(recipe.length_mm, width_mm, length_ratio, width_ratio, limits)
        toolpath = build_toolpath(profile, toolpath_params(params, tilt))
    except GeometryError as exc:
        return RecipePreview(width_mm, tilt_deg=tilt, errors=tuple(e.message for e in exc.errors))
    polyline = toolpath.to_polyline(PREVIEW_CHORD_MM)
    origin = (params["start_x_mm"], params["start_y_mm"])
    return RecipePreview(
        width_mm=width_mm,
        outline=tuple(stave_outline(profile, origin)),
        toolpath=tuple((p[0], p[1]) for p in polyline),
        cutting=tuple(bool(p[3]) for p in polyline),
        tilt_deg=tilt,
        head_width_mm=profile.W1,
        d_mm=profile.D,
        r_mm=profile.R,
    )
