"""The machine's view of the database (see :mod:`app.machine.store`), over ``app.data``.

Two flavours: :class:`DatabaseStore` writes at once (tests, ``stave simulate``), and
:class:`ThreadedStore` hands writes to a writer thread with its own connection, because an
SQLite commit with ``synchronous = FULL`` waits for the disk, and the machine loop must not.
Reads (a recipe at Start, the parameters) stay synchronous: they happen while nothing moves.
"""

from __future__ import annotations

import logging
import queue
import threading
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

from app.config import MachineConfig
from app.data.database import Database
from app.data.errors import DataError, NotFoundError
from app.data.recipe import Recipe
from app.data.records import AlarmEvent, PieceResult, ProductionRecord
from app.data.records import AlarmState as StoredAlarmState
from app.data.users import Role, User
from app.machine.alarms import AlarmTransition
from app.machine.process_params import config_parameters, stave_limits
from app.machine.snapshot import AlarmState
from app.machine.store import PieceRecord

log = logging.getLogger(__name__)

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
    )


def _service_user(db: Database) -> User:
    return next(u for u in db.list_users() if u.role is Role.SERVICE)


def seed_parameters(db: Database, config: MachineConfig) -> None:
    """A database nobody has tuned yet takes the configuration's factory values."""
    if db.parameter_history(limit=1):
        return
    values = {k: v for k, v in config_parameters(config).items() if k in db.get_parameters()}
    db.set_parameters(values, _service_user(db))


class DatabaseStore:
    def __init__(self, db: Database) -> None:
        self.db = db
        self._machine_user = _service_user(db)

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
            from dataclasses import replace

            recipe = replace(recipe, id=existing.id)
        return self.db.save_recipe(recipe, self._machine_user)

    def parameters(self) -> dict[str, float]:
        return self.db.get_parameters()

    def piece_counts(self, shift_start: float) -> tuple[int, int]:
        return self.db.piece_counts(_utc(shift_start))

    def record_piece(self, piece: PieceRecord) -> None:
        try:
            self.db.record_piece(production_record(piece))
        except (DataError, ValueError) as exc:
            log.error("production record not stored: %s", exc)

    def record_alarm(self, transition: AlarmTransition) -> None:
        try:
            self.db.record_alarm_event(alarm_event(transition))
        except (DataError, ValueError) as exc:
            log.error("alarm history not stored: %s", exc)

    def close(self) -> None:
        self.db.close()


class ThreadedStore(DatabaseStore):
    """Writes go through a queue to a thread with its own connection."""

    def __init__(self, db: Database) -> None:
        super().__init__(db)
        self._queue: queue.Queue[Callable[[DatabaseStore], None] | None] = queue.Queue()
        self._thread = threading.Thread(
            target=self._run, args=(db.path,), name="db-writer", daemon=True
        )
        self._thread.start()

    def _run(self, path: Path) -> None:
        with Database.open(path) as db:
            writer = DatabaseStore(db)
            while True:
                job = self._queue.get()
                if job is None:
                    return
                job(writer)

    def record_piece(self, piece: PieceRecord) -> None:
        self._queue.put(lambda w: w.record_piece(piece))

    def record_alarm(self, transition: AlarmTransition) -> None:
        self._queue.put(lambda w: w.record_alarm(transition))

    def close(self) -> None:
        self._queue.put(None)
        self._thread.join(timeout=10)
        super().close()


def open_store(db_path: Path, config: MachineConfig, *, threaded: bool) -> DatabaseStore:
    db = Database.open(db_path, limits=stave_limits(config))
    try:
        seed_parameters(db, config)
    except DataError as exc:
        log.warning("factory parameters from the configuration not applied: %s", exc)
    return ThreadedStore(db) if threaded else DatabaseStore(db)
