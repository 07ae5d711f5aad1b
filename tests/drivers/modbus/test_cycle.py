"""A full automatic cycle on the Modbus backend: the real machine layer (state machine, cycle,
planner, executor) drives the emulated drives and I/O coupler over Modbus TCP, and measures
the board with the serial gauge on a pty, as it would on the machine."""

from __future__ import annotations

from pathlib import Path

from app.cli.simulate import Watch
from app.config import parse_config
from app.drivers.cia402 import Cia402State
from app.drivers.modbus.emulator import ModbusEmulator
from app.machine import commands as cmd
from app.machine.runtime import MachineRuntime
from app.machine.states import LATCHED_STATES, MachineState
from tests.drivers.cycle_helpers import cut_one_board, select_sample_recipe
from tests.drivers.modbus.helpers import machine_table, tcp_modbus, with_port
from tests.drivers.serial_gauge.fake_gauge import FakeGauge

BOARD_MM = 150.0


def test_full_automatic_cycle_on_modbus(tmp_path: Path) -> None:
    gauge = FakeGauge()
    # 20 ms: the test's machine time runs as fast as the Modbus exchanges allow, and fewer
    # periods keep the test short; the cycle is the same at any period.
    # X and Y have incremental encoders: the machine homes the axes through the drives'
    # homing method, over Modbus, before the cycle. The home switches sit inside the soft
    # limits (a drive stops a little past the reference edge; on the soft limit itself the
    # machine layer refuses to hold the axis there).
    table = machine_table(
        tcp_modbus(),
        period_ms=20.0,
        # Z (absolute) parked on its reference edge: its drive finishes
        # homing within one period.
        sim={"start_position": {"X": 40.0, "Y": 30.0, "Z": 0.0}},
        axes={
            "X": {"encoder": "incremental", "home_switch_position": 0.0},
            "Y": {"encoder": "incremental", "home_switch_position": 0.0},
            "Z": {"home_switch_position": 0.0},
        },
    )
    table["gauge"] = {"name": "serial", "serial": {"port": gauge.path}}
    emulator = ModbusEmulator(parse_config(table))
    world = emulator.world

    def width_line() -> bytes:
        board = world.board
        return f"W={board.true_width_mm:.2f}\r\n".encode() if board else b"W=0.00\r\n"

    gauge.reply_for = width_line
    runtime: MachineRuntime | None = None
    spindle_seen: list[bool] = []
    try:
        config = with_port(table, emulator.serve_tcp())
        runtime = MachineRuntime.create(config, tmp_path / "cycle.db")
        assert runtime.backend.name == "modbus"
        watch = Watch()
        runtime.on_tick.append(watch.observe)
        runtime.on_tick.append(lambda _rt: spindle_seen.append(world.outputs.spindle_on))
        runtime.start()
        c = runtime.controller
        select_sample_recipe(runtime)
        assert c.state is MachineState.NOT_HOMED
        c.post(cmd.Home())
        runtime.run_until(
            lambda m: m.state is MachineState.READY or m.state in LATCHED_STATES, 300.0
        )
        assert c.state is MachineState.READY, c.state_text()
        assert c.axes.all_homed()
        world.load_board(BOARD_MM)
        runtime.run_for(0.1)
        requests_before = sum(emulator.requests.values())
        cut_one_board(runtime, watch, BOARD_MM)  # the width measured by the gauge
        # Everything went over the wire: the coupler switched the spindle on and off again,
        # the drives moved the cutter, and none of them faulted.
        assert any(spindle_seen) and not world.outputs.spindle_on
        assert sum(emulator.requests.values()) - requests_before > 1000
        assert all(d.state is not Cia402State.FAULT for d in world.drives.values())
        assert gauge.requests >= 2  # configure's check, then the board
    finally:
        if runtime is not None:
            runtime.shutdown()
        emulator.stop()
        gauge.close()
