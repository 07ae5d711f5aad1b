"""Killing the writer at any moment loses nothing committed and leaves a database that opens.

A real writer process (``tests/data/crash_writer.py``) writes recipes, batches, pieces,
parameters and alarms in a loop and prints each commit after it returned. Two ways to kill it
with SIGKILL, alternating:

* from outside: the test reads a random number of those lines and kills it, so the kill lands
  wherever the writer happens to be (very often in the fsync of a commit);
* from inside: the writer kills itself at a random SQLite progress callback (every 50 VM
  instructions), i.e. in the middle of a statement or a transaction - on a fresh file, in the
  middle of creating the database.

After each kill the database is reopened and checked: integrity, every reported commit present
and intact, every batch of three recipes complete or absent.
"""

from __future__ import annotations

import os
import random
import signal
import subprocess
import sys
from dataclasses import dataclass, field
from datetime import UTC, datetime, timedelta
from pathlib import Path

import pytest

from app.data.database import Database

ITERATIONS = 30
SEED = 20240502
ROOT = Path(__file__).resolve().parents[2]


@dataclass
class Reported:
    """What the writers said they committed, over all runs on one database."""

    recipes: dict[int, str] = field(default_factory=dict)
    batches: dict[str, list[int]] = field(default_factory=dict)
    pieces: dict[int, float] = field(default_factory=dict)
    speeds: list[float] = field(default_factory=list)
    alarms: set[int] = field(default_factory=set)

    def take(self, line: str) -> None:
        kind, _, rest = line.partition(" ")
        if kind == "R":
            recipe_id, name = rest.split(" ", 1)
            self.recipes[int(recipe_id)] = name
        elif kind == "B":
            tag, *ids = rest.split()
            self.batches[tag] = [int(i) for i in ids]
        elif kind == "P":
            piece_id, width = rest.split()
            self.pieces[int(piece_id)] = float(width)
        elif kind == "S":
            self.speeds.append(float(rest))
        elif kind == "A":
            self.alarms.add(int(rest))
        else:
            assert kind in ("OPENING", "OPEN"), line


def run_and_kill(
    path: Path, reported: Reported, lines_before_kill: int | None, die_after: int | None = None
) -> int:
    """Start a writer; kill it after ``lines_before_kill`` lines (None: it kills itself after
    ``die_after`` SQLite progress callbacks). Returns the lines read before the kill."""
    extra = [] if die_after is None else [str(die_after)]
    writer = subprocess.Popen(
        [sys.executable, "-m", "tests.data.crash_writer", str(path), *extra],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert writer.stdout is not None and writer.stderr is not None
    read = 0
    try:
        while lines_before_kill is not None and read < lines_before_kill:
            line = writer.stdout.readline()
            if not line:  # the writer died by itself: that is a failure, show why
                writer.wait(timeout=30)
                pytest.fail(f"writer exited {writer.returncode}: {writer.stderr.read()}")
            reported.take(line.strip())
            read += 1
    finally:
        if lines_before_kill is not None:
            os.kill(writer.pid, signal.SIGKILL)
        writer.wait(timeout=60)
    # Lines already in the pipe were printed after their commit returned: they count too.
    for line in writer.stdout.read().splitlines():
        if line.strip():
            reported.take(line.strip())
    writer.stdout.close()
    writer.stderr.close()
    assert writer.returncode == -signal.SIGKILL
    return read


def check(path: Path, reported: Reported) -> None:
    with Database.open(path) as db:
        assert db.integrity_problems() == []
        recipes = {r.id: r for r in db.list_recipes()}
        for recipe_id, name in reported.recipes.items():
            assert recipe_id in recipes and recipes[recipe_id].name == name
            assert recipes[recipe_id].validate(db.limits) == []
        for tag, ids in reported.batches.items():
            assert [recipes[i].name for i in ids] == [f"batch {tag} {k}" for k in range(3)]
        # All or nothing, also for batches whose commit was never reported.
        tags: dict[str, int] = {}
        for recipe in recipes.values():
            if recipe.name.startswith("batch "):
                tag = recipe.name.split()[1]
                tags[tag] = tags.get(tag, 0) + 1
        assert set(tags.values()) <= {3}
        now = datetime.now(UTC)
        pieces = {p.id: p for p in db.list_production(now - timedelta(days=1), now)}
        for piece_id, width in reported.pieces.items():
            assert pieces[piece_id].width_mm == width
        history = db.parameter_history("xy_speed_mm_s", limit=100_000)
        logged = iter([c.new_value for c in reversed(history)])
        # The reported changes appear in the log in order (a change committed but killed
        # before its report line may sit between them).
        assert all(any(value == seen for seen in logged) for value in reported.speeds)
        if history:
            assert db.get_parameter("xy_speed_mm_s") == history[0].new_value
        alarms = {a.id for a in db.list_alarm_events()}
        assert reported.alarms <= alarms


@pytest.mark.slow
def test_killing_the_writer_at_random_moments_loses_nothing_committed(tmp_path: Path) -> None:
    rng = random.Random(SEED)
    path = tmp_path / "crash.db"
    reported = Reported()
    created_by_a_killed_writer = 0
    for iteration in range(ITERATIONS):
        if iteration % 10 == 0:
            # A fresh file: the writer dies inside the creation transaction (or just after).
            path = tmp_path / f"crash-{iteration}.db"
            reported = Reported()
            run_and_kill(path, reported, None, die_after=rng.randint(1, 60))
            created_by_a_killed_writer += path.exists()
        elif iteration % 2:
            run_and_kill(path, reported, rng.randint(0, 60))
        else:
            run_and_kill(path, reported, None, die_after=rng.randint(1, 600))
        check(path, reported)
    assert created_by_a_killed_writer > 0
    # The kills landed among many commits of every kind.
    assert len(reported.recipes) > 5 and len(reported.batches) > 5 and len(reported.pieces) > 5
