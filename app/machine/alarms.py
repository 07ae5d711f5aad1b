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

from app.machine.refusals import Refusal
from app.machine.snapshot import AlarmArgument, AlarmState, AlarmView

# What an alarm found: a Refusal is a message for the operator (a template with its
# arguments, translated by the screens); a str is a device's or a library's own words,
# English and technical, shown only in the alarm's details.
AlarmDetail = Refusal | str


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
    """An alarm's words for the people at the machine (ISA-18.2's "alarm response
    procedure"): the title on the banner, then what it means, why it usually happens and
    what to do, so that an operator on night shift can act without a manual. English here;
    the screens translate every text by its English wording."""

    code: AlarmCode
    text: str
    severity: Severity
    description: str
    causes: tuple[str, ...]
    remedy: str


def _d(
    code: AlarmCode,
    text: str,
    severity: Severity,
    description: str,
    causes: tuple[str, ...],
    remedy: str,
) -> AlarmDefinition:
    return AlarmDefinition(code, text, severity, description, causes, remedy)


_F = Severity.FAULT
_W = Severity.WARNING

CATALOGUE: dict[AlarmCode, AlarmDefinition] = {
    d.code: d
    for d in (
        _d(
            AlarmCode.ESTOP,
            "Emergency stop",
            _F,
            "The emergency stop chain is open: every drive stopped and lost power.",
            (
                "An emergency stop button is pressed.",
                "A safety relay or a wire of the chain is open.",
            ),
            "Make sure nobody is in danger, release the button (turn it), then press Reset.",
        ),
        _d(
            AlarmCode.GUARD_OPEN,
            "Guard open during motion",
            _F,
            "The guard was opened while an axis or the cutter moved; the machine stopped.",
            ("Somebody opened the guard.", "The guard switch is loose or badly adjusted."),
            "Close the guard, check that nothing is in the way, then press Reset.",
        ),
        _d(
            AlarmCode.DRIVE_FAULT,
            "Drive fault",
            _F,
            "A servo drive reports a fault and has switched its motor off.",
            (
                "Over-current or over-temperature: the axis is stuck or overloaded.",
                "Supply voltage too high or too low.",
                "A cable to the motor or its encoder is damaged.",
            ),
            "Read the fault code in the details, look at the axis for anything jammed, then "
            "press Reset. If it comes back, call a technician with the code.",
        ),
        _d(
            AlarmCode.FOLLOWING_ERROR,
            "Following error too large",
            _F,
            "An axis lags too far behind where it should be; it was stopped before it "
            "could go somewhere unexpected.",
            (
                "The axis is blocked or runs stiffly (chips, a board in the way, dry guides).",
                "Feed or acceleration set higher than the axis can follow.",
                "A drive or encoder problem.",
            ),
            "Clear the axis, check that it moves freely, then press Reset. If it repeats, "
            "lower the feed or call a technician.",
        ),
        _d(
            AlarmCode.LIMIT_SWITCH,
            "Limit switch reached",
            _F,
            "An axis ran onto its end-of-travel switch and was stopped.",
            (
                "The axis was jogged past its range.",
                "The home position is lost or wrong.",
                "A limit switch is faulty or was hit by a board.",
            ),
            "Press Reset, jog the axis away from the switch on the Manual screen (the "
            "opposite direction only), then home the machine.",
        ),
        _d(
            AlarmCode.DRIVE_NOT_ENABLED,
            "Drive not enabled during motion",
            _F,
            "A drive switched its power stage off while the axis was meant to move.",
            (
                "The drive's enable or safe torque off input dropped.",
                "The drive lost its supply.",
            ),
            "Check the drive's display and its supply, then press Reset.",
        ),
        _d(
            AlarmCode.DRIVE_DID_NOT_ENABLE,
            "Drive did not enable",
            _F,
            "A drive did not switch its power stage on when asked.",
            (
                "The emergency stop chain or safe torque off is still open.",
                "The drive is in fault or has no supply.",
            ),
            "Check the emergency stop buttons and the drive's display, then press Reset.",
        ),
        _d(
            AlarmCode.HOMING_INCOMPLETE,
            "Homing did not complete",
            _F,
            "An axis did not find its home position within the expected time.",
            (
                "The home switch is faulty, dirty or out of place.",
                "The axis was blocked or stopped during homing.",
            ),
            "Check the axis and its home switch, then press Reset and home again.",
        ),
        _d(
            AlarmCode.HOME_LOST,
            "Axis lost its home position",
            _F,
            "A drive no longer knows where its axis is; the cut was stopped.",
            ("The drive was switched off or restarted.", "An encoder signal was lost."),
            "Press Reset and home the machine before the next board.",
        ),
        _d(
            AlarmCode.COMMUNICATION_LOST,
            "Communication with the drives or I/O lost",
            _F,
            "The computer no longer hears a drive or the I/O; the machine stopped.",
            (
                "A network or bus cable is unplugged or broken.",
                "A drive or the I/O module lost its supply or restarted.",
                "A switch between them failed.",
            ),
            "Check the cables and the supply of the device named in the details, then press "
            "Reset (it reconnects).",
        ),
        _d(
            AlarmCode.DEVICE_REFUSED,
            "A drive or the I/O refused a request",
            _F,
            "A device answered but refused what the machine asked of it.",
            (
                "The device is configured differently from the machine's configuration.",
                "A device was replaced by another model or firmware.",
            ),
            "Call a technician with the code in the details; then press Reset.",
        ),
        _d(
            AlarmCode.GAUGE_NO_READING,
            "Width gauge gave no reading",
            _F,
            "The width gauge sent no measurement in time; the board was not cut.",
            ("The gauge is not in contact with the board.", "The gauge's cable is loose."),
            "Check the gauge and its cable, then press Reset: the board is measured again.",
        ),
        _d(
            AlarmCode.GAUGE_UNREADABLE,
            "Width gauge reading not understood",
            _F,
            "The width gauge sent something that is not a width.",
            (
                "The gauge reports its own error (out of range, no contact).",
                "Wrong serial settings or a faulty cable.",
            ),
            "Check the gauge's display and cable, then press Reset.",
        ),
        _d(
            AlarmCode.WIDTH_NOT_ALLOWED,
            "Measured width not allowed for this recipe",
            _F,
            "The board is narrower or wider than the recipe can cut; it was not cut.",
            (
                "The board is too narrow or too wide for this recipe.",
                "The wrong recipe is selected.",
            ),
            "Take the board off (or choose the right recipe), then press Reset.",
        ),
        _d(
            AlarmCode.GAUGE_DISCONNECTED,
            "Width gauge disconnected",
            _F,
            "The width gauge's connection is gone; no board can be measured.",
            ("The gauge's cable or adapter is unplugged.", "The gauge lost its supply."),
            "Plug the gauge in again, then press Reset (it reconnects).",
        ),
        _d(
            AlarmCode.BARREL_NOT_CLOSABLE,
            "Board too narrow to close the barrel",
            _F,
            "Cut to fit, this board would leave a gap in the barrel that no stave can close.",
            ("The board is narrower than the barrel still needs.",),
            "Take the board off and put a wider one on, then press Reset.",
        ),
        _d(
            AlarmCode.CLAMPS_SENSOR,
            "Clamps did not reach their sensor",
            _F,
            "The clamps did not close or open in time, as their sensor reports.",
            (
                "Air pressure too low.",
                "The board is in the way or the clamps are jammed.",
                "A faulty or misadjusted sensor.",
            ),
            "Check the air pressure and the clamps, then press Reset.",
        ),
        _d(
            AlarmCode.CENTERING_SENSOR,
            "Centering device did not reach its sensor",
            _F,
            "The centering device did not extend or retract in time.",
            (
                "Air pressure too low.",
                "The board is in the way or the device is jammed.",
                "A faulty or misadjusted sensor.",
            ),
            "Check the air pressure and the centering device, then press Reset.",
        ),
        _d(
            AlarmCode.SPINDLE_NOT_STARTED,
            "Spindle did not start",
            _F,
            "The spindle did not report running in time; nothing was cut.",
            (
                "The spindle's motor protection tripped.",
                "The spindle's contactor or its running signal is faulty.",
            ),
            "Check the spindle's motor protection switch, then press Reset.",
        ),
        _d(
            AlarmCode.SPINDLE_STOPPED,
            "Spindle stopped while cutting",
            _F,
            "The spindle stopped during a cut; the axes were stopped at once.",
            (
                "The motor protection tripped (a blunt cutter, too much feed).",
                "The supply of the spindle dropped.",
            ),
            "Check the cutter and the motor protection. Press Reset, then resume or abandon "
            "the board.",
        ),
        _d(
            AlarmCode.BOARD_REMOVED,
            "Board removed during the cycle",
            _F,
            "The part-present sensor lost the board while the cycle was using it.",
            ("The board was taken off or moved.", "The sensor is dirty or misadjusted."),
            "Make sure the table is clear or the board is in place, then press Reset.",
        ),
        _d(
            AlarmCode.OUTSIDE_TRAVEL,
            "Tool path outside the axis travel",
            _F,
            "The cut would need an axis beyond its travel; nothing moved there.",
            (
                "The recipe's stave does not fit this machine.",
                "The board is wider than the machine can cut.",
            ),
            "Take the board off and check the recipe, then press Reset.",
        ),
        _d(
            AlarmCode.PLANNING_FAILED,
            "Tool path could not be planned",
            _F,
            "The machine could not compute the cut for this board.",
            ("The recipe's values give no shape for this width.", "A software fault."),
            "Take the board off and check the recipe, then press Reset. If it repeats with a "
            "good recipe, call service with the details.",
        ),
        _d(
            AlarmCode.APPROACH_CROSSES_BOARD,
            "Move refused: it would cross the board",
            _F,
            "The way to the cut would take the cutter through the board; nothing moved.",
            ("An axis stands where the approach cannot go round the board.",),
            "Press Reset, move the cutter clear of the board on the Manual screen, then start "
            "again.",
        ),
        _d(
            AlarmCode.HANDWHEEL_JUMP,
            "Handwheel count jumped further than a hand can turn it",
            _F,
            "The handwheel's counter changed by more between two readings than a hand can "
            "turn it; nothing moved on that reading.",
            (
                "Electrical noise on the handwheel's cable or a bad connector.",
                "The handwheel or its counter input is faulty.",
            ),
            "Check the handwheel's cable and plug, then press Reset. If it repeats, call a "
            "technician.",
        ),
        _d(
            AlarmCode.INTERNAL_ERROR,
            "Internal error in the machine process",
            _F,
            "The machine's software met a situation it does not handle; it stopped safely.",
            ("A software fault.",),
            "Note the time and the details, press Reset, and tell service.",
        ),
        _d(
            AlarmCode.JOG_NOT_REFRESHED,
            "Jog stopped: no refresh from the screen",
            _W,
            "A jog stopped because the screen no longer confirmed that its button is held.",
            ("The screen was busy or frozen.", "The touch was lost while holding the button."),
            "Press and hold the jog button again.",
        ),
        _d(
            AlarmCode.DEVICE_EVENT,
            "Device event",
            _W,
            "A drive or the I/O reported an event; the machine keeps going.",
            ("A warning inside the device.",),
            "Read the details; call a technician if it repeats.",
        ),
        _d(
            AlarmCode.RECORDS_WAITING,
            "Records waiting for the database",
            _W,
            "Production and alarm records are kept on the side because the database is busy "
            "or missing; nothing is lost yet.",
            ("The disk is full or slow.", "Another program holds the database."),
            "Call a technician to free disk space or the database; the records are written "
            "once it answers.",
        ),
        _d(
            AlarmCode.PIN_LOCKED,
            "PIN entry locked after repeated wrong PINs",
            _W,
            "Too many wrong PINs were entered; PIN entry waits before it accepts another.",
            ("A wrong PIN was tried several times.",),
            "Wait until the lock ends, then enter the right PIN.",
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
    detail: Refusal | None = None  # what was found, kept coded for the screens to translate


@dataclass
class Alarm:
    alarm_id: int
    definition: AlarmDefinition
    source: str
    detail: Refusal | None
    technical: str
    state: AlarmState
    raised_at: float
    arguments: tuple[AlarmArgument, ...] = ()

    @property
    def text(self) -> str:
        """The English line the history, the logs and the plant keep."""
        found = str(self.detail) if self.detail is not None else self.technical
        return f"{self.definition.text}: {found}" if found else self.definition.text

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
            self.detail,
            self.technical,
        )


def split_detail(detail: AlarmDetail) -> tuple[Refusal | None, str]:
    """(the operator's message, the technical text) of a detail."""
    if isinstance(detail, Refusal):
        return detail, ""
    return None, detail


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
            alarm.detail,
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
        detail: AlarmDetail = "",
        arguments: tuple[AlarmArgument, ...] = (),
    ) -> Alarm:
        """The condition of alarm ``code`` at ``source`` is active (idempotent)."""
        definition = CATALOGUE[code]
        message, technical = split_detail(detail)
        key = (code, source)
        alarm = self._alarms.get(key)
        if alarm is None:
            alarm = Alarm(
                next(self._ids),
                definition,
                source,
                message,
                technical,
                AlarmState.NORMAL,
                self.wall_clock(),
                arguments,
            )
            self._alarms[key] = alarm
        elif alarm.state is AlarmState.RTN_UNACKED:
            if detail:
                alarm.detail, alarm.technical = message, technical
            alarm.arguments = arguments or alarm.arguments
            alarm.raised_at = self.wall_clock()
        self._apply(alarm, AlarmAction.CONDITION_ON)
        return alarm

    def clear(self, code: AlarmCode, source: str = "") -> None:
        """The condition returned to normal."""
        alarm = self._alarms.get((code, source))
        if alarm is not None:
            self._apply(alarm, AlarmAction.CONDITION_OFF)

    def clear_all_conditions(
        self, keep: Callable[[Alarm], bool] = lambda _a: False, user: str = ""
    ) -> None:
        """On Reset (by ``user``): every event condition is over, except those ``keep``
        says still hold."""
        for alarm in list(self._alarms.values()):
            if alarm.state in (AlarmState.ACTIVE_UNACKED, AlarmState.ACTIVE_ACKED) and not keep(
                alarm
            ):
                self._apply(alarm, AlarmAction.CONDITION_OFF, user)

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
