"""One jog arbitration: the screen, the handwheel, the joystick and a USB pendant never fight.

Why a state machine and not "last one wins": a technician turning the wheel while a colleague
holds a screen button must not have the axis jerk between two commands, and a stick knocked
while the wheel is in use must not take over a moving axis. So one source owns the jog at a
time; another source's touch is refused (and said so) while the owner or any axis still
moves; the owner gives the jog up only once every source and every axis has been at rest
for ``SETTLE_S``, and then the next source that is touched takes it.

The table is the whole rule (every row tested): ``(state, event) -> next state``.
"""

from __future__ import annotations

import enum

from app.machine.refusals import Reason, Refusal
from app.machine.snapshot import JogSource

SETTLE_S = 0.3
"""All at rest this long before the jog is free for another source (a slowly turned wheel
pauses between counts without losing the jog)."""


class ArbiterState(enum.Enum):
    FREE = "free"
    SCREEN = "screen"
    HANDWHEEL = "handwheel"
    JOYSTICK = "joystick"
    PENDANT = "pendant"


class ArbiterEvent(enum.Enum):
    TOUCH_SCREEN = "touch screen"
    TOUCH_HANDWHEEL = "touch handwheel"
    TOUCH_JOYSTICK = "touch joystick"
    TOUCH_PENDANT = "touch pendant"
    AT_REST = "all at rest"  # every source and axis at rest for SETTLE_S
    LEAVE = "leave manual"  # manual mode ended, or a fault stopped everything


OWNER: dict[JogSource, ArbiterState] = {
    JogSource.SCREEN: ArbiterState.SCREEN,
    JogSource.HANDWHEEL: ArbiterState.HANDWHEEL,
    JogSource.JOYSTICK: ArbiterState.JOYSTICK,
    JogSource.PENDANT: ArbiterState.PENDANT,
}
TOUCH: dict[JogSource, ArbiterEvent] = {
    JogSource.SCREEN: ArbiterEvent.TOUCH_SCREEN,
    JogSource.HANDWHEEL: ArbiterEvent.TOUCH_HANDWHEEL,
    JogSource.JOYSTICK: ArbiterEvent.TOUCH_JOYSTICK,
    JogSource.PENDANT: ArbiterEvent.TOUCH_PENDANT,
}
BUSY: dict[ArbiterState, Reason] = {
    ArbiterState.SCREEN: Reason.SCREEN_HAS_JOG,
    ArbiterState.HANDWHEEL: Reason.HANDWHEEL_HAS_JOG,
    ArbiterState.JOYSTICK: Reason.JOYSTICK_HAS_JOG,
    ArbiterState.PENDANT: Reason.PENDANT_HAS_JOG,
}


def _table() -> dict[tuple[ArbiterState, ArbiterEvent], ArbiterState]:
    table: dict[tuple[ArbiterState, ArbiterEvent], ArbiterState] = {}
    for state in ArbiterState:
        for source, event in TOUCH.items():
            # Free: the touched source takes the jog; owned: the owner keeps it.
            table[state, event] = OWNER[source] if state is ArbiterState.FREE else state
        table[state, ArbiterEvent.AT_REST] = ArbiterState.FREE
        table[state, ArbiterEvent.LEAVE] = ArbiterState.FREE
    return table


TRANSITIONS: dict[tuple[ArbiterState, ArbiterEvent], ArbiterState] = _table()


class JogArbiter:
    def __init__(self) -> None:
        self.state = ArbiterState.FREE
        self._rest_since_s: float | None = None

    @property
    def owner(self) -> JogSource | None:
        for source, state in OWNER.items():
            if state is self.state:
                return source
        return None

    def _fire(self, event: ArbiterEvent) -> None:
        self.state = TRANSITIONS[self.state, event]

    def touch(self, source: JogSource) -> Refusal | None:
        """``source`` wants to jog: None if it owns the jog now, else why not."""
        self._fire(TOUCH[source])
        if self.state is OWNER[source]:
            self._rest_since_s = None
            return None
        return Refusal(BUSY[self.state])

    def tick(self, now_s: float, at_rest: bool) -> None:
        """Once per period: ``at_rest`` when no source commands motion and no axis moves."""
        if not at_rest:
            self._rest_since_s = None
            return
        if self._rest_since_s is None:
            self._rest_since_s = now_s
        if now_s - self._rest_since_s >= SETTLE_S - 1e-9:
            self._fire(ArbiterEvent.AT_REST)

    def leave(self) -> None:
        self._fire(ArbiterEvent.LEAVE)
        self._rest_since_s = None
