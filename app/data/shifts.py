"""Production days and shifts as time windows.

A shift is a window of wall-clock time on the machine's site: the first shift of a day starts
``first_start_h`` hours after midnight, the next ones follow every ``length_h`` hours. A shift
belongs to the day it starts on, even if it ends after midnight (a night shift 22:00-06:00 is
the last shift of the day it began). Windows are half-open, [start, end), so a piece finished
exactly at a change of shift counts in the new one.

Times are computed on the wall clock and then placed in the time zone (the machine's local zone
unless one is given), so "the 06:00 shift" starts at 06:00 on both sides of a daylight-saving
change.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from datetime import date, datetime, time, timedelta, tzinfo


@dataclass(frozen=True)
class ShiftPlan:
    """How a day is divided into shifts (see the ``production`` parameters)."""

    first_start_h: float = 6.0
    length_h: float = 8.0
    count: int = 3

    def __post_init__(self) -> None:
        if not 0 <= self.first_start_h < 24:
            raise ValueError(
                f"first_start_h = {self.first_start_h} is out of range: allowed 0 <= h < 24"
            )
        if not 0 < self.length_h <= 24:
            raise ValueError(f"length_h = {self.length_h} is out of range: allowed 0 < h <= 24")
        if isinstance(self.count, bool) or not isinstance(self.count, int) or self.count < 1:
            raise ValueError(f"count = {self.count!r} is out of range: allowed an integer >= 1")
        if self.length_h * self.count > 24:
            raise ValueError(
                f"count * length_h = {self.count} * {self.length_h} h is more than a day"
            )

    @classmethod
    def from_parameters(cls, parameters: Mapping[str, float]) -> ShiftPlan:
        """The plan from the system parameters (``shift_first_start_h`` and friends)."""
        return cls(
            first_start_h=float(parameters["shift_first_start_h"]),
            length_h=float(parameters["shift_length_h"]),
            count=int(parameters["shifts_per_day"]),
        )


def _place(wall: datetime, tz: tzinfo | None) -> datetime:
    """Attach the zone to a naive wall-clock time (the local zone if ``tz`` is None)."""
    return wall.astimezone() if tz is None else wall.replace(tzinfo=tz)


def day_window(day: date, tz: tzinfo | None = None) -> tuple[datetime, datetime]:
    """[midnight, next midnight) of ``day`` in ``tz`` (local time if None)."""
    midnight = datetime.combine(day, time(0))
    return _place(midnight, tz), _place(midnight + timedelta(days=1), tz)


def shift_window(
    day: date, shift_number: int, plan: ShiftPlan, tz: tzinfo | None = None
) -> tuple[datetime, datetime]:
    """[start, end) of shift ``shift_number`` (1 = the first of the day) that starts on ``day``."""
    if isinstance(shift_number, bool) or not 1 <= shift_number <= plan.count:
        raise ValueError(
            f"shift = {shift_number!r} is out of range: allowed 1 to {plan.count} (shifts_per_day)"
        )
    start = datetime.combine(day, time(0)) + timedelta(
        hours=plan.first_start_h + (shift_number - 1) * plan.length_h
    )
    return _place(start, tz), _place(start + timedelta(hours=plan.length_h), tz)


def current_shift(now: datetime, plan: ShiftPlan, tz: tzinfo | None = None) -> tuple[int, datetime]:
    """The shift running at ``now`` (number, start), or the last one started if none runs.

    The machine layer passes the start to ``Database.piece_counts`` for the shift's count.
    """
    local_now = now.astimezone(tz)
    latest: tuple[int, datetime] | None = None
    for days_back in (1, 0):
        day = local_now.date() - timedelta(days=days_back)
        for number in range(1, plan.count + 1):
            start, _ = shift_window(day, number, plan, tz)
            if start <= local_now and (latest is None or start > latest[1]):
                latest = (number, start)
    if latest is None:  # pragma: no cover - the day before always has a started shift
        raise AssertionError("no shift started in the last two days")
    return latest
