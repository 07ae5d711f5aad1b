"""Manual jogs with a board on the table stay out of its keep-out: a continuous jog stops at
the edge, a step into it is refused with the reason; away from it, or beside it, nothing
changes."""

from __future__ import annotations

from pathlib import Path

import pytest

from app.machine import commands as cmd
from app.machine.planner.jog_keepout import jog_reach
from app.machine.planner.keepout import TableKeepOut
from app.machine.refusals import Reason
from app.machine.states import MachineState
from tests.machine.conftest import Rig, homed_at_power_up, make_rig

PARAMS = {
    "start_x_mm": 300.0,
    "start_y_mm": 400.0,
    "tool_radius_mm": 25.0,
    "machine_height_mm": 250.0,
    "tilt_clearance_mm": 100.0,
}
BOARD = TableKeepOut.for_board(1000.0, 200.0, PARAMS)


def test_a_jog_toward_the_board_stops_at_its_edge_and_one_beside_it_does_not() -> None:
    box = BOARD.box(0.0)
    below = (600.0, 0.0, 0.0)
    assert jog_reach(BOARD, below, "Y", 800.0) == box.y_min  # into the board: stops at the edge
    assert jog_reach(BOARD, below, "Y", -10.0) == -10.0  # away from it
    assert jog_reach(BOARD, below, "X", 3900.0) == 3900.0  # beside it
    left = (0.0, 400.0, 0.0)
    assert jog_reach(BOARD, left, "X", 3900.0) == box.x_min
    assert jog_reach(BOARD, (box.x_max + 5.0, 400.0, 0.0), "X", 0.0) == box.x_max
    assert jog_reach(BOARD, (600.0, 400.0, 0.0), "Y", 0.0) == 0.0  # over it: let it out


def test_a_tilt_that_would_swing_the_cutter_into_the_board_stops_short() -> None:
    edge = BOARD.box(0.0).y_min - 30.0
    reach = jog_reach(BOARD, (600.0, edge, 0.0), "Z", 15.0)
    assert 0.0 < reach < 15.0
    assert not BOARD.inside((600.0, edge, reach))
    assert BOARD.inside((600.0, edge, reach + 1e-6))


def test_jogs_on_the_machine_keep_out_of_the_board(rig: Rig) -> None:
    c = rig.controller
    rig.world.load_board(150.0)
    rig.set_parameters({"jog_xy_speed_mm_s": 250.0, "jog_xy_accel_mm_s2": 2000.0})
    rig.send(cmd.EnterManual(), run_s=0.1)
    assert c.state is MachineState.MANUAL and c.manual.keep_out is not None
    rig.send(cmd.JogStep("X", 600.0 - c.manual.position("X")), run_s=3.0)  # beside the board
    assert c.manual.position("X") == pytest.approx(600.0)
    edge = c.manual.keep_out.box(c.manual.position("Z")).y_min
    rig.send(cmd.JogContinuous("Y", 1, 1))
    assert c.message is not None and c.message.reason is Reason.JOG_STOPS_AT_BOARD
    for _ in range(30):  # held for 3 s: far more than the way to the board
        rig.send(cmd.JogContinuous("Y", 1, 1), run_s=0.1)
    assert c.manual.position("Y") == pytest.approx(edge)
    rig.send(cmd.JogRelease("Y"), run_s=0.5)
    rig.send(cmd.JogContinuous("Y", 1, 2))
    assert c.message is not None and c.message.reason is Reason.JOG_AT_BOARD
    rig.send(cmd.JogStep("Y", 10.0), run_s=0.5)
    assert c.message is not None and c.message.reason is Reason.JOG_STEP_INTO_BOARD
    assert c.manual.position("Y") == pytest.approx(edge)
    rig.send(cmd.JogStep("Y", -50.0), run_s=1.0)  # away from it: as always
    assert c.manual.position("Y") == pytest.approx(edge - 50.0)


def test_go_to_a_position_goes_around_the_board_or_is_refused(tmp_path: Path) -> None:
    rig = make_rig(tmp_path, homed_at_power_up())
    try:
        _go_around_the_board(rig)
    finally:
        rig.runtime.shutdown()


def _go_around_the_board(rig: Rig) -> None:
    c = rig.controller
    rig.send(cmd.MoveTo(600.0, 100.0, 0.0))
    assert c.message is not None and c.message.reason is Reason.OPEN_MANUAL_TO_JOG
    assert c.axes.all_homed()
    rig.world.load_board(150.0)
    rig.set_parameters({"xy_rapid_speed_mm_s": 300.0})
    rig.send(cmd.EnterManual(), run_s=0.1)
    board = c.manual.keep_out
    assert board is not None
    box = board.box(15.0)  # at any tilt
    below, above = (box.x_min + 100.0, box.y_min - 50.0), (box.x_min + 100.0, box.y_max + 50.0)
    rig.send(cmd.MoveTo(*below, 0.0))
    assert c.message is None or c.message.reason is not Reason.MOVE_REFUSED
    rig.until(lambda ctl: not ctl.manual_move.running, 30.0)
    assert c.manual.position("Y") == pytest.approx(below[1], abs=0.05)  # the drive follows

    crossed: list[tuple[float, float, float]] = []

    def watch(runtime) -> None:  # type: ignore[no-untyped-def]
        xyz = tuple(runtime.controller.axes.command[n] for n in ("X", "Y", "Z"))
        if board.inside(xyz):
            crossed.append(xyz)

    rig.runtime.on_tick.append(watch)
    rig.send(cmd.MoveTo(*above, 0.0))  # the straight line runs through the board
    rig.until(lambda ctl: not ctl.manual_move.running, 60.0)
    rig.runtime.on_tick.remove(watch)
    assert crossed == []  # around it
    assert (c.manual.position("X"), c.manual.position("Y")) == pytest.approx(above, abs=0.05)

    rig.send(cmd.MoveTo(600.0, 400.0, 0.0))  # onto the board
    assert c.message is not None and c.message.reason is Reason.MOVE_REFUSED
    rig.send(cmd.MoveTo(600.0, 5000.0, 0.0))
    assert c.message is not None and c.message.reason is Reason.MOVE_OUTSIDE_TRAVEL
    assert not c.manual_move.running
