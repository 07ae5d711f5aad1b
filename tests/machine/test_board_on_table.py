"""The simulated operator's hands on the table: a finished board is taken off or replaced
(never a clamped one), and the cycle says which board it waits for."""

from __future__ import annotations

from app.machine import commands as cmd
from app.machine.refusals import Reason
from app.machine.states import CycleStep, MachineState
from tests.machine.conftest import Rig


def _one_piece(rig: Rig) -> None:
    before = rig.controller.pieces_total
    rig.send(cmd.Start())
    rig.until(lambda c: c.pieces_total == before + 1 and c.state is MachineState.READY)


def test_the_finished_board_is_taken_off_and_the_next_one_cut(ready_rig: Rig) -> None:
    rig, c = ready_rig, ready_rig.controller
    _one_piece(rig)
    assert c.inputs.part_present  # nobody took it off
    rig.send(cmd.Start())
    assert c.cycle is not None and c.cycle.step is CycleStep.WAIT_FOR_PART
    assert c.snapshot().cycle.finished_board_on_table
    rig.run(1.0)
    assert c.cycle.step is CycleStep.WAIT_FOR_PART  # the finished board is never cut again

    rig.send(cmd.RemoveBoard(), run_s=0.1)
    assert not c.inputs.part_present
    assert not c.snapshot().cycle.finished_board_on_table  # now it waits for a board
    rig.send(cmd.LoadBoard(150.0), run_s=0.1)
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.CLAMPING)

    rig.until(lambda c: c.inputs.clamps_closed)
    for command in (cmd.RemoveBoard(), cmd.LoadBoard(150.0)):
        rig.send(command)
        assert c.message is not None and c.message.reason is Reason.UNCLAMP_BOARD_FIRST
    assert c.inputs.part_present
    rig.until(lambda c: c.state is MachineState.READY)
    assert c.pieces_total == 2
