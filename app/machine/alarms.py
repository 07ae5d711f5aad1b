"""Alarms with the ISA-18.2 life cycle, and the catalogue of every alarm the machine raises.

Why ISA-18.2: an operator must see what went wrong even if the condition has already gone
(a following-error fault that cleared itself still needs a look), and a technician must be
able to reconstruct what happened from the history. So an alarm whose condition returns to
normal stays shown until acknowledged (RTN_UNACKED), and every transition is kept.

Conditions: an alarm is active while its condition holds. For continuous conditions (E-stop
chain open, guard open, a drive in FAULT) the machine clears the condition when it reads
healthy again; for events (a sensor that never arrived, a bad gauge reading) the condition is
cleared by the operator's Reset, when the machine is made ready again.
"""

from __future__ import annotations

import enum
import itertools
import time
from collections.abc import Callable
from dataclasses import dataclass, field

from app.machine.snapshot import AlarmArgument, AlarmState, AlarmView


class AlarmCode(enum.StrEnum):
    """Every alarm the machine raises. The values are the codes the database history, the
    README and the operators know; a StrEnum, so a code is stored and shown as that text."""

    ESTOP = "E001"
    GUARD_OPEN = "E002"
    DRIVE_FAULT = "E010"
    FOLLOWING_ERROR = "E011"
    LIMIT_SWITCH = "E012"
    DRIVE_NOT_ENABLED = "E013"
    DRIVE_DID_NOT_ENABLE = "E014"
    HOMING_INCOMPLETE = "E015"
    HOME_LOST = "E016"
    COMMUNICATION_LOST = "E020"
    DEVICE_REFUSED = "E021"
    GAUGE_NO_READING = "E030"
    GAUGE_UNREADABLE = "E031"
    WIDTH_NOT_ALLOWED = "E032"
    GAUGE_DISCONNECTED = "E033"
    BARREL_NOT_CLOSABLE = "E034"
    CLAMPS_SENSOR = "E040"
    CENTERING_SENSOR = "E041"
    SPINDLE_NOT_STARTED = "E042"
    SPINDLE_STOPPED = "E043"
    BOARD_REMOVED = "E044"
    OUTSIDE_TRAVEL = "E050"
    PLANNING_FAILED = "E051"
    APPROACH_CROSSES_BOARD = "E052"
    HANDWHEEL_JUMP = "E060"
    INTERNAL_ERROR = "E090"
    JOG_NOT_REFRESHED = "W101"
    DEVICE_EVENT = "W102"
    RECORDS_WAITING = "W103"
    PIN_LOCKED = "W104"


class Severity(enum.Enum):
    FAULT = "fault"  # stops the machine (state ERROR or EMERGENCY_STOP)
    WARNING = "warning"  # informs; the machine keeps going


@dataclass(frozen=True)
class AlarmDefinition:
    code: AlarmCode
    text: str
    severity: Severity


CATALOGUE: dict[AlarmCode, AlarmDefinition] = {
    d.code: d
    for d in (
        AlarmDefinition(AlarmCode.ESTOP, "Emergency stop", Severity.FAULT),
        AlarmDefinition(AlarmCode.GUARD_OPEN, "Guard open during motion", Severity.FAULT),
        AlarmDefinition(AlarmCode.DRIVE_FAULT, "Drive fault", Severity.FAULT),
        AlarmDefinition(AlarmCode.FOLLOWING_ERROR, "Following error too large", Severity.FAULT),
        AlarmDefinition(AlarmCode.LIMIT_SWITCH, "Limit switch reached", Severity.FAULT),
        AlarmDefinition(
            AlarmCode.DRIVE_NOT_ENABLED, "Drive not enabled during motion", Severity.FAULT
        ),
        AlarmDefinition(AlarmCode.DRIVE_DID_NOT_ENABLE, "Drive did not enable", Severity.FAULT),
        AlarmDefinition(AlarmCode.HOMING_INCOMPLETE, "Homing did not complete", Severity.FAULT),
        AlarmDefinition(AlarmCode.HOME_LOST, "Axis lost its home position", Severity.FAULT),
        AlarmDefinition(
            AlarmCode.COMMUNICATION_LOST,
            "Communication with the drives or I/O lost",
            Severity.FAULT,
        ),
        AlarmDefinition(
            AlarmCode.DEVICE_REFUSED, "A drive or the I/O refused a request", Severity.FAULT
        ),
        AlarmDefinition(AlarmCode.GAUGE_NO_READING, "Width gauge gave no reading", Severity.FAULT),
        AlarmDefinition(
            AlarmCode.GAUGE_UNREADABLE, "Width gauge reading not understood", Severity.FAULT
        ),
        AlarmDefinition(
            AlarmCode.WIDTH_NOT_ALLOWED,
            "Measured width not allowed for this recipe",
            Severity.FAULT,
        ),
        AlarmDefinition(AlarmCode.GAUGE_DISCONNECTED, "Width gauge disconnected", Severity.FAULT),
        AlarmDefinition(
            AlarmCode.BARREL_NOT_CLOSABLE, "Board too narrow to close the barrel", Severity.FAULT
        ),
        AlarmDefinition(
            AlarmCode.CLAMPS_SENSOR, "Clamps did not reach their sensor", Severity.FAULT
        ),
        AlarmDefinition(
            AlarmCode.CENTERING_SENSOR, "Centering device did not reach its sensor", Severity.FAULT
        ),
        AlarmDefinition(AlarmCode.SPINDLE_NOT_STARTED, "Spindle did not start", Severity.FAULT),
        AlarmDefinition(AlarmCode.SPINDLE_STOPPED, "Spindle stopped while cutting", Severity.FAULT),
        AlarmDefinition(AlarmCode.BOARD_REMOVED, "Board removed during the cycle", Severity.FAULT),
        AlarmDefinition(
            AlarmCode.OUTSIDE_TRAVEL, "Tool path outside the axis travel", Severity.FAULT
        ),
        AlarmDefinition(
            AlarmCode.PLANNING_FAILED, "Tool path could not be planned", Severity.FAULT
        ),
        AlarmDefinition(
            AlarmCode.APPROACH_CROSSES_BOARD,
            "Move refused: it would cross the board",
            Severity.FAULT,
        ),
        AlarmDefinition(
            AlarmCode.HANDWHEEL_JUMP,
            "Handwheel count jumped further than a hand can turn it",
            Severity.FAULT,
        ),
        AlarmDefinition(
            AlarmCode.INTERNAL_ERROR, "Internal error in the machine process", Severity.FAULT
        ),
        AlarmDefinition(
            AlarmCode.JOG_NOT_REFRESHED, "Jog stopped: no refresh from the screen", Severity.WARNING
        ),
        AlarmDefinition(AlarmCode.DEVICE_EVENT, "Device event", Severity.WARNING),
        AlarmDefinition(
            AlarmCode.RECORDS_WAITING, "Records waiting for the database", Severity.WARNING
        ),
        AlarmDefinition(
            AlarmCode.PIN_LOCKED, "PIN entry locked after repeated wrong PINs", Severity.WARNING
        ),
    )
}


def definition_of(code: str) -> AlarmDefinition | None:
    """The definition of an alarm known by its code's text (from a record, a peer), or None
    for a code this machine does not raise."""
    try:
        return CATALOGUE.get(AlarmCode(code))
    except ValueError:
        return None


class AlarmAction(enum.Enum):
    CONDITION_ON = "condition active"
    CONDITION_OFF = "condition cleared"
    ACKNOWLEDGE = "acknowledged"


# ISA-18.2 state transitions: (state, action) -> next state. Pairs not listed change nothing.
ALARM_TRANSITIONS: dict[tuple[AlarmState, AlarmAction], AlarmState] = {
    (AlarmState.NORMAL, AlarmAction.CONDITION_ON): AlarmState.ACTIVE_UNACKED,
    (AlarmState.ACTIVE_UNACKED, AlarmAction.ACKNOWLEDGE): AlarmState.ACTIVE_ACKED,
    (AlarmState.ACTIVE_UNACKED, AlarmAction.CONDITION_OFF): AlarmState.RTN_UNACKED,
    (AlarmState.ACTIVE_ACKED, AlarmAction.CONDITION_OFF): AlarmState.NORMAL,
    (AlarmState.RTN_UNACKED, AlarmAction.ACKNOWLEDGE): AlarmState.NORMAL,
    (AlarmState.RTN_UNACKED, AlarmAction.CONDITION_ON): AlarmState.ACTIVE_UNACKED,
}


@dataclass(frozen=True)
class AlarmTransition:
    """One line of the alarm history."""

    alarm_id: int
    code: AlarmCode
    text: str
    source: str
    from_state: AlarmState
    to_state: AlarmState
    time: float  # epoch seconds
    user: str = ""


@dataclass
class Alarm:
    alarm_id: int
    definition: AlarmDefinition
    source: str
    detail: str
    state: AlarmState
    raised_at: float
    arguments: tuple[AlarmArgument, ...] = ()

    @property
    def text(self) -> str:
        return f"{self.definition.text}: {self.detail}" if self.detail else self.definition.text

    def view(self) -> AlarmView:
        return AlarmView(
            self.alarm_id,
            self.definition.code,
            self.text,
            self.source,
            self.state,
            self.raised_at,
            self.definition.severity.value,
            self.arguments,
        )


@dataclass
class AlarmManager:
    """Holds the alarms that are not NORMAL and reports every transition to ``on_transition``
    (the database writer). One alarm per (code, source): a condition that comes back while its
    alarm is still shown re-activates that alarm instead of adding a second line."""

    on_transition: Callable[[AlarmTransition], None] = lambda _t: None
    wall_clock: Callable[[], float] = time.time
    _alarms: dict[tuple[AlarmCode, str], Alarm] = field(default_factory=dict)
    _ids: itertools.count[int] = field(default_factory=lambda: itertools.count(1))
    history: list[AlarmTransition] = field(default_factory=list)
    history_limit: int = 1000

    def _apply(self, alarm: Alarm, action: AlarmAction, user: str = "") -> None:
        target = ALARM_TRANSITIONS.get((alarm.state, action))
        if target is None:
            return
        transition = AlarmTransition(
            alarm.alarm_id,
            alarm.definition.code,
            alarm.text,
            alarm.source,
            alarm.state,
            target,
            self.wall_clock(),
            user,
        )
        alarm.state = target
        self.history.append(transition)
        del self.history[: -self.history_limit]
        if target is AlarmState.NORMAL:
            self._alarms.pop((alarm.definition.code, alarm.source), None)
        self.on_transition(transition)

    def raise_alarm(
        self,
        code: AlarmCode,
        source: str = "",
        detail: str = "",
        arguments: tuple[AlarmArgument, ...] = (),
    ) -> Alarm:
        """The condition of alarm ``code`` at ``source`` is active (idempotent)."""
        definition = CATALOGUE[code]
        key = (code, source)
        alarm = self._alarms.get(key)
        if alarm is None:
            alarm = Alarm(
                next(self._ids),
                definition,
                source,
                detail,
                AlarmState.NORMAL,
                self.wall_clock(),
                arguments,
            )
            self._alarms[key] = alarm
        elif alarm.state is AlarmState.RTN_UNACKED:
            alarm.detail = detail or alarm.detail
            alarm.arguments = arguments or alarm.arguments
            alarm.raised_at = self.wall_clock()
        self._apply(alarm, AlarmAction.CONDITION_ON)
        return alarm

    def clear(self, code: AlarmCode, source: str = "") -> None:
        """The condition returned to normal."""
        alarm = self._alarms.get((code, source))
        if alarm is not None:
            self._apply(alarm, AlarmAction.CONDITION_OFF)

    def clear_all_conditions(self, keep: Callable[[Alarm], bool] = lambda _a: False) -> None:
        """On Reset: every event condition is over, except those ``keep`` says still hold."""
        for alarm in list(self._alarms.values()):
            if alarm.state in (AlarmState.ACTIVE_UNACKED, AlarmState.ACTIVE_ACKED) and not keep(
                alarm
            ):
                self._apply(alarm, AlarmAction.CONDITION_OFF)

    def acknowledge(self, alarm_id: int = 0, user: str = "") -> int:
        """Acknowledge one alarm, or all with ``alarm_id`` 0; returns how many changed."""
        changed = 0
        for alarm in list(self._alarms.values()):
            if alarm_id in (0, alarm.alarm_id) and alarm.state in (
                AlarmState.ACTIVE_UNACKED,
                AlarmState.RTN_UNACKED,
            ):
                self._apply(alarm, AlarmAction.ACKNOWLEDGE, user)
                changed += 1
        return changed

    def is_active(self, code: AlarmCode, source: str = "") -> bool:
        alarm = self._alarms.get((code, source))
        return alarm is not None and alarm.state in (
            AlarmState.ACTIVE_UNACKED,
            AlarmState.ACTIVE_ACKED,
        )

    def active_faults(self) -> list[Alarm]:
        return [
            a
            for a in self._alarms.values()
            if a.definition.severity is Severity.FAULT
            and a.state in (AlarmState.ACTIVE_UNACKED, AlarmState.ACTIVE_ACKED)
        ]

    def views(self) -> tuple[AlarmView, ...]:
        return tuple(
            a.view() for a in sorted(self._alarms.values(), key=lambda a: a.raised_at, reverse=True)
        )
