"""The machine's states and the table of every allowed transition.

Why a table: the original PLC spread its mode logic over Main, Step and Manual routines, and
nobody could say from the code which state could follow which. Here every transition is one
row of ``TRANSITIONS`` keyed by (state, event); anything not in the table is refused, and a
test walks every row.

    state            event                 next state        what it means
    ---------------  --------------------  ----------------  -----------------------------------
    POWER_UP         STARTED_HOMED         READY             every axis has an absolute position
    POWER_UP         STARTED_UNHOMED       NOT_HOMED         an incremental axis lost its position
    NOT_HOMED        HOME                  HOMING            operator: home all axes
    READY            HOME                  HOMING            operator: home again
    HOMING           HOMING_DONE           READY
    HOMING           STOP                  STOPPING
    READY            START                 AUTOMATIC         cycle starts (waits for a board)
    AUTOMATIC        STOP                  STOPPING          controlled stop along the path
    AUTOMATIC        CYCLE_DONE            READY             piece counted, ready for the next
    STOPPING         STOPPED               READY (homed) / NOT_HOMED
    NOT_HOMED        ENTER_MANUAL          MANUAL
    READY            ENTER_MANUAL          MANUAL
    MANUAL           LEAVE_MANUAL          READY (homed) / NOT_HOMED
    any but E-STOP   FAULT                 ERROR             latched; immediate stop
    any              ESTOP                 EMERGENCY_STOP    latched; immediate stop
    ERROR            RESET                 READY (homed) / NOT_HOMED   only when the cause is gone
    EMERGENCY_STOP   RESET                 READY (homed) / NOT_HOMED   only when the chain is closed

Target states that depend on whether every axis is homed are written as the pair
(READY, NOT_HOMED) and resolved by :func:`next_state`.
"""

from __future__ import annotations

import enum


class MachineState(enum.Enum):
    POWER_UP = "power-up"
    NOT_HOMED = "not homed"
    HOMING = "homing"
    READY = "ready"
    AUTOMATIC = "automatic"
    MANUAL = "manual"
    STOPPING = "stopping"
    ERROR = "error"
    EMERGENCY_STOP = "emergency stop"


class CycleStep(enum.Enum):
    """Steps of the automatic cycle (docs/MACHINE.md section 4, the original Step routine)."""

    WAIT_FOR_PART = "waiting for a board"
    CENTERING = "centering"
    CLAMPING = "clamping"
    MEASURING = "measuring"
    RETRACTING = "moving clear of the board"
    STARTING_SPINDLE = "starting spindle"
    CUTTING_A = "cutting side A"
    REPOSITIONING = "repositioning and tilting"
    CUTTING_B = "cutting side B"
    RETURNING = "returning"
    UNCLAMPING = "unclamping"


class TimedStep(enum.Enum):
    """The steps a cycle's time is split into (in the order they normally come): finer than
    CycleStep, the approach apart from side A and the waits apart (``app.machine.cycle_times``
    books every period to one of them)."""

    WAITING = "waiting"
    CENTERING = "centering"
    CLAMPING = "clamping"
    MEASURING = "measuring"
    SPINDLE = "spindle"
    RETRACTING = "retracting"
    APPROACH = "approach"
    SIDE_A = "side_a"
    REPOSITIONING = "repositioning"
    SIDE_B = "side_b"
    RETURN = "return"
    UNCLAMPING = "unclamping"


class Mode(enum.Enum):
    AUTOMATIC = "automatic"
    MANUAL = "manual"


class Event(enum.Enum):
    STARTED_HOMED = "started homed"
    STARTED_UNHOMED = "started unhomed"
    HOME = "home"
    HOMING_DONE = "homing done"
    START = "start"
    STOP = "stop"
    STOPPED = "stopped"
    CYCLE_DONE = "cycle done"
    ENTER_MANUAL = "enter manual"
    LEAVE_MANUAL = "leave manual"
    FAULT = "fault"
    ESTOP = "emergency stop"
    RESET = "reset"


# A target that depends on the homing status: (if homed, if not homed).
HomedChoice = tuple[MachineState, MachineState]
Target = MachineState | HomedChoice

_HOMED_OR_NOT: HomedChoice = (MachineState.READY, MachineState.NOT_HOMED)

TRANSITIONS: dict[tuple[MachineState, Event], Target] = {
    (MachineState.POWER_UP, Event.STARTED_HOMED): MachineState.READY,
    (MachineState.POWER_UP, Event.STARTED_UNHOMED): MachineState.NOT_HOMED,
    (MachineState.NOT_HOMED, Event.HOME): MachineState.HOMING,
    (MachineState.READY, Event.HOME): MachineState.HOMING,
    (MachineState.HOMING, Event.HOMING_DONE): MachineState.READY,
    (MachineState.HOMING, Event.STOP): MachineState.STOPPING,
    (MachineState.READY, Event.START): MachineState.AUTOMATIC,
    (MachineState.AUTOMATIC, Event.STOP): MachineState.STOPPING,
    (MachineState.AUTOMATIC, Event.CYCLE_DONE): MachineState.READY,
    (MachineState.STOPPING, Event.STOPPED): _HOMED_OR_NOT,
    (MachineState.NOT_HOMED, Event.ENTER_MANUAL): MachineState.MANUAL,
    (MachineState.READY, Event.ENTER_MANUAL): MachineState.MANUAL,
    (MachineState.MANUAL, Event.LEAVE_MANUAL): _HOMED_OR_NOT,
    (MachineState.ERROR, Event.RESET): _HOMED_OR_NOT,
    (MachineState.EMERGENCY_STOP, Event.RESET): _HOMED_OR_NOT,
}

# Faults and E-stop are accepted from every state (E-stop even while already in ERROR).
for _state in MachineState:
    if _state is not MachineState.EMERGENCY_STOP:
        TRANSITIONS[(_state, Event.ESTOP)] = MachineState.EMERGENCY_STOP
    if _state not in (MachineState.ERROR, MachineState.EMERGENCY_STOP):
        TRANSITIONS[(_state, Event.FAULT)] = MachineState.ERROR

LATCHED_STATES = frozenset({MachineState.ERROR, MachineState.EMERGENCY_STOP})
MOVING_STATES = frozenset({MachineState.HOMING, MachineState.AUTOMATIC, MachineState.STOPPING})
"""The states in which the machine moves on its own (the guard must stay closed, Stop stops
it, nothing else may start); the one definition every rule uses."""

# The signal tower: green while the machine works on its own, yellow while it waits for the
# operator or winds down, red while latched.
GREEN_LAMP_STATES = frozenset({MachineState.AUTOMATIC, MachineState.HOMING})
YELLOW_LAMP_STATES = frozenset({MachineState.MANUAL, MachineState.STOPPING, MachineState.NOT_HOMED})


def lamps(state: MachineState) -> dict[str, bool]:
    """The signal tower's outputs for ``state`` (OutputImage field names)."""
    return {
        "lamp_green": state in GREEN_LAMP_STATES,
        "lamp_yellow": state in YELLOW_LAMP_STATES,
        "lamp_red": state in LATCHED_STATES,
    }


class TransitionRefused(Exception):
    """An event the current state does not accept. The operator's commands are checked by
    the rules of ``app.machine.permissions`` first (with the reasons the screens show), so
    this only happens when those rules and this table disagree."""

    def __init__(self, state: MachineState, event: Event) -> None:
        super().__init__(f"{event.value} is not possible while {state.value}")
        self.state = state
        self.event = event


def next_state(state: MachineState, event: Event, all_homed: bool) -> MachineState:
    """The state after ``event``; raises TransitionRefused if the table has no such row."""
    target = TRANSITIONS.get((state, event))
    if target is None:
        raise TransitionRefused(state, event)
    if isinstance(target, tuple):
        return target[0] if all_homed else target[1]
    return target
