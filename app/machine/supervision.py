"""Supervision: everything that must stop the machine, read from the inputs and the drives'
feedback each period, in one module a safety reviewer can read alone.

Why pure and separate: the controller only acts on the verdict (raise the alarm, stop at
once, latch the state); what counts as a fault, and when, is decided here, without devices
or time, and tested case by case. The software is not the safety function: the E-stop chain
and the guard interlock are hardware; this is the second line that stops the motion, latches
the state and tells the operator why.

Checked every period:

* the E-stop chain (``estop_ok`` false: alarm E001, state EMERGENCY_STOP);
* the guard, opened while something moves (E002);
* every drive in FAULT: E012 if a limit switch is active (or its fault code says so), E011
  for a following-error fault (CiA 402 emergency code 0x8611), otherwise E010; a drive out
  of FAULT clears those. One cause gives one alarm: the feedback checks below add nothing
  that a faulted drive's alarm already says about its axis;
* while the automatic cycle moves (``check_feedback``): feedback present (E020), drive fault
  (E010), drive enabled (E013), following error within its limit (E011), limit switches
  (E012), the setpoint within the soft limits (E050), and every axis still homed (E016).
"""

from __future__ import annotations

import enum
import math
from collections.abc import Mapping
from dataclasses import dataclass

from app.config import AxisConfig
from app.drivers.contracts import AxisFeedback, InputImage
from app.machine.alarms import AlarmCode, AlarmDetail
from app.machine.refusals import Reason, Refusal, refusal
from app.machine.snapshot import AlarmArgument
from app.machine.states import MOVING_STATES, MachineState

FOLLOWING_ERROR_FAULT = 0x8611  # CiA 402 "following error" emergency code
EMERGENCY_REASONS = {
    0x8611: Reason.EMCY_FOLLOWING_ERROR,
    0x7300: Reason.EMCY_SENSOR,
    0x8130: Reason.EMCY_HEARTBEAT,
    0x2310: Reason.EMCY_OVERCURRENT,
    0x3210: Reason.EMCY_OVERVOLTAGE,
    0x4310: Reason.EMCY_OVERTEMPERATURE,
    0xFF01: Reason.EMCY_LIMIT_SWITCH,
}
LIMIT_SWITCH_FAULTS = frozenset({0xFF01})


def fault_code_text(fault_code: int) -> str:
    return f"0x{fault_code:04X}"


def fault_detail(axis: str, fault_code: int) -> Refusal:
    """A drive's fault code, with its meaning where CiA 402 gives one."""
    reason = EMERGENCY_REASONS.get(fault_code)
    causes = (Refusal(reason),) if reason is not None else ()
    return Refusal(Reason.DRIVE_IN_FAULT_DETAIL, (axis, fault_code_text(fault_code)), causes)


DRIVE_FAULT_ALARMS = (AlarmCode.DRIVE_FAULT, AlarmCode.FOLLOWING_ERROR, AlarmCode.LIMIT_SWITCH)


class ViolationKind(enum.Enum):
    NO_FEEDBACK = "no feedback"
    DRIVE_FAULT = "drive fault"
    NOT_ENABLED = "drive not enabled"
    FOLLOWING_ERROR = "following error"
    LIMIT_POSITIVE = "positive limit switch"
    LIMIT_NEGATIVE = "negative limit switch"
    SOFT_LIMIT = "setpoint outside the soft limits"


@dataclass(frozen=True)
class Violation:
    """One thing wrong with one axis in one period; ``message`` is ready for an alarm."""

    axis: str
    kind: ViolationKind
    value: float
    limit: float
    message: Refusal


def check_feedback(
    feedback: Mapping[str, AxisFeedback],
    setpoint: Mapping[str, float] | None,
    axes: Mapping[str, AxisConfig],
    *,
    motion_active: bool = True,
    previous_setpoint: Mapping[str, float] | None = None,
) -> list[Violation]:
    """Everything that must stop the motion this period, per axis (pure function).

    Checked for every configured axis: feedback present; drive not faulted; drive enabled
    (only while ``motion_active``: a trajectory or jog runs); |following error| within
    ``following_error_limit``; neither limit switch active; the setpoint (if given) within
    the soft limits [min_position, max_position], except (with ``previous_setpoint``) a
    setpoint outside them that is nearer the range than the previous one: the move back
    into the range from an axis that stands outside (after homing onto a switch beyond the
    soft limit, after a trip)."""
    violations: list[Violation] = []
    for name, config in axes.items():
        fb = feedback.get(name)
        if fb is None:
            violations.append(
                Violation(
                    name,
                    ViolationKind.NO_FEEDBACK,
                    math.nan,
                    math.nan,
                    refusal(Reason.NO_FEEDBACK_DETAIL, name),
                )
            )
            continue
        unit = config.unit
        if fb.faulted:
            violations.append(
                Violation(
                    name,
                    ViolationKind.DRIVE_FAULT,
                    float(fb.fault_code),
                    0.0,
                    fault_detail(name, fb.fault_code),
                )
            )
        elif motion_active and not fb.enabled:
            violations.append(
                Violation(
                    name,
                    ViolationKind.NOT_ENABLED,
                    float(fb.statusword),
                    0.0,
                    refusal(Reason.DRIVE_NOT_ENABLED_DETAIL, name, fb.power_state.value),
                )
            )
        if abs(fb.following_error) > config.following_error_limit:
            violations.append(
                Violation(
                    name,
                    ViolationKind.FOLLOWING_ERROR,
                    fb.following_error,
                    config.following_error_limit,
                    refusal(
                        Reason.FOLLOWING_ERROR_DETAIL,
                        name,
                        f"{fb.following_error:.3f}",
                        unit,
                        config.following_error_limit,
                    ),
                )
            )
        if fb.limit_positive:
            violations.append(
                Violation(
                    name,
                    ViolationKind.LIMIT_POSITIVE,
                    fb.position,
                    config.max_position,
                    refusal(Reason.LIMIT_POSITIVE_DETAIL, name, f"{fb.position:.3f}", unit),
                )
            )
        if fb.limit_negative:
            violations.append(
                Violation(
                    name,
                    ViolationKind.LIMIT_NEGATIVE,
                    fb.position,
                    config.min_position,
                    refusal(Reason.LIMIT_NEGATIVE_DETAIL, name, f"{fb.position:.3f}", unit),
                )
            )
        if setpoint is not None and name in setpoint:
            target = setpoint[name]
            outside = _outside(target, config)
            before = None if previous_setpoint is None else previous_setpoint.get(name)
            if outside > 0.0 and (before is None or outside > _outside(before, config)):
                bound = config.max_position if target > config.max_position else config.min_position
                violations.append(
                    Violation(
                        name,
                        ViolationKind.SOFT_LIMIT,
                        target,
                        bound,
                        refusal(
                            Reason.SOFT_LIMIT_DETAIL,
                            name,
                            f"{target:.3f}",
                            unit,
                            config.min_position,
                            config.max_position,
                        ),
                    )
                )
    return violations


def _outside(position: float, config: AxisConfig) -> float:
    """How far ``position`` lies outside the soft limits (0 inside)."""
    return max(config.min_position - position, position - config.max_position, 0.0)


# What a faulted drive's own alarm (E010, E011 or E012) already says about its axis.
FAULT_KINDS = frozenset(
    {
        ViolationKind.DRIVE_FAULT,
        ViolationKind.FOLLOWING_ERROR,
        ViolationKind.LIMIT_POSITIVE,
        ViolationKind.LIMIT_NEGATIVE,
    }
)

VIOLATION_ALARMS = {
    ViolationKind.NO_FEEDBACK: AlarmCode.COMMUNICATION_LOST,
    ViolationKind.DRIVE_FAULT: AlarmCode.DRIVE_FAULT,
    ViolationKind.NOT_ENABLED: AlarmCode.DRIVE_NOT_ENABLED,
    ViolationKind.FOLLOWING_ERROR: AlarmCode.FOLLOWING_ERROR,
    ViolationKind.LIMIT_POSITIVE: AlarmCode.LIMIT_SWITCH,
    ViolationKind.LIMIT_NEGATIVE: AlarmCode.LIMIT_SWITCH,
    ViolationKind.SOFT_LIMIT: AlarmCode.OUTSIDE_TRAVEL,
}


_MEASURED_KINDS = frozenset(
    {
        ViolationKind.FOLLOWING_ERROR,
        ViolationKind.LIMIT_POSITIVE,
        ViolationKind.LIMIT_NEGATIVE,
        ViolationKind.SOFT_LIMIT,
    }
)


def violation_arguments(
    violation: Violation, axes: Mapping[str, AxisConfig]
) -> tuple[AlarmArgument, ...]:
    """The axis, and the value and limit where both are numbers in the axis' unit."""
    axis = AlarmArgument("axis", violation.axis)
    if violation.kind not in _MEASURED_KINDS or not math.isfinite(violation.value):
        return (axis,)
    config = axes.get(violation.axis)
    unit = config.unit if config is not None else ""
    return (
        axis,
        AlarmArgument("value", violation.value, unit),
        AlarmArgument("limit", violation.limit, unit),
    )


@dataclass(frozen=True)
class Finding:
    """One fault to raise: the alarm, where, and the detail for the operator."""

    code: AlarmCode
    source: str
    detail: AlarmDetail = ""
    arguments: tuple[AlarmArgument, ...] = ()


@dataclass(frozen=True)
class Verdict:
    """What supervision found this period. ``estop`` and ``faults`` stop the machine at once
    and latch it; ``normal`` are the (alarm, source) conditions that read healthy again (their
    alarms stay shown until acknowledged)."""

    estop: bool
    faults: tuple[Finding, ...]
    normal: tuple[tuple[AlarmCode, str], ...]


@dataclass(frozen=True)
class Motion:
    """What is moving this period, as the controller knows it."""

    state: MachineState
    cycle_moving: bool  # the automatic cycle's axes or devices are in motion
    cycle_active: bool  # an automatic cycle exists (it may be waiting for a board)
    homing: bool


def drive_fault_code(fb: AxisFeedback) -> AlarmCode:
    """The alarm for a drive in FAULT: a limit switch, a following error, or any other."""
    if fb.limit_positive or fb.limit_negative or fb.fault_code in LIMIT_SWITCH_FAULTS:
        return AlarmCode.LIMIT_SWITCH
    if fb.fault_code == FOLLOWING_ERROR_FAULT:
        return AlarmCode.FOLLOWING_ERROR
    return AlarmCode.DRIVE_FAULT


def supervise(
    inputs: InputImage,
    feedback: Mapping[str, AxisFeedback],
    setpoint: Mapping[str, float],
    axes: Mapping[str, AxisConfig],
    motion: Motion,
) -> Verdict:
    """Everything that must stop the machine this period (see the module's list)."""
    faults: list[Finding] = []
    normal: list[tuple[AlarmCode, str]] = []
    estop = not inputs.estop_ok
    if not estop:
        normal.append((AlarmCode.ESTOP, "E-stop chain"))
    something_moves = motion.state in MOVING_STATES and (
        not motion.cycle_active or motion.cycle_moving or motion.homing
    )
    if not inputs.guard_closed and something_moves:
        faults.append(Finding(AlarmCode.GUARD_OPEN, "guard", Refusal(Reason.GUARD_OPENED)))
    elif inputs.guard_closed:
        normal.append((AlarmCode.GUARD_OPEN, "guard"))
    for name, fb in feedback.items():
        if fb.faulted:
            arguments = (AlarmArgument("axis", name), AlarmArgument("fault_code", fb.fault_code))
            detail = fault_detail(name, fb.fault_code)
            faults.append(Finding(drive_fault_code(fb), name, detail, arguments))
        else:
            # Out of FAULT: those conditions are normal again. E013 is an event, cleared
            # by Reset.
            normal.extend((code, name) for code in DRIVE_FAULT_ALARMS)
    if motion.cycle_moving:
        for violation in check_feedback(feedback, setpoint, axes):
            if violation.kind in FAULT_KINDS and feedback[violation.axis].faulted:
                continue  # one cause, one alarm: the drive's fault above already names it
            faults.append(
                Finding(
                    VIOLATION_ALARMS[violation.kind],
                    violation.axis,
                    violation.message,
                    violation_arguments(violation, axes),
                )
            )
        if not (feedback and all(fb.homed for fb in feedback.values())):
            faults.append(Finding(AlarmCode.HOME_LOST, "axes", Refusal(Reason.HOME_LOST_DETAIL)))
    return Verdict(estop, tuple(faults), tuple(normal))
