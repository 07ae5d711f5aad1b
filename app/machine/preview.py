"""The plan view's data: the stave outline and the tool path, in machine X/Y.

Computed in the machine process once per planned board (and for the selected recipe at a
nominal width, so the operator sees the stave before the first board is measured), and sent
to the screens with its id: the GUI draws without computing the geometry of the cut."""

from __future__ import annotations

from collections.abc import Mapping

from app.data.recipe import Recipe
from app.geometry.errors import GeometryError
from app.geometry.limits import StaveLimits
from app.geometry.outline import stave_outline
from app.geometry.profile import StaveProfile, solve_profile
from app.geometry.toolpath import ToolPath, ToolPathParams, build_toolpath
from app.machine.snapshot import PlanPreview

PREVIEW_CHORD_MM = 0.2  # plenty for a drawing a few hundred pixels wide


def build_preview(plan_id: int, profile: StaveProfile, toolpath: ToolPath) -> PlanPreview:
    params = toolpath.params
    outline = stave_outline(profile, (params.start_x_mm, params.start_y_mm))
    polyline = toolpath.to_polyline(PREVIEW_CHORD_MM)
    return PlanPreview(
        plan_id=plan_id,
        outline_xy=tuple(outline),
        toolpath_xy=tuple((p[0], p[1]) for p in polyline),
        cutting_mask=tuple(bool(p[3]) for p in polyline),
    )


def nominal_width_mm(recipe: Recipe, limits: StaveLimits, last_width_mm: float | None) -> float:
    """The board width a recipe is shown with before a board is measured: the last measured
    width, else a typical 150 mm raised until the head is wide enough, within the limits."""
    if last_width_mm is not None:
        return last_width_mm
    needed = limits.min_head_width_mm / max(recipe.width_ratio.value, 1e-9) + 1.0
    return min(limits.max_width_mm, max(150.0, needed))


def recipe_preview(
    plan_id: int,
    recipe: Recipe,
    params: Mapping[str, float],
    limits: StaveLimits,
    last_width_mm: float | None,
) -> PlanPreview | None:
    """The selected recipe drawn for its nominal width, or None when it cannot be solved
    for that width (the screens then show no stave until a board is measured)."""
    width_mm = nominal_width_mm(recipe, limits, last_width_mm)
    try:
        tilt_deg = recipe.tilt_for_width_deg(width_mm, limits)
        profile = solve_profile(
            recipe.length_mm, width_mm, recipe.length_ratio.value, recipe.width_ratio.value, limits
        )
        toolpath = build_toolpath(profile, ToolPathParams.from_parameters(params, tilt_deg))
    except (GeometryError, ValueError, ArithmeticError, KeyError):
        return None
    return build_preview(plan_id, profile, toolpath)
