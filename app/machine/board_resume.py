"""Between the controller and the interrupted board: what to remember, and how to go on.

Why a module of its own: the controller only decides *when* (an interruption, an operator's
Resume or Abandon); what is remembered of the board (``interrupted.py``) and how the
continuation is planned (``planner/continuation.py``) are pure and tested on their own.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from app.data.recipe import Recipe
from app.geometry.limits import StaveLimits
from app.machine.cycle import AutomaticCycle, ContinueJob
from app.machine.cycle_plan import PlannedStave, plan_board
from app.machine.interrupted import InterruptedBoard
from app.machine.planner.continuation import Continuation, plan_continuation
from app.machine.planner.limits import MotionLimits
from app.machine.planner.trajectory import Phase
from app.table_outlines import TableOutline


def interruption(
    cycle: AutomaticCycle,
    xyz: tuple[float, float, float],
    reason: str,
    previous: InterruptedBoard | None,
) -> InterruptedBoard | None:
    """The record of a board whose cut has begun (None if it has not: a fresh Start is safe
    then, nothing was cut and the cutter has not left home)."""
    if not cycle.board_partly_cut:
        return None
    phase = cycle.cut_phase or (previous.phase if previous is not None else Phase.APPROACH)
    width = cycle.outcome.width_mm
    if width is None and previous is not None:
        width = previous.width_mm
    return InterruptedBoard(
        recipe_id=cycle.recipe.id,
        recipe_name=cycle.recipe.name,
        width_mm=float(width if width is not None else 0.0),
        phase=phase,
        x_mm=xyz[0],
        y_mm=xyz[1],
        z_deg=xyz[2],
        reason=reason,
        started_s=previous.started_s if previous is not None else cycle.started_s,
    )


def continue_job(
    recipe: Recipe,
    board: InterruptedBoard,
    params: Mapping[str, float],
    stave_limits: StaveLimits,
    motion_limits: MotionLimits,
    *,
    resume: bool,
    devices: Sequence[TableOutline] = (),
) -> ContinueJob:
    """The planning job (run on the planning worker) of Resume or Abandon: the same board
    planned again from the recipe and its measured width, then the way on from where the
    cutter stands."""
    params = dict(params)
    home = (params["home_x_mm"], params["home_y_mm"], params["home_z_deg"])

    def job(start: tuple[float, float, float]) -> tuple[PlannedStave, Continuation]:
        planned = plan_board(
            recipe, board.width_mm, params, stave_limits, motion_limits, home, devices=devices
        )
        continuation = plan_continuation(
            planned.toolpath, board.phase, start, motion_limits, resume=resume, devices=devices
        )
        return planned, continuation

    return job
