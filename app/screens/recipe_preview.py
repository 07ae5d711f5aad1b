"""What the recipe screen previews for a chosen board width: the stave and its tool path.

Why computed in the GUI (and no Qt here): a preview is geometry only, solved in well under a
millisecond, and the operator wants it to follow every keypad entry; no motion is planned.
The numbers are the same functions the machine uses for the real cut (``solve_profile``,
``build_toolpath``), so the preview cannot disagree with the cut.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from app.data.recipe import Recipe
from app.geometry.errors import GeometryError
from app.geometry.limits import StaveLimits, validate_stave
from app.geometry.outline import stave_outline
from app.geometry.profile import solve_profile
from app.geometry.toolpath import ToolPathParams, build_toolpath

PREVIEW_CHORD_MM = 0.2

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
        toolpath = build_toolpath(profile, ToolPathParams.from_parameters(params, tilt))
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
