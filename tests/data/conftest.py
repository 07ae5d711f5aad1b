"""Fixtures for the data layer: real databases on disk, a simulated clock, the default users.

Creating a database hashes three PINs with scrypt (a fraction of a second), so one brand-new
database is made per session and copied (closed, checkpointed: one file) for each test.
"""

from __future__ import annotations

import shutil
from collections.abc import Iterator
from dataclasses import dataclass, field
from datetime import UTC, datetime, timedelta
from pathlib import Path

import pytest

from app.data.database import Database
from app.data.users import Role, User


@dataclass
class SimClock:
    """Simulated time: advances only when told to."""

    now: datetime = field(default_factory=lambda: datetime(2024, 5, 2, 8, 0, tzinfo=UTC))

    def __call__(self) -> datetime:
        return self.now

    def advance(self, seconds: float) -> datetime:
        self.now += timedelta(seconds=seconds)
        return self.now


@pytest.fixture(scope="session")
def template_db(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("template") / "template.db"
    Database.open(path).close()
    assert not Path(f"{path}-wal").exists()  # the last close checkpointed everything
    return path


@pytest.fixture
def clock() -> SimClock:
    return SimClock()


@pytest.fixture
def db_path(template_db: Path, tmp_path: Path) -> Path:
    path = tmp_path / "stave.db"
    shutil.copyfile(template_db, path)
    return path


@pytest.fixture
def db(db_path: Path, clock: SimClock) -> Iterator[Database]:
    with Database.open(db_path, clock=clock) as database:
        yield database


@pytest.fixture
def users(db: Database) -> dict[Role, User]:
    return {user.role: user for user in db.list_users()}
