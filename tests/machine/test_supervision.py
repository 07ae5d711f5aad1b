"""Supervision, case by case: the feedback checks of a moving cycle, and the verdict of one
period (E-stop chain, guard, drive faults, limit switches, lost home)."""

from __future__ import annotations

from dataclasses import replace

import pytest

from app.drivers.contracts import AxisFeedback, InputImage
from app.machine.alarms import AlarmCode
from app.machine.refusals import Reason, Refusal
from app.machine.snapshot import AlarmArgument
from app.machine.states import MachineState
from app.machine.supervision import (
    DRIVE_FAULT_ALARMS,
    Finding,
    Motion,
    ViolationKind,
    check_feedback,
    supervise,
)
from tests.machine.planner.support import CONFIG

ENABLED = 0x27  # operation enabled
HEALTHY = {name: AxisFeedback(name, ENABLED, 10.0, 0.0, 0.01) for name in ("X", "Y", "Z")}
SETPOINT = {"X": 10.0, "Y": 10.0, "Z": 1.0}


def test_healthy_feedback_has_no_violation() -> None:
    assert check_feedback(HEALTHY, SETPOINT, CONFIG.axes) == []


@pytest.mark.parametrize(
    ("axis", "change", "kind", "text"),
    [
        ("X", {"following_error": 2.5}, ViolationKind.FOLLOWING_ERROR, "following error 2.500"),
        ("Y", {"following_error": -2.1}, ViolationKind.FOLLOWING_ERROR, "exceeds 2 mm"),
        ("Z", {"limit_positive": True}, ViolationKind.LIMIT_POSITIVE, "positive limit"),
        ("X", {"limit_negative": True}, ViolationKind.LIMIT_NEGATIVE, "negative limit"),
        (
            "Y",
            {"statusword": 0x08, "fault_code": 0x7500},
            ViolationKind.DRIVE_FAULT,
            "fault code 0x7500",
        ),
        ("Z", {"statusword": 0x40}, ViolationKind.NOT_ENABLED, "switch on disabled"),
    ],
)
def test_each_violation_names_the_axis(axis, change, kind, text) -> None:
    feedback = dict(HEALTHY)
    feedback[axis] = replace(feedback[axis], **change)
    violations = check_feedback(feedback, SETPOINT, CONFIG.axes)
    assert [(v.axis, v.kind) for v in violations] == [(axis, kind)]
    message = str(violations[0].message)
    assert message.startswith(f"axis {axis}") and text in message


def test_not_enabled_is_only_a_violation_while_moving_and_missing_feedback_is() -> None:
    feedback = dict(HEALTHY)
    feedback["X"] = replace(feedback["X"], statusword=0x40)
    assert check_feedback(feedback, None, CONFIG.axes, motion_active=False) == []
    del feedback["Y"]
    kinds = [v.kind for v in check_feedback(feedback, None, CONFIG.axes, motion_active=False)]
    assert kinds == [ViolationKind.NO_FEEDBACK]


def test_a_setpoint_beyond_the_soft_limit_is_a_violation() -> None:
    violations = check_feedback(HEALTHY, {"X": 4000.0, "Y": 0.0, "Z": 0.0}, CONFIG.axes)
    assert [(v.axis, v.kind, v.limit) for v in violations] == [
        ("X", ViolationKind.SOFT_LIMIT, CONFIG.axes["X"].max_position)
    ]


def test_a_setpoint_standing_or_moving_back_into_the_soft_limits_is_no_violation() -> None:
    low = CONFIG.axes["X"].min_position
    inward = check_feedback(
        HEALTHY,
        {"X": low - 0.01, "Y": 0.0, "Z": 0.0},
        CONFIG.axes,
        previous_setpoint={"X": low - 0.02, "Y": 0.0, "Z": 0.0},
    )
    assert inward == []
    outward = check_feedback(
        HEALTHY,
        {"X": low - 0.02, "Y": 0.0, "Z": 0.0},
        CONFIG.axes,
        previous_setpoint={"X": low - 0.01, "Y": 0.0, "Z": 0.0},
    )
    assert [(v.axis, v.kind) for v in outward] == [("X", ViolationKind.SOFT_LIMIT)]
    still = check_feedback(
        HEALTHY,
        {"X": low - 0.02, "Y": 0.0, "Z": 0.0},
        CONFIG.axes,
        previous_setpoint={"X": low - 0.02, "Y": 0.0, "Z": 0.0},
    )
    assert still == []


# -- the verdict of one period ----------------------------------------------------------------

FAULT = 0x08  # CiA 402 statusword: fault
IDLE = Motion(MachineState.READY, cycle_moving=False, cycle_active=False, homing=False)
CUTTING = Motion(MachineState.AUTOMATIC, cycle_moving=True, cycle_active=True, homing=False)
WAITING = Motion(MachineState.AUTOMATIC, cycle_moving=False, cycle_active=True, homing=False)
HOMING = Motion(MachineState.HOMING, cycle_moving=False, cycle_active=False, homing=True)
STOPPING = Motion(MachineState.STOPPING, cycle_moving=True, cycle_active=True, homing=False)
HOMED = {name: replace(fb, homed=True) for name, fb in HEALTHY.items()}


HEALTHY_INPUTS = InputImage()


def verdict(inputs: InputImage = HEALTHY_INPUTS, feedback=None, motion: Motion = IDLE):
    axes = HOMED if feedback is None else feedback
    return supervise(inputs, axes, SETPOINT, CONFIG.axes, motion)


def test_a_healthy_machine_has_nothing_to_stop() -> None:
    result = verdict()
    assert not result.estop and result.faults == ()
    assert (AlarmCode.ESTOP, "E-stop chain") in result.normal
    assert (AlarmCode.GUARD_OPEN, "guard") in result.normal
    assert {(code, "X") for code in DRIVE_FAULT_ALARMS} <= set(result.normal)


def test_an_open_estop_chain_stops_whatever_the_state() -> None:
    for motion in (IDLE, CUTTING, HOMING):
        result = verdict(InputImage(estop_ok=False), motion=motion)
        assert result.estop
        assert (AlarmCode.ESTOP, "E-stop chain") not in result.normal


@pytest.mark.parametrize(
    ("motion", "fault"),
    [(IDLE, False), (WAITING, False), (CUTTING, True), (HOMING, True), (STOPPING, True)],
)
def test_the_guard_faults_only_while_something_moves(motion: Motion, fault: bool) -> None:
    result = verdict(InputImage(guard_closed=False), motion=motion)
    opened = Refusal(Reason.GUARD_OPENED)
    expected = (Finding(AlarmCode.GUARD_OPEN, "guard", opened),) if fault else ()
    assert result.faults == expected
    assert (AlarmCode.GUARD_OPEN, "guard") not in result.normal


@pytest.mark.parametrize(
    ("changes", "code"),
    [
        ({"fault_code": 0x2310}, AlarmCode.DRIVE_FAULT),
        ({"fault_code": 0x8611}, AlarmCode.FOLLOWING_ERROR),
        ({"fault_code": 0xFF01, "limit_positive": True}, AlarmCode.LIMIT_SWITCH),
        ({"fault_code": 0x2310, "limit_negative": True}, AlarmCode.LIMIT_SWITCH),
    ],
)
def test_a_drive_in_fault_is_named_by_its_cause(
    changes: dict[str, object], code: AlarmCode
) -> None:
    feedback = {**HOMED, "Y": replace(HOMED["Y"], statusword=FAULT, **changes)}
    (finding,) = verdict(feedback=feedback).faults
    assert (finding.code, finding.source) == (code, "Y")
    assert str(finding.detail).startswith(f"axis Y, fault code 0x{changes['fault_code']:04X}")
    assert finding.arguments == (
        AlarmArgument("axis", "Y"),
        AlarmArgument("fault_code", changes["fault_code"]),
    )
    assert not any(source == "Y" for _, source in verdict(feedback=feedback).normal)


@pytest.mark.parametrize("flag", [True, False])
def test_a_limit_switch_while_cutting_gives_one_alarm(flag: bool) -> None:
    """The drive's fault and the feedback check see the same switch: one cause, one alarm
    (E012, whether the drive reports the switch's input or only its fault code)."""
    tripped = replace(HOMED["X"], statusword=FAULT, fault_code=0xFF01, limit_positive=flag)
    faults = verdict(feedback={**HOMED, "X": tripped}, motion=CUTTING).faults
    assert [(f.code, f.source) for f in faults] == [(AlarmCode.LIMIT_SWITCH, "X")]
    assert str(faults[0].detail) == "axis X, fault code 0xFF01: limit switch"


def test_the_moving_cycle_checks_the_feedback_and_the_home() -> None:
    lost_home = {**HOMED, "Z": replace(HOMED["Z"], homed=False)}
    assert verdict(feedback=lost_home, motion=WAITING).faults == ()
    codes = [f.code for f in verdict(feedback=lost_home, motion=CUTTING).faults]
    assert codes == [AlarmCode.HOME_LOST]
    far = {**HOMED, "X": replace(HOMED["X"], following_error=99.0)}
    (finding,) = verdict(feedback=far, motion=CUTTING).faults
    assert (finding.code, finding.source) == (AlarmCode.FOLLOWING_ERROR, "X")
    # The arguments a plant system reads: the axis, the value and its limit in mm.
    limit = CONFIG.axes["X"].following_error_limit
    assert finding.arguments == (
        AlarmArgument("axis", "X"),
        AlarmArgument("value", 99.0, "mm"),
        AlarmArgument("limit", limit, "mm"),
    )
    assert verdict(feedback=far, motion=IDLE).faults == ()
