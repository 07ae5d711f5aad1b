"""A range of production in figures, for the Production screen: SQL aggregates, not records.

Why aggregates in SQL: a panel keeps years of records (some 150 boards an hour, around the
clock, is over a million a year); the screen shows a shift or a month, so the database counts
and bins with its time index and hands back at most a few hundred rows (hours, width bins,
alarm codes). Only the cycle times are per piece, and of the newest ``MAX_CYCLE_POINTS``.

Hours are the hours of the stored UTC time stamps (the time zones a panel runs in are whole
hours from UTC, so an hour of UTC is an hour on the wall clock).

A piece's cycle time is drawn without its wait for the board (``waiting`` in its step times),
as the main screen shows it: how long the machine worked on the board, not how long the
operator took to bring it. The bound it is drawn against is the part of its own recorded
step times the machine cannot shorten: the centering and clamping strokes, the gauge's
reading, both sides and the repositioning between them (the cuts run at the jerk-limited
optimum, see ``app/machine/cycle_floor.py``). With the strokes at their nominal times it
lies below the machine's floor (the approach and what is left of the unclamping stroke are
not in it); it needs no plan, because the records keep the step times, not the plan a floor
is computed from. Records from before the step times were kept have no bound.
"""

from __future__ import annotations

import enum
import sqlite3
from collections.abc import Mapping
from dataclasses import dataclass
from datetime import UTC, datetime, timedelta, tzinfo

from app.data.database import Database
from app.data.records import PieceResult, format_utc, parse_utc
from app.data.shifts import ShiftPlan, current_shift, day_window

MAX_CYCLE_POINTS = 2000
"""Cycle times drawn per piece: the newest of the range (a shift has about 1,200 boards)."""
BOUND_STEPS = ("centering", "clamping", "measuring", "side_a", "repositioning", "side_b")
"""The recorded steps the bound is the sum of (keys of ``step_times_json``)."""
WIDTH_BIN_CHOICES_MM = (1.0, 2.0, 5.0, 10.0, 20.0, 50.0)
MAX_WIDTH_BINS = 30
"""The finest bin of ``WIDTH_BIN_CHOICES_MM`` that gives at most this many bins is used."""


class StatsRange(enum.Enum):
    """The ranges the screen offers."""

    THIS_SHIFT = "this_shift"
    LAST_SHIFT = "last_shift"
    TODAY = "today"
    LAST_7_DAYS = "last_7_days"
    LAST_30_DAYS = "last_30_days"


def range_window(
    choice: StatsRange, now: datetime, plan: ShiftPlan, tz: tzinfo | None = None
) -> tuple[datetime, datetime]:
    """[start, end) of ``choice`` at ``now`` on the site's wall clock (local time if ``tz`` is
    None): whole shifts and whole days, so a range always means the same hours."""
    if choice in (StatsRange.THIS_SHIFT, StatsRange.LAST_SHIFT):
        _number, start = current_shift(now, plan, tz)
        if choice is StatsRange.LAST_SHIFT:
            _number, start = current_shift(start - timedelta(microseconds=1), plan, tz)
        return start, start + timedelta(hours=plan.length_h)
    today = now.astimezone(tz).date()
    days = {StatsRange.TODAY: 1, StatsRange.LAST_7_DAYS: 7, StatsRange.LAST_30_DAYS: 30}[choice]
    start, _ = day_window(today - timedelta(days=days - 1), tz)
    _, end = day_window(today, tz)
    return start, end


@dataclass(frozen=True)
class HourCount:
    hour: datetime  # the start of the hour, UTC
    count: int


@dataclass(frozen=True)
class WidthBin:
    low_mm: float  # the bin is [low_mm, low_mm + ProductionStats.width_bin_mm)
    count: int


@dataclass(frozen=True)
class CyclePoint:
    time: datetime  # UTC, the end of the cycle
    cycle_s: float
    bound_s: float | None  # None: the record has no step times


@dataclass(frozen=True)
class ProductionStats:
    """What the Production screen shows of [start, end)."""

    start: datetime
    end: datetime
    counts: Mapping[str, int]  # result value -> boards, every result present
    pieces_per_hour: tuple[HourCount, ...]  # finished staves; hours without any left out
    alarms_per_hour: tuple[HourCount, ...]  # alarms raised; hours without any left out
    alarm_codes: tuple[tuple[str, int], ...]  # code -> times raised, the most frequent first
    width_bin_mm: float
    widths: tuple[WidthBin, ...]  # measured boards (any result), bins without any left out
    cycles: tuple[CyclePoint, ...]  # finished staves, oldest first, the newest MAX_CYCLE_POINTS


def _hour(text: str) -> datetime:
    return datetime.strptime(text, "%Y-%m-%dT%H").replace(tzinfo=UTC)


# A piece's cycle time without its wait for the board (the operator's pace, not the
# machine's), as the main screen counts it; records without step times keep the whole time.
_WORK_SQL = "cycle_time_s - coalesce(json_extract(step_times_json, '$.waiting'), 0)"


def _bound_sql() -> str:
    terms = " + ".join(f"coalesce(json_extract(step_times_json, '$.{s}'), 0)" for s in BOUND_STEPS)
    return f"CASE WHEN step_times_json IS NULL THEN NULL ELSE {terms} END"


def width_bin_mm(low_mm: float, high_mm: float) -> float:
    """The bin width for measured widths from ``low_mm`` to ``high_mm``."""
    for size in WIDTH_BIN_CHOICES_MM:
        if (high_mm - low_mm) / size < MAX_WIDTH_BINS:
            return size
    return WIDTH_BIN_CHOICES_MM[-1]


def production_stats(db: Database, start: datetime, end: datetime) -> ProductionStats:
    """The figures of [start, end) in one read transaction (a consistent picture while the
    machine writes). ValueError when the range is empty."""
    if end <= start:
        raise ValueError(f"end = {end.isoformat()} is not after start = {start.isoformat()}")
    conn = db._conn
    window = (format_utc(start), format_utc(end))
    in_range = "time >= ? AND time < ?"
    conn.execute("BEGIN")
    try:
        counts = {result.value: 0 for result in PieceResult}
        for row in conn.execute(
            f"SELECT result, count(*) FROM production WHERE {in_range} GROUP BY result", window
        ):
            counts[str(row[0])] = int(row[1])
        pieces = _per_hour(
            conn,
            f"SELECT substr(time, 1, 13) AS h, count(*) FROM production "
            f"WHERE result = 'ok' AND {in_range} GROUP BY h ORDER BY h",
            window,
        )
        raised = f"FROM alarm_events WHERE from_state = 'normal' AND {in_range}"
        alarms = _per_hour(
            conn,
            f"SELECT substr(time, 1, 13) AS h, count(*) {raised} GROUP BY h ORDER BY h",
            window,
        )
        codes = tuple(
            (str(row[0]), int(row[1]))
            for row in conn.execute(
                f"SELECT code, count(*) AS n {raised} GROUP BY code ORDER BY n DESC, code", window
            )
        )
        bin_mm, widths = _widths(conn, in_range, window)
        cycles = tuple(
            CyclePoint(parse_utc(row[0]), float(row[1]), None if row[2] is None else float(row[2]))
            for row in reversed(
                conn.execute(
                    f"SELECT time, {_WORK_SQL}, {_bound_sql()} FROM production "
                    f"WHERE result = 'ok' AND {in_range} ORDER BY time DESC, id DESC LIMIT ?",
                    (*window, MAX_CYCLE_POINTS),
                ).fetchall()
            )
        )
    finally:
        conn.execute("COMMIT")
    return ProductionStats(start, end, counts, pieces, alarms, codes, bin_mm, widths, cycles)


def _per_hour(conn: sqlite3.Connection, sql: str, window: tuple[str, str]) -> tuple[HourCount, ...]:
    return tuple(HourCount(_hour(str(row[0])), int(row[1])) for row in conn.execute(sql, window))


def _widths(
    conn: sqlite3.Connection, in_range: str, window: tuple[str, str]
) -> tuple[float, tuple[WidthBin, ...]]:
    measured = f"FROM production WHERE width_mm IS NOT NULL AND {in_range}"
    low, high = conn.execute(f"SELECT min(width_mm), max(width_mm) {measured}", window).fetchone()
    if low is None:
        return WIDTH_BIN_CHOICES_MM[0], ()
    size = width_bin_mm(float(low), float(high))
    # floor(width / size) without SQLite's optional math functions (widths may be negative
    # in principle: the cast truncates towards zero, the comparison corrects it).
    ratio = "(width_mm / ?)"
    bin_sql = f"(CAST({ratio} AS INTEGER) - ({ratio} < CAST({ratio} AS INTEGER)))"
    rows = conn.execute(
        f"SELECT {bin_sql} AS b, count(*) {measured} GROUP BY b ORDER BY b",
        (size, size, size, *window),
    )
    return size, tuple(WidthBin(int(row[0]) * size, int(row[1])) for row in rows)
