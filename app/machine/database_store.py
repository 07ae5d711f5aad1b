"""The machine's view of the database (see :mod:`app.machine.store`), over ``app.data``.

Two flavours: :class:`DatabaseStore` writes at once (tests, ``stave simulate``), and
:class:`ThreadedStore` hands writes to a writer thread with its own connection, because an
SQLite commit with ``synchronous = FULL`` waits for the disk, and the machine loop must not.
Reads (a recipe at Start, the parameters) stay synchronous: they happen while nothing moves.

What the machine writes by itself (production records, alarm transitions, the factory values
of an untuned database) is never dropped: each goes into the journal of
:mod:`app.data.pending` first, and stays there, retried with a growing pause, until the
database has taken it, across restarts. A busy database (an import, a backup) only delays the
records; :meth:`DatabaseStore.unstored_age_s` tells the controller how long the oldest one
has waited, and it raises an alarm (W103) when that grows beyond
:data:`app.machine.store.RECORD_DELAY_ALARM_S`.
"""

from __future__ import annotations

import contextlib
import logging
import queue
import threading
import time
from collections import deque
from collections.abc import Callable
from dataclasses import replace
from datetime import UTC, datetime
from pathlib import Path

from app.config import MachineConfig
from app.data.barrel_records import BarrelRecord, BarrelStaveRecord
from app.data.database import Database
from app.data.errors import DataError, NotFoundError, StorageError
from app.data.pending import (
    AlarmWrite,
    BarrelStaveWrite,
    BarrelWrite,
    MachineStateWrite,
    PendingWrite,
    PieceWrite,
    SeedParametersWrite,
    WriteJournal,
    journal_path,
)
from app.data.recipe import Recipe
from app.data.records import AlarmEvent, PieceResult, ProductionRecord
from app.data.records import AlarmState as StoredAlarmState
from app.data.users import CONFIGURATION_ACTOR, SIMULATION_ACTOR, Role, User
from app.machine.alarms import AlarmTransition
from app.machine.interrupted import InterruptedBoard, InterruptedRecordError
from app.machine.process_params import config_parameters, stave_limits
from app.machine.recipe_on_machine import recipe_from_json, recipe_to_json
from app.machine.refusals import refusal_to_json
from app.machine.snapshot import AlarmState
from app.machine.store import PieceRecord

log = logging.getLogger(__name__)

INTERRUPTED_KEY = "interrupted_board"
OPEN_BARREL_KEY = "open_barrel"
SELECTED_RECIPE_KEY = "selected_recipe"

_ALARM_STATES = {
    AlarmState.NORMAL: StoredAlarmState.NORMAL,
    AlarmState.ACTIVE_UNACKED: StoredAlarmState.ACTIVE_UNACKED,
    AlarmState.ACTIVE_ACKED: StoredAlarmState.ACTIVE_ACKED,
    AlarmState.RTN_UNACKED: StoredAlarmState.RETURNED_UNACKED,
}


def _utc(epoch_s: float) -> datetime:
    return datetime.fromtimestamp(epoch_s, UTC)


def production_record(piece: PieceRecord) -> ProductionRecord:
    return ProductionRecord(
        time=_utc(piece.time),
        recipe_id=piece.recipe_id,
        recipe_name=piece.recipe_name,
        width_mm=piece.width_mm,
        d_mm=piece.d_mm,
        r_mm=piece.r_mm,
        cycle_time_s=piece.cycle_time_s,
        result=PieceResult(piece.result),
        alarm_code=piece.alarm_code,
        tilt_deg=piece.tilt_deg,
        resumed=piece.resumed,
        step_times_s=dict(piece.step_times_s),
        barrel_number=piece.barrel_number,
        stave_number=piece.stave_number,
        operator_name=piece.operator_name or None,
    )


def alarm_event(t: AlarmTransition) -> AlarmEvent:
    return AlarmEvent(
        time=_utc(t.time),
        code=t.code,
        text=t.text,
        source=t.source or "machine",
        from_state=_ALARM_STATES[t.from_state],
        to_state=_ALARM_STATES[t.to_state],
        user_name=t.user or None,
        detail_json=None if t.detail is None else refusal_to_json(t.detail),
    )


RETRY_FIRST_S = 0.2
RETRY_MAX_S = 5.0
WRITER_BUSY_TIMEOUT_S = 2.0
"""The writer's own wait for SQLite's lock per attempt; it retries after that, it never gives up."""
WRITER_PAGE_CACHE_KIB = 256
"""The writer connection's page cache: it only appends records and looks up the last few, so
the pages it needs are the right edges of a few B-trees (a few dozen pages of 4 KiB). With the
general bound (2 MiB) its cache kept every new page of the growing file, 0.4 KiB a board,
and would have grown for about 5,000 boards; with this bound it stops after about 400."""


def _service_user(db: Database) -> User:
    return next(u for u in db.list_users() if u.role is Role.SERVICE)


def seed_values(db: Database, config: MachineConfig) -> dict[str, float] | None:
    """The factory values a database nobody has tuned yet takes (None: it has been tuned)."""
    if db.parameter_history(limit=1):
        return None
    return {k: v for k, v in config_parameters(config).items() if k in db.get_parameters()}


def apply_write(db: Database, write: PendingWrite, logged_as: str | None = None) -> None:
    """Store one pending write (StorageError: try again later; RecordError/ParameterError: the
    write itself is invalid and can never be stored); ``logged_as`` names the machine in the
    parameter log (the simulation) instead of the service user whose authority it uses."""
    if isinstance(write, PieceWrite):
        db.record_piece(write.record, skip_if_stored=True)
    elif isinstance(write, AlarmWrite):
        db.record_alarm_event(write.event, skip_if_stored=True)
    elif isinstance(write, MachineStateWrite):
        db.set_machine_state(write.key, write.value)
    elif isinstance(write, BarrelWrite):
        db.record_barrel(write.record)
    elif isinstance(write, BarrelStaveWrite):
        db.record_barrel_stave(write.record)
    elif not db.parameter_history(limit=1):  # still untuned: nobody has changed anything since
        seeded_as = logged_as or CONFIGURATION_ACTOR
        db.set_parameters(write.values, _service_user(db), logged_as=seeded_as)


class DurableWriter:
    """The journal and the queue of writes not stored yet, oldest first, in order."""

    def __init__(self, journal: WriteJournal, clock: Callable[[], float] = time.monotonic):
        self.journal = journal
        self._clock = clock
        self._pending: deque[tuple[PendingWrite, float]] = deque()
        self._lock = threading.Lock()
        self.retry_s = 0.0
        self.logged_as: str | None = None  # the machine's name in the parameter log
        now = clock()
        for write in journal.entries():
            self._pending.append((write, now))
        if self._pending:
            log.warning(
                "%s: %d records from before the restart to store", journal.path, len(self._pending)
            )

    def submit(self, write: PendingWrite) -> None:
        """Journal ``write`` (on disk before it is tried) and queue it."""
        try:
            self.journal.append(write)
        except OSError as exc:  # the disk refuses the journal: the queue still holds it
            log.error(
                "%s: journal not written (%s); the record waits in memory", self.journal.path, exc
            )
        with self._lock:
            self._pending.append((write, self._clock()))

    def pending(self) -> int:
        with self._lock:
            return len(self._pending)

    def waiting_barrel_number(self) -> int:
        """The highest barrel number of the writes not stored yet (0: none)."""
        with self._lock:
            numbers = [w.record.number for w, _t in self._pending if isinstance(w, BarrelWrite)]
        return max(numbers, default=0)

    def waiting_state(self, key: str) -> tuple[bool, str | None]:
        """(True, value) of the newest machine-state write of ``key`` not stored yet, or
        (False, None): what a read must see before the database has it."""
        with self._lock:
            for write, _t in reversed(self._pending):
                if isinstance(write, MachineStateWrite) and write.key == key:
                    return True, write.value
        return False, None

    def oldest_age_s(self) -> float:
        with self._lock:
            return self._clock() - self._pending[0][1] if self._pending else 0.0

    def flush(self, db: Database) -> bool:
        """Store what waits, in order; True when nothing is left (the journal is then emptied).

        On StorageError the write stays first in line and ``retry_s`` says when to try again
        (doubling from RETRY_FIRST_S up to RETRY_MAX_S).
        """
        while True:
            with self._lock:
                if not self._pending:
                    break
                write = self._pending[0][0]
            try:
                apply_write(db, write, self.logged_as)
            except StorageError as exc:
                self.retry_s = min(RETRY_MAX_S, max(RETRY_FIRST_S, self.retry_s * 2))
                log.warning(
                    "record waits for the database (%s); retry in %.1f s", exc, self.retry_s
                )
                return False
            except (DataError, ValueError) as exc:
                log.error(
                    "record refused by the database and kept in the log only: %s (%s)", exc, write
                )
            with self._lock:
                self._pending.popleft()
        self.retry_s = 0.0
        try:
            self.journal.clear()
        except OSError as exc:
            log.error(
                "%s: journal not emptied (%s); its records are stored", self.journal.path, exc
            )
        return True


class DatabaseStore:
    """``logged_as``: the name the change logs give the machine's own changes (seeded
    parameters, recipes a simulation run is given); None logs them as the service user."""

    def __init__(self, db: Database, *, logged_as: str | None = None) -> None:
        self.db = db
        self._machine_user = _service_user(db)
        self._logged_as = logged_as
        self.writer = DurableWriter(WriteJournal(journal_path(db.path)))
        self.writer.logged_as = logged_as
        if self.writer.pending():
            self._kick()

    def recipe(self, recipe_id: int) -> Recipe | None:
        try:
            return self.db.get_recipe(recipe_id)
        except NotFoundError:
            return None

    def first_recipe_id(self) -> int | None:
        recipes = self.db.list_recipes()
        return recipes[0].id if recipes else None

    def recipe_by_name(self, name: str) -> Recipe | None:
        return self.db.get_recipe_by_name(name)

    def recipes(self) -> list[Recipe]:
        return self.db.list_recipes()

    def save_recipe(self, recipe: Recipe) -> Recipe:
        existing = self.db.get_recipe_by_name(recipe.name)
        if existing is not None:
            recipe = replace(recipe, id=existing.id)
        return self.db.save_recipe(recipe, self._machine_user, logged_as=self._logged_as)

    def parameters(self) -> dict[str, float]:
        return self.db.get_parameters()

    def piece_counts(self, shift_start: float) -> tuple[int, int]:
        return self.db.piece_counts(_utc(shift_start))

    def record_piece(self, piece: PieceRecord) -> None:
        self._submit(PieceWrite(production_record(piece)))

    def record_alarm(self, transition: AlarmTransition) -> None:
        self._submit(AlarmWrite(alarm_event(transition)))

    def seed_parameters(self, values: dict[str, float]) -> None:
        self._submit(SeedParametersWrite(values))

    def _submit(self, write: PendingWrite) -> None:
        self.writer.submit(write)
        self._kick()

    def _kick(self) -> None:
        """Try to store what waits (here at once; the threaded store wakes its writer)."""
        self.writer.flush(self.db)

    def unstored_age_s(self) -> float:
        """How long the oldest record not yet in the database has waited (0: none waits)."""
        return self.writer.oldest_age_s()

    def interrupted_board(self) -> InterruptedBoard | None:
        text = self._machine_state(INTERRUPTED_KEY)
        if text is None:
            return None
        try:
            return InterruptedBoard.from_json(text)
        except InterruptedRecordError as exc:
            # Unreadable: the board's state is unknown, which the caller treats as the
            # worst case (a board on the table): never as "nothing was cut".
            log.error("%s", exc)
            raise

    def save_interrupted_board(self, board: InterruptedBoard | None) -> None:
        self._submit(MachineStateWrite(INTERRUPTED_KEY, None if board is None else board.to_json()))

    def record_barrel(self, barrel: BarrelRecord) -> None:
        self._submit(BarrelWrite(barrel))

    def record_barrel_stave(self, stave: BarrelStaveRecord) -> None:
        self._submit(BarrelStaveWrite(stave))

    def last_barrel_number(self) -> int:
        return max(self.db.last_barrel_number(), self.writer.waiting_barrel_number())

    def open_barrel(self) -> str | None:
        return self._machine_state(OPEN_BARREL_KEY)

    def save_open_barrel(self, text: str | None) -> None:
        self._submit(MachineStateWrite(OPEN_BARREL_KEY, text))

    def _machine_state(self, key: str) -> str | None:
        """The newest value of ``key``: the one waiting to be stored, else the stored one."""
        waiting, text = self.writer.waiting_state(key)
        return text if waiting else self.db.machine_state(key)

    def selected_recipe(self) -> Recipe | None:
        text = self._machine_state(SELECTED_RECIPE_KEY)
        return None if text is None else recipe_from_json(text)

    def save_selected_recipe(self, recipe: Recipe | None) -> None:
        value = None if recipe is None else recipe_to_json(recipe)
        self._submit(MachineStateWrite(SELECTED_RECIPE_KEY, value))

    def close(self) -> None:
        self.writer.flush(self.db)
        self.db.close()


class ThreadedStore(DatabaseStore):
    """Writes go through a queue to a thread with its own connection, retried until stored."""

    CLOSE_TIMEOUT_S = 10.0

    def __init__(self, db: Database, *, logged_as: str | None = None) -> None:
        self._wake: queue.Queue[bool] = queue.Queue()
        self._closing = threading.Event()
        self._close_deadline = 0.0
        super().__init__(db, logged_as=logged_as)
        self._thread = threading.Thread(
            target=self._run, args=(db.path,), name="db-writer", daemon=True
        )
        self._thread.start()

    def _run(self, path: Path) -> None:
        db: Database | None = None
        try:
            while True:
                if db is None:
                    db = self._open_writer(path)
                done = db is not None and self.writer.flush(db)
                if self._closing.is_set() and (done or time.monotonic() > self._close_deadline):
                    return
                with contextlib.suppress(queue.Empty):
                    self._wake.get(
                        timeout=None if done else max(self.writer.retry_s, RETRY_FIRST_S)
                    )
        finally:
            if db is not None:
                db.close()

    def _open_writer(self, path: Path) -> Database | None:
        try:
            return Database.open(
                path,
                busy_timeout_s=WRITER_BUSY_TIMEOUT_S,
                load_samples=False,
                page_cache_kib=WRITER_PAGE_CACHE_KIB,
            )
        except DataError as exc:
            self.writer.retry_s = min(RETRY_MAX_S, max(RETRY_FIRST_S, self.writer.retry_s * 2))
            log.warning("database not available for the records (%s)", exc)
            return None

    def _kick(self) -> None:
        self._wake.put(True)

    def close(self) -> None:
        """Store what waits (up to CLOSE_TIMEOUT_S); what is still not stored stays journalled."""
        self._close_deadline = time.monotonic() + self.CLOSE_TIMEOUT_S
        self._closing.set()
        self._wake.put(True)
        self._thread.join(timeout=self.CLOSE_TIMEOUT_S + WRITER_BUSY_TIMEOUT_S + 1.0)
        self.db.close()


def open_store(db_path: Path, config: MachineConfig, *, threaded: bool) -> DatabaseStore:
    db = Database.open(db_path, limits=stave_limits(config))
    # What the simulated machine changes is logged as the simulation, not as a person.
    logged_as = SIMULATION_ACTOR if config.backend == "sim" else None
    store = (
        ThreadedStore(db, logged_as=logged_as)
        if threaded
        else DatabaseStore(db, logged_as=logged_as)
    )
    values = seed_values(db, config)
    if values:
        store.seed_parameters(values)
    return store
