"""resources/machine-modbus.toml: it loads, it documents the default map, its RTU variant is
valid, and its machine tables are those of machine.toml."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

from app.config import load_config, parse_config
from app.drivers import registry
from app.drivers.modbus.settings import (
    DEFAULT_INPUT_BITS,
    DEFAULT_OUTPUT_BITS,
    ModbusSettings,
    parse_drive_map,
)
from app.drivers.serial_gauge.settings import DEFAULT_PATTERN

RESOURCES = Path(__file__).resolve().parents[3] / "resources"
SAMPLE = RESOURCES / "machine-modbus.toml"


def test_the_sample_loads_and_states_the_default_map() -> None:
    config = load_config(SAMPLE)
    backend = registry.create_backend(config)
    gauge = registry.create_gauge(config, backend)
    settings = backend.extras["modbus_settings"]
    assert isinstance(settings, ModbusSettings)
    default_map = parse_drive_map({}, "backend.modbus.drive_map", "")  # DEFAULT_DRIVE_MAP
    assert all(d.map == default_map for d in settings.drives.values())
    assert dict(settings.coupler.input_bits) == DEFAULT_INPUT_BITS
    assert dict(settings.coupler.output_bits) == DEFAULT_OUTPUT_BITS
    assert gauge.settings.pattern.pattern == DEFAULT_PATTERN  # type: ignore[attr-defined]
    assert config.backend == "modbus" and config.gauge == "serial"


def test_the_commented_rtu_variant_is_valid() -> None:
    text = SAMPLE.read_text()
    text = re.sub(r"^(host|port) = .*$", "", text, flags=re.MULTILINE)
    text = re.sub(r"^transport = \"tcp\".*$", "", text, flags=re.MULTILINE)
    text = re.sub(
        r"^# (transport|serial_port|baudrate|parity|stopbits|rtu_\w+) = ",
        r"\1 = ",
        text,
        flags=re.MULTILINE,
    )
    text = text.replace("period_ms = 4.0", "period_ms = 50.0")
    config = parse_config(tomllib.loads(text))
    settings = registry.create_backend(config).extras["modbus_settings"]
    assert isinstance(settings, ModbusSettings)
    assert settings.link.serial is not None and settings.link.serial.port == "/dev/ttyUSB0"


def test_the_machine_tables_are_those_of_machine_toml() -> None:
    sample = tomllib.loads(SAMPLE.read_text())
    shipped = tomllib.loads((RESOURCES / "machine.toml").read_text())
    for table in ("axes", "io", "process", "database", "logging", "ui"):
        assert sample.get(table) == shipped.get(table), table
