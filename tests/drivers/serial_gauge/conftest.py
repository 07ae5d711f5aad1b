from __future__ import annotations

from collections.abc import Iterator

import pytest

from tests.drivers.serial_gauge.fake_gauge import FakeGauge
from tests.drivers.thread_guard import no_thread_left_behind  # noqa: F401 (autouse fixture)


@pytest.fixture
def fake() -> Iterator[FakeGauge]:
    gauge = FakeGauge()
    yield gauge
    gauge.close()
