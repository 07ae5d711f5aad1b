"""The controlword walk, one row of the table at a time (pure logic, no bus)."""

from __future__ import annotations

import pytest

from app.drivers.contracts import (
    CW_DISABLE_VOLTAGE,
    CW_ENABLE_OPERATION,
    CW_FAULT_RESET,
    CW_QUICK_STOP,
    CW_SHUTDOWN,
    CW_SWITCH_ON,
    SW_HOMING_ATTAINED,
    SW_TARGET_REACHED,
    Cia402State,
)
from app.drivers.modbus.cia402 import (
    CW_HOMING_START,
    ENABLE_WALK,
    SW_HOMING_ERROR,
    Cia402Commander,
)

S = Cia402State
# A statusword for each state (the patterns of contracts._STATUSWORD_TABLE, bit 9 remote).
SW = {
    S.NOT_READY_TO_SWITCH_ON: 0x0200,
    S.SWITCH_ON_DISABLED: 0x0240,
    S.READY_TO_SWITCH_ON: 0x0231,
    S.SWITCHED_ON: 0x0233,
    S.OPERATION_ENABLED: 0x0237,
    S.QUICK_STOP_ACTIVE: 0x0217,
    S.FAULT_REACTION_ACTIVE: 0x021F,
    S.FAULT: 0x0218,
}
POSITION, HOMING = 8, 6


def commander() -> Cia402Commander:
    return Cia402Commander(POSITION, HOMING)


@pytest.mark.parametrize(
    ("state", "controlword"),
    [
        (S.NOT_READY_TO_SWITCH_ON, CW_DISABLE_VOLTAGE),
        (S.SWITCH_ON_DISABLED, CW_SHUTDOWN),  # transition 2
        (S.READY_TO_SWITCH_ON, CW_SWITCH_ON),  # 3
        (S.SWITCHED_ON, CW_ENABLE_OPERATION),  # 4
        (S.OPERATION_ENABLED, CW_ENABLE_OPERATION),
        (S.QUICK_STOP_ACTIVE, CW_DISABLE_VOLTAGE),  # 12, then walk again
    ],
)
def test_enable_walk_row(state: Cia402State, controlword: int) -> None:
    assert ENABLE_WALK[state] == controlword
    c = commander()
    c.enable()
    c.observe(SW[state])
    command = c.command()
    assert command.controlword == controlword and command.mode == POSITION
    assert command.track_actual is (state is not S.OPERATION_ENABLED)


def test_nothing_requested_means_disable_voltage() -> None:
    c = commander()
    for state in S:
        c.observe(SW[state])
        assert c.command().controlword == CW_DISABLE_VOLTAGE


@pytest.mark.parametrize("fault", [S.FAULT, S.FAULT_REACTION_ACTIVE])
def test_a_fault_cancels_the_request_and_is_never_reset_by_itself(fault: Cia402State) -> None:
    c = commander()
    c.enable()
    c.observe(SW[S.OPERATION_ENABLED])
    c.observe(SW[fault])
    for state in (fault, S.FAULT, S.SWITCH_ON_DISABLED, S.SWITCH_ON_DISABLED):
        c.observe(SW[state])
        assert c.command().controlword == CW_DISABLE_VOLTAGE  # not reset, not re-enabled


def test_fault_reset_is_a_rising_edge_of_bit_7_then_disabled() -> None:
    c = commander()
    c.observe(SW[S.FAULT])
    c.fault_reset()
    words = [c.command().controlword for _ in range(4)]
    assert words == [CW_DISABLE_VOLTAGE, CW_FAULT_RESET, CW_DISABLE_VOLTAGE, CW_DISABLE_VOLTAGE]


def test_quick_stop_and_disable() -> None:
    c = commander()
    c.enable()
    c.observe(SW[S.OPERATION_ENABLED])
    c.quick_stop()
    assert c.command().controlword == CW_QUICK_STOP
    c.observe(SW[S.QUICK_STOP_ACTIVE])
    assert c.command().controlword == CW_QUICK_STOP
    c.disable()
    assert c.command().controlword == CW_DISABLE_VOLTAGE


def homing_commander() -> Cia402Commander:
    c = commander()
    c.enable()
    c.observe(SW[S.OPERATION_ENABLED])
    c.start_homing()
    return c


def test_homing_needs_an_enabled_drive() -> None:
    c = commander()
    c.observe(SW[S.SWITCH_ON_DISABLED])
    with pytest.raises(ValueError, match="enable it first"):
        c.start_homing()
    c.enable()
    c.start_homing()  # enabling is enough: the homing waits for OPERATION ENABLED
    assert c.homing_active
    assert c.command().mode == POSITION  # still walking to enabled


def test_homing_sequence_and_success() -> None:
    c = homing_commander()
    oe = SW[S.OPERATION_ENABLED]
    arm = c.command()
    assert (arm.controlword, arm.mode, arm.track_actual) == (CW_ENABLE_OPERATION, HOMING, True)
    c.observe(oe | SW_TARGET_REACHED | SW_HOMING_ATTAINED)  # stale bits of an earlier homing
    start = c.command()
    assert start.controlword == CW_ENABLE_OPERATION | CW_HOMING_START and start.mode == HOMING
    # Stale "attained" before the drive was seen homing does not count.
    assert c.observe(oe | SW_TARGET_REACHED | SW_HOMING_ATTAINED) is None and c.homing_active
    assert c.command().controlword & CW_HOMING_START
    assert c.observe(oe) is None  # in progress
    outcome = c.observe(oe | SW_TARGET_REACHED | SW_HOMING_ATTAINED)
    assert outcome is not None and outcome.ok
    # One more period "active", back in position mode at the actual position: the encoder
    # frame may have moved to the machine frame within this very period.
    assert c.homing_active
    finish = c.command()
    assert (finish.controlword, finish.mode, finish.track_actual) == (
        CW_ENABLE_OPERATION,
        POSITION,
        True,
    )
    assert c.observe(oe | SW_TARGET_REACHED | SW_HOMING_ATTAINED) is None
    assert not c.homing_active
    after = c.command()
    assert (after.controlword, after.mode, after.track_actual) == (
        CW_ENABLE_OPERATION,
        POSITION,
        False,
    )


@pytest.mark.parametrize(
    ("statusword", "reason"),
    [
        (SW[S.OPERATION_ENABLED] | SW_HOMING_ERROR, "homing error"),
        (SW[S.OPERATION_ENABLED] | SW_TARGET_REACHED, "without finding the reference"),
        (SW[S.SWITCHED_ON], "left operation enabled"),
        (SW[S.FAULT], "drive fault"),
    ],
)
def test_homing_failures(statusword: int, reason: str) -> None:
    c = homing_commander()
    c.command()
    c.observe(SW[S.OPERATION_ENABLED])
    c.command()
    c.observe(SW[S.OPERATION_ENABLED])  # seen in progress
    outcome = c.observe(statusword)
    assert outcome is not None and not outcome.ok and reason in outcome.reason
    assert not c.homing_active and c.command().mode == POSITION


def test_a_homing_finished_within_one_period_is_recognised() -> None:
    """A drive starting on its reference edge may be done before the master reads again:
    "attained" clear just before the start edge is enough to trust the next "attained"."""
    c = homing_commander()
    oe = SW[S.OPERATION_ENABLED]
    c.command()  # arm
    c.observe(oe | SW_TARGET_REACHED)  # homing mode, not started, not attained
    c.command()  # start edge
    outcome = c.observe(oe | SW_TARGET_REACHED | SW_HOMING_ATTAINED)
    assert outcome is not None and outcome.ok
