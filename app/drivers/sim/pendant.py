"""The simulated machine's handwheel and joystick, as their terminals read.

Why physical and not a value set from outside: the machine layer must see what a real
coupler gives it, a 16-bit counter that wraps and moves a few counts per read, and analog
values around a centre that is never exactly mid-scale. So a turn is spread over time at a
rate a hand can spin (``turn``), the counter wraps at 2^16, and the stick's centre reads a
little off mid-scale, which the machine's start-up calibration takes out.
"""

from __future__ import annotations

from dataclasses import dataclass

COUNTER_MODULUS = 1 << 16
DEFAULT_TURN_RATE_COUNTS_S = 400.0  # a steady hand: four turns of a 100-line wheel a second
CENTRE_OFFSET_COUNTS = 120  # the stick at rest reads this far from mid-scale


@dataclass(frozen=True)
class HandwheelInputs:
    """What the handwheel's terminals read: the selector, the multiplier, the enable button
    and the raw counter."""

    axis: str  # "" (off), "X", "Y" or "Z"
    multiplier: int  # 1, 10 or 100
    enable: bool
    count: int


class SimHandwheel:
    """The handwheel: selector, multiplier, enable and an encoder counted into 16 bits."""

    AXES = ("", "X", "Y", "Z")
    MULTIPLIERS = (1, 10, 100)

    def __init__(self, start_count: int = 65_000) -> None:
        self.axis = ""
        self.multiplier = 1
        self.enable = False
        self._count = start_count % COUNTER_MODULUS  # near the wrap: it is crossed soon
        self._to_turn = 0.0  # counts still to be turned by the hand
        self._rate_counts_s = DEFAULT_TURN_RATE_COUNTS_S
        self._fraction = 0.0

    def select(self, axis: str, multiplier: int) -> None:
        if axis not in self.AXES:
            raise ValueError(f"handwheel axis = {axis!r} is not allowed: '', 'X', 'Y' or 'Z'")
        if multiplier not in self.MULTIPLIERS:
            raise ValueError(f"handwheel multiplier = {multiplier!r} is not allowed: 1, 10 or 100")
        self.axis = axis
        self.multiplier = multiplier

    def turn(self, counts: int, rate_counts_s: float = DEFAULT_TURN_RATE_COUNTS_S) -> None:
        """Turn the wheel by ``counts`` (negative: the other way) at ``rate_counts_s``."""
        if not rate_counts_s > 0.0:
            raise ValueError(f"rate_counts_s = {rate_counts_s!r} is not allowed: above 0")
        self._to_turn += counts
        self._rate_counts_s = rate_counts_s

    def jump(self, counts: int) -> None:
        """The counter jumps at once (a counter reset, a replaced coupler): fault injection."""
        self._count = (self._count + counts) % COUNTER_MODULUS

    @property
    def turning(self) -> bool:
        return abs(self._to_turn) >= 1.0

    def step(self, dt_s: float) -> None:
        if self._to_turn == 0.0:
            return
        amount = min(abs(self._to_turn), self._rate_counts_s * dt_s + self._fraction)
        whole = int(amount)
        self._fraction = amount - whole if abs(self._to_turn) > whole else 0.0
        direction = 1 if self._to_turn > 0 else -1
        self._to_turn -= direction * whole
        if abs(self._to_turn) < 1.0:
            self._to_turn = 0.0
            self._fraction = 0.0
        self._count = (self._count + direction * whole) % COUNTER_MODULUS

    def inputs(self) -> HandwheelInputs:
        return HandwheelInputs(self.axis, self.multiplier, self.enable, self._count)


class SimJoystick:
    """Two (or three) analog inputs around a centre, scaled in counts."""

    def __init__(self, mid_scale_counts: int, full_scale_counts: int) -> None:
        self.mid_scale_counts = mid_scale_counts
        self.full_scale_counts = full_scale_counts
        self.deflection = {"X": 0.0, "Y": 0.0, "Z": 0.0}

    def push(self, x: float = 0.0, y: float = 0.0, z: float = 0.0) -> None:
        """Hold the stick at these fractions of full deflection (-1..1); 0 lets it go."""
        for name, value in (("X", x), ("Y", y), ("Z", z)):
            if not -1.0 <= value <= 1.0:
                raise ValueError(f"joystick {name} = {value!r} is not allowed: -1 to 1")
            self.deflection[name] = value

    def counts(self, axis: str) -> int:
        centre = self.mid_scale_counts + CENTRE_OFFSET_COUNTS
        return round(centre + self.deflection[axis] * self.full_scale_counts)
