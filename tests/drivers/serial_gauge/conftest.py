from __future__ import annotations

import threading
from collections.abc import Iterator

import pytest

from tests.drivers.serial_gauge.fake_gauge import FakeGauge


@pytest.fixture(autouse=True)
def no_thread_left_behind() -> Iterator[None]:
    before = set(threading.enumerate())
    yield
    left = [t for t in threading.enumerate() if t not in before and t.is_alive()]
    for thread in left:
        thread.join(timeout=2.0)
    assert not [t for t in left if t.is_alive()], f"threads left running: {left}"


@pytest.fixture
def fake() -> Iterator[FakeGauge]:
    gauge = FakeGauge()
    yield gauge
    gauge.close()
