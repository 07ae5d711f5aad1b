"""Planning one board of a barrel being raised: its place, bevels and width, then the cut.

Why apart from ``cycle_plan``: the barrel decides what the board becomes (an ordinary stave
at the bevels of its place, or the closing stave cut to the gap) before the one recipe-to-cut
composition runs; the board too narrow to close the barrel is refused here, before anything
moves, with the choice the operator has. Runs on the planner thread with one immutable
``BarrelSet`` value.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

from app.data.recipe import Recipe
from app.geometry.barrel_section import FULL_TURN_RAD
from app.geometry.errors import GeometryError
from app.geometry.limits import StaveLimits
from app.machine.alarms import AlarmCode
from app.machine.barrel_set import BarrelSet, BoardChoice, Placement
from app.machine.cycle_plan import PlannedStave, PlanningError, plan_board
from app.machine.planner.limits import MotionLimits

TOO_NARROW_ALARM = AlarmCode.BARREL_NOT_CLOSABLE


def new_barrel(recipe: Recipe, limits: StaveLimits, number: int = 1) -> BarrelSet | None:
    """An empty barrel of the recipe's belly section (None: the recipe has a fixed tilt).

    The narrowest stave it accepts is the recipe's narrowest board: a head of the minimum
    width at the recipe's width ratio; the widest is the widest board the machine takes."""
    section = recipe.barrel_section
    if section is None:
        return None
    min_width = limits.min_head_width_mm / recipe.width_ratio.value
    return BarrelSet(section, min_width, (), number, max_stave_width_mm=limits.max_width_mm)


def plan_barrel_board(
    barrel: BarrelSet,
    choice: BoardChoice | None,
    recipe: Recipe,
    width_mm: float,
    params: Mapping[str, float],
    stave_limits: StaveLimits,
    motion_limits: MotionLimits,
    start_xyz: tuple[float, float, float],
) -> PlannedStave:
    """Place the board in the barrel and plan its cut; PlanningError as ``plan_board`` does,
    and E034 for a board that would leave a gap no stave can close."""
    try:
        placed = barrel.place(width_mm, choice)
    except GeometryError as exc:
        message = "; ".join(e.message for e in exc.errors)
        raise PlanningError(
            AlarmCode.WIDTH_NOT_ALLOWED, f"width {width_mm:.2f} mm: {message}", exc.errors
        ) from exc
    if placed.placement is Placement.TOO_NARROW and choice is BoardChoice.CLOSE_NOW:
        raise PlanningError(
            TOO_NARROW_ALARM,
            f"stave {placed.number}: the closing stave was chosen and the {width_mm:.1f} mm "
            f"board is narrower than the gap of {barrel.gap_mm:.1f} mm: put in a board of at "
            f"least {barrel.gap_mm:.1f} mm, or choose one more normal stave",
        )
    if placed.placement is Placement.TOO_NARROW:
        left = barrel.section.chord_mm(placed.stave.end_t_rad, FULL_TURN_RAD)
        raise PlanningError(
            TOO_NARROW_ALARM,
            f"stave {placed.number}: the {width_mm:.1f} mm board is narrower than the gap of "
            f"{barrel.gap_mm:.1f} mm and would leave {left:.1f} mm, less than a stave "
            f"({barrel.min_stave_width_mm:.1f} mm): put in a board of at least "
            f"{barrel.gap_mm:.1f} mm, or choose to cut this one as an ordinary stave",
        )
    target = placed.target_width_mm
    stave = replace(
        recipe.stave,
        tilt=placed.tilt_rule,
        target_width_mm=recipe.target_width_mm if target is None else target,
    )
    planned = plan_board(
        recipe, width_mm, params, stave_limits, motion_limits, start_xyz, stave=stave
    )
    return replace(planned, barrel_stave=placed)
