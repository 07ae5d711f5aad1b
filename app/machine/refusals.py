"""Everything the machine tells the operator in words: why a command is refused, and how a
Reset ended, as codes with arguments.

Why codes: the machine has no Qt and no language; the screens translate. A ``Refusal``
travels in the snapshot as its ``Reason`` and its arguments (axis names, numbers, a
device's own detail); the screens translate the reason's English template (Qt's ``%1``
placeholders) and fill in the arguments. The list of texts to translate is this enum.
"""

from __future__ import annotations

import enum
import json
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any


class Reason(enum.Enum):
    """The English template of each message; ``%1``, ``%2``... are the arguments."""

    LATCHED_ERROR = "machine is in error: press Reset first"
    LATCHED_ESTOP = "machine is in emergency stop: press Reset first"
    LATCHED_ESTOP_PRESSED = (
        "machine is in emergency stop: release the emergency stop button, then press Reset"
    )
    STARTING_UP = "machine is still starting up"
    LEAVE_MANUAL_FIRST = "leave manual mode first"
    CYCLE_RUNNING = "a cycle is already running"
    NOT_HOMED = "axes are not homed: home the machine first"
    NOT_POSSIBLE_HOMING = "not possible while homing"
    NOT_POSSIBLE_STOPPING = "not possible while stopping"
    NOT_POSSIBLE_NOT_HOMED = "not possible while not homed"
    NOT_POSSIBLE_AUTOMATIC = "not possible while automatic"
    NOT_POSSIBLE_MANUAL = "not possible while manual"
    NOT_POSSIBLE_READY = "not possible while ready"
    PARTLY_CUT_RESUME_OR_ABANDON = "a board is partly cut: Resume or Abandon it"
    PARTLY_CUT_FIRST = "a board is partly cut: Resume or Abandon it first"
    NO_BOARD_PARTLY_CUT = "no board is partly cut"
    NOT_HOMED_ABANDON = "axes are not homed: abandon the board (their position is unknown)"
    UNCLAMPED_ABANDON = "the board was unclamped: it may have moved, abandon it"
    BOARD_ON_TABLE_UNHOMED = (
        "a board is on the table and the axes do not know where they are: "
        "take the board off before homing"
    )
    INTERRUPTED_BOARD = "%1: Resume or Abandon"
    RECIPE_GONE_ABANDON = "recipe %1 no longer exists: abandon the board"
    RESUMING = "resuming the board"
    ABANDONING = "abandoning the board"
    ABANDONED = "board abandoned: take it off"
    ABANDONED_UNCLAMPED = (
        "board abandoned and unclamped: take it off (nothing moved: check that the cutter "
        "is clear of it)"
    )
    SELECT_RECIPE_FIRST = "select a recipe first"
    CLOSE_GUARD_FIRST = "close the guard first"
    SPINDLE_LOOSE_BOARD = (
        "a board is on the table and not clamped: clamp it or take it off before the spindle starts"
    )
    NOTHING_MOVING = "nothing is moving"
    NOTHING_TO_RESET = "nothing to reset"
    RELEASE_ESTOP_FIRST = "release the emergency stop first"
    BUSY_AUTOMATIC = "machine is busy (automatic): stop it first"
    BUSY_HOMING = "machine is busy (homing): stop it first"
    BUSY_STOPPING = "machine is busy (stopping): stop it first"
    ALREADY_MANUAL = "already in manual mode"
    NOT_MANUAL = "not in manual mode"
    OPEN_MANUAL_TO_JOG = "open the Manual screen to jog"
    WAIT_FOR_CYCLE_END = "wait until the cycle has ended"
    SIMULATION_ONLY = "only on the simulated machine"
    UNCLAMP_BOARD_FIRST = "the board is clamped: unclamp it first"
    UNKNOWN_COMMAND = "unknown command"
    NOT_POSSIBLE_NOW = "%1 is not possible while %2"
    RECIPE_MISSING = "recipe %1 does not exist"
    SELECTED_RECIPE_DELETED = (
        "recipe %1, selected on the machine, has been deleted: select a recipe"
    )
    SELECTED_RECIPE_CHANGED = (
        "recipe %1 has been changed since it was selected: the machine keeps the version it "
        "was selected with; select it again to cut the new version"
    )
    SELECTED_RECIPE_UNREADABLE = (
        "the recipe selected before the restart cannot be read: select a recipe"
    )
    FIXED_TILT_NO_BARREL = "recipe %1 has a fixed tilt: it makes no barrel"
    FEED_OVERRIDE_RANGE = "feed override %1 % is not allowed: 0 to 120 %"
    RECONNECT_FAILED = "reconnection failed: %1"
    RESET_DONE = "reset done"
    RESET_FAILED = "reset failed"
    DRIVE_STILL_FAULTED = "%1 still in fault %2"
    ESTOP_STILL_PRESSED = "emergency stop still pressed"
    COMMS_NOT_RESTORED = "communication not restored"
    AXIS_UNKNOWN = "axis %1 is not allowed: X, Y or Z"
    JOG_DIRECTION_INVALID = "jog direction %1 is not allowed: -1 or 1"
    LIMIT_SWITCH_POSITIVE = "%1+ limit switch is active: jog %1 in the - direction only"
    LIMIT_SWITCH_NEGATIVE = "%1- limit switch is active: jog %1 in the + direction only"
    STEP_OF_ZERO = "a step of 0 moves nothing"
    RELEASE_JOG_FIRST = "axis %1 is moving: release the jog first"
    MOVE_OUTSIDE_TRAVEL = "go to position: %1 = %2 is not allowed: %3 to %4"
    MOVE_REFUSED = "go to position refused: %1"
    MOVE_RUNNING = "the axes are going to a position: wait, or press Stop"
    JOG_AT_BOARD = "jog %1 refused: the cutter is at the board's keep-out (a board is on the table)"
    JOG_STOPS_AT_BOARD = "jog %1 stops at %2, the edge of the board's keep-out"
    JOG_STEP_INTO_BOARD = (
        "step of %1 refused: the cutter would enter the board's keep-out at %2 (a board is on "
        "the table)"
    )
    JOG_HOLD_ENDED = (
        "jog %1 was stopped: no refresh from the screen for %2 s; release the button and "
        "press it again"
    )
    AT_SOFT_LIMIT = "axis %1 is at its soft limit"
    AT_LOWER_SOFT_LIMIT = "axis %1 is at its lower soft limit %2"
    AT_UPPER_SOFT_LIMIT = "axis %1 is at its upper soft limit %2"
    BEYOND_LOWER_SOFT_LIMIT = (
        "axis %1 is below its lower soft limit %2 (at %3): only motion back toward the range "
        "is allowed"
    )
    BEYOND_UPPER_SOFT_LIMIT = (
        "axis %1 is above its upper soft limit %2 (at %3): only motion back toward the range "
        "is allowed"
    )
    CLIPPED_TO_LOWER_SOFT_LIMIT = "clipped to the lower soft limit %1"
    CLIPPED_TO_UPPER_SOFT_LIMIT = "clipped to the upper soft limit %1"
    SIMULATION_REFUSED = "the simulation refused: %1"
    HOMING_REFUSED = "homing refused: %1"
    HOMING_AROUND_BOARD = "a board is on the table: moving clear of it before homing"
    PLANT_NOTICE = "%1"  # a job notice from the plant connection, in the plant's words
    SCREEN_HAS_JOG = "the screen is jogging: release it and let the axes stop first"
    HANDWHEEL_HAS_JOG = "the handwheel is jogging: let it and the axes come to rest first"
    JOYSTICK_HAS_JOG = "the joystick is jogging: let it go and the axes stop first"
    PENDANT_HAS_JOG = "the USB pendant is jogging: let it and the axes come to rest first"
    HANDWHEEL_IGNORED = "handwheel ignored: it jogs only on the Manual screen"
    JOYSTICK_IGNORED = "joystick ignored: it jogs only on the Manual screen"
    PENDANT_IGNORED = "USB pendant ignored: it jogs only on the Manual screen"
    HOLD_ENABLE = "hold the enable button to jog with the handwheel or the joystick"
    JOYSTICK_NOT_CENTRED = (
        "joystick %1 reads %2 counts off its centre at start-up: let it go, it is calibrated "
        "once at rest"
    )
    HANDWHEEL_JUMPED = "the counter moved %1 counts in one read; a hand turns at most %2"

    # What an alarm found, after its title (the axis is the alarm's source).
    NO_FEEDBACK_DETAIL = "axis %1: no feedback from its drive"
    DRIVE_IN_FAULT_DETAIL = "axis %1, fault code %2"
    DRIVE_NOT_ENABLED_DETAIL = "axis %1: drive not enabled while moving (%2)"
    FOLLOWING_ERROR_DETAIL = "axis %1: following error %2 %3 exceeds %4 %3"
    LIMIT_POSITIVE_DETAIL = "axis %1: positive limit switch at %2 %3"
    LIMIT_NEGATIVE_DETAIL = "axis %1: negative limit switch at %2 %3"
    SOFT_LIMIT_DETAIL = "axis %1: setpoint %2 %3 outside the travel %4 to %5 %3"
    EMCY_FOLLOWING_ERROR = "following error"
    EMCY_SENSOR = "position sensor"
    EMCY_HEARTBEAT = "heartbeat or life guard"
    EMCY_OVERCURRENT = "over-current"
    EMCY_OVERVOLTAGE = "DC link over-voltage"
    EMCY_OVERTEMPERATURE = "drive over-temperature"
    EMCY_LIMIT_SWITCH = "limit switch"
    GUARD_OPENED = "the guard was opened"
    HOME_LOST_DETAIL = "an axis lost its home position"
    RECORDS_WAITING_DETAIL = "the oldest has waited %1 s"
    PART_SENSOR_OFF = "the part-present sensor went off during the cycle"
    PARTLY_CUT_GONE = "the partly cut board is no longer on the table"
    CENTERING_EXTENDED = "centering device not extended after %1 s"
    CENTERING_RETRACTED = "centering device not retracted after %1 s"
    CLAMPS_CLOSED = "clamps not closed after %1 s"
    CLAMPS_OPENED = "clamps not open after %1 s"
    SPINDLE_RUNNING = "spindle not running after %1 s"
    SPINDLE_FEEDBACK_LOST = "the spindle's running signal went off"
    GAUGE_NO_READING_DETAIL = "no reading within %1 s"
    DRIVE_FAULT_WHILE_HOMING = "axis %1: drive fault %2 while homing"
    DRIVE_DID_NOT_ENABLE_DETAIL = "axis %1: drive did not enable within %2 s"
    HOMING_DID_NOT_START = "axis %1: homing did not start within %2 s"
    HOME_SWITCH_NOT_FOUND = "axis %1: homing ended without finding the home switch"
    HOMING_TIMEOUT = "axis %1: not homed after %2 s"
    JOG_NOT_REFRESHED_DETAIL = "axis %1 stopped: the screen stopped confirming the jog"


def fill(template: str, args: tuple[str, ...]) -> str:
    """Qt's QString::arg for ``%1``..``%9``: each placeholder replaced by its argument (the
    screens fill a translated template the same way)."""
    text = template
    for number in range(len(args), 0, -1):  # %10 before %1, should there ever be ten
        text = text.replace(f"%{number}", args[number - 1])
    return text


@dataclass(frozen=True)
class Refusal:
    """One message: its reason, the arguments of the reason's template, and the causes that
    explain it (a failed Reset lists what still holds)."""

    reason: Reason
    args: tuple[str, ...] = ()
    causes: tuple[Refusal, ...] = ()

    def text(self, translate: Callable[[str], str] = str) -> str:
        """The message with each template passed through ``translate`` (the screens pass
        their translation; the default gives the English text)."""
        text = fill(translate(self.reason.value), self.args)
        if self.causes:
            text += ": " + "; ".join(cause.text(translate) for cause in self.causes)
        return text

    def __str__(self) -> str:
        """The English text (logs, tests, the command line)."""
        return self.text()


def refusal_to_json(message: Refusal) -> str:
    """A message as stored with an alarm's history (its reason by name, so a reworded
    template still finds it), for the screens to show later in the user's language."""
    return json.dumps(_refusal_mapping(message), ensure_ascii=False)


def _refusal_mapping(message: Refusal) -> dict[str, Any]:
    return {
        "reason": message.reason.name,
        "args": list(message.args),
        "causes": [_refusal_mapping(cause) for cause in message.causes],
    }


def refusal_from_json(text: str | None) -> Refusal | None:
    """Inverse of :func:`refusal_to_json`; None for no text, or for one this software cannot
    read (a reason it does not have): the caller shows the stored English line then."""
    if not text:
        return None
    try:
        return _refusal_from_mapping(json.loads(text))
    except (ValueError, KeyError, TypeError):
        return None


def _refusal_from_mapping(fields: dict[str, Any]) -> Refusal:
    return Refusal(
        Reason[fields["reason"]],
        tuple(str(arg) for arg in fields["args"]),
        tuple(_refusal_from_mapping(cause) for cause in fields["causes"]),
    )


def refusal(reason: Reason, *args: object) -> Refusal:
    """A Refusal with its arguments as the text shown (numbers as ``:g``)."""
    return Refusal(reason, tuple(f"{a:g}" if isinstance(a, float) else str(a) for a in args))
