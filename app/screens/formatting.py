"""How numbers, durations and times appear on the panel (pure functions, no Qt).

Why one place: a position shown with two decimals on one screen and three on another makes an
operator wonder which one is right; every screen formats through these.
"""

from __future__ import annotations

import math
from datetime import datetime, time, timedelta


def format_number(value: float, decimals: int = 3) -> str:
    """``value`` with at most ``decimals`` decimals and no trailing zeros ("12.5", "1000")."""
    if not math.isfinite(value):
        return "—"
    text = f"{value:.{decimals}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    if text in ("-0", ""):
        text = "0"
    return text


def format_position(value: float, decimals: int = 2) -> str:
    """An axis position with a fixed number of decimals, so the digits do not jump."""
    if not math.isfinite(value):
        return "—"
    text = f"{value:.{decimals}f}"
    return "0." + "0" * decimals if text == "-0." + "0" * decimals else text


def format_duration(seconds: float | None) -> str:
    """m:ss below an hour, h:mm:ss above; "—" when unknown."""
    if seconds is None or not math.isfinite(seconds) or seconds < 0:
        return "—"
    total = round(seconds)
    hours, rest = divmod(total, 3600)
    minutes, secs = divmod(rest, 60)
    if hours:
        return f"{hours}:{minutes:02d}:{secs:02d}"
    return f"{minutes}:{secs:02d}"


def format_optional(value: float | None, decimals: int = 1, unit: str = "") -> str:
    """A measured value that may be missing."""
    if value is None or not math.isfinite(value):
        return "—"
    suffix = f" {unit}" if unit else ""
    return f"{value:.{decimals}f}{suffix}"


def format_clock(moment: datetime) -> str:
    """A local date and time as the histories show it."""
    return moment.astimezone().strftime("%Y-%m-%d %H:%M:%S")


def format_table_time(moment: datetime) -> str:
    """A local time in a history table: day, month and time (the year is rarely needed)."""
    return moment.astimezone().strftime("%d.%m. %H:%M:%S")


def format_time_range(start: datetime, end: datetime) -> str:
    """A half-open range of local time, [start, end): whole days as dates only ("03.04. –
    02.05."), otherwise times, with the end's date only when it differs (a night shift)."""
    local_start, local_end = start.astimezone(), end.astimezone()
    if local_start.time() == local_end.time() == time(0):
        last_day = local_end.date() - timedelta(days=1)
        first = local_start.strftime("%d.%m.")
        return first if last_day == local_start.date() else f"{first} – {last_day:%d.%m.}"
    first = local_start.strftime("%d.%m. %H:%M")
    if local_end.date() == local_start.date():
        return f"{first} – {local_end:%H:%M}"
    return f"{first} – {local_end:%d.%m. %H:%M}"
