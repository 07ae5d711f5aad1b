"""Pieces this shift follow the shift plan (the production parameters): a restart in the
middle of a shift counts the pieces the shift made before it, not 0."""

from __future__ import annotations

from pathlib import Path

from app.machine.production import Production, shift_start_s
from app.machine.store import PieceRecord
from tests.machine.conftest import Rig, make_rig


def _piece(at_s: float) -> PieceRecord:
    return PieceRecord(at_s, None, "Barrique", 150.0, None, None, None, 60.0, "ok")


def test_the_shift_counter_follows_the_plan_across_a_restart(rig: Rig, tmp_path: Path) -> None:
    c = rig.controller
    now = c.wall_clock()
    start = shift_start_s(c.params, now)
    assert start <= now
    assert c.production.shift_start == start  # not the moment the program started
    c.store.record_piece(_piece(start + (now - start) / 2))  # earlier in this shift
    c.store.record_piece(_piece(start - 60.0))  # the shift before
    rig.runtime.shutdown()
    rig = make_rig(tmp_path)
    try:
        assert rig.controller.pieces_shift == 1
        assert rig.controller.pieces_total == 2
    finally:
        rig.runtime.shutdown()


def test_the_plans_next_shift_forgets_the_last_operator(rig: Rig) -> None:
    """At the plan's next shift the last operator's name leaves the records, and the panel is
    told (``plan_shifts_begun``) so that it asks the new operator's name."""
    params = dict(rig.controller.params)
    start = shift_start_s(params, rig.controller.wall_clock())
    length_s = params["shift_length_h"] * 3600.0
    now = [start + 60.0]
    production = Production(rig.controller.store, lambda: now[0])
    production.follow_shifts(params)
    production.operator_name = "ana"
    production.tick(10.0)  # the same shift: nothing changes
    assert (production.plan_shifts_begun, production.operator_name) == (0, "ana")
    now[0] = start + length_s + 1.0
    production.tick(20.0)
    assert (production.plan_shifts_begun, production.operator_name) == (1, "")
    assert production.shift_start == start + length_s and production.pieces_shift == 0
    production.follow_shifts(params)  # parameters reloaded: not a new shift
    assert production.plan_shifts_begun == 1
