"""Logging to a rotating file in the user's log directory and to the console.

Why rotating: a panel PC runs for years on a small disk; the log must never fill it.
Why both: a technician reads the console while commissioning, service reads the file later.
"""

from __future__ import annotations

import logging
import logging.handlers
from pathlib import Path

from platformdirs import user_log_dir

APP_NAME = "stave-jointer"
LOG_FORMAT = "%(asctime)s %(levelname)-7s %(processName)s %(name)s: %(message)s"


def default_log_dir() -> Path:
    return Path(user_log_dir(APP_NAME, appauthor=False))


def setup_logging(
    log_dir: str = "", level: str = "INFO", console: bool = True, file_name: str = "stave.log"
) -> Path:
    """Configure the root logger; returns the log file path. Safe to call more than once."""
    directory = Path(log_dir) if log_dir else default_log_dir()
    directory.mkdir(parents=True, exist_ok=True)
    log_file = directory / file_name
    root = logging.getLogger()
    for handler in list(root.handlers):
        if getattr(handler, "_stave", False):
            root.removeHandler(handler)
            handler.close()
    file_handler = logging.handlers.RotatingFileHandler(
        log_file, maxBytes=2_000_000, backupCount=5, encoding="utf-8"
    )
    handlers: list[logging.Handler] = [file_handler]
    if console:
        handlers.append(logging.StreamHandler())
    for handler in handlers:
        handler.setFormatter(logging.Formatter(LOG_FORMAT))
        handler._stave = True  # type: ignore[attr-defined]
        root.addHandler(handler)
    root.setLevel(level)
    return log_file
