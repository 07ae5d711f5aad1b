"""From a recipe and a measured width to a planned stave: the checked cut, then its trajectory.

Why separate from the sequencing: this is pure computation (no devices, no time), shared by
the automatic cycle, ``stave simulate`` and the benchmarks, and it may run on a worker
thread of the machine process so that planning never delays a setpoint. The geometry of the
cut is ``app.geometry.stave_cut.cut_stave``, the one composition the previews use too; only
the motion planning is added here.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from app.data.recipe import Recipe
from app.geometry.curved_profile import SideProfile
from app.geometry.errors import FieldError
from app.geometry.limits import StaveLimits
from app.geometry.stave_cut import CutStage, StaveCut, StaveCutRefused, StaveSpec, cut_stave
from app.geometry.toolpath import ToolPath
from app.geometry.width_range import cuttable_widths
from app.machine.alarms import AlarmCode
from app.machine.barrel_set import NextStave
from app.machine.planner.keepout import KeepOutRefused
from app.machine.planner.limits import MotionLimits
from app.machine.planner.stave_plan import (
    JOIN_TOLERANCE_MM,
    StavePlan,
    from_first_cut,
    plan_stave,
)
from app.table_outlines import TableOutline


class PlanningError(Exception):
    """The board cannot be cut: ``code`` is the alarm to raise, the message says why."""

    def __init__(self, code: AlarmCode, message: str, errors: tuple[FieldError, ...] = ()) -> None:
        super().__init__(message)
        self.code = code
        self.errors = errors


@dataclass(frozen=True)
class PlannedStave:
    cut: StaveCut
    plan: StavePlan
    barrel_stave: NextStave | None = None
    """Where the stave goes in the barrel being raised (None: no barrel)."""

    @property
    def width_mm(self) -> float:
        return self.cut.width_mm

    @property
    def tilt_deg(self) -> float:
        """The bevel recorded for the board (both sides alike today)."""
        return self.cut.tilts.a_deg

    @property
    def profile(self) -> SideProfile:
        return self.cut.profile

    @property
    def toolpath(self) -> ToolPath:
        return self.cut.toolpath


def plan_board(
    recipe: Recipe,
    width_mm: float,
    params: Mapping[str, float],
    stave_limits: StaveLimits,
    motion_limits: MotionLimits,
    start_xyz: tuple[float, float, float],
    stave: StaveSpec | None = None,
    devices: Sequence[TableOutline] = (),
) -> PlannedStave:
    """Validate the measured width against the recipe and the machine, then plan the cut.

    Raises PlanningError with alarm E032 (width not allowed), E050 (outside the travel) or
    E051 (the planner failed), E052 (the approach would cross the board), never anything
    else. ``stave`` replaces the recipe's (a barrel's stave: its place's bevels, a target
    width)."""
    spec = recipe.stave if stave is None else stave
    try:
        cut = cut_stave(spec, width_mm, params, stave_limits)
    except StaveCutRefused as exc:
        code = (
            AlarmCode.OUTSIDE_TRAVEL
            if exc.stage is CutStage.TRAVEL
            else AlarmCode.WIDTH_NOT_ALLOWED
        )
        message = "; ".join(e.message for e in exc.errors)
        if exc.stage is CutStage.TILT:
            message = f"width {width_mm:.2f} mm: {message}"
        # One alarm the operator can act on: the measured width and the recipe's bound.
        widths = cuttable_widths(spec, params, stave_limits)
        if widths is None:
            code = AlarmCode.WIDTH_NOT_ALLOWED
            message = f"this recipe cuts no board on this machine ({message})"
        elif not widths.contains(width_mm):
            code, message = AlarmCode.WIDTH_NOT_ALLOWED, widths.refusal(width_mm)
        raise PlanningError(code, message, exc.errors) from exc
    toolpath = cut.toolpath
    first = toolpath.segments[0]
    if math.dist(start_xyz, (*first.start, first.z_start_deg)) > JOIN_TOLERANCE_MM:
        toolpath = from_first_cut(toolpath)  # straight to the lead-in, not through home
    try:
        plan = plan_stave(toolpath, start_xyz, motion_limits, devices=devices)
    except KeepOutRefused as exc:
        raise PlanningError(AlarmCode.APPROACH_CROSSES_BOARD, str(exc)) from exc
    except (ValueError, ArithmeticError) as exc:
        raise PlanningError(AlarmCode.PLANNING_FAILED, str(exc)) from exc
    return PlannedStave(cut, plan)
