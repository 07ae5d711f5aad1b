"""A USB pendant's or gamepad's input events turned into what the machine jogs by.

Why event by event and pure: evdev delivers a stream of (type, code, value) events, each
batch closed by a SYN_REPORT; the state they leave (buttons held, stick positions, wheel
detents turned) is what counts, and the same stream must always map to the same jog. So the
mapping keeps that state and knows nothing of devices: tests replay recorded streams.

- The enable button (``enable``) must be held for anything to move (the machine checks it).
- A stick's value is scaled by its range (the device's absinfo: min, max) to -1..1 about the
  middle of the range; the deadband and the curve are the machine's.
- The wheel (a relative axis, one event per detent) adds its detents times the multiplier.
- The select_* and step_* buttons choose the wheel's axis and multiplier on their press
  (like the rotary switches of a handwheel); they stay chosen.
- A SYN_DROPPED (the kernel's buffer overran) discards the batch and releases everything:
  the state is unknown until the next report.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from app.drivers.contracts import PendantReading

EV_SYN, EV_KEY, EV_REL, EV_ABS = 0x00, 0x01, 0x02, 0x03
SYN_REPORT, SYN_DROPPED = 0, 3
STICK_AXES = {"stick_x": "X", "stick_y": "Y", "stick_z": "Z"}
SELECTS = {"select_off": "", "select_x": "X", "select_y": "Y", "select_z": "Z"}
STEPS = {"step_x1": 1, "step_x10": 10, "step_x100": 100}


@dataclass(frozen=True)
class AxisRange:
    """An absolute axis's range as the device reports it (absinfo)."""

    minimum: int
    maximum: int

    def deflection(self, value: int) -> float:
        middle = (self.minimum + self.maximum) / 2.0
        half = (self.maximum - self.minimum) / 2.0
        if half <= 0:
            return 0.0
        return max(-1.0, min(1.0, (value - middle) / half))


class EventMapping:
    """The pendant's state from its events. ``codes`` maps each role (``enable``,
    ``stick_x``, ``wheel``, ``select_x``, ``step_x10``...) to its (type, code); ``ranges``
    gives each stick's absinfo by code."""

    def __init__(
        self, codes: Mapping[str, tuple[int, int]], ranges: Mapping[int, AxisRange]
    ) -> None:
        self._roles = {value: role for role, value in codes.items()}
        self._ranges = dict(ranges)
        self._enable = False
        self._axis = ""
        self._multiplier = 1
        self._sticks: dict[str, float] = {}
        self._detents = 0  # wheel detents reported and not yet read
        self._pending_detents = 0  # in the batch not closed by a SYN_REPORT yet
        self._pending: dict[str, float] = {}
        self._dropped = False

    def feed(self, event_type: int, code: int, value: int) -> None:
        if event_type == EV_SYN:
            self._sync(code)
            return
        if self._dropped:
            return
        role = self._roles.get((event_type, code))
        if role is None:
            return
        if event_type == EV_KEY:
            self._key(role, value)
        elif event_type == EV_ABS and role in STICK_AXES:
            scale = self._ranges.get(code, AxisRange(-32768, 32767))
            self._pending[STICK_AXES[role]] = scale.deflection(value)
        elif event_type == EV_REL and role == "wheel":
            self._pending_detents += value

    def _key(self, role: str, value: int) -> None:
        pressed = value != 0  # 1 press, 2 autorepeat, 0 release
        if role == "enable":
            self._enable = pressed
        elif pressed and role in SELECTS:
            self._axis = SELECTS[role]
        elif pressed and role in STEPS:
            self._multiplier = STEPS[role]

    def _sync(self, code: int) -> None:
        if code == SYN_DROPPED:
            self._dropped = True
            self.release()
            return
        if code != SYN_REPORT:
            return
        if self._dropped:  # the report after a drop closes the lost batch: discard it
            self._dropped = False
            self._pending.clear()
            self._pending_detents = 0
            return
        self._sticks.update(self._pending)
        self._pending.clear()
        self._detents += self._pending_detents
        self._pending_detents = 0

    def release(self) -> None:
        """Everything at rest (an unplugged device, a dropped batch)."""
        self._enable = False
        self._sticks = dict.fromkeys(self._sticks, 0.0)
        self._detents = 0
        self._pending.clear()
        self._pending_detents = 0

    def reading(self) -> PendantReading:
        """The state now, with the wheel's detents since the last reading."""
        detents, self._detents = self._detents, 0
        return PendantReading(
            enable=self._enable,
            axis=self._axis,
            multiplier=self._multiplier,
            increments=detents * self._multiplier,
            sticks=dict(self._sticks),
        )
