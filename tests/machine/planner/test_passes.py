"""Several passes per side: the planner keeps each side's passes and the moves back between
them in that side's cut (spindle on, at the feed on the board), and the cut time counts them."""

from __future__ import annotations

from dataclasses import replace

import pytest

from app.geometry.profile import solve_profile
from app.geometry.toolpath import build_toolpath
from app.machine.planner.stave_plan import plan_stave
from app.machine.planner.trajectory import Phase

from .support import HOME, LIMITS, params


def test_passes_are_planned_within_the_side_and_cost_cut_time() -> None:
    profile = solve_profile(1000.0, 150.0, 0.25, 0.75)
    single = plan_stave(build_toolpath(profile, params()), HOME, LIMITS)
    path = build_toolpath(profile, replace(params(), roughing_allowances_mm=(10.0,)))
    plan = plan_stave(path, HOME, LIMITS)
    phases = [c.chunk.phase for c in plan.chunks]
    # A's passes and the move back between them, then B's: each side one block of its phase.
    cut_phases = [p for p in phases if p in (Phase.CUT_A, Phase.CUT_B)]
    first_b = cut_phases.index(Phase.CUT_B)
    assert set(cut_phases[:first_b]) == {Phase.CUT_A} and set(cut_phases[first_b:]) == {Phase.CUT_B}
    for side in ("A", "B"):
        assert plan.cut_length_mm(side) > 2 * single.cut_length_mm(side) - 1e-6
        assert plan.cut_time_s(side) > 2 * single.cut_time_s(side)
    assert plan.cut_length_mm("A") == pytest.approx(
        sum(s.length_mm for s in path.segments if s.side == "A"), rel=1e-9
    )
