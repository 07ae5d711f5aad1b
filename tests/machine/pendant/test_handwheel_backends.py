"""The handwheel through each backend's I/O: its switches as input bits and its counter as a
register or object, read by the real machine layer; 1000 counts at x1 are 1.000 mm and the
axis follows. The simulation's own backend is tested in test_pendant_sim.py; here the same
simulated machine is met over Modbus TCP (the emulator on loopback) and over CANopen (the
world's nodes on python-can's virtual bus)."""

from __future__ import annotations

import uuid
from pathlib import Path
from typing import Any

from app.config import parse_config
from app.drivers.modbus.emulator import ModbusEmulator
from app.drivers.sim.gauge import SimGauge
from app.drivers.sim.settings import parse_gauge_settings
from app.drivers.sim.world import SimWorld
from app.machine import commands as cmd
from app.machine.database_store import open_store
from app.machine.runtime import MachineRuntime
from app.machine.states import MachineState
from tests.drivers.canopen import conftest as can_rig
from tests.drivers.modbus.helpers import machine_table, tcp_modbus, with_port

WHEEL_BITS = {
    "handwheel_x": 11,
    "handwheel_y": 12,
    "handwheel_z": 13,
    "handwheel_x10": 14,
    "handwheel_x100": 15,
    "jog_enable": 16,
}
PENDANT = {"handwheel": {"fitted": True}, "joystick": {"fitted": False}}


def turn_1000_counts(runtime: MachineRuntime, world: SimWorld) -> None:
    """The operator's gestures at the machine: Manual screen, X at x1, enable, 1000 counts."""
    c = runtime.controller
    c.post(cmd.EnterManual())
    runtime.run_for(0.1)
    assert c.state is MachineState.MANUAL, c.state_text()
    x0 = c.manual.position("X")
    world_x0 = world.axis_positions()["X"]
    world.handwheel.select("X", 1)
    world.handwheel.enable = True
    runtime.run_for(0.2)
    world.handwheel.turn(1000, 1000.0)
    assert runtime.run_until(lambda m: not world.handwheel.turning, 5.0)
    runtime.run_for(0.3)
    assert c.manual.position("X") == x0 + 1.0
    assert abs(world.axis_positions()["X"] - (world_x0 + 1.0)) < 0.005
    assert c.snapshot().pendant.wheel_axis == "X"


def modbus_table() -> dict[str, Any]:
    registers = {"handwheel_count": 40}
    table = machine_table(
        tcp_modbus(io={"inputs": WHEEL_BITS, "registers": registers}),
        period_ms=20.0,
        axes={"X": {"encoder": "absolute"}, "Y": {"encoder": "absolute"}},
    )
    table["pendant"] = PENDANT
    return table


def test_the_handwheel_over_modbus(tmp_path: Path) -> None:
    table = modbus_table()
    emulator = ModbusEmulator(parse_config(table))
    runtime: MachineRuntime | None = None
    try:
        config = with_port(table, emulator.serve_tcp())
        runtime = MachineRuntime.create(config, tmp_path / "modbus.db")
        runtime.start()
        turn_1000_counts(runtime, emulator.world)
        assert emulator.requests["io"] > 100
    finally:
        if runtime is not None:
            runtime.shutdown()
        emulator.stop()


def test_the_handwheel_over_canopen(tmp_path: Path) -> None:
    channel = f"stave-wheel-{uuid.uuid4().hex[:12]}"
    inputs = {**can_rig.INPUT_BITS, **WHEEL_BITS}
    analog = {"handwheel_count": 2}
    settings = can_rig.canopen_settings(
        channel, heartbeat_ms=100, heartbeat_timeout_ms=1000, master_heartbeat_timeout_ms=1000
    )
    settings["io"] = {**settings["io"], "inputs": inputs, "analog": analog}
    data = {
        "backend": {"name": "canopen", "period_ms": 10.0, "canopen": settings},
        "axes": {"X": {"encoder": "absolute"}, "Y": {"encoder": "absolute"}},
        "pendant": PENDANT,
    }
    config = parse_config(data)
    world = SimWorld.from_config(config)
    bus = can_rig.world_bus(world, channel, inputs, analog)
    runtime: MachineRuntime | None = None
    try:
        gauge = SimGauge(parse_gauge_settings({}), world, config.period_s)
        gauge.configure()
        store = open_store(tmp_path / "stave.db", config, threaded=False)
        runtime = MachineRuntime(config, store, gauge=gauge)
        runtime.on_tick.append(lambda rt: bus.follow_clock(rt.time_s))
        runtime.start()
        turn_1000_counts(runtime, world)
    finally:
        if runtime is not None:
            runtime.shutdown()
        bus.close()
