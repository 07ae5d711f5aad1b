"""Where the database lives by default.

The database belongs to the machine's user account, not to the installation: a software update
replaces the program but must never touch recipes, parameters or counts. So the default is the
per-user data directory that platformdirs picks for the platform (``~/.local/share/stave-jointer``
on Linux, ``%LOCALAPPDATA%\\stave-jointer`` on Windows). The environment variable
``STAVE_JOINTER_DB`` overrides it (deployments and tests that want another place without
passing a path through every layer); the command line's ``--db`` and ``Database.open(path)``
take any path.
"""

from __future__ import annotations

import os
from pathlib import Path

from platformdirs import user_data_dir

APP_DIR_NAME = "stave-jointer"
DATABASE_FILE_NAME = "stave.db"
DATABASE_PATH_ENV = "STAVE_JOINTER_DB"


def default_database_path() -> Path:
    """Return the database path: ``$STAVE_JOINTER_DB`` if set, else the user data directory."""
    override = os.environ.get(DATABASE_PATH_ENV, "").strip()
    if override:
        return Path(override).expanduser()
    return Path(user_data_dir(APP_DIR_NAME, appauthor=False)) / DATABASE_FILE_NAME
