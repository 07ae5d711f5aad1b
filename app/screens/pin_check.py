"""Checks a PIN on a worker thread, so the screen keeps refreshing meanwhile.

Why a thread: a PIN is stored as a salted scrypt hash and checking one costs about 60 ms per
user (measured: up to 170 ms with the three default users); on the GUI thread that would
freeze the panel. The worker opens its own connection to the database file (a SQLite
connection belongs to one thread) and reports back through a queued Qt signal.
"""

from __future__ import annotations

import itertools
import threading
from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QObject, Signal

from app.data.database import Database
from app.data.errors import DataError
from app.data.users import User

Result = Callable[["User | None", str], None]


class PinChecker(QObject):
    """``check(pin, on_result)`` calls ``on_result(user_or_None, error_text)`` later, on the
    GUI thread; only the newest request is answered."""

    _done = Signal(int, object, str)

    def __init__(self, database_path: Path, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.database_path = database_path
        self._ids = itertools.count(1)
        self._pending: dict[int, Result] = {}
        self._threads: list[threading.Thread] = []
        self._done.connect(self._deliver)

    @property
    def busy(self) -> bool:
        return bool(self._pending)

    def check(self, pin: str, on_result: Result) -> None:
        request = next(self._ids)
        self._pending = {request: on_result}  # an older request is no longer wanted
        thread = threading.Thread(
            target=self._work, args=(request, pin), name="pin-check", daemon=True
        )
        self._threads = [t for t in self._threads if t.is_alive()] + [thread]
        thread.start()

    def _work(self, request: int, pin: str) -> None:
        user: User | None = None
        error = ""
        try:
            database = Database.open(self.database_path, load_samples=False)
            try:
                user = database.authenticate(pin)
            finally:
                database.close()
        except (DataError, OSError) as exc:
            error = str(exc)
        self._done.emit(request, user, error)

    def _deliver(self, request: int, user: object, error: str) -> None:
        on_result = self._pending.pop(request, None)
        if on_result is not None:
            on_result(user if isinstance(user, User) else None, error)

    def wait(self, timeout_s: float = 5.0) -> None:
        """Join the worker threads (shutting down)."""
        for thread in self._threads:
            thread.join(timeout_s)
        self._threads = []
