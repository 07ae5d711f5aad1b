"""Planning a board of a barrel: the place's bevels and the closing width reach the cut, a
board too narrow to close the barrel is refused (E034) unless the operator chose to cut it."""

from __future__ import annotations

import pytest

from app.cli.solve import PROCESS_DEFAULTS
from app.data.recipe import TiltMode
from app.geometry.limits import DEFAULT_LIMITS
from app.machine.barrel_job import new_barrel, plan_barrel_board
from app.machine.barrel_set import BoardChoice, Placement
from app.machine.cycle_plan import PlanningError
from tests.data.test_recipe import make_recipe

from .planner.support import HOME, LIMITS

ROUND = make_recipe(name="Round 600", tilt_mode=TiltMode.BARREL, barrel_diameter_mm=600.0)


def plan(barrel, width_mm: float, choice: BoardChoice | None = None):
    return plan_barrel_board(
        barrel, choice, ROUND, width_mm, PROCESS_DEFAULTS, DEFAULT_LIMITS, LIMITS, HOME
    )


@pytest.fixture
def seventeen_staves():
    barrel = new_barrel(ROUND, DEFAULT_LIMITS)
    assert barrel is not None and barrel.min_stave_width_mm == pytest.approx(60.0 / 0.8)
    for _ in range(17):
        barrel = barrel.with_stave(barrel.place(100.0))
    return barrel


def test_a_fixed_tilt_recipe_makes_no_barrel() -> None:
    assert new_barrel(make_recipe(), DEFAULT_LIMITS) is None


def test_the_closing_stave_is_cut_to_the_gap(seventeen_staves) -> None:
    board = seventeen_staves.place(100.0)
    assert board.placement is Placement.ORDINARY  # leaves 76.3 mm: a stave still fits
    after = seventeen_staves.with_stave(board)
    planned = plan(after, 150.0)
    assert planned.barrel_stave is not None
    assert planned.barrel_stave.placement is Placement.CLOSING
    assert planned.cut.width_mm == pytest.approx(76.3091, abs=5e-5)
    assert planned.cut.board_width_mm == 150.0
    assert planned.cut.tilts.a_deg == pytest.approx(7.306772, abs=1e-6)
    assert planned.cut.tilts.b_deg == pytest.approx(7.306772, abs=1e-6)


def test_a_board_too_narrow_to_close_is_e034_unless_chosen(seventeen_staves) -> None:
    # ROUND's width ratio 4/5 makes 75 mm the narrowest stave; 110 mm would leave 66 mm.
    with pytest.raises(PlanningError) as caught:
        plan(seventeen_staves, 110.0)
    assert caught.value.code == "E034"
    assert "put in a board of at least 174.4 mm" in str(caught.value)
    planned = plan(seventeen_staves, 110.0, BoardChoice.CUT_ORDINARY)
    assert planned.barrel_stave is not None
    assert planned.barrel_stave.placement is Placement.ORDINARY
    assert planned.cut.width_mm == 110.0
