"""The permission rules, row by row, and their agreement with the state table: a command the
rules accept leads somewhere in the table, and every command-driven row of the table is
reachable through the rules."""

from __future__ import annotations

import ast
import re
from dataclasses import replace
from pathlib import Path

import pytest

from app.drivers.contracts import InputImage
from app.machine import commands as cmd
from app.machine.barrel_set import BoardChoice
from app.machine.permissions import RULES, Facts, allowed_commands, may
from app.machine.refusals import Reason, Refusal, fill, refusal
from app.machine.states import TRANSITIONS, Event, MachineState

S = MachineState
R = Reason
GOOD = Facts(S.READY, True, True, InputImage(), False, False)
OPEN_GUARD = InputImage(guard_closed=False)
ESTOP = InputImage(estop_ok=False)
CLAMPED = InputImage(part_present=True, clamps_closed=True, clamps_open=False)

# (command, changes to GOOD, expected reason or None) - one row per branch of every rule
ROWS: list[tuple[cmd.Command, dict[str, object], Reason | None]] = [
    (cmd.Start(), {}, None),
    (cmd.Start(), {"state": S.ERROR}, R.LATCHED_ERROR),
    (cmd.Start(), {"state": S.EMERGENCY_STOP}, R.LATCHED_ESTOP),
    # while the button is still pressed Reset is refused: the hint must not say "press Reset"
    (cmd.Start(), {"state": S.EMERGENCY_STOP, "inputs": ESTOP}, R.LATCHED_ESTOP_PRESSED),
    (cmd.Start(), {"state": S.POWER_UP}, R.STARTING_UP),
    (cmd.Start(), {"state": S.MANUAL}, R.LEAVE_MANUAL_FIRST),
    (cmd.Start(), {"state": S.AUTOMATIC}, R.CYCLE_RUNNING),
    (cmd.Start(), {"state": S.NOT_HOMED, "all_homed": False}, R.NOT_HOMED),
    (cmd.Start(), {"all_homed": False}, R.NOT_HOMED),
    (cmd.Start(), {"state": S.HOMING}, R.NOT_POSSIBLE_HOMING),
    (cmd.Start(), {"state": S.STOPPING}, R.NOT_POSSIBLE_STOPPING),
    (cmd.Start(), {"state": S.NOT_HOMED}, R.NOT_POSSIBLE_NOT_HOMED),
    (cmd.Start(), {"recipe_loaded": False}, R.SELECT_RECIPE_FIRST),
    (cmd.Start(), {"inputs": OPEN_GUARD}, R.CLOSE_GUARD_FIRST),
    (cmd.Start(), {"interrupted": True}, R.PARTLY_CUT_RESUME_OR_ABANDON),
    (cmd.Resume(), {}, R.NO_BOARD_PARTLY_CUT),
    (cmd.Resume(), {"interrupted": True, "inputs": CLAMPED}, None),
    (cmd.Resume(), {"interrupted": True, "state": S.ERROR}, R.LATCHED_ERROR),
    (cmd.Resume(), {"interrupted": True, "all_homed": False}, R.NOT_HOMED_ABANDON),
    (cmd.Resume(), {"interrupted": True, "state": S.MANUAL}, R.NOT_POSSIBLE_MANUAL),
    (cmd.Resume(), {"interrupted": True}, R.UNCLAMPED_ABANDON),
    (
        cmd.Resume(),
        {"interrupted": True, "interrupted_unclamped": True, "inputs": CLAMPED},
        R.UNCLAMPED_ABANDON,
    ),
    (
        cmd.Resume(),
        {"interrupted": True, "inputs": replace(CLAMPED, guard_closed=False)},
        R.CLOSE_GUARD_FIRST,
    ),
    (cmd.Abandon(), {}, R.NO_BOARD_PARTLY_CUT),
    (cmd.Abandon(), {"interrupted": True, "state": S.NOT_HOMED, "all_homed": False}, None),
    (cmd.Abandon(), {"interrupted": True, "state": S.AUTOMATIC}, R.NOT_POSSIBLE_AUTOMATIC),
    (cmd.Abandon(), {"interrupted": True, "inputs": OPEN_GUARD}, R.CLOSE_GUARD_FIRST),
    (cmd.Home(), {"interrupted": True}, R.PARTLY_CUT_FIRST),
    (
        cmd.Home(),
        {"state": S.NOT_HOMED, "all_homed": False, "inputs": InputImage(part_present=True)},
        R.BOARD_ON_TABLE_UNHOMED,
    ),
    (cmd.Stop(), {"state": S.AUTOMATIC}, None),
    (cmd.Stop(), {"state": S.HOMING}, None),
    (cmd.Stop(), {"state": S.STOPPING}, None),
    (cmd.Stop(), {"state": S.MANUAL}, None),
    (cmd.Stop(), {}, R.NOTHING_MOVING),
    (cmd.Reset(), {"state": S.ERROR}, None),
    (cmd.Reset(), {}, R.NOTHING_TO_RESET),
    (cmd.Reset(), {"state": S.EMERGENCY_STOP, "inputs": ESTOP}, R.RELEASE_ESTOP_FIRST),
    (cmd.Home(), {"state": S.NOT_HOMED, "all_homed": False}, None),
    (cmd.Home(), {"state": S.MANUAL, "inputs": OPEN_GUARD}, None),
    (cmd.Home(), {"state": S.ERROR}, R.LATCHED_ERROR),
    (cmd.Home(), {"state": S.AUTOMATIC}, R.BUSY_AUTOMATIC),
    (cmd.Home(), {"state": S.HOMING}, R.BUSY_HOMING),
    (cmd.Home(), {"state": S.STOPPING}, R.BUSY_STOPPING),
    (cmd.Home(), {"inputs": OPEN_GUARD}, R.CLOSE_GUARD_FIRST),
    (cmd.EnterManual(), {}, None),
    (cmd.EnterManual(), {"state": S.POWER_UP}, R.STARTING_UP),
    (cmd.EnterManual(), {"state": S.MANUAL}, R.ALREADY_MANUAL),
    (cmd.EnterManual(), {"state": S.AUTOMATIC}, R.BUSY_AUTOMATIC),
    (cmd.LeaveManual(), {"state": S.MANUAL}, None),
    (cmd.LeaveManual(), {}, R.NOT_MANUAL),
    (cmd.JogContinuous("X", 1), {"state": S.MANUAL}, None),
    (cmd.JogStep("X", 1.0), {"state": S.EMERGENCY_STOP}, R.LATCHED_ESTOP),
    (cmd.JogStep("X", 1.0), {}, R.OPEN_MANUAL_TO_JOG),
    (cmd.SetClamps(True), {}, R.OPEN_MANUAL_TO_JOG),
    (cmd.SetSpindle(True), {"state": S.MANUAL}, None),
    (cmd.SetSpindle(True), {"state": S.MANUAL, "inputs": OPEN_GUARD}, R.CLOSE_GUARD_FIRST),
    (cmd.SetSpindle(True), {}, R.OPEN_MANUAL_TO_JOG),
    (cmd.MoveTo(600.0, 100.0, 0.0), {"state": S.MANUAL}, None),
    (cmd.MoveTo(600.0, 100.0, 0.0), {"state": S.MANUAL, "all_homed": False}, R.NOT_HOMED),
    (cmd.MoveTo(600.0, 100.0, 0.0), {}, R.OPEN_MANUAL_TO_JOG),
    (cmd.SelectRecipe(1), {}, None),
    (cmd.SelectRecipe(1), {"cycle_running": True}, R.WAIT_FOR_CYCLE_END),
    (cmd.SelectRecipe(1), {"state": S.STOPPING}, R.WAIT_FOR_CYCLE_END),
    (cmd.StartBarrel(), {}, None),
    (cmd.StartBarrel(), {"state": S.AUTOMATIC}, R.WAIT_FOR_CYCLE_END),
    (cmd.ChooseBoard(next(iter(BoardChoice))), {"cycle_running": True}, R.WAIT_FOR_CYCLE_END),
    (cmd.InjectFault("drive_fault", "X"), {"simulation": True}, None),
    (cmd.LoadBoard(150.0), {}, R.SIMULATION_ONLY),
    (cmd.LoadBoard(150.0), {"simulation": True}, None),
    (cmd.LoadBoard(150.0), {"simulation": True, "inputs": CLAMPED}, R.UNCLAMP_BOARD_FIRST),
    (cmd.RemoveBoard(), {}, R.SIMULATION_ONLY),
    (cmd.RemoveBoard(), {"simulation": True}, None),
    (cmd.RemoveBoard(), {"simulation": True, "inputs": CLAMPED}, R.UNCLAMP_BOARD_FIRST),
    (cmd.ClearFaults(), {}, R.SIMULATION_ONLY),
    (cmd.SelectHandwheel("X", 10), {}, R.SIMULATION_ONLY),
    (cmd.TurnHandwheel(100), {"simulation": True, "state": S.ERROR}, None),
    (cmd.HoldJogEnable(True), {}, R.SIMULATION_ONLY),
    (cmd.PushJoystick(0.5), {"simulation": True}, None),
    (cmd.JogRelease("X"), {"state": S.ERROR}, None),
    (cmd.Acknowledge(0), {"state": S.EMERGENCY_STOP}, None),
    (cmd.Shutdown(), {"state": S.POWER_UP}, None),
]


@pytest.mark.parametrize(("command", "changes", "expected"), ROWS)
def test_rule_row(
    command: cmd.Command, changes: dict[str, object], expected: Reason | None
) -> None:
    verdict = may(command, replace(GOOD, **changes))  # type: ignore[arg-type]
    assert (verdict.reason if verdict else None) is expected


def test_every_command_has_a_rule_and_the_rows_visit_them_all() -> None:
    assert set(RULES) == set(cmd.Command.__args__)  # type: ignore[attr-defined]
    assert {type(command) for command, _, _ in ROWS} >= set(RULES) - {
        cmd.SetFeedOverride,
        cmd.ReloadParameters,
        cmd.ResetShiftCounter,
        cmd.SetUser,
    }
    assert allowed_commands(GOOD)["Start"] is None
    assert allowed_commands(GOOD)["LoadBoard"] == Refusal(R.SIMULATION_ONLY)


def test_a_stranger_is_refused() -> None:
    assert may("Start", GOOD) == Refusal(R.UNKNOWN_COMMAND)  # type: ignore[arg-type]


# The commands that drive the state table, and the event each one raises.
COMMAND_EVENTS: dict[type[cmd.Command], Event] = {
    cmd.Start: Event.START,
    cmd.Home: Event.HOME,
    cmd.EnterManual: Event.ENTER_MANUAL,
    cmd.LeaveManual: Event.LEAVE_MANUAL,
    cmd.Reset: Event.RESET,
    cmd.Stop: Event.STOP,
}
COMMANDS = {cmd.Start: cmd.Start(), cmd.Home: cmd.Home(), cmd.EnterManual: cmd.EnterManual()}
COMMANDS |= {cmd.LeaveManual: cmd.LeaveManual(), cmd.Reset: cmd.Reset(), cmd.Stop: cmd.Stop()}
# Accepted without a transition: Home and Stop in manual act inside MANUAL, a Stop while
# STOPPING is already under way.
NO_EVENT = {(cmd.Home, S.MANUAL), (cmd.Stop, S.MANUAL), (cmd.Stop, S.STOPPING)}


@pytest.mark.parametrize("state", list(MachineState))
@pytest.mark.parametrize("kind", list(COMMAND_EVENTS))
def test_the_rules_and_the_state_table_agree(kind: type[cmd.Command], state: MachineState) -> None:
    facts = replace(GOOD, state=state)
    accepted = may(COMMANDS[kind], facts) is None
    in_table = (state, COMMAND_EVENTS[kind]) in TRANSITIONS
    if (kind, state) in NO_EVENT:
        assert accepted and not in_table
    else:
        assert accepted == in_table


def test_a_refusal_fills_its_template_and_lists_its_causes() -> None:
    assert str(refusal(R.DRIVE_STILL_FAULTED, "X", "0x2310")) == "X still in fault 0x2310"
    failed = Refusal(R.RESET_FAILED, causes=(Refusal(R.ESTOP_STILL_PRESSED),))
    assert str(failed) == "reset failed: emergency stop still pressed"
    assert failed.text(str.upper) == "RESET FAILED: EMERGENCY STOP STILL PRESSED"
    assert str(refusal(R.FEED_OVERRIDE_RANGE, 150.0)).startswith("feed override 150 %")
    assert fill("%1 and %2, %1", ("a", "b")) == "a and b, a"


def test_every_template_numbers_its_placeholders_from_one() -> None:
    for reason in Reason:
        numbers = sorted({int(n) for n in re.findall(r"%(\d)", reason.value)})
        assert numbers == list(range(1, len(numbers) + 1)), reason


def test_no_alarm_code_is_written_as_text_in_the_machine_layer() -> None:
    """Alarm codes are AlarmCode members; the codes' text lives in the alarm table only."""
    machine = Path(__file__).resolve().parents[2] / "app" / "machine"
    found = [
        f"{path.name}:{node.lineno} {node.value!r}"
        for path in machine.rglob("*.py")
        if path.name != "alarms.py"
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8")))
        if isinstance(node, ast.Constant)
        and isinstance(node.value, str)
        and re.fullmatch(r"[EW]\d{3}", node.value)
    ]
    assert found == []
