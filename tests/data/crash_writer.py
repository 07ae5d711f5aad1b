"""The writer process of the crash test: writes to the database in a loop and reports every
commit on stdout (flushed, after the call returned), until it is killed.

    python -m tests.data.crash_writer DB_PATH [DIE_AFTER]

With DIE_AFTER the writer kills itself with SIGKILL from inside SQLite, at its DIE_AFTER-th
progress callback (one every 50 virtual-machine instructions of any statement): the kill then
lands at a chosen point inside a statement or a transaction, creation of the database
included, which a kill from outside hits only by luck. The SQLite library is the real one; the
progress handler only picks the moment.

Lines: ``OPENING`` before Database.open, ``OPEN`` after it; then per commit one of
``R <id> <name>`` (a recipe), ``B <tag> <id> <id> <id>`` (a batch of three recipes in one
transaction), ``P <id> <width_mm>`` (a piece), ``S <value>`` (xy_speed_mm_s set),
``A <id>`` (an alarm event).
"""

from __future__ import annotations

import os
import signal
import sqlite3
import sys
from collections.abc import Callable
from dataclasses import replace
from datetime import UTC, datetime
from pathlib import Path

from app.data.database import Database
from app.data.recipe import BarrelType, Recipe
from app.data.records import AlarmEvent, AlarmState, PieceResult, ProductionRecord
from app.data.users import Role
from app.geometry.ratio import Ratio

BASE = Recipe(
    id=None,
    name="base",
    length_mm=1000.0,
    thickness_mm=30.0,
    length_ratio=Ratio(1, 5),
    width_ratio=Ratio(4, 5),
    barrel_type=BarrelType.ROUND,
    tilt_deg=8.0,
    barrel_diameter_mm=760.0,
    barrel_perimeter_mm=None,
)


def report(line: str) -> None:
    sys.stdout.write(line + "\n")
    sys.stdout.flush()


def die_inside_sqlite(after_callbacks: int) -> None:
    """Make every new connection SIGKILL this process at its ``after_callbacks``-th callback."""
    real_connect: Callable[..., sqlite3.Connection] = sqlite3.connect
    calls = 0

    def progress() -> int:
        nonlocal calls
        calls += 1
        if calls >= after_callbacks:
            os.kill(os.getpid(), signal.SIGKILL)
        return 0

    def connect(*args: object, **kwargs: object) -> sqlite3.Connection:
        connection = real_connect(*args, **kwargs)
        connection.set_progress_handler(progress, 50)
        return connection

    sqlite3.connect = connect  # type: ignore[assignment]


def main(path: Path) -> None:
    tag = os.getpid()
    report("OPENING")
    with Database.open(path) as db:
        report("OPEN")
        technician = next(u for u in db.list_users() if u.role is Role.TECHNICIAN)
        step = 0
        while True:
            step += 1
            kind = step % 5
            if kind == 0:
                saved = db.save_recipe(replace(BASE, name=f"crash {tag}-{step}"), technician)
                report(f"R {saved.id} {saved.name}")
            elif kind == 1:
                batch = [replace(BASE, name=f"batch {tag}-{step} {k}") for k in range(3)]
                ids = [str(r.id) for r in db.save_recipes(batch, technician)]
                report(f"B {tag}-{step} {' '.join(ids)}")
            elif kind == 2:
                width = 100.0 + step % 50
                record = db.record_piece(
                    ProductionRecord(
                        datetime.now(UTC), 1, "crash", width, 12.0, 5000.0, 88.0, PieceResult.OK
                    )
                )
                report(f"P {record.id} {width}")
            elif kind == 3:
                current = db.get_parameter("xy_speed_mm_s")
                value = 51.0 if current >= 450.0 else current + 1.0  # always a change: logged
                db.set_parameter("xy_speed_mm_s", value, technician)
                report(f"S {value}")
            else:
                event = db.record_alarm_event(
                    AlarmEvent(
                        datetime.now(UTC),
                        "CRASH",
                        "crash test",
                        "test",
                        AlarmState.NORMAL,
                        AlarmState.ACTIVE_UNACKED,
                    )
                )
                report(f"A {event.id}")


if __name__ == "__main__":
    if len(sys.argv) > 2:
        die_inside_sqlite(int(sys.argv[2]))
    main(Path(sys.argv[1]))
