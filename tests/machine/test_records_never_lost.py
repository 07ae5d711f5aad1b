"""A busy or unavailable database delays the machine's records and never loses one.

The import-while-cutting case: a technician imports thousands of recipes while the machine
cuts, and the write lock is held for longer than the writer's busy timeout (here by a foreign
connection doing what the old import did, then by the real import). Every board cut and every
alarm transition must be in the database afterwards, W103 must be raised while they wait, and
a journal must carry waiting records across a restart without storing any twice.
"""

from __future__ import annotations

import sqlite3
import threading
import time
from contextlib import closing
from datetime import UTC, datetime
from pathlib import Path

import pytest

from app.config import load_config
from app.data.database import Database
from app.data.exchange import import_recipes
from app.data.pending import WriteJournal, journal_path
from app.data.recipe_files import recipes_to_csv
from app.data.users import Role
from app.machine import commands as cmd
from app.machine import core as controller_module
from app.machine.database_store import DatabaseStore, ThreadedStore, open_store
from app.machine.runtime import MachineRuntime
from app.machine.states import MachineState
from app.machine.store import PieceRecord

from .conftest import Rig

EPOCH = datetime(2000, 1, 1, tzinfo=UTC)


def piece(n: int) -> PieceRecord:
    return PieceRecord(1.7e9 + n, None, f"board {n}", 150.0, 10.0, 5000.0, 8.0, 28.0, "ok")


def hold_write_lock(
    path: Path, started: threading.Event, release: threading.Event, timeout_s: float = 60.0
) -> None:
    with closing(sqlite3.connect(path, isolation_level=None, timeout=30)) as conn:
        conn.execute("BEGIN IMMEDIATE")
        started.set()
        release.wait(timeout_s)
        conn.execute("COMMIT")


def test_import_while_cutting_stores_every_record(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(controller_module, "RECORD_DELAY_ALARM_S", 0.5)
    db_path = tmp_path / "stave.db"
    runtime = MachineRuntime.create(load_config(), db_path, threaded_store=True)
    runtime.start()
    rig = Rig(runtime)
    rig.home()
    rig.select()
    with Database.open(db_path) as db:
        template = db.list_recipes()[0]
        technician = next(u for u in db.list_users() if u.role is Role.TECHNICIAN)
    big = tmp_path / "big.csv"
    big.write_text(
        recipes_to_csv(
            [
                template.__class__(**{**template.__dict__, "name": f"Import {i}"})
                for i in range(3000)
            ]
        ),
        encoding="utf-8",
    )
    locked, release = threading.Event(), threading.Event()
    reports: list[str] = []

    def technician_imports() -> None:
        hold_write_lock(db_path, locked, release)  # as the old import held it, for long
        with Database.open(db_path) as db:
            reports.append(import_recipes(db, big, technician).summary())

    worker = threading.Thread(target=technician_imports)
    worker.start()
    assert locked.wait(10)

    def cut_one() -> None:
        rig.load()
        rig.send(cmd.Start())
        rig.until(lambda c: c.state is MachineState.READY, 200.0)

    cycles = 0
    for _ in range(2):  # boards cut while the database is locked
        cut_one()
        cycles += 1
    deadline = time.monotonic() + 20
    while not rig.controller.alarms.is_active("W103", "database"):
        assert time.monotonic() < deadline, "W103 not raised while records wait"
        rig.run(0.5)
        time.sleep(0.05)
    assert rig.controller.store.unstored_age_s() > 0.5
    release.set()  # the lock goes; the real import runs in batches while boards are cut
    while worker.is_alive() or cycles < 4:
        cut_one()
        cycles += 1
    worker.join()
    # The store retries with a growing pause (real time, up to 5 s): W103 goes back to normal
    # once its last retry has stored everything that waited.
    deadline = time.monotonic() + 20
    while rig.controller.store.unstored_age_s() > 0.0 or rig.controller.alarms.is_active(
        "W103", "database"
    ):
        assert time.monotonic() < deadline, "records still wait 20 s after the import ended"
        rig.run(0.5)
        time.sleep(0.05)
    transitions = list(rig.controller.alarms.history)
    runtime.shutdown()

    assert any(t.code == "W103" and t.to_state.name != "ACTIVE_UNACKED" for t in transitions)
    assert reports and "3000 accepted (3000 new" in reports[0]
    with Database.open(db_path) as db:
        assert db.piece_counts(EPOCH) == (cycles, cycles)
        stored = db.list_alarm_events()
        assert len(db.list_recipes()) == 7 + 3000
    assert {(t.code, t.to_state.name) for t in transitions} <= {
        (e.code, "RTN_UNACKED" if e.to_state.name == "RETURNED_UNACKED" else e.to_state.name)
        for e in stored
    }
    assert any(e.code == "W103" for e in stored)
    assert journal_path(db_path).read_bytes() == b""


def test_waiting_records_survive_a_restart_and_are_stored_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(ThreadedStore, "CLOSE_TIMEOUT_S", 0.3)
    db_path = tmp_path / "stave.db"
    Database.open(db_path).close()
    locked, release = threading.Event(), threading.Event()
    holder = threading.Thread(target=hold_write_lock, args=(db_path, locked, release))
    holder.start()
    assert locked.wait(10)
    store = open_store(db_path, load_config(), threaded=True)
    for n in range(3):
        store.record_piece(piece(n))
    time.sleep(0.2)
    assert store.unstored_age_s() > 0
    store.close()  # the lock is still held: the records stay in the journal
    assert len(WriteJournal(journal_path(db_path)).entries()) >= 3
    release.set()
    holder.join()

    # Pretend the first one was stored just before a crash, before the journal was emptied.
    with Database.open(db_path) as db:
        written = WriteJournal(journal_path(db_path)).entries()
        first = next(w for w in written if hasattr(w, "record"))
        db.record_piece(first.record)  # type: ignore[union-attr]
    with Database.open(db_path) as db:
        restarted = DatabaseStore(db)  # stores the journal at start
        assert restarted.unstored_age_s() == 0.0
        assert db.piece_counts(EPOCH) == (3, 3)  # nothing lost, nothing twice
    assert journal_path(db_path).read_bytes() == b""


def test_a_torn_last_journal_line_is_skipped_and_the_others_kept(tmp_path: Path) -> None:
    journal = WriteJournal(tmp_path / "stave.db.pending")
    from app.data.pending import PieceWrite
    from app.machine.database_store import production_record

    journal.append(PieceWrite(production_record(piece(1))))
    with journal.path.open("ab") as stream:
        stream.write(b'{"kind": "piece", "time": "2024-')
    assert [w.record.recipe_name for w in journal.entries()] == ["board 1"]  # type: ignore[union-attr]
    assert journal.path.stat().st_mode & 0o077 == 0
