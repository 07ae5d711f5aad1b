"""The Production screen's figures from a real SQLite file with known records: exact counts,
hours, bins and bounds; the ranges on the wall clock; the export of a range read back."""

from __future__ import annotations

import csv
import io
from datetime import UTC, datetime, timedelta, timezone
from pathlib import Path

import pytest

from app.data.csv_cells import from_csv_text
from app.data.database import Database
from app.data.exchange import export_production_csv
from app.data.production_stats import (
    MAX_CYCLE_POINTS,
    HourCount,
    StatsRange,
    WidthBin,
    production_stats,
    range_window,
    width_bin_mm,
)
from app.data.records import AlarmEvent, AlarmState, PieceResult, ProductionRecord
from app.data.shifts import ShiftPlan

T0 = datetime(2024, 5, 2, 6, 0, tzinfo=UTC)
STEPS = {
    "waiting": 3.0,
    "centering": 0.8,
    "clamping": 0.6,
    "measuring": 0.3,
    "approach": 1.1,
    "side_a": 9.0,
    "repositioning": 1.9,
    "side_b": 9.0,
    "unclamping": 0.3,
}
BOUND_S = 0.8 + 0.6 + 0.3 + 9.0 + 1.9 + 9.0


def piece(
    minutes: float,
    result: PieceResult = PieceResult.OK,
    width_mm: float | None = 140.0,
    *,
    steps: dict[str, float] | None = None,
    name: str = "Barrique",
    alarm: str | None = None,
) -> ProductionRecord:
    return ProductionRecord(
        time=T0 + timedelta(minutes=minutes),
        recipe_id=None,
        recipe_name=name,
        width_mm=width_mm,
        d_mm=None,
        r_mm=None,
        cycle_time_s=sum((steps or STEPS).values()) if steps != {} else 30.0,
        result=result,
        alarm_code=alarm,
        step_times_s=STEPS if steps is None else steps,
    )


def alarm(
    minutes: float, code: str, to_state: AlarmState = AlarmState.ACTIVE_UNACKED
) -> AlarmEvent:
    from_state = (
        AlarmState.NORMAL if to_state is AlarmState.ACTIVE_UNACKED else AlarmState.ACTIVE_UNACKED
    )
    return AlarmEvent(T0 + timedelta(minutes=minutes), code, "text", "X", from_state, to_state)


@pytest.fixture
def filled(db: Database) -> Database:
    # 06:xx: three staves (widths 139.9, 140.0, 143.2), one rejected (no width)
    for minutes, width in ((1, 139.9), (20, 140.0), (59.99, 143.2)):
        db.record_piece(piece(minutes, width_mm=width))
    db.record_piece(piece(30, PieceResult.REJECTED, None, steps={}, alarm="E032"))
    # 07:xx: one stave of a record without step times, one aborted at 151.0
    db.record_piece(piece(75, width_mm=150.4, steps={}))
    db.record_piece(piece(80, PieceResult.ABORTED, 151.0, steps={}, alarm="E040"))
    # 09:xx: one stave; and one just outside the range (10:00 is the end)
    db.record_piece(piece(185, width_mm=141.0))
    db.record_piece(piece(240, width_mm=300.0))
    # alarms: raised twice E032 (06:xx, 07:xx), once E040 (07:xx); transitions that are not
    # a raising are not counted, nor one outside the range
    db.record_alarm_event(alarm(30, "E032"))
    db.record_alarm_event(alarm(31, "E032", AlarmState.ACTIVE_ACKED))
    db.record_alarm_event(alarm(70, "E032"))
    db.record_alarm_event(alarm(80, "E040"))
    db.record_alarm_event(alarm(250, "E040"))
    return db


def test_counts_hours_and_codes_of_a_range_are_exact(filled: Database) -> None:
    stats = production_stats(filled, T0, T0 + timedelta(hours=4))
    assert dict(stats.counts) == {"ok": 5, "rejected": 1, "aborted": 1}
    assert stats.pieces_per_hour == (
        HourCount(T0, 3),
        HourCount(T0 + timedelta(hours=1), 1),
        HourCount(T0 + timedelta(hours=3), 1),
    )
    assert stats.alarms_per_hour == (
        HourCount(T0, 1),
        HourCount(T0 + timedelta(hours=1), 2),
    )
    assert stats.alarm_codes == (("E032", 2), ("E040", 1))


def test_widths_are_binned_by_the_finest_bin_that_keeps_the_chart_readable(
    filled: Database,
) -> None:
    stats = production_stats(filled, T0, T0 + timedelta(hours=4))
    # 139.9 to 151.0: 11.1 mm, 1 mm bins; the rejected board has no width and is not counted
    assert stats.width_bin_mm == 1.0
    assert stats.widths == (
        WidthBin(139.0, 1),
        WidthBin(140.0, 1),
        WidthBin(141.0, 1),
        WidthBin(143.0, 1),
        WidthBin(150.0, 1),
        WidthBin(151.0, 1),
    )
    # with the 300 mm board: 160.1 mm, 10 mm bins
    wide = production_stats(filled, T0, T0 + timedelta(hours=5))
    assert wide.width_bin_mm == 10.0
    assert [(b.low_mm, b.count) for b in wide.widths] == [
        (130.0, 1),
        (140.0, 3),
        (150.0, 2),
        (300.0, 1),
    ]
    assert width_bin_mm(100.0, 129.0) == 1.0
    assert width_bin_mm(100.0, 130.0) == 2.0
    assert width_bin_mm(0.0, 10_000.0) == 50.0


def test_cycle_times_come_with_their_bound_from_the_recorded_steps(filled: Database) -> None:
    stats = production_stats(filled, T0, T0 + timedelta(hours=4))
    assert [p.time for p in stats.cycles] == [
        T0 + timedelta(minutes=m) for m in (1, 20, 59.99, 75, 185)
    ]
    worked_s = sum(STEPS.values()) - STEPS["waiting"]  # the wait for the board is not drawn
    assert [p.cycle_s for p in stats.cycles] == pytest.approx([worked_s] * 3 + [30.0, worked_s])
    bounds = [p.bound_s for p in stats.cycles]
    assert bounds[3] is None  # a record from before the step times were kept
    assert [b for b in bounds if b is not None] == pytest.approx([BOUND_S] * 4)


def test_only_the_newest_cycles_are_drawn(db: Database) -> None:
    with db._write() as conn:  # a long shift written at once (record_piece is one transaction each)
        conn.executemany(
            "INSERT INTO production (time, recipe_name, width_mm, cycle_time_s, result) "
            "VALUES (?, 'Barrique', 140.0, ?, 'ok')",
            [
                ((T0 + timedelta(seconds=i)).strftime("%Y-%m-%dT%H:%M:%S.%fZ"), float(i))
                for i in range(MAX_CYCLE_POINTS + 5)
            ],
        )
    stats = production_stats(db, T0, T0 + timedelta(hours=1))
    assert stats.counts["ok"] == MAX_CYCLE_POINTS + 5
    assert len(stats.cycles) == MAX_CYCLE_POINTS
    assert stats.cycles[0].cycle_s == 5.0 and stats.cycles[-1].cycle_s == MAX_CYCLE_POINTS + 4
    assert stats.pieces_per_hour == (HourCount(T0, MAX_CYCLE_POINTS + 5),)


def test_an_empty_range_gives_zeros_and_a_reversed_one_is_refused(db: Database) -> None:
    stats = production_stats(db, T0, T0 + timedelta(hours=1))
    assert dict(stats.counts) == {"ok": 0, "rejected": 0, "aborted": 0}
    assert stats.pieces_per_hour == stats.alarms_per_hour == stats.widths == stats.cycles == ()
    with pytest.raises(ValueError, match=r"end = .* is not after start"):
        production_stats(db, T0, T0)


CET = timezone(timedelta(hours=1))
PLAN = ShiftPlan(first_start_h=6.0, length_h=8.0, count=3)


@pytest.mark.parametrize(
    ("choice", "now", "start", "end"),
    [
        (StatsRange.THIS_SHIFT, (2024, 5, 2, 15, 30), (2024, 5, 2, 14), (2024, 5, 2, 22)),
        (StatsRange.LAST_SHIFT, (2024, 5, 2, 15, 30), (2024, 5, 2, 6), (2024, 5, 2, 14)),
        # the night shift began the day before
        (StatsRange.THIS_SHIFT, (2024, 5, 2, 3, 0), (2024, 5, 1, 22), (2024, 5, 2, 6)),
        (StatsRange.LAST_SHIFT, (2024, 5, 2, 6, 0), (2024, 5, 1, 22), (2024, 5, 2, 6)),
        (StatsRange.TODAY, (2024, 5, 2, 3, 0), (2024, 5, 2, 0), (2024, 5, 3, 0)),
        (StatsRange.LAST_7_DAYS, (2024, 5, 2, 3, 0), (2024, 4, 26, 0), (2024, 5, 3, 0)),
        (StatsRange.LAST_30_DAYS, (2024, 5, 2, 3, 0), (2024, 4, 3, 0), (2024, 5, 3, 0)),
    ],
)
def test_ranges_are_whole_shifts_and_days_on_the_wall_clock(
    choice: StatsRange,
    now: tuple[int, ...],
    start: tuple[int, ...],
    end: tuple[int, ...],
) -> None:
    window = range_window(choice, datetime(*now, tzinfo=CET), PLAN, CET)
    assert window == (datetime(*start, tzinfo=CET), datetime(*end, tzinfo=CET))


def test_the_export_of_a_range_reads_back_as_its_records(filled: Database, tmp_path: Path) -> None:
    filled.record_piece(piece(90, name="=HYPERLINK(1)"))
    start, end = T0, T0 + timedelta(hours=4)
    path = tmp_path / "stick" / "production.csv"
    assert export_production_csv(filled, path, start, end, UTC) == 8
    rows = list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"), newline="")))
    stored = filled.list_production(start, end)
    assert [int(r["id"]) for r in rows] == [r.id for r in stored]
    assert [from_csv_text(r["recipe_name"]) for r in rows] == [r.recipe_name for r in stored]
    assert [r["recipe_name"] for r in rows if r["recipe_name"].startswith("'")] == [
        "'=HYPERLINK(1)"
    ]
    assert [r["result"] for r in rows] == [r.result.value for r in stored]
    assert [float(r["width_mm"]) if r["width_mm"] else None for r in rows] == [
        r.width_mm for r in stored
    ]
    assert [r["alarm_code"] for r in rows] == [r.alarm_code or "" for r in stored]
    counts = production_stats(filled, start, end).counts
    assert sum(counts.values()) == len(rows)
    assert path.stat().st_mode & 0o077 == 0  # the safe writer's private file
