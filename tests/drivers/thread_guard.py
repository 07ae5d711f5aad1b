"""``no_thread_left_behind``: the autouse fixture of the driver tests that run servers,
relays and pty readers on threads.

Why shared: a test that leaves a server or relay thread running is a defect (pymodbus' own
test suite does the same); the Modbus tests, the serial gauge tests and ``stave probe``'s
tests all check it, and the check must be the same everywhere. A module imports it to use it
(``from tests.drivers.thread_guard import no_thread_left_behind``): pytest finds a fixture by
its name in the module, and only those modules are watched.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator

import pytest


@pytest.fixture(autouse=True)
def no_thread_left_behind() -> Iterator[None]:
    """Fail the test if a thread it started is still alive 2 s after it ended."""
    before = set(threading.enumerate())
    yield
    left = [t for t in threading.enumerate() if t not in before and t.is_alive()]
    for thread in left:
        thread.join(timeout=2.0)
    left = [t for t in left if t.is_alive()]
    assert not left, f"threads left running: {left}"
