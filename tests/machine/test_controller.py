"""The machine as an operator meets it: power-up, homing, cycles, stop, E-stop, faults, reset.

Every test drives the real controller, planner, executor and simulated drives on a simulated
clock, through the same commands the screens send."""

from __future__ import annotations

import logging

import pytest

from app.data.database import Database
from app.machine import commands as cmd
from app.machine.operator_room import STOP_LOCKOUT_S
from app.machine.snapshot import AlarmState
from app.machine.states import CycleStep, MachineState
from tests.machine.conftest import Rig


def test_power_up_with_incremental_encoders_is_not_homed(rig: Rig) -> None:
    assert rig.state is MachineState.NOT_HOMED
    snapshot = rig.controller.snapshot()
    assert "not homed" in str(snapshot.allowed["Start"])
    rig.send(cmd.Start())
    assert rig.state is MachineState.NOT_HOMED
    assert "not homed" in str(rig.controller.message)
    assert not any(a.enabled for a in snapshot.axes), "power-up enables no drive"


def test_homing_all_axes_then_ready(rig: Rig) -> None:
    rig.home()
    assert rig.controller.axes.all_homed()
    assert rig.controller.snapshot().allowed["Start"] is None


def test_full_cycle_counts_and_records_the_piece(ready_rig: Rig, tmp_path) -> None:
    rig = ready_rig
    rig.send(cmd.Start())
    seen: set[CycleStep] = set()

    def done(c) -> bool:  # type: ignore[no-untyped-def]
        if c.cycle is not None:
            seen.add(c.cycle.step)
        return c.state is MachineState.READY

    rig.until(done, 200.0)
    assert rig.controller.pieces_total == 1 and rig.controller.pieces_shift == 1
    # No return home: the next board's approach starts where side B ended.
    returning = CycleStep.RETURNING
    assert set(CycleStep) - {CycleStep.WAIT_FOR_PART, CycleStep.RETRACTING, returning} <= seen
    assert returning not in seen
    assert not rig.world.outputs.spindle_on and not rig.world.outputs.clamps_close
    last = rig.controller.finished_cycles[-1][0]
    assert last.result == "ok" and 140 < last.width_mm < 160
    with Database.open(tmp_path / "stave.db") as db:
        assert db.piece_counts(__import__("datetime").datetime(2000, 1, 1).astimezone())[1] == 1


def test_a_finished_board_is_not_cut_twice(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.send(cmd.Start())
    rig.until(lambda c: c.state is MachineState.READY, 200.0)
    rig.send(cmd.Start())
    rig.run(3.0)
    assert rig.controller.cycle is not None
    assert rig.controller.cycle.step is CycleStep.WAIT_FOR_PART
    assert rig.controller.pieces_total == 1


def test_stop_during_cut_is_controlled_and_nothing_resumes(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.CUTTING_A)
    rig.run(2.0)
    rig.send(cmd.Stop())
    assert rig.state is MachineState.STOPPING
    rig.until(lambda c: c.state is MachineState.READY, 10.0)
    still = rig.positions()
    rig.run(5.0)
    assert rig.positions() == pytest.approx(still, abs=0.01)
    assert not rig.world.outputs.spindle_on
    interrupted = rig.controller.partly_cut.board
    assert interrupted is not None and interrupted.reason == "stop"
    assert rig.controller.pieces_total == 0, "a partly cut board is not a piece"


def test_second_stop_within_lockout_is_ignored(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.world.remove_board()
    rig.send(cmd.Start())  # waits for a board
    assert rig.state is MachineState.AUTOMATIC
    rig.send(cmd.Stop())
    rig.until(lambda c: c.state is MachineState.READY, 2.0)
    rig.send(cmd.Start())
    rig.send(cmd.Stop())  # within 500 ms of the first stop
    assert rig.state is MachineState.AUTOMATIC
    rig.run(STOP_LOCKOUT_S)
    rig.send(cmd.Stop())
    rig.until(lambda c: c.state is MachineState.READY, 2.0)


def test_stop_push_button(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.CUTTING_A)
    rig.world.press_stop()
    rig.until(lambda c: c.state is MachineState.READY, 10.0)


def test_estop_latches_and_needs_reset_then_start(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.CUTTING_A)
    rig.run(1.0)
    rig.world.set_estop(True)
    rig.run(0.02)
    assert rig.state is MachineState.EMERGENCY_STOP
    assert not rig.world.outputs.spindle_on
    rig.send(cmd.Reset())
    assert rig.state is MachineState.EMERGENCY_STOP
    assert "emergency stop" in str(rig.controller.message)
    rig.run(2.0)
    rig.world.set_estop(False)
    rig.run(1.0)
    assert rig.state is MachineState.EMERGENCY_STOP, "releasing the E-stop resets nothing"
    still = rig.positions()
    rig.send(cmd.Reset())
    rig.run(1.0)
    assert rig.state in (MachineState.READY, MachineState.NOT_HOMED)
    assert not any(a.enabled for a in rig.controller.snapshot().axes), "reset enables nothing"
    rig.run(3.0)
    assert rig.positions() == pytest.approx(still, abs=0.01)
    alarm = next(a for a in rig.controller.snapshot().alarms if a.code == "E001")
    assert alarm.state is AlarmState.RTN_UNACKED
    rig.send(cmd.Acknowledge(alarm.alarm_id))
    assert all(a.code != "E001" for a in rig.controller.snapshot().alarms)


def test_drive_fault_latches_error_and_reset_ends_disabled(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.CUTTING_B, 120.0)
    rig.faults.inject("drive_fault", "Y")
    rig.run(0.05)
    assert rig.state is MachineState.ERROR
    assert any(a.code == "E010" and a.source == "Y" for a in rig.controller.snapshot().alarms)
    rig.run(2.0)
    assert not rig.moving()
    rig.faults.clear_injections()
    rig.send(cmd.Reset(), run_s=0.5)
    assert rig.state is MachineState.READY
    snapshot = rig.controller.snapshot()
    assert all(a.power_state == "switch on disabled" for a in snapshot.axes)
    assert rig.controller.cycle is None


def _log_lines(caplog: pytest.LogCaptureFixture, text: str) -> list[str]:
    return [r.getMessage() for r in caplog.records if text in r.getMessage()]


def test_manual_jog_hold_release_and_deadman(rig: Rig, caplog: pytest.LogCaptureFixture) -> None:
    caplog.set_level(logging.INFO, logger="app.machine")
    rig.send(cmd.SetUser("anna"))
    rig.home()
    rig.send(cmd.EnterManual())
    assert rig.state is MachineState.MANUAL
    x0 = rig.positions()[0]
    for _ in range(10):  # the screen refreshes while the button is held
        rig.send(cmd.JogContinuous("X", +1), run_s=0.05)
    rig.send(cmd.JogRelease("X"), run_s=1.0)
    x1 = rig.positions()[0]
    assert x1 > x0 + 1.0
    rig.run(1.0)
    assert rig.positions()[0] == pytest.approx(x1, abs=0.01), "jog stops on release"
    rig.send(cmd.JogContinuous("X", +1), run_s=0.05)  # then no refresh: the dead-man stops it
    rig.run(2.0)
    x2 = rig.positions()[0]
    rig.run(1.0)
    assert rig.positions()[0] == pytest.approx(x2, abs=0.01)
    assert x2 - x1 < 100.0
    rig.send(cmd.JogStep("Y", 10.0), run_s=2.0)
    assert abs(rig.positions()[1] - (rig.controller.axes.command["Y"])) < 0.01
    rig.send(cmd.LeaveManual())
    assert rig.state is MachineState.READY
    # The machine log: each held jog once (not each refresh), the dead-man stop once, every
    # action with the user at the panel.
    jogs = _log_lines(caplog, f"{cmd.JogContinuous('X', +1)} by anna")
    assert len(jogs) == 2
    assert len(_log_lines(caplog, "jog X stopped by its dead-man")) == 1
    for action in ("EnterManual() by anna", "JogStep(axis='Y', step=10.0) by anna"):
        assert len(_log_lines(caplog, action)) == 1


def test_jog_refused_outside_manual_and_start_refused_in_manual(
    rig: Rig, caplog: pytest.LogCaptureFixture
) -> None:
    caplog.set_level(logging.INFO, logger="app.machine")
    rig.home()
    for _ in range(10):  # a held jog button refreshes ten times a second: one log line
        rig.send(cmd.JogContinuous("X", 1), run_s=0.1)
    assert "Manual" in str(rig.controller.message)
    assert len(_log_lines(caplog, "open the Manual screen to jog")) == 1
    rig.send(cmd.EnterManual())
    rig.send(cmd.Start())
    assert rig.state is MachineState.MANUAL
    assert "manual" in str(rig.controller.message)


def test_guard_opened_during_cut_is_a_fault(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.CUTTING_A)
    rig.run(0.5)
    rig.world.set_guard(False)
    rig.run(0.02)
    assert rig.state is MachineState.ERROR
    assert any(a.code == "E002" for a in rig.controller.snapshot().alarms)


def test_width_out_of_range_is_refused_before_cutting(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.load(295.0)
    rig.send(cmd.Start())
    rig.until(lambda c: c.state is MachineState.ERROR, 30.0)
    alarm = next(a for a in rig.controller.snapshot().alarms if a.code == "E032")
    assert "board 295.0 mm" in alarm.text and "at most 178.6 mm" in alarm.text
    assert rig.controller.finished_cycles[-1][0].result == "rejected"


def test_unplugged_gauge_is_reconnected_by_reset(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.faults.inject("comms_loss", "gauge")
    rig.send(cmd.Start())
    rig.until(lambda c: c.state is MachineState.ERROR, 30.0)
    assert any(a.code == "E033" for a in rig.controller.snapshot().alarms)
    rig.faults.clear_injections()
    rig.send(cmd.Reset(), run_s=0.5)
    assert rig.state is MachineState.READY
    rig.load(150.0)
    rig.send(cmd.Start())
    rig.until(lambda c: c.state is not MachineState.AUTOMATIC, 200.0)
    assert rig.state is MachineState.READY and rig.controller.pieces_total == 1


def test_selected_recipe_is_previewed_before_a_board_is_measured(rig: Rig) -> None:
    snapshot = rig.controller.snapshot()
    assert snapshot.plan_id > 0, "the first recipe is shown at power-up"
    preview = rig.controller.plan_preview(snapshot.plan_id)
    assert preview is not None and len(preview.outline_xy) > 100
    xs = [x for x, _ in preview.outline_xy]
    recipe = rig.controller.recipe
    assert recipe is not None
    assert max(xs) - min(xs) == pytest.approx(recipe.length_mm, abs=1e-6)
    rig.select("Foudre 12000 l")
    assert rig.controller.snapshot().plan_id == snapshot.plan_id + 1


def test_after_a_limit_trip_jog_only_away_from_the_switch(rig: Rig) -> None:
    rig.home()
    rig.send(cmd.EnterManual())
    rig.faults.inject("limit_switch", "X+")
    rig.send(cmd.JogStep("X", 1.0), run_s=0.5)
    assert rig.state is MachineState.ERROR
    assert any(a.code == "E012" for a in rig.controller.snapshot().alarms)
    rig.send(cmd.Reset(), run_s=0.5)
    rig.send(cmd.EnterManual())
    x0 = rig.positions()[0]
    rig.send(cmd.JogStep("X", 5.0), run_s=1.0)
    assert "X+ limit switch is active" in str(rig.controller.message)
    assert rig.positions()[0] == pytest.approx(x0, abs=0.01)
    rig.send(cmd.JogStep("X", -5.0), run_s=2.0)
    assert rig.state is MachineState.MANUAL
    assert rig.positions()[0] == pytest.approx(x0 - 5.0, abs=0.05)
