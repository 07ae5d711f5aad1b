"""A barrel being raised: ordinary staves at their place, the closing stave cut to the gap,
the board too narrow to close it, the estimate of staves left."""

from __future__ import annotations

import math

import pytest

from app.geometry.barrel_section import BarrelSection, plan_barrel
from app.geometry.limits import DEFAULT_LIMITS
from app.machine.barrel_set import BarrelSet, BoardChoice, Placement

OVAL = BarrelSection(350.0, 250.0)


def raise_barrel(barrel: BarrelSet, widths: list[float]) -> BarrelSet:
    for width in widths:
        barrel = barrel.with_stave(barrel.place(width))
    return barrel


def test_an_oval_barrel_of_100_mm_boards_closes_with_the_worked_example_stave() -> None:
    barrel = raise_barrel(BarrelSet(OVAL, 80.0), [100.0] * 18)
    expected = plan_barrel(OVAL, [100.0] * 18)
    assert barrel.staves == expected.staves
    assert not barrel.closed and barrel.staves_left_estimate() == 1
    closing = barrel.place(120.0)  # any board at least as wide as the gap closes it
    assert closing.number == 19 and closing.placement is Placement.CLOSING
    assert closing.target_width_mm == pytest.approx(88.3871, abs=5e-5)
    assert closing.tilts.a_deg == pytest.approx(13.1755, abs=5e-5)
    assert closing.tilts.b_deg == pytest.approx(13.9145, abs=5e-5)
    # The rule the cut uses gives the closing joints' bevels at the target width.
    tilts = closing.tilt_rule.tilts_for_width(closing.target_width_mm, DEFAULT_LIMITS)
    assert tilts.a_deg == pytest.approx(closing.tilts.a_deg, abs=1e-7)
    assert tilts.b_deg == pytest.approx(closing.tilts.b_deg, abs=1e-7)
    done = barrel.with_stave(closing)
    assert done.closed and done.gap_mm < 1e-6 and done.staves_left_estimate() == 0
    assert done.next_barrel() == BarrelSet(OVAL, 80.0, (), 2)


def test_each_ordinary_stave_gets_the_bevels_of_its_place() -> None:
    barrel = raise_barrel(BarrelSet(OVAL, 80.0), [100.0, 100.0])
    third = barrel.place(100.0)
    assert third.placement is Placement.ORDINARY and third.target_width_mm is None
    assert (third.tilts.a_deg, third.tilts.b_deg) == pytest.approx((8.3781, 7.6402), abs=5e-5)
    assert third.tilt_rule.tilts_for_width(100.0, DEFAULT_LIMITS) == third.tilts


def test_a_board_that_would_leave_too_small_a_gap_needs_the_operator() -> None:
    barrel = raise_barrel(BarrelSet(BarrelSection.circle(600.0), 80.0), [100.0] * 17)
    gap = barrel.gap_mm  # 174.4 mm: a 100 mm board would leave 76.3 mm, under 80
    assert gap == pytest.approx(600.0 * math.sin(math.radians((360 - 17 * 19.188137) / 2)))
    assert barrel.place(100.0).placement is Placement.TOO_NARROW
    forced = barrel.place(100.0, BoardChoice.CUT_ORDINARY)
    assert forced.placement is Placement.ORDINARY
    assert barrel.place(90.0).placement is Placement.ORDINARY  # leaves 86 mm: fine
    assert barrel.place(180.0).placement is Placement.CLOSING


def test_before_the_first_stave() -> None:
    barrel = BarrelSet(OVAL, 80.0)
    assert barrel.gap_mm == math.inf and not barrel.closed
    assert barrel.mean_width_mm is None and barrel.staves_left_estimate() is None
    first = barrel.place(100.0)
    assert first.number == 1 and first.stave.start_t_rad == 0.0


def test_a_gap_wider_than_the_widest_board_is_no_closing_stave_yet() -> None:
    # Round 690 mm barrel after 8 staves of 140 mm: the gap's chord is about 680 mm, a single
    # chord, but no board is that wide, so the operator is not asked about closing.
    round_690 = BarrelSection.circle(690.0)
    barrel = raise_barrel(BarrelSet(round_690, 75.0, max_stave_width_mm=280.0), [140.0] * 8)
    assert barrel.gap_mm > 280.0
    assert barrel.closing_width_mm() is None
    assert barrel.place(140.0, BoardChoice.CLOSE_NOW).placement is Placement.ORDINARY
    # Without the machine's limit (a barrel kept before the limit was), the same gap asks.
    assert raise_barrel(BarrelSet(round_690, 75.0), [140.0] * 8).closing_width_mm() is not None
    # Once the gap fits a board, the question comes, and a wide enough board closes it.
    nearly = raise_barrel(barrel, [140.0] * 6)
    closing_mm = nearly.closing_width_mm()
    assert closing_mm is not None and closing_mm <= 280.0
    assert nearly.place(closing_mm + 1.0).placement is Placement.CLOSING
