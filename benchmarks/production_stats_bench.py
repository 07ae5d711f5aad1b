"""How long the Production screen's figures take on a year of records.

    .venv/bin/python benchmarks/production_stats_bench.py            # a year at 150 boards/h
    .venv/bin/python benchmarks/production_stats_bench.py --boards-per-hour 60

A new database is filled with a year of production around the clock (every 20th board
rejected, every 100th aborted, an alarm raised for each of them, the step times of a real
cycle in every record) and the figures of each range the screen offers are read, the newest
range first as the screen would, three times each; the best time is printed. The screen reads
them on a worker thread, so these times are how long the charts wait, never how long the
panel stands still. Nothing here is asserted.
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from datetime import UTC, datetime, timedelta
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from app.data.database import Database  # noqa: E402
from app.data.production_stats import StatsRange, production_stats, range_window  # noqa: E402
from app.data.records import format_utc  # noqa: E402
from app.data.shifts import ShiftPlan  # noqa: E402

STEPS = {
    "waiting": 0.4,
    "centering": 0.8,
    "clamping": 0.6,
    "measuring": 0.3,
    "spindle": 0.5,
    "approach": 1.14,
    "side_a": 9.12,
    "repositioning": 1.92,
    "side_b": 9.12,
    "unclamping": 0.34,
}
BATCH = 50_000


def fill(db: Database, now: datetime, boards_per_hour: float) -> int:
    """A year of records up to ``now``; returns how many."""
    step_s = 3600.0 / boards_per_hour
    count = int(365 * 24 * boards_per_hour)
    steps_json = json.dumps(STEPS)
    rows: list[tuple[object, ...]] = []
    alarms: list[tuple[object, ...]] = []
    with db._write() as conn:
        for i in range(count):
            moment = format_utc(now - timedelta(seconds=i * step_s))
            result = "rejected" if i % 20 == 0 else "aborted" if i % 100 == 1 else "ok"
            rows.append((moment, 100.0 + (i * 7) % 120, sum(STEPS.values()), result, steps_json))
            if result != "ok":
                code = "E032" if result == "rejected" else "E040"
                alarms.append((moment, code))
            if len(rows) == BATCH or i == count - 1:
                conn.executemany(
                    "INSERT INTO production (time, recipe_name, width_mm, cycle_time_s, "
                    "result, step_times_json) VALUES (?, 'Barrique', ?, ?, ?, ?)",
                    rows,
                )
                conn.executemany(
                    "INSERT INTO alarm_events (time, code, text, source, from_state, to_state) "
                    "VALUES (?, ?, 'text', 'machine', 'normal', 'active_unacked')",
                    alarms,
                )
                rows, alarms = [], []
    return count


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--boards-per-hour", type=float, default=150.0)
    args = parser.parse_args()
    now = datetime.now(UTC)
    with tempfile.TemporaryDirectory() as tmp:
        db = Database.open(Path(tmp) / "year.db", load_samples=False)
        try:
            started = time.perf_counter()
            count = fill(db, now, args.boards_per_hour)
            print(f"{count:,} records written in {time.perf_counter() - started:.1f} s")
            plan = ShiftPlan.from_parameters(db.get_parameters())
            for choice in StatsRange:
                start, end = range_window(choice, now, plan)
                best_s = float("inf")
                for _ in range(3):
                    t0 = time.perf_counter()
                    stats = production_stats(db, start, end)
                    best_s = min(best_s, time.perf_counter() - t0)
                boards = sum(stats.counts.values())
                print(
                    f"{choice.value:13s} {boards:7,d} boards, {len(stats.cycles):5d} cycle "
                    f"points, {len(stats.widths):3d} width bins: {best_s * 1000:7.1f} ms"
                )
        finally:
            db.close()


if __name__ == "__main__":
    main()
