"""The serial gauge driver against a gauge at the far end of a pty."""

from __future__ import annotations

import select
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import pytest

from app.config import parse_config
from app.drivers.contracts import (
    CommunicationError,
    GaugeReading,
    LifecycleError,
    LifecycleState,
)
from app.drivers.serial_gauge.gauge import SerialWidthGauge
from app.drivers.serial_gauge.settings import parse_serial_gauge_settings
from tests.drivers.serial_gauge.fake_gauge import FakeGauge


class FakeClock:
    def __init__(self) -> None:
        self.now = 1000.0

    def __call__(self) -> float:
        return self.now


def make_gauge(fake: FakeGauge, clock: FakeClock | None = None, **serial: Any) -> SerialWidthGauge:
    config = parse_config({"gauge": {"name": "serial", "serial": {"port": fake.path, **serial}}})
    settings = parse_serial_gauge_settings(config.gauge_settings["serial"], config)
    return SerialWidthGauge(settings, clock=clock) if clock else SerialWidthGauge(settings)


@contextmanager
def active(gauge: SerialWidthGauge) -> Iterator[SerialWidthGauge]:
    gauge.configure()
    gauge.activate()
    try:
        yield gauge
    finally:
        gauge.shutdown()


def wait_for_reading(gauge: SerialWidthGauge, timeout_s: float = 2.0) -> GaugeReading:
    """Wait on the port (select, not sleep) until poll gives a reading."""
    for _ in range(100):
        reading = gauge.poll()
        if reading is not None:
            return reading
        ready, _, _ = select.select([gauge.fileno()], [], [], timeout_s)
        assert ready, "the gauge sent nothing"
    raise AssertionError("no reading")


def test_request_and_reply(fake: FakeGauge) -> None:
    with active(make_gauge(fake)) as gauge:
        assert fake.requests == 1  # configure checked that the gauge answers
        assert gauge.poll() is None  # nothing without a request
        gauge.request()
        reading = wait_for_reading(gauge)
        assert reading.ok and reading.width_mm == pytest.approx(123.45)
        assert reading.raw == "W=123.45"
        assert gauge.poll() is None  # one reading per request
        fake.reply = b"W=201.5\r\n"
        gauge.request()
        assert wait_for_reading(gauge).width_mm == pytest.approx(201.5)


def test_partial_lines_and_stale_input(fake: FakeGauge) -> None:
    with active(make_gauge(fake)) as gauge:
        fake.stop_thread()
        fake.write(b"W=99.0\r\n")  # an answer nobody asked for
        gauge.request()  # flushes stale input, then asks
        assert fake.take_request() == b"?\r\n"
        fake.write(b"W=1")
        select.select([gauge.fileno()], [], [], 2.0)
        assert gauge.poll() is None  # half a line is not a reading
        fake.write(b"50.25\r")
        fake.write(b"\nW=77\r\n")
        reading = wait_for_reading(gauge)
        assert reading.width_mm == pytest.approx(150.25)


@pytest.mark.parametrize(
    ("reply", "error"),
    [
        (b"ERR\r\n", "garbage: 'ERR' does not match"),
        (b"W=512.0\r\n", "out of range: 512 mm"),
        (b"\x00\x13\xff\x81\r\n", "garbage"),
    ],
)
def test_garbage_and_out_of_range_replies(fake: FakeGauge, reply: bytes, error: str) -> None:
    with active(make_gauge(fake)) as gauge:
        fake.reply = reply
        gauge.request()
        reading = wait_for_reading(gauge)
        assert reading.width_mm is None and error in reading.error
        fake.reply = b"W=123.0\r\n"
        gauge.request()  # the next request is good again
        assert wait_for_reading(gauge).ok


def test_a_runaway_line_is_garbage(fake: FakeGauge) -> None:
    with active(make_gauge(fake, max_line_bytes=32)) as gauge:
        fake.reply = b"W" * 100
        gauge.request()
        reading = wait_for_reading(gauge)
        assert "without a line terminator" in reading.error


def test_an_unplugged_gauge_raises(fake: FakeGauge) -> None:
    with active(make_gauge(fake)) as gauge:
        fake.unplug()
        with pytest.raises(CommunicationError, match="is gone \\(gauge unplugged\\?\\)"):
            gauge.poll()
        assert gauge.lifecycle_state is LifecycleState.ERROR
        with pytest.raises(LifecycleError):
            gauge.request()


def test_a_silent_gauge_raises_after_the_reply_timeout(fake: FakeGauge) -> None:
    clock = FakeClock()
    with active(make_gauge(fake, clock, reply_timeout_ms=200.0)) as gauge:
        fake.auto = False
        gauge.request()
        clock.now += 0.199
        assert gauge.poll() is None
        clock.now += 0.002
        with pytest.raises(CommunicationError, match="no answer to the request within 200 ms"):
            gauge.poll()
        fake.auto = True
        gauge.request()  # the port itself is fine: the next request may succeed
        assert wait_for_reading(gauge).ok


def test_configure_fails_when_the_gauge_does_not_answer(fake: FakeGauge) -> None:
    fake.auto = False
    gauge = make_gauge(fake, reply_timeout_ms=30.0)
    with pytest.raises(CommunicationError, match="no answer to the request within 30 ms"):
        gauge.configure()
    assert gauge.lifecycle_state is LifecycleState.ERROR
    assert gauge.fileno() == -1  # the port was released
    fake.auto = True
    gauge.configure()  # an operator's retry
    gauge.shutdown()


def test_configure_fails_on_a_missing_port(fake: FakeGauge) -> None:
    gauge = make_gauge(fake)
    gauge.settings = type(gauge.settings)(
        **{**gauge.settings.__dict__, "port": "/dev/no-such-gauge"}
    )
    with pytest.raises(CommunicationError, match="cannot open /dev/no-such-gauge"):
        gauge.configure()


def test_streaming_gauge() -> None:
    fake = FakeGauge(mode="stream", reply=b"+0150.40\r\n")
    try:
        with active(make_gauge(fake, mode="stream")) as gauge:
            assert gauge.poll() is None  # not armed: lines are read and dropped
            gauge.request()
            assert wait_for_reading(gauge).width_mm == pytest.approx(150.4)
            fake.line = b"+0151.00\r\n"
            fake.stop_thread()
            fake.write(b"+0160.00\r\n+01")  # already there before the request: stale
            gauge.request()
            fake.write(b"70.00\r\n+0180.00\r\n")
            assert wait_for_reading(gauge).width_mm == pytest.approx(180.0)
    finally:
        fake.close()
