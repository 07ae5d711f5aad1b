"""Homing with a board on the table: clear of it first (and says so), never through it; with
axes that do not know where they are, refused until the board is off."""

from __future__ import annotations

from pathlib import Path

from app.machine import commands as cmd
from app.machine.states import CycleStep, MachineState
from tests.machine.conftest import Rig, make_rig
from tests.machine.keepout_watch import KeepOutWatch

WIDTH_MM = 150.0


def test_homing_with_a_clamped_board_moves_clear_first_and_never_crosses_it(
    tmp_path: Path,
) -> None:
    rig = make_rig(tmp_path)
    try:
        rig.home()
        rig.select()
        rig.load(WIDTH_MM)
        c = rig.controller
        assert c.recipe is not None
        # Cut side A, stop over the board's far side, abandon the board (it stays clamped
        # until unclamped: here the operator then jogs the cutter beyond the board's far side).
        rig.send(cmd.Start())
        rig.until(lambda m: m.cycle is not None and m.cycle.step is CycleStep.CLAMPING)
        rig.send(cmd.Stop())
        rig.until(lambda m: m.state is MachineState.READY, 10.0)
        rig.send(cmd.EnterManual())
        rig.send(cmd.SetClamps(True), 1.0)
        assert rig.world.inputs().clamps_closed
        params = c.store.parameters()
        far_y = params["start_y_mm"] + 200.0  # beyond the board, on the side away from Y's switch
        rig.send(cmd.JogStep("Y", far_y - rig.positions()[1]), 15.0)
        rig.send(cmd.JogStep("X", 600.0 - rig.positions()[0]), 15.0)
        rig.send(cmd.JogStep("Z", -rig.positions()[2]), 5.0)  # upright
        assert abs(rig.positions()[1] - far_y) < 0.5, rig.positions()
        watch = KeepOutWatch(dict(params), c.recipe.length_mm, 280.0)  # the widest board
        rig.runtime.on_tick.append(watch)
        rig.send(cmd.Home())
        assert "moving clear" in str(c.message), (c.message, rig.positions())
        rig.until(lambda m: m.homing is None, 300.0)
        assert c.axes.all_homed()
        assert watch.touching_periods == 0, watch.violations[:3]
    finally:
        rig.runtime.shutdown()


def test_homing_with_a_board_and_unknown_positions_is_refused(tmp_path: Path) -> None:
    rig: Rig = make_rig(tmp_path)
    try:
        assert rig.state is MachineState.NOT_HOMED
        rig.load(WIDTH_MM)
        reason = rig.controller.snapshot().allowed["Home"]
        assert "take the board off" in str(reason)
        rig.send(cmd.Home())
        assert rig.state is MachineState.NOT_HOMED and not rig.moving()
        rig.world.remove_board()
        rig.run(0.1)
        assert rig.controller.snapshot().allowed["Home"] is None
    finally:
        rig.runtime.shutdown()
