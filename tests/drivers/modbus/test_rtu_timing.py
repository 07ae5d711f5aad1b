"""Frame sizes and the RTU period estimate, by hand against the Modbus serial line spec."""

from __future__ import annotations

import pytest

from app.config import parse_config
from app.drivers.modbus.rtu_timing import coupler_frames, drive_frames, estimate_rtu_cycle
from app.drivers.modbus.settings import parse_modbus_settings
from tests.drivers.modbus.helpers import machine_table, tcp_modbus


def settings(modbus):  # type: ignore[no-untyped-def]
    config = parse_config(machine_table(modbus, period_ms=50.0))
    return parse_modbus_settings(config.backend_settings["modbus"], config)


RTU = {"transport": "rtu", "serial_port": "/dev/ttyUSB0", "baudrate": 115200, "parity": "E"}


def test_frame_sizes_of_the_default_map() -> None:
    s = settings(RTU)
    # fc 3 request 8 bytes; reply 1+1+1+7*2+2 = 19. fc 16 request 1+1+2+2+1+4*2+2 = 17; reply 8.
    assert drive_frames(s.drives["X"].map) == ((8, 19), (17, 8))
    # fc 2 for 11 inputs: reply 1+1+1+2+2 = 7. fc 15 for 6 coils: 1+1+2+2+1+1+2 = 10; reply 8.
    assert coupler_frames(s.coupler) == [("io read", 8, 7), ("io write", 10, 8)]


def test_estimate_at_115200_8e1() -> None:
    estimate = estimate_rtu_cycle(settings(RTU))
    assert estimate is not None
    char_s = 11 / 115200
    assert estimate.character_s == pytest.approx(char_s)
    assert estimate.frame_gap_s == pytest.approx(0.00175)
    assert estimate.bytes_per_cycle == 3 * (8 + 19 + 17 + 8) + (8 + 7 + 10 + 8)
    assert estimate.cycle_s == pytest.approx(189 * char_s + 8 * 2 * 0.00175)
    assert estimate.xy_skew_s == pytest.approx(25 * char_s + 2 * 0.00175)
    assert [t.label for t in estimate.transactions] == [
        "X read",
        "Y read",
        "Z read",
        "io read",
        "X write",
        "Y write",
        "Z write",
        "io write",
    ]


def test_measured_gaps_and_slow_devices_change_the_estimate() -> None:
    fast = estimate_rtu_cycle(
        settings({**RTU, "parity": "N", "rtu_frame_gap_ms": 0.3, "rtu_turnaround_ms": 0.5})
    )
    slow = estimate_rtu_cycle(settings({**RTU, "rtu_turnaround_ms": 5.0}))
    assert fast is not None and slow is not None
    assert fast.cycle_s == pytest.approx(189 * 10 / 115200 + 8 * (0.5 + 0.3) / 1000)
    assert slow.cycle_s == pytest.approx(189 * 11 / 115200 + 8 * (5.0 + 1.75) / 1000)


def test_tcp_has_no_estimate() -> None:
    assert estimate_rtu_cycle(settings(tcp_modbus())) is None
