"""Line framing and parsing, bytes in, readings out."""

from __future__ import annotations

from typing import Any

import pytest
from hypothesis import given
from hypothesis import settings as settings_
from hypothesis import strategies as st

from app.config import parse_config
from app.drivers.serial_gauge.lines import LineBuffer, Overflow, parse_line
from app.drivers.serial_gauge.settings import SerialGaugeSettings, parse_serial_gauge_settings


def settings(**serial: Any) -> SerialGaugeSettings:
    config = parse_config(
        {"gauge": {"name": "serial", "serial": {"port": "/dev/ttyUSB9", **serial}}}
    )
    return parse_serial_gauge_settings(config.gauge_settings["serial"], config)


def test_partial_lines_are_kept_until_the_terminator() -> None:
    buffer = LineBuffer(b"\r\n", 64)
    assert buffer.feed(b"W=12") == []
    assert buffer.feed(b"3.4\r") == []  # the terminator itself arrives in two reads
    assert buffer.feed(b"\nW=1") == [b"W=123.4"]
    assert buffer.feed(b"0\r\nW=2\r\nW") == [b"W=10", b"W=2"]


def test_a_line_without_terminator_is_reported_once_and_skipped() -> None:
    buffer = LineBuffer(b"\n", 16)
    out = buffer.feed(b"x" * 20)
    assert len(out) == 1 and isinstance(out[0], Overflow) and out[0].size == 20
    assert buffer.feed(b"y" * 40) == []  # still the same runaway line
    assert buffer.feed(b"tail\nW=5\n") == [b"W=5"]


def test_resync_starts_after_the_next_terminator() -> None:
    buffer = LineBuffer(b"\n", 64)
    buffer.feed(b"W=1")
    buffer.resync()
    assert buffer.feed(b"7\nW=2\n") == [b"W=2"]


@pytest.mark.parametrize(
    ("line", "width"),
    [
        (b"123.45", 123.45),
        (b"W=123.45", 123.45),
        (b"  +98.5 mm", 98.5),
        (b"W: 150", 150.0),
        (b"150.", 150.0),
    ],
)
def test_default_pattern(line: bytes, width: float) -> None:
    reading = parse_line(line, settings())
    assert reading is not None and reading.ok and reading.width_mm == pytest.approx(width)
    assert reading.raw == line.decode().strip()


@pytest.mark.parametrize(
    ("line", "error"),
    [
        (b"ERR 7", "garbage: 'ERR 7' does not match gauge.serial.pattern"),
        (b"\xff\xfe12", "garbage"),
        (b"W=12.3.4", "garbage"),
        (b"W=999.0", "out of range: 999 mm is outside the gauge's range 30 to 300 mm"),
        (b"W=-5", "out of range"),
        (b"W=0", "out of range"),
    ],
)
def test_garbage_and_out_of_range_are_readings_without_a_width(line: bytes, error: str) -> None:
    reading = parse_line(line, settings())
    assert reading is not None and reading.width_mm is None and not reading.ok
    assert error in reading.error


def test_unit_scale_custom_pattern_and_limits() -> None:
    s = settings(
        pattern=r"^(?P<width>\d+\.\d+) in$", unit_scale=25.4, min_width_mm=50.0, max_width_mm=280.0
    )
    reading = parse_line(b"5.000 in", s)
    assert reading is not None and reading.width_mm == pytest.approx(127.0)
    bad = parse_line(b"12.000 in", s)
    assert bad is not None and "304.8 mm is outside" in bad.error


def test_empty_lines_and_overflow() -> None:
    assert parse_line(b"\r", settings()) is None
    reading = parse_line(Overflow(200, b"\x00\x01abc"), settings())
    assert reading is not None and "200 bytes without a line terminator" in reading.error


def test_a_babbling_stream_after_a_resync_is_garbage_not_silence() -> None:
    buffer = LineBuffer(b"\n", 16)
    buffer.resync()  # stream mode: the reading starts after the next terminator
    out = buffer.feed(b"x" * 40)  # ... which never comes
    assert len(out) == 1 and isinstance(out[0], Overflow)
    assert buffer.feed(b"y" * 40) == []  # reported once
    assert buffer.feed(b"\nW=5\n") == [b"W=5"]


@settings_(max_examples=200, deadline=None)
@given(st.lists(st.binary(max_size=40), max_size=12), st.booleans())
def test_any_bytes_give_lines_or_readings_never_an_exception(
    chunks: list[bytes], resync: bool
) -> None:
    s = settings(max_line_bytes=16, min_width_mm=30.0, max_width_mm=300.0)
    buffer = LineBuffer(b"\r\n", 16)
    if resync:
        buffer.resync()
    for chunk in chunks:
        for line in buffer.feed(chunk):
            parse_line(line, s)
            if isinstance(line, bytes):
                assert len(line) <= 16 + len(chunk) and b"\r\n" not in line
