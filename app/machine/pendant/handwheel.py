"""The handwheel (manual pulse generator): its selector, multiplier and counter, turned into
where the selected axis goes.

Why absolute targets and not steps: 1000 counts at x1 must be 1.000 mm, exactly. Adding
0.001 a thousand times in floating point is not 1.0; so while the wheel owns the jog each
axis keeps where it started (``origin``) and a whole number of increments (0.001 mm or
0.001 deg) since, and its target is ``origin + increments / 1000``.

Why counts may be dropped: a fast spin must stop when the wheel stops. If the axis kept every
count it would run on long after the hand has let go (lag build-up, the classic complaint
about MPG jogging with a low jog speed). So the target never runs further ahead of the axis
than it can stop from its jog velocity on its jog ramp plus two periods' travel; counts
beyond that are dropped, and the axis stops within its ramp once the wheel stops.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.drivers.contracts import InputImage
from app.machine.axes import AxisGroup
from app.machine.manual import ManualControl
from app.machine.pendant.counter import CounterUnwrap, max_step_per_read
from app.machine.refusals import Refusal
from app.pendant_settings import HandwheelSettings

INCREMENTS_PER_UNIT = 1000  # the x1 increment is 0.001 mm (X, Y) or 0.001 deg (Z)
MULTIPLIERS = (1, 10, 100)


@dataclass(frozen=True)
class WheelSelection:
    axis: str  # "" when the selector is off
    multiplier: int


def wheel_selection(inputs: InputImage) -> WheelSelection:
    """What the selector and the multiplier switch say. Two axes at once (a broken selector)
    select none; x10 and x100 at once give x1: a fault never chooses the larger motion."""
    chosen = [
        axis
        for axis, on in (
            ("X", inputs.handwheel_x),
            ("Y", inputs.handwheel_y),
            ("Z", inputs.handwheel_z),
        )
        if on
    ]
    axis = chosen[0] if len(chosen) == 1 else ""
    if inputs.handwheel_x10 and inputs.handwheel_x100:
        multiplier = 1
    else:
        multiplier = 100 if inputs.handwheel_x100 else 10 if inputs.handwheel_x10 else 1
    return WheelSelection(axis, multiplier)


@dataclass(frozen=True)
class WheelTurn:
    """One read of the wheel: the increments turned (multiplier applied), and the counts of
    a jump larger than a hand can turn (0 when none)."""

    selection: WheelSelection
    increments: int
    jump_counts: int = 0


class Handwheel:
    """The wheel's counter and switches, read once per period."""

    def __init__(self, settings: HandwheelSettings, period_s: float) -> None:
        self.unwrap = CounterUnwrap(max_step_per_read(settings.max_counts_per_s, period_s))
        self._per_increment = settings.counts_per_increment
        self._residue = 0

    def forget(self) -> None:
        """A reconnect, a fault, a Reset: the next count is a first read again."""
        self.unwrap.forget()
        self._residue = 0

    def read(self, inputs: InputImage) -> WheelTurn:
        selection = wheel_selection(inputs)
        result = self.unwrap.read(inputs.handwheel_count)
        if result.jumped:
            self._residue = 0
            return WheelTurn(selection, 0, result.jump_counts)
        counts = self._residue + result.counts
        increments = abs(counts) // self._per_increment * (1 if counts >= 0 else -1)
        self._residue = counts - increments * self._per_increment
        return WheelTurn(selection, increments * selection.multiplier)


@dataclass
class WheelFollower:
    """Where the wheel has each axis go while it owns the jog (see the module's docstring)."""

    period_s: float
    origin: dict[str, float] = field(default_factory=dict)
    increments: dict[str, int] = field(default_factory=dict)

    def reset(self) -> None:
        """The wheel gave up the jog: the next turn starts from where the axes stand."""
        self.origin.clear()
        self.increments.clear()

    def target(self, axis: str) -> float:
        return self.origin[axis] + self.increments[axis] / INCREMENTS_PER_UNIT

    def turn(
        self, axis: str, increments: int, manual: ManualControl, axes: AxisGroup
    ) -> Refusal | None:
        if axis not in self.origin:
            self.origin[axis] = manual.jog_target(axis)
            self.increments[axis] = 0
        origin = self.origin[axis]
        wanted = self.increments[axis] + increments
        velocity = manual.speed("Z" if axis == "Z" else "XY")[0]
        lead = manual.stopping_distance(axis) + 2.0 * self.period_s * velocity
        now = manual.position(axis)
        target = origin + wanted / INCREMENTS_PER_UNIT
        if target > now + lead:
            wanted = int((now + lead - origin) * INCREMENTS_PER_UNIT)  # toward the origin
        elif target < now - lead:
            wanted = -int((origin - now + lead) * INCREMENTS_PER_UNIT)
        taken, reason = manual.follow(axis, origin + wanted / INCREMENTS_PER_UNIT, axes)
        self.increments[axis] = round((taken - origin) * INCREMENTS_PER_UNIT)
        return reason
