"""``[backend.modbus]``: the default map, and every bad value named by its dotted key."""

from __future__ import annotations

from typing import Any

import pytest

from app.config import ConfigError, parse_config
from app.drivers import registry
from app.drivers.modbus.settings import (
    DEFAULT_INPUT_BITS,
    DataType,
    Endpoint,
    RegisterTable,
    Transport,
    WordOrder,
    parse_modbus_settings,
)
from tests.drivers.modbus.helpers import machine_table, tcp_modbus


def settings_of(modbus: dict[str, Any], **kwargs: Any):  # type: ignore[no-untyped-def]
    config = parse_config(machine_table(modbus, **kwargs))
    return parse_modbus_settings(config.backend_settings["modbus"], config)


def error_of(modbus: dict[str, Any], **kwargs: Any) -> ConfigError:
    with pytest.raises(ConfigError) as info:
        config = parse_config(machine_table(modbus, **kwargs))
        registry.create_backend(config)
    return info.value


def test_default_register_map() -> None:
    s = settings_of({"host": "10.0.0.5"})
    assert s.link.transport is Transport.TCP
    assert s.link.endpoint == Endpoint("10.0.0.5", 502)
    assert [d.device_id for d in s.drives.values()] == [1, 2, 3]
    m = s.drives["X"].map
    assert m.status_table is RegisterTable.HOLDING
    assert (m.statusword.address, m.position.address, m.fault_code and m.fault_code.address) == (
        0x0000,
        0x0001,
        0x0005,
    )
    assert m.position.data_type is DataType.INT32 and m.word_order is WordOrder.BIG
    assert m.read_block == (0x0000, 7)
    assert m.write_block == (0x0010, 4)
    assert (m.position_mode_value, m.homing_mode_value) == (8, 6)
    assert s.coupler.device_id == 10
    assert dict(s.coupler.input_bits) == DEFAULT_INPUT_BITS
    assert s.coupler.input_count == 11 and s.coupler.output_count == 6


@pytest.mark.parametrize(
    ("modbus", "key", "allowed"),
    [
        ({}, "backend.modbus.host", "host name or IP address"),
        ({"host": "h", "hots": "x"}, "backend.modbus.hots", "known key"),
        ({"host": "h", "transport": "udp"}, "backend.modbus.transport", "'tcp', 'rtu'"),
        ({"host": "h", "timeout_ms": 0}, "backend.modbus.timeout_ms", ">= 1"),
        ({"host": "h", "baudrate": 9600}, "backend.modbus.baudrate", "an RTU setting"),
        ({"transport": "rtu"}, "backend.modbus.serial_port", "/dev/ttyUSB0"),
        (
            {"transport": "rtu", "serial_port": "/dev/x", "host": "h"},
            "backend.modbus.host",
            "a TCP setting",
        ),
        (
            {"transport": "rtu", "serial_port": "/dev/x", "parity": "M"},
            "backend.modbus.parity",
            "'N', 'E', 'O'",
        ),
        (
            {"host": "h", "drive_map": {"position": 0}},
            "backend.modbus.drive_map.position",
            "not inside statusword",
        ),
        (
            {"host": "h", "drive_map": {"position_type": "int64"}},
            "backend.modbus.drive_map.position_type",
            "'int16'",
        ),
        (
            {"host": "h", "drive_map": {"target": 0x0014}},
            "backend.modbus.drive_map.target",
            "must be contiguous",
        ),
        (
            {"host": "h", "drive_map": {"inputs": 0x0100}},
            "backend.modbus.drive_map.inputs",
            "within 125 registers",
        ),
        (
            {"host": "h", "drive_map": {"controlword": 0x0002}},
            "backend.modbus.drive_map.controlword",
            "not inside position",
        ),
        (
            {"host": "h", "drive_map": {"home_switch_bit": 1}},
            "backend.modbus.drive_map.home_switch_bit",
            "different from",
        ),
        (
            {"host": "h", "drive_map": {"homing_mode_value": 8}},
            "backend.modbus.drive_map.homing_mode_value",
            "different from position_mode_value",
        ),
        (
            {"host": "h", "drive_map": {"statusword": 0x10000}},
            "backend.modbus.drive_map.statusword",
            "0 to 65535",
        ),
        (
            {"host": "h", "drives": {"Z": {"counts_per_unit": 0}}},
            "backend.modbus.drives.Z.counts_per_unit",
            "other than 0",
        ),
        ({"host": "h", "drives": {"W": {}}}, "backend.modbus.drives.W", "known key"),
        (
            {"host": "h", "drives": {"Y": {"device_id": 1}}},
            "backend.modbus.drives.Y.device_id",
            "not already used by backend.modbus.drives.X",
        ),
        (
            {"host": "h", "drives": {"Z": {"map": {"target": 0x0011}}}},
            "backend.modbus.drives.Z.map.target",
            "not inside mode",
        ),
        (
            {"transport": "rtu", "serial_port": "/dev/x", "drives": {"X": {"host": "h"}}},
            "backend.modbus.drives.X.host",
            "every device is on backend.modbus.serial_port",
        ),
        (
            {"host": "h", "io": {"inputs": {"estop_ok": -1}}},
            "backend.modbus.io.inputs.estop_ok",
            "safety chain",
        ),
        (
            {"host": "h", "io": {"inputs": {"part_present": 7}}},
            "backend.modbus.io.inputs.estop_ok",
            "not already used by part_present",
        ),
        ({"host": "h", "io": {"inverted": ["estop"]}}, "backend.modbus.io.inverted", "input names"),
        (
            {"host": "h", "io": {"inputs": {"stop_button": -1}, "inverted": ["stop_button"]}},
            "backend.modbus.io.inverted",
            "wired input",
        ),
        (
            {"host": "h", "io": {"outputs": {"lamp_blue": 7}}},
            "backend.modbus.io.outputs.lamp_blue",
            "known key",
        ),
    ],
)
def test_bad_values_name_key_value_and_what_is_allowed(
    modbus: dict[str, Any], key: str, allowed: str
) -> None:
    error = error_of(modbus)
    assert error.key == key
    assert allowed in str(error), str(error)


def test_per_axis_map_override_and_endpoint() -> None:
    s = settings_of(
        tcp_modbus(
            drives={
                "Z": {
                    "device_id": 1,
                    "host": "10.0.0.9",
                    "counts_per_unit": -500.0,
                    "map": {"word_order": "little", "position_type": "float32"},
                }
            }
        )
    )
    assert s.drives["X"].map.word_order is WordOrder.BIG
    z = s.drives["Z"]
    assert z.map.word_order is WordOrder.LITTLE and z.map.target.data_type is DataType.FLOAT32
    # Same unit id as X is fine: Z is on its own server.
    assert z.endpoint == Endpoint("10.0.0.9", 502) and z.device_id == 1
    assert z.counts_per_unit == -500.0 and z.velocity_counts_per_unit_s == -500.0


def test_unmapped_optional_fields_and_inverted_inputs() -> None:
    s = settings_of(
        tcp_modbus(
            drive_map={
                "velocity": -1,
                "inputs": -1,
                "fault_code": -1,
                "mode": -1,
                "target": 0x0011,
            },
            io={"inverted": ["estop_ok"], "inputs": {"reset_button": -1}},
        )
    )
    m = s.drives["X"].map
    assert m.velocity is None and m.inputs is None and m.fault_code is None and m.mode is None
    assert m.read_block == (0, 3) and m.write_block == (0x10, 3)
    assert s.coupler.inverted == frozenset({"estop_ok"})
    assert "reset_button" not in s.coupler.input_bits


def test_rtu_refuses_a_period_the_line_cannot_hold() -> None:
    rtu = {"transport": "rtu", "serial_port": "/dev/ttyUSB0", "baudrate": 115200}
    error = error_of(rtu, period_ms=20.0)
    assert error.key == "backend.period_ms"
    # 8 transactions, 189 bytes of 11 bits (8E1), each transaction two 1.75 ms silences.
    expected_ms = 189 * 11 / 115200 * 1000 + 8 * 2 * 1.75
    assert f"at least {expected_ms:.1f} ms" in str(error) and "115200 baud" in str(error)
    settings_of(rtu, period_ms=50.0)  # what the default map needs fits in 50 ms


def test_the_backend_is_built_but_not_connected() -> None:
    # Nothing listens on port 9 of 127.0.0.1: building must not connect.
    config = parse_config(machine_table(tcp_modbus(port=9)))
    backend = registry.create_backend(config)
    assert backend.name == "modbus"
    assert backend.motion.axis_names == ("X", "Y", "Z")
    assert backend.motion.lifecycle_state.value == "unconfigured"
