"""The simulated operator's hands on the table: a board is taken off or replaced, never a
clamped one. (The finished board left on the table after a piece, and the cycle saying so,
are in the Main screen's whole-cycle test.)"""

from __future__ import annotations

from app.machine import commands as cmd
from app.machine.refusals import Reason
from tests.machine.conftest import Rig


def test_a_board_is_taken_off_or_replaced_but_never_while_clamped(rig: Rig) -> None:
    c = rig.controller
    rig.send(cmd.LoadBoard(150.0), run_s=0.1)
    assert c.inputs.part_present
    rig.send(cmd.EnterManual())
    rig.send(cmd.SetClamps(True))
    rig.until(lambda ctl: ctl.inputs.clamps_closed, 5.0)
    for command in (cmd.RemoveBoard(), cmd.LoadBoard(160.0)):
        rig.send(command, run_s=0.1)
        assert c.message is not None and c.message.reason is Reason.UNCLAMP_BOARD_FIRST
        assert c.inputs.part_present and rig.world.board.true_width_mm == 150.0
    rig.send(cmd.SetClamps(False))
    rig.until(lambda ctl: not ctl.inputs.clamps_closed, 5.0)
    rig.send(cmd.LoadBoard(160.0), run_s=0.2)  # replaced: off, then the next one on
    assert c.inputs.part_present and rig.world.board.true_width_mm == 160.0
    rig.send(cmd.RemoveBoard(), run_s=0.1)
    assert not c.inputs.part_present and rig.world.board is None
