"""Modbus RTU: the same backend on a serial line (two ptys back to back), every drive and the
coupler on one line with their own unit ids."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import pytest

from app.config import parse_config
from app.drivers.contracts import (
    CommunicationError,
    DeviceEventKind,
    LifecycleState,
    MachineBackend,
)
from app.drivers.modbus.backend import create_backend
from app.drivers.modbus.emulator import ModbusEmulator
from tests.drivers.modbus.helpers import bus_of, cycle, machine_table, run_until
from tests.drivers.modbus.pty_bridge import PtyBridge

START = {"X": 10.0, "Y": 20.0, "Z": -3.0}


@contextmanager
def rtu_rig(**modbus: Any) -> Iterator[tuple[ModbusEmulator, MachineBackend, PtyBridge]]:
    bridge = PtyBridge()
    rtu = {
        "transport": "rtu",
        "serial_port": bridge.right,
        "baudrate": 115200,
        "parity": "N",
        "timeout_ms": 1000.0,
        **modbus,
    }  # a pty refuses parity
    config = parse_config(machine_table(rtu, period_ms=50.0, sim={"start_position": START}))
    emulator = ModbusEmulator(config)
    backend = create_backend(config)
    try:
        emulator.serve_rtu(bridge.left, baudrate=115200, parity="N")
        for device in backend.devices():
            device.configure()
            device.activate()
        yield emulator, backend, bridge
    finally:
        for device in backend.devices():
            device.shutdown()
        emulator.stop()
        bridge.close()


def test_rtu_line_with_three_drives_and_the_coupler() -> None:
    with rtu_rig() as (emulator, backend, _bridge):
        fb = backend.motion.read_axes()
        assert {n: round(f.position, 3) for n, f in fb.items()} == START
        emulator.world.load_board(120.0)
        assert backend.io.read_inputs().part_present
        backend.motion.enable("Y")
        run_until(backend, lambda f: f["Y"].enabled, 10)
        fb = run_until(
            backend,
            lambda f: abs(f["Y"].position - 21.0) < 0.01,
            200,
            setpoints=lambda i, _f: {"Y": min(20.0 + 0.1 * (i + 1), 21.0)},
        )
        assert emulator.world.axis_positions()["Y"] == pytest.approx(21.0, abs=0.01)
        assert bus_of(backend).link_names == [f"rtu {_bridge.right} 115200 baud"]


def test_a_drive_silent_on_the_line_loses_the_link() -> None:
    with rtu_rig(timeout_ms=40.0, retries=0, max_consecutive_failures=2) as (
        emulator,
        backend,
        _bridge,
    ):
        emulator.mute("Y")
        backend.motion.read_axes()  # one failure of Y: tolerated
        with pytest.raises(CommunicationError, match="2 failed exchanges in a row") as info:
            backend.motion.read_axes()
        assert info.value.device == "Y"
        assert [e.kind for e in backend.io.events()] == [DeviceEventKind.COMMUNICATION_LOST]


def test_an_unplugged_adapter_is_a_lost_link_at_once() -> None:
    with rtu_rig() as (_emulator, backend, bridge):
        cycle(backend)
        bridge.unplug_right()
        with pytest.raises(CommunicationError, match="connection lost"):
            cycle(backend)
        assert backend.motion.lifecycle_state is LifecycleState.ERROR
