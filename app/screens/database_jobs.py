"""Reads and exports of the database on a worker thread, answered on the GUI thread.

Why: the GUI never blocks, and a month of production counted or written to a USB stick may
take longer than a frame. The worker opens its own connection to the database file for each
job (a SQLite connection belongs to one thread, as with the PIN check) and reports back
through a queued Qt signal. Jobs run one after the other; a job of a kind that was asked for
again before it started is skipped (only the newest figures are wanted), and only the newest
request of each kind is answered.
"""

from __future__ import annotations

import contextlib
import itertools
import logging
from collections.abc import Callable
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path
from typing import Any

from PySide6.QtCore import QObject, Signal

from app.data.database import Database
from app.data.errors import DataError

log = logging.getLogger(__name__)

Job = Callable[[Database], Any]
Answer = Callable[[Any, str], None]
"""Called with (the job's result, "") or (None, the error in one line)."""


class DatabaseJobs(QObject):
    _done = Signal(str, int, object, str)

    def __init__(self, database_path: Path, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.database_path = database_path
        self._ids = itertools.count(1)
        self._newest: dict[str, int] = {}
        self._answers: dict[tuple[str, int], Answer] = {}
        self._pool: ThreadPoolExecutor | None = None
        self._futures: list[Future[None]] = []
        self._done.connect(self._deliver)

    @property
    def busy(self) -> bool:
        return bool(self._answers)

    def run(self, kind: str, job: Job, on_result: Answer) -> None:
        """Run ``job`` with a connection of its own; ``on_result`` is called later on this
        (the GUI) thread, unless another job of ``kind`` was asked for meanwhile."""
        request = next(self._ids)
        self._newest[kind] = request
        self._answers = {k: a for k, a in self._answers.items() if k[0] != kind}
        self._answers[(kind, request)] = on_result
        if self._pool is None:
            self._pool = ThreadPoolExecutor(max_workers=1, thread_name_prefix="database-jobs")
        self._futures = [f for f in self._futures if not f.done()]
        self._futures.append(self._pool.submit(self._work, kind, request, job))

    def _work(self, kind: str, request: int, job: Job) -> None:
        if self._newest.get(kind) != request:
            return  # asked for again before it started
        result: Any = None
        error = ""
        try:
            database = Database.open(self.database_path, load_samples=False)
            try:
                result = job(database)
            finally:
                database.close()
        except (DataError, OSError, ValueError) as exc:
            error = str(exc)
        except Exception as exc:  # a worker thread must answer whatever went wrong
            log.exception("database job %s failed", kind)
            error = f"{type(exc).__name__}: {exc}"
        # RuntimeError: the screen is gone (shutting down), nobody to answer.
        with contextlib.suppress(RuntimeError):
            self._done.emit(kind, request, result, error)

    def _deliver(self, kind: str, request: int, result: object, error: str) -> None:
        on_result = self._answers.pop((kind, request), None)
        if on_result is not None and self._newest.get(kind) == request:
            on_result(None if error else result, error)

    def wait(self, timeout_s: float = 10.0) -> None:
        """Let the running jobs finish (tests; shutting down)."""
        for future in self._futures:
            future.exception(timeout_s)
        self._futures = []
