"""The one CiA 402 master, row by row and rule by rule (pure logic, no bus).

Each row of the controlword table is also walked on the simulated drive's own transition
table (``app.drivers.sim.cia402``, the drive side of the standard), so that the master's
words and a drive's reactions are checked against each other, not against a copy."""

from __future__ import annotations

import pytest

from app.drivers.cia402 import (
    CW_DISABLE_VOLTAGE,
    CW_ENABLE_OPERATION,
    CW_FAULT_RESET,
    CW_HOMING_START,
    CW_QUICK_STOP,
    CW_SHUTDOWN,
    CW_SWITCH_ON,
    NEXT_CONTROLWORD,
    SW_HOMING_ATTAINED,
    SW_HOMING_ERROR,
    SW_REMOTE,
    SW_TARGET_REACHED,
    Cia402Master,
    Cia402State,
    HomingPhase,
    OperationMode,
    PowerRequest,
    Refusal,
    RequestRefusedError,
    decode_statusword,
)
from app.drivers.sim.cia402 import STATUSWORD_BASE, TRANSITIONS, decode_controlword

S = Cia402State
R = PowerRequest
SW = {state: base | SW_REMOTE for state, base in STATUSWORD_BASE.items()}
OE = SW[S.OPERATION_ENABLED]
CSP = int(OperationMode.CYCLIC_SYNC_POSITION)
HOMING = int(OperationMode.HOMING)


def master(reports_mode: bool = True) -> Cia402Master:
    return Cia402Master(reports_mode=reports_mode)


def observe(m: Cia402Master, statusword: int, mode: int = CSP) -> None:
    m.observe(statusword, mode if m.reports_mode else None)


def drive_step(state: Cia402State, controlword: int) -> Cia402State:
    return TRANSITIONS.get((state, decode_controlword(controlword)), (state, ""))[0]


# ---- the vocabulary ------------------------------------------------------------------------


@pytest.mark.parametrize("state", list(S))
def test_every_state_decodes_from_its_statusword(state: Cia402State) -> None:
    assert decode_statusword(SW[state]) is state


# ---- the table -----------------------------------------------------------------------------


def test_every_request_and_state_has_a_controlword_and_none_resets() -> None:
    assert set(NEXT_CONTROLWORD) == {(r, s) for r in R for s in S}
    assert not any(cw & CW_FAULT_RESET for cw in NEXT_CONTROLWORD.values())


@pytest.mark.parametrize(("request_", "state"), sorted(NEXT_CONTROLWORD, key=str))
def test_each_row_moves_the_drive_toward_the_request(
    request_: PowerRequest, state: Cia402State
) -> None:
    """Walking the drive's table with the master's words, every start state reaches the
    request's goal (or stays where only the drive or an operator's reset may move it)."""
    goal = {
        R.ENABLED: S.OPERATION_ENABLED,
        R.DISABLED: S.SWITCH_ON_DISABLED,
        R.QUICK_STOP: S.QUICK_STOP_ACTIVE,
    }[request_]
    current = state
    for _ in range(5):
        current = drive_step(current, NEXT_CONTROLWORD[(request_, current)])
    if state in (S.FAULT, S.FAULT_REACTION_ACTIVE, S.NOT_READY_TO_SWITCH_ON):
        assert current is state
    elif request_ is R.QUICK_STOP and state not in (S.OPERATION_ENABLED, S.QUICK_STOP_ACTIVE):
        assert current is S.SWITCH_ON_DISABLED  # quick stop of a drive without torque
    else:
        assert current is goal


@pytest.mark.parametrize(("request_", "state"), sorted(NEXT_CONTROLWORD, key=str))
def test_the_master_sends_the_tables_row(request_: PowerRequest, state: Cia402State) -> None:
    m = master()
    observe(m, SW[state])
    if request_ is R.ENABLED and state in (S.FAULT, S.FAULT_REACTION_ACTIVE):
        with pytest.raises(RequestRefusedError):
            m.enable()
    elif request_ is R.ENABLED:
        m.enable()
    elif request_ is R.QUICK_STOP:
        m.quick_stop()
    command = m.command()
    assert command.controlword == NEXT_CONTROLWORD[(request_, state)]
    assert command.follows_setpoints is (state is S.OPERATION_ENABLED)


def test_enable_walks_one_step_per_period_to_operation_enabled() -> None:
    m = master()
    state = S.SWITCH_ON_DISABLED
    observe(m, SW[state])
    m.enable()
    words = []
    for _ in range(4):
        words.append(m.command().controlword)
        state = drive_step(state, words[-1])
        observe(m, SW[state])
    assert words == [CW_SHUTDOWN, CW_SWITCH_ON, CW_ENABLE_OPERATION, CW_ENABLE_OPERATION]
    assert state is S.OPERATION_ENABLED


def test_enable_from_quick_stop_goes_through_switch_on_disabled() -> None:
    """Decision: transition 12 then 2, 3, 4, not 16 (optional in the standard)."""
    m = master()
    observe(m, SW[S.QUICK_STOP_ACTIVE])
    m.enable()
    assert m.command().controlword == CW_DISABLE_VOLTAGE


# ---- never re-enabled, never reset by itself -----------------------------------------------


@pytest.mark.parametrize("fault", [S.FAULT, S.FAULT_REACTION_ACTIVE])
def test_a_fault_cancels_the_request_and_is_never_reset_by_itself(fault: Cia402State) -> None:
    m = master()
    observe(m, OE)
    m.enable()
    observe(m, SW[fault])
    assert m.request is R.DISABLED
    for state in (fault, S.FAULT, S.SWITCH_ON_DISABLED, S.SWITCH_ON_DISABLED):
        observe(m, SW[state])
        assert m.command().controlword == CW_DISABLE_VOLTAGE


def test_enable_on_a_faulted_drive_is_refused_with_its_reason() -> None:
    m = master()
    observe(m, SW[S.FAULT])
    with pytest.raises(RequestRefusedError, match="fault reset comes first") as refused:
        m.enable()
    assert refused.value.refusal is Refusal.ENABLE_IN_FAULT


def test_enable_during_a_fault_reset_is_refused() -> None:
    m = master()
    observe(m, SW[S.SWITCH_ON_DISABLED])
    m.fault_reset()
    with pytest.raises(RequestRefusedError) as refused:
        m.enable()
    assert refused.value.refusal is Refusal.ENABLE_DURING_RESET


def test_a_drive_that_quick_stops_on_its_own_keeps_braking_and_is_not_re_enabled() -> None:
    """Safe torque off (stop category 1): the drive goes to QUICK STOP ACTIVE by itself; the
    master holds quick stop (the ramp goes on) and never walks it back up."""
    m = master()
    observe(m, OE)
    m.enable()
    m.command()
    observe(m, SW[S.QUICK_STOP_ACTIVE])
    assert m.request is R.QUICK_STOP and "on its own" in m.dropped
    assert m.command().controlword == CW_QUICK_STOP
    observe(m, SW[S.SWITCH_ON_DISABLED])  # torque removed by the drive at standstill
    assert [m.command().controlword for _ in range(3)] == [CW_DISABLE_VOLTAGE] * 3


def test_a_step_the_drive_refuses_cancels_the_enable() -> None:
    """Safe torque off holds the drive in SWITCH ON DISABLED: the request is given up, so
    releasing the E-stop later powers nothing."""
    m = Cia402Master(reports_mode=True, step_limit_periods=3)
    observe(m, SW[S.SWITCH_ON_DISABLED])
    m.enable()
    words = [m.command().controlword for _ in range(6)]
    assert words[:3] == [CW_SHUTDOWN] * 3 and words[3:] == [CW_DISABLE_VOLTAGE] * 3
    assert m.request is R.DISABLED and "safe torque off" in m.dropped


def test_the_self_test_is_waited_for() -> None:
    m = Cia402Master(reports_mode=True, step_limit_periods=3)
    observe(m, SW[S.NOT_READY_TO_SWITCH_ON])
    m.enable()
    assert [m.command().controlword for _ in range(10)] == [CW_DISABLE_VOLTAGE] * 10
    observe(m, SW[S.SWITCH_ON_DISABLED])
    assert m.command().controlword == CW_SHUTDOWN


def test_a_drive_falling_back_during_the_walk_cancels_the_enable() -> None:
    m = master()
    observe(m, SW[S.SWITCH_ON_DISABLED])
    m.enable()
    m.command()
    observe(m, SW[S.READY_TO_SWITCH_ON])
    observe(m, SW[S.SWITCH_ON_DISABLED])
    assert m.request is R.DISABLED and "fell back" in m.dropped


def test_a_new_request_after_a_drop_walks_again() -> None:
    m = master()
    observe(m, OE)
    m.enable()
    observe(m, SW[S.SWITCH_ON_DISABLED])
    assert m.request is R.DISABLED
    m.enable()  # an operator's command
    assert m.command().controlword == CW_SHUTDOWN


# ---- fault reset ---------------------------------------------------------------------------


def test_fault_reset_is_zero_then_the_edge_held_until_the_drive_leaves_fault() -> None:
    m = master()
    observe(m, SW[S.FAULT])
    m.fault_reset()
    assert m.command().controlword == CW_DISABLE_VOLTAGE  # bit 7 low first
    assert m.command().controlword == CW_FAULT_RESET  # the rising edge
    assert m.command().controlword == CW_FAULT_RESET  # held: the drive still shows FAULT
    observe(m, SW[S.SWITCH_ON_DISABLED])
    assert [m.command().controlword for _ in range(5)] == [CW_DISABLE_VOLTAGE] * 5
    assert m.request is R.DISABLED


def test_one_edge_is_enough_for_a_drive_that_answers_at_once() -> None:
    m = master(reports_mode=False)
    observe(m, SW[S.FAULT])
    m.fault_reset()
    words = [m.command().controlword]
    words.append(m.command().controlword)
    observe(m, SW[S.SWITCH_ON_DISABLED])
    words.append(m.command().controlword)
    assert words == [CW_DISABLE_VOLTAGE, CW_FAULT_RESET, CW_DISABLE_VOLTAGE]


def test_fault_reset_gives_up_after_a_bounded_edge() -> None:
    m = Cia402Master(reports_mode=True, reset_edge_periods=5)
    observe(m, SW[S.FAULT])
    m.fault_reset()
    words = [m.command().controlword for _ in range(12)]
    assert words[0] == CW_DISABLE_VOLTAGE and words.count(CW_FAULT_RESET) == 5
    assert words[-1] == CW_DISABLE_VOLTAGE


def test_fault_reset_ends_disabled_on_the_drive_table() -> None:
    """The drive leaves FAULT on the edge (transition 15, in the drive model) and the master
    then keeps it in SWITCH ON DISABLED."""
    m = master()
    observe(m, SW[S.FAULT])
    m.fault_reset()
    m.command()
    assert m.command().controlword & CW_FAULT_RESET
    observe(m, SW[S.SWITCH_ON_DISABLED])
    state = S.SWITCH_ON_DISABLED
    for _ in range(3):
        state = drive_step(state, m.command().controlword)
    assert state is S.SWITCH_ON_DISABLED


# ---- disable and quick stop ----------------------------------------------------------------


@pytest.mark.parametrize("state", list(S))
def test_disable_and_quick_stop_are_accepted_in_every_state(state: Cia402State) -> None:
    m = master()
    observe(m, SW[state])
    m.disable()
    assert m.command().controlword == CW_DISABLE_VOLTAGE
    m.quick_stop()
    assert m.command().controlword in (CW_QUICK_STOP, CW_DISABLE_VOLTAGE)


# ---- homing ----------------------------------------------------------------------------------


def enabled_master(reports_mode: bool) -> Cia402Master:
    m = master(reports_mode)
    observe(m, OE)
    m.enable()
    return m


def test_homing_needs_operation_enabled() -> None:
    m = master()
    observe(m, SW[S.SWITCHED_ON])
    with pytest.raises(RequestRefusedError) as refused:
        m.start_homing()
    assert refused.value.refusal is Refusal.HOMING_NOT_ENABLED


def test_homing_handshake_with_the_mode_display() -> None:
    m = enabled_master(reports_mode=True)
    m.start_homing()
    assert m.homing_active and not m.homed
    select = m.command()
    assert (select.controlword, select.mode, select.follows_setpoints) == (
        CW_ENABLE_OPERATION,
        OperationMode.HOMING,
        False,
    )
    observe(m, OE, CSP)  # the mode is not shown yet: still selecting
    assert m.command().controlword == CW_ENABLE_OPERATION
    observe(m, OE | SW_TARGET_REACHED | SW_HOMING_ATTAINED, HOMING)  # an earlier run's bits
    start = m.command()
    assert start.controlword == CW_ENABLE_OPERATION | CW_HOMING_START
    # The earlier run's "attained" does not count before the run was seen in progress.
    assert m.observe(OE | SW_TARGET_REACHED | SW_HOMING_ATTAINED, HOMING) is None
    assert m.homing is HomingPhase.RUNNING
    assert m.command().controlword & CW_HOMING_START
    assert m.observe(OE, HOMING) is None  # in progress
    outcome = m.observe(OE | SW_TARGET_REACHED | SW_HOMING_ATTAINED, HOMING)
    assert outcome is not None and outcome.ok and m.homed
    back = m.command()
    assert (back.mode, back.follows_setpoints) == (OperationMode.CYCLIC_SYNC_POSITION, False)
    observe(m, OE, HOMING)  # the drive has not switched yet: target stays at actual
    assert m.homing_active and not m.command().follows_setpoints
    observe(m, OE, CSP)
    assert not m.homing_active and m.command().follows_setpoints


def test_homing_handshake_without_the_mode_display() -> None:
    """Modbus maps without 0x6061: a mode written is in effect one period later."""
    m = enabled_master(reports_mode=False)
    m.start_homing()
    assert m.command().mode is OperationMode.HOMING
    observe(m, OE | SW_TARGET_REACHED)
    assert m.command().controlword == CW_ENABLE_OPERATION | CW_HOMING_START
    observe(m, OE)
    outcome = m.observe(OE | SW_TARGET_REACHED | SW_HOMING_ATTAINED)
    assert outcome is not None and outcome.ok
    assert m.homing_active  # one more period at the actual position, in position mode
    back = m.command()
    assert (back.mode, back.follows_setpoints) == (OperationMode.CYCLIC_SYNC_POSITION, False)
    observe(m, OE)
    assert not m.homing_active and m.command().follows_setpoints


def test_a_homing_finished_within_one_period_is_recognised() -> None:
    """A drive starting on its reference may be done before the master reads again:
    "attained" clear just before the start edge is enough to trust the next "attained"."""
    m = enabled_master(reports_mode=False)
    m.start_homing()
    m.command()
    observe(m, OE | SW_TARGET_REACHED)  # homing mode, not started, not attained
    m.command()  # the start edge
    outcome = m.observe(OE | SW_TARGET_REACHED | SW_HOMING_ATTAINED)
    assert outcome is not None and outcome.ok


def test_a_late_statusword_after_the_edge_is_waited_for() -> None:
    """CANopen answers a SYNC with a statusword sampled before that SYNC's command: the
    first answer after the edge still shows "reached, not attained"; that is not a failure."""
    m = enabled_master(reports_mode=True)
    m.start_homing()
    m.command()
    observe(m, OE | SW_TARGET_REACHED, HOMING)
    m.command()
    assert m.observe(OE | SW_TARGET_REACHED, HOMING) is None
    assert m.homing is HomingPhase.RUNNING


@pytest.mark.parametrize(
    ("statusword", "reason"),
    [
        (OE | SW_HOMING_ERROR, "homing error"),
        (OE | SW_TARGET_REACHED, "without finding the reference"),
        (SW[S.SWITCHED_ON], "left operation enabled"),
        (SW[S.FAULT], "drive fault"),
    ],
)
def test_homing_failures(statusword: int, reason: str) -> None:
    m = enabled_master(reports_mode=False)
    m.start_homing()
    m.command()
    observe(m, OE | SW_TARGET_REACHED | SW_HOMING_ATTAINED)
    m.command()
    observe(m, OE)  # seen in progress
    outcome = m.observe(statusword)
    assert outcome is not None and not outcome.ok and reason in outcome.reason
    assert not m.homed
    assert m.command().mode is OperationMode.CYCLIC_SYNC_POSITION


@pytest.mark.parametrize("stop", [Cia402Master.quick_stop, Cia402Master.disable])
def test_homing_is_ended_by_quick_stop_and_disable(stop) -> None:  # type: ignore[no-untyped-def]
    m = enabled_master(reports_mode=True)
    m.start_homing()
    m.command()
    stop(m)
    command = m.command()
    assert command.mode is OperationMode.CYCLIC_SYNC_POSITION
    assert command.controlword in (CW_QUICK_STOP, CW_DISABLE_VOLTAGE)
    assert m.last_homing is not None and not m.last_homing.ok


def test_homing_ended_by_a_fault_returns_to_the_position_mode() -> None:
    m = enabled_master(reports_mode=True)
    m.start_homing()
    m.command()
    observe(m, SW[S.FAULT], HOMING)
    assert m.command().mode is OperationMode.CYCLIC_SYNC_POSITION
    observe(m, SW[S.FAULT], CSP)
    assert not m.homing_active
