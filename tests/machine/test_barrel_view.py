"""What the screens are given of the barrel being raised: the joints, the stave being cut,
what is left, and when to ask about the closing stave; and the operator's answer."""

from __future__ import annotations

import math

import pytest

from app.geometry.barrel_section import FULL_TURN_RAD, BarrelSection
from app.machine.barrel_set import BarrelSet, BoardChoice, Placement
from app.machine.barrel_view import barrel_view
from app.machine.cycle_plan import PlanningError

from .test_barrel_job import plan


def round_600(staves: int) -> BarrelSet:
    barrel = BarrelSet(BarrelSection.circle(600.0), 75.0)
    for _ in range(staves):
        barrel = barrel.with_stave(barrel.place(100.0))
    return barrel


def test_an_empty_barrel_asks_nothing() -> None:
    view = barrel_view(round_600(0), None, None)
    assert view.joints_xy == ((300.0, 0.0),) and view.staves_done == 0
    assert view.gap_mm is None and view.closing_width_mm is None and not view.ask_closing
    assert view.perimeter_left_mm == pytest.approx(600.0 * math.pi, rel=1e-12)


def test_the_stave_being_cut_is_drawn_and_the_question_waits_for_it() -> None:
    barrel = round_600(3)
    current = barrel.place(100.0)
    view = barrel_view(barrel, current, None)
    assert len(view.joints_xy) == 4 and view.current_number == 4
    assert view.current_xy == (barrel.section.point(current.stave.start_t_rad), view.current_xy[1])
    assert math.dist(*view.current_xy) == pytest.approx(100.0, abs=1e-9)
    angle_left = FULL_TURN_RAD - 3 * 2 * math.asin(100.0 / 600.0)
    assert view.perimeter_left_mm == pytest.approx(300.0 * angle_left, rel=1e-9)
    assert view.staves_left == 16 and view.closing_width_mm is None


def test_once_one_stave_closes_the_gap_the_operator_is_asked() -> None:
    barrel = round_600(18)  # docs/MACHINE.md section 7: the closing stave is 76.3091 mm
    view = barrel_view(barrel, None, None)
    assert view.closing_width_mm == pytest.approx(76.3091, abs=5e-5) and view.ask_closing
    assert barrel_view(barrel, None, BoardChoice.CLOSE_NOW).choice is BoardChoice.CLOSE_NOW
    assert not barrel_view(barrel, barrel.place(150.0), None).ask_closing  # being cut
    closed = barrel.with_stave(barrel.place(150.0))
    done = barrel_view(closed, None, None)
    assert done.closed and done.perimeter_left_mm == 0.0 and not done.ask_closing


def test_the_closing_stave_chosen_refuses_a_board_narrower_than_the_gap() -> None:
    barrel = round_600(18)
    assert barrel.place(70.0, BoardChoice.CLOSE_NOW).placement is Placement.TOO_NARROW
    assert barrel.place(80.0, BoardChoice.CLOSE_NOW).placement is Placement.CLOSING
    with pytest.raises(PlanningError) as caught:
        plan(barrel, 70.0, BoardChoice.CLOSE_NOW)
    assert caught.value.code == "E034" and "choose one more normal stave" in str(caught.value)
    # One more normal stave: a board of 40 mm would leave 36 mm (no stave): cut as chosen.
    assert barrel.place(40.0).placement is Placement.TOO_NARROW
    assert barrel.place(40.0, BoardChoice.CUT_ORDINARY).placement is Placement.ORDINARY
