"""What every backend's full-cycle test does the same way: pick the sample recipe, and cut one
board and check the machine layer's verdict on it.

Why shared: the cycle tests of the CANopen and Modbus backends prove the same thing (the
real machine layer cuts a stave through that backend), so the recipe and the verdict must be
the same for both; only how the board gets there and what the bus saw differ per backend.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from app.cli.simulate import Watch
from app.data.recipe_files import load_recipe_file
from app.machine import commands as cmd
from app.machine.runtime import MachineRuntime
from app.machine.states import LATCHED_STATES, MachineState

SAMPLE_RECIPES = (
    Path(__file__).resolve().parents[2] / "resources" / "recipes" / "sample_recipes.json"
)


def select_sample_recipe(runtime: MachineRuntime) -> None:
    """Store the first sample recipe and select it."""
    c = runtime.controller
    recipe = c.store.save_recipe(load_recipe_file(SAMPLE_RECIPES)[0])
    assert recipe.id is not None
    c.post(cmd.SelectRecipe(recipe.id))


def cut_one_board(runtime: MachineRuntime, watch: Watch, board_mm: float) -> None:
    """Press Start on a READY machine with a board in and wait for the cycle to end: it must
    end READY without an alarm, with one piece of the board's width, a positive rise D,
    and the cutter within 0.1 mm of the contour (``watch`` observed every tick)."""
    c = runtime.controller
    c.post(cmd.Start())
    runtime.run_for(2 * runtime.period_s)
    assert runtime.run_until(
        lambda m: m.state in LATCHED_STATES or (m.state is MachineState.READY and m.cycle is None),
        300.0,
    ), c.state_text()
    assert c.state is MachineState.READY, c.state_text()
    assert [a.code for a in c.alarms.views()] == []
    assert c.pieces_total == 1 and len(c.finished_cycles) == 1
    piece, cycle = c.finished_cycles[0]
    assert piece.width_mm == pytest.approx(board_mm, abs=0.01)
    assert cycle.outcome.d_mm is not None and cycle.outcome.d_mm > 0
    watch.flush_contour_error()
    assert watch.max_contour_error_mm < 0.1
