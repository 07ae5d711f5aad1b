"""The handwheel's 16-bit position counter, unwrapped into counts moved since the last read.

Why a pure module: the counter in the coupler or I/O node counts encoder edges into 16 bits
and wraps (65535 -> 0 turning up, 0 -> 65535 turning down). The software sees one value per
read and must tell "turned a little across the wrap" from "turned a lot": a wrong guess is
an axis moving 65 mm the other way. The rule is modular arithmetic: the step between two
reads is the difference modulo 2^16 taken in -32768..32767, which is right as long as the
wheel can never turn half the counter's range between two reads. The configuration says how
far a hand can spin the wheel between two reads (``max_step_counts``); a larger step is not
a turn but a fault (a counter reset, a swapped register, a coupler replaced under power):
the machine raises an alarm and moves nothing.

What never moves: the first read (the counter's value is wherever it stood; only changes
count), a read after a reconnect or a fault (``forget``), and a missing value (an unwired
counter reads ``None``).
"""

from __future__ import annotations

from dataclasses import dataclass

COUNTER_BITS = 16
COUNTER_MODULUS = 1 << COUNTER_BITS
HALF_RANGE = COUNTER_MODULUS // 2
MAX_STEP_LIMIT = HALF_RANGE - 1
"""The largest step per read the unwrap can tell apart from a turn the other way."""


def wrapped_step(previous: int, current: int) -> int:
    """The signed step from ``previous`` to ``current`` on a 16-bit counter, in
    -32768..32767 (the shorter way round)."""
    step = (current - previous) % COUNTER_MODULUS
    return step - COUNTER_MODULUS if step >= HALF_RANGE else step


@dataclass(frozen=True)
class CounterRead:
    """One read's outcome: the counts moved (0 when nothing may move) and, for a jump larger
    than the wheel can turn, the step seen (``jump_counts``, else 0)."""

    counts: int
    jump_counts: int = 0

    @property
    def jumped(self) -> bool:
        return self.jump_counts != 0


class CounterUnwrap:
    """Turns successive raw 16-bit counter values into counts moved, read by read."""

    def __init__(self, max_step_counts: int) -> None:
        if (
            isinstance(max_step_counts, bool)
            or not isinstance(max_step_counts, int)
            or not 1 <= max_step_counts <= MAX_STEP_LIMIT
        ):
            raise ValueError(
                f"max_step_counts = {max_step_counts!r} is not allowed: "
                f"a whole number from 1 to {MAX_STEP_LIMIT}"
            )
        self.max_step_counts = max_step_counts
        self._previous: int | None = None
        self.total_counts = 0  # every count moved since construction (for the display, tests)

    def forget(self) -> None:
        """The next value is a first read again (after a reconnect, a fault, a Reset)."""
        self._previous = None

    def read(self, raw: int | None) -> CounterRead:
        if raw is None:
            self._previous = None
            return CounterRead(0)
        if not 0 <= raw < COUNTER_MODULUS:
            raise ValueError(
                f"counter value = {raw!r} is not allowed: a whole number from 0 to "
                f"{COUNTER_MODULUS - 1}"
            )
        previous, self._previous = self._previous, raw
        if previous is None:
            return CounterRead(0)
        step = wrapped_step(previous, raw)
        if abs(step) > self.max_step_counts:
            self._previous = None  # what comes after a jump is a first read again
            return CounterRead(0, step)
        self.total_counts += step
        return CounterRead(step)


def max_step_per_read(max_counts_per_s: float, period_s: float) -> int:
    """The largest step one read may show: the fastest spin over one period, rounded up, and
    one read's worth more (a read the bus skipped shows two periods' turn)."""
    return min(MAX_STEP_LIMIT, max(1, int(-(-max_counts_per_s * period_s // 1))) * 2)
