"""From a recipe and a measured width to a planned stave: geometry, tool path, trajectory.

Why separate from the sequencing: this is pure computation (no devices, no time), shared by
the automatic cycle, ``stave simulate`` and the benchmarks, and it may run on a worker
thread of the machine process so that planning never delays a setpoint.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from app.data.recipe import Recipe
from app.geometry.errors import FieldError, GeometryError
from app.geometry.limits import StaveLimits, check_toolpath_travel, validate_stave
from app.geometry.profile import StaveProfile, solve_profile
from app.geometry.toolpath import ToolPath, ToolPathParams, build_toolpath
from app.machine.planner.limits import MotionLimits
from app.machine.planner.stave_plan import StavePlan, plan_stave


class PlanningError(Exception):
    """The board cannot be cut: ``code`` is the alarm to raise, the message says why."""

    def __init__(self, code: str, message: str, errors: tuple[FieldError, ...] = ()) -> None:
        super().__init__(message)
        self.code = code
        self.errors = errors


@dataclass(frozen=True)
class PlannedStave:
    width_mm: float
    tilt_deg: float
    profile: StaveProfile
    toolpath: ToolPath
    plan: StavePlan


def recipe_tilt_deg(recipe: Recipe, width_mm: float) -> float:
    """The bevel for this board: the recipe's fixed tilt, or derived from the barrel."""
    return recipe.tilt_for_width_deg(width_mm)


def plan_board(
    recipe: Recipe,
    width_mm: float,
    params: Mapping[str, float],
    stave_limits: StaveLimits,
    motion_limits: MotionLimits,
    start_xyz: tuple[float, float, float],
) -> PlannedStave:
    """Validate the measured width against the recipe and the machine, then plan the cut.

    Raises PlanningError with alarm E032 (width not allowed), E050 (outside the travel) or
    E051 (the planner failed), never anything else."""
    try:
        tilt_deg = recipe_tilt_deg(recipe, width_mm)
    except (ValueError, ArithmeticError) as exc:
        raise PlanningError("E032", f"width {width_mm:.2f} mm: {exc}") from exc
    errors = validate_stave(
        recipe.length_mm,
        width_mm,
        recipe.length_ratio.value,
        recipe.width_ratio.value,
        stave_limits,
        thickness_mm=recipe.thickness_mm,
        tilt_deg=tilt_deg,
    )
    if errors:
        raise PlanningError("E032", "; ".join(e.message for e in errors), tuple(errors))
    try:
        profile = solve_profile(
            recipe.length_mm,
            width_mm,
            recipe.length_ratio.value,
            recipe.width_ratio.value,
            stave_limits,
        )
        toolpath = build_toolpath(profile, ToolPathParams.from_parameters(params, tilt_deg))
    except GeometryError as exc:
        raise PlanningError("E032", str(exc), exc.errors) from exc
    travel = check_toolpath_travel(toolpath, stave_limits)
    if travel:
        raise PlanningError("E050", "; ".join(e.message for e in travel), tuple(travel))
    try:
        plan = plan_stave(toolpath, start_xyz, motion_limits)
    except (ValueError, ArithmeticError) as exc:
        raise PlanningError("E051", str(exc)) from exc
    return PlannedStave(width_mm, tilt_deg, profile, toolpath, plan)
