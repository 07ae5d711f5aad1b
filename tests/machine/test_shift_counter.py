"""Pieces this shift follow the shift plan (the production parameters): a restart in the
middle of a shift counts the pieces the shift made before it, not 0."""

from __future__ import annotations

from pathlib import Path

from app.machine.production import shift_start_s
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
