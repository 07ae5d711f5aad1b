"""``[gauge.serial]``: every bad value named by its dotted key."""

from __future__ import annotations

from typing import Any

import pytest

from app.config import ConfigError, parse_config
from app.drivers import registry
from app.drivers.serial_gauge.gauge import SerialWidthGauge
from app.drivers.serial_gauge.settings import GaugeMode


def create(serial: dict[str, Any]):  # type: ignore[no-untyped-def]
    config = parse_config({"gauge": {"name": "serial", "serial": serial}})
    return registry.create_gauge(config, registry.create_backend(config))


@pytest.mark.parametrize(
    ("serial", "key", "allowed"),
    [
        ({}, "gauge.serial.port", "/dev/ttyUSB0"),
        ({"port": "/dev/x", "prot": 1}, "gauge.serial.prot", "known key"),
        ({"port": "/dev/x", "mode": "poll"}, "gauge.serial.mode", "'request', 'stream'"),
        ({"port": "/dev/x", "request": ""}, "gauge.serial.request", "non-empty"),
        ({"port": "/dev/x", "terminator": ""}, "gauge.serial.terminator", "non-empty"),
        ({"port": "/dev/x", "request": "µ?"}, "gauge.serial.request", "ASCII"),
        (
            {"port": "/dev/x", "pattern": "(\\d+"},
            "gauge.serial.pattern",
            "valid regular expression",
        ),
        ({"port": "/dev/x", "pattern": "\\d+"}, "gauge.serial.pattern", "(?P<width>...)"),
        ({"port": "/dev/x", "unit_scale": 0}, "gauge.serial.unit_scale", "> 0"),
        (
            {"port": "/dev/x", "min_width_mm": 100, "max_width_mm": 90},
            "gauge.serial.max_width_mm",
            "greater than min_width_mm (100)",
        ),
        ({"port": "/dev/x", "baudrate": 12}, "gauge.serial.baudrate", "300 to 4000000"),
        ({"port": "/dev/x", "parity": "X"}, "gauge.serial.parity", "'N', 'E', 'O'"),
    ],
)
def test_bad_values(serial: dict[str, Any], key: str, allowed: str) -> None:
    with pytest.raises(ConfigError) as info:
        create(serial)
    assert info.value.key == key
    assert allowed in str(info.value)


def test_defaults_and_escapes() -> None:
    gauge = create({"port": "/dev/ttyUSB3", "mode": "stream", "terminator": "\r"})
    assert isinstance(gauge, SerialWidthGauge)
    s = gauge.settings
    assert (s.baudrate, s.bytesize, s.parity, s.stopbits) == (9600, 8, "N", 1)
    assert s.mode is GaugeMode.STREAM and s.terminator == b"\r" and s.request == b"?\r\n"
    assert (s.min_width_mm, s.max_width_mm, s.reply_timeout_s) == (30.0, 300.0, 0.5)
    assert gauge.lifecycle_state.value == "unconfigured"  # the port opens in configure
