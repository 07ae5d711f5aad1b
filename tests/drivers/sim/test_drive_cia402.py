"""The simulated drive's CiA 402 power state machine: every row of the transition table,
every statusword pattern, the fault reset edge, and what a drive does in each state."""

from __future__ import annotations

import pytest

from app.drivers.cia402 import (
    CW_DISABLE_VOLTAGE,
    CW_ENABLE_OPERATION,
    CW_FAULT_RESET,
    CW_QUICK_STOP,
    CW_SHUTDOWN,
    CW_SWITCH_ON,
    SW_REMOTE,
    Cia402State,
    decode_statusword,
)
from app.drivers.sim.cia402 import (
    STATUSWORD_BASE,
    TRANSITIONS,
    Command,
    EmcyCode,
    decode_controlword,
)
from app.drivers.sim.drive import DriveParams, SimDrive
from app.drivers.sim.settings import SimSettings
from tests.drivers.sim.rig import make_config

S = Cia402State
DT = 0.001
COMMAND_WORDS = {
    Command.SHUTDOWN: CW_SHUTDOWN,
    Command.SWITCH_ON: CW_SWITCH_ON,
    Command.ENABLE_OPERATION: CW_ENABLE_OPERATION,
    Command.DISABLE_VOLTAGE: CW_DISABLE_VOLTAGE,
    Command.QUICK_STOP: CW_QUICK_STOP,
}
# How to reach each state from SWITCH ON DISABLED with controlwords.
PATHS: dict[Cia402State, tuple[int, ...]] = {
    S.SWITCH_ON_DISABLED: (),
    S.READY_TO_SWITCH_ON: (CW_SHUTDOWN,),
    S.SWITCHED_ON: (CW_SHUTDOWN, CW_SWITCH_ON),
    S.OPERATION_ENABLED: (CW_SHUTDOWN, CW_SWITCH_ON, CW_ENABLE_OPERATION),
    S.QUICK_STOP_ACTIVE: (CW_SHUTDOWN, CW_SWITCH_ON, CW_ENABLE_OPERATION, CW_QUICK_STOP),
}


class Emcy(list[tuple[str, int, str]]):
    def __call__(self, device: str, code: int, text: str) -> None:
        self.append((device, code, text))


def make_drive(start: float = 100.0) -> tuple[SimDrive, Emcy]:
    axis = make_config(axes={"X": {"encoder": "absolute"}}).axes["X"]
    params = DriveParams.from_config(axis, SimSettings(), 0.004, 4)
    emcy = Emcy()
    drive = SimDrive("X", params, start, emcy)
    return drive, emcy


def drive_in(state: Cia402State) -> tuple[SimDrive, Emcy]:
    drive, emcy = make_drive()
    drive.step(DT)
    for word in PATHS[state]:
        drive.write_controlword(word)
    assert drive.state is state
    return drive, emcy


def test_power_up_goes_from_not_ready_to_switch_on_disabled() -> None:
    drive, _ = make_drive()
    assert drive.state is S.NOT_READY_TO_SWITCH_ON
    assert decode_statusword(drive.statusword) is S.NOT_READY_TO_SWITCH_ON
    drive.write_controlword(CW_SHUTDOWN)  # ignored while not ready
    drive.step(DT)
    assert drive.state is S.SWITCH_ON_DISABLED


@pytest.mark.parametrize(
    ("word", "command"),
    [
        (0x06, Command.SHUTDOWN),
        (0x0E, Command.SHUTDOWN),
        (0x07, Command.SWITCH_ON),
        (0x0F, Command.ENABLE_OPERATION),
        (0x00, Command.DISABLE_VOLTAGE),
        (0x05, Command.DISABLE_VOLTAGE),
        (0x0D, Command.DISABLE_VOLTAGE),
        (0x02, Command.QUICK_STOP),
        (0x0B, Command.QUICK_STOP),
        (0x1F, Command.ENABLE_OPERATION),
    ],
)
def test_controlword_decoding_follows_the_device_control_table(word: int, command: Command) -> None:
    assert decode_controlword(word) is command


@pytest.mark.parametrize(("start", "command"), sorted(TRANSITIONS, key=str))
def test_every_transition_of_the_table(start: Cia402State, command: Command) -> None:
    drive, _ = drive_in(start)
    drive.write_controlword(COMMAND_WORDS[command])
    expected, _number = TRANSITIONS[(start, command)]
    assert drive.state is expected
    assert decode_statusword(drive.statusword) is expected


@pytest.mark.parametrize("start", list(PATHS))
@pytest.mark.parametrize("command", list(Command))
def test_commands_outside_the_table_leave_the_state_alone(
    start: Cia402State, command: Command
) -> None:
    if (start, command) in TRANSITIONS:
        return
    drive, _ = drive_in(start)
    drive.write_controlword(COMMAND_WORDS[command])
    assert drive.state is start


@pytest.mark.parametrize("state", list(PATHS))
def test_statusword_patterns_are_exactly_the_contract_ones(state: Cia402State) -> None:
    drive, _ = drive_in(state)
    word = drive.statusword
    assert decode_statusword(word) is state
    assert word & SW_REMOTE
    mask = 0x4F if state is S.SWITCH_ON_DISABLED else 0x6F
    assert word & mask == STATUSWORD_BASE[state]


def test_fault_then_reset_needs_a_rising_edge_and_ends_switch_on_disabled() -> None:
    drive, emcy = drive_in(S.OPERATION_ENABLED)
    drive.inject_power_stage_fault(True)
    drive.step(DT)  # a power stage fault removes torque at once: 13 and 14 in one substep
    assert drive.state is S.FAULT and decode_statusword(drive.statusword) is S.FAULT
    assert drive.fault_code == EmcyCode.CONTINUOUS_OVERCURRENT
    assert emcy == [("X", 0x2310, "Continuous over-current")]
    drive.inject_power_stage_fault(False)
    drive.write_controlword(CW_FAULT_RESET)  # the previous word was 0x0F: a rising edge...
    assert drive.state is S.SWITCH_ON_DISABLED  # ...transition 15
    assert drive.fault_code == 0


def test_fault_reaction_brakes_on_the_ramp_then_shows_fault() -> None:
    drive, emcy = drive_in(S.OPERATION_ENABLED)
    for i in range(1, 51):  # 50 mm/s towards +
        drive.write_target(100.0 + 0.2 * i)
        for _ in range(4):
            drive.step(DT)
    drive.stick_limit_switch(positive=True, active=True)
    drive.step(DT)
    assert drive.state is S.FAULT_REACTION_ACTIVE
    assert decode_statusword(drive.statusword) is S.FAULT_REACTION_ACTIVE
    assert drive.true_velocity > 40.0
    steps = 0
    while drive.state is S.FAULT_REACTION_ACTIVE:
        drive.step(DT)
        steps += 1
    assert drive.state is S.FAULT
    assert abs(drive.true_velocity) < 1.0  # stopped on the quick-stop ramp, then torque off
    assert steps > 5
    assert emcy[-1][:2] == ("X", EmcyCode.POSITIVE_LIMIT_SWITCH)


def test_fault_reset_without_an_edge_does_nothing() -> None:
    drive, _ = drive_in(S.OPERATION_ENABLED)
    drive.write_controlword(CW_FAULT_RESET)  # no fault yet: ignored, bit 7 now high
    drive.inject_power_stage_fault(True)
    drive.step(DT)
    drive.step(DT)
    drive.inject_power_stage_fault(False)
    drive.write_controlword(CW_FAULT_RESET)  # still high: no edge
    assert drive.state is S.FAULT
    drive.write_controlword(CW_DISABLE_VOLTAGE)
    drive.write_controlword(CW_FAULT_RESET)
    assert drive.state is S.SWITCH_ON_DISABLED


def test_fault_reset_is_refused_while_the_cause_lasts() -> None:
    drive, _ = drive_in(S.SWITCH_ON_DISABLED)
    drive.inject_power_stage_fault(True)
    drive.step(DT)
    drive.step(DT)
    assert drive.state is S.FAULT
    drive.write_controlword(CW_DISABLE_VOLTAGE)
    drive.write_controlword(CW_FAULT_RESET)
    assert drive.state is S.FAULT


def test_in_fault_no_command_but_reset_is_obeyed() -> None:
    drive, _ = drive_in(S.OPERATION_ENABLED)
    drive.inject_power_stage_fault(True)
    drive.step(DT)
    drive.step(DT)
    drive.inject_power_stage_fault(False)
    for word in (CW_SHUTDOWN, CW_SWITCH_ON, CW_ENABLE_OPERATION, CW_QUICK_STOP):
        drive.write_controlword(word)
        assert drive.state is S.FAULT


@pytest.mark.parametrize("state", [S.SWITCH_ON_DISABLED, S.READY_TO_SWITCH_ON, S.SWITCHED_ON])
def test_without_operation_enabled_targets_are_not_followed(state: Cia402State) -> None:
    drive, _ = drive_in(state)
    drive.write_target(150.0)
    for _ in range(200):
        drive.step(DT)
    assert drive.position == 100.0
    assert drive.following_error == 0.0


def test_operation_enabled_follows_targets() -> None:
    drive, _ = drive_in(S.OPERATION_ENABLED)
    for i in range(1, 101):  # 0.1 mm per 4 ms = 25 mm/s
        drive.write_target(100.0 + 0.1 * i)
        for _ in range(4):
            drive.step(DT)
    for _ in range(400):
        drive.step(DT)
    assert drive.position == pytest.approx(110.0, abs=1e-3)


def test_enabling_holds_the_axis_where_it_is() -> None:
    drive, _ = drive_in(S.SWITCHED_ON)
    drive.write_target(180.0)  # a stale target written before enabling
    drive.write_controlword(CW_ENABLE_OPERATION)
    for _ in range(100):
        drive.step(DT)
    assert drive.position == pytest.approx(100.0, abs=1e-9)


def test_an_axis_moved_by_hand_stays_there_and_is_held_there_when_enabled() -> None:
    drive, _ = drive_in(S.SWITCHED_ON)  # voltage on, no torque: the load moves freely
    drive.move_by_hand(120.0)
    drive.write_controlword(CW_ENABLE_OPERATION)
    for _ in range(100):
        drive.step(DT)
    assert drive.position == pytest.approx(120.0, abs=1e-9)
    with pytest.raises(ValueError, match="X: move_by_hand needs a drive without torque"):
        drive.move_by_hand(100.0)  # a powered drive holds its axis
    assert drive.position == pytest.approx(120.0, abs=1e-9)


def test_a_power_cycle_forgets_the_drive_state_and_keeps_the_world() -> None:
    axis = make_config(axes={"X": {"encoder": "incremental"}}).axes["X"]
    drive = SimDrive("X", DriveParams.from_config(axis, SimSettings(), 0.004, 4), 100.0, Emcy())
    drive.step(DT)
    drive.move_by_hand(30.0)
    drive.stick_limit_switch(positive=True, active=True)
    for word in PATHS[S.OPERATION_ENABLED]:
        drive.write_controlword(word)
    drive.power_cycle()
    assert drive.state is S.NOT_READY_TO_SWITCH_ON and drive.controlword == 0
    assert drive.position == 0.0 and not drive.homed  # an incremental encoder starts at 0
    assert drive.true_position == pytest.approx(130.0) and drive.limit_positive
    drive.step(DT)
    assert drive.state is S.SWITCH_ON_DISABLED


def test_statusword_bits_beyond_the_power_state() -> None:
    drive, _ = drive_in(S.OPERATION_ENABLED)
    assert drive.statusword & (1 << 12)  # CSP: the drive follows the command value
    assert drive.statusword & (1 << 4)  # voltage enabled
    off, _ = drive_in(S.SWITCH_ON_DISABLED)
    assert not off.statusword & (1 << 4)
