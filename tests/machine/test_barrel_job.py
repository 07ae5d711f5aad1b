"""Planning a board of a barrel: the place's bevels and the closing width reach the cut, a
board too narrow to close the barrel is refused (E034) unless the operator chose to cut it."""

from __future__ import annotations

import math

import pytest

from app.cli.solve import PROCESS_DEFAULTS
from app.data.recipe import BarrelType
from app.geometry.limits import DEFAULT_LIMITS
from app.geometry.stave_cut import MAX_DEPTH_PARAMETER
from app.machine.barrel_job import new_barrel, plan_barrel_board
from app.machine.barrel_set import BoardChoice, Placement
from app.machine.cycle_plan import PlanningError
from app.machine.planner.trajectory import Phase
from tests.data.test_recipe import make_recipe

from .planner.support import HOME, LIMITS

ROUND = make_recipe(name="Round 600", barrel_type=BarrelType.ROUND, barrel_diameter_mm=600.0)


def plan(barrel, width_mm: float, choice: BoardChoice | None = None, params=PROCESS_DEFAULTS):
    return plan_barrel_board(barrel, choice, ROUND, width_mm, params, DEFAULT_LIMITS, LIMITS, HOME)


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


def test_the_closing_staves_roughing_passes_run_at_the_cutting_feed(seventeen_staves) -> None:
    """Every pass of each side - roughing and finishing - reaches the cutting feed and never
    exceeds it; only the moves back round the board between passes are travel moves."""
    after = seventeen_staves.with_stave(seventeen_staves.place(100.0))
    planned = plan(after, 250.0, None, {**PROCESS_DEFAULTS, MAX_DEPTH_PARAMETER: 40.0})
    assert planned.cut.passes == 3  # (250 - 0.8 * 76.3) / 2 = 94.5 mm a side at the heads
    feed = LIMITS.feed_mm_s
    for phase in (Phase.CUT_A, Phase.CUT_B):
        runs: list[list[float]] = []  # the path speeds of each cutting run, in order
        previous_cutting = False
        for item in planned.plan.chunks:
            if item.chunk.phase is not phase:
                continue
            if item.chunk.cutting and not previous_cutting:
                runs.append([])
            previous_cutting = item.chunk.cutting
            if item.chunk.cutting:
                steps = 200
                for k in range(steps + 1):
                    t = item.t_start_s + (item.t_end_s - item.t_start_s) * k / steps
                    s = item.sample(t)
                    runs[-1].append(math.hypot(s.vx, s.vy))
        assert len(runs) == planned.cut.passes
        for speeds in runs:
            assert max(speeds) == pytest.approx(feed, rel=1e-3)
            assert max(speeds) <= feed * (1 + 1e-9)
