"""The Modbus TCP backend against a real pymodbus server on 127.0.0.1 emulating the drives
and the I/O coupler (no mocks): lifecycle, CiA 402, homing, I/O, and the trade's handling of
exception replies, silence and dead connections."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from pymodbus.client import ModbusTcpClient

from app.config import parse_config
from app.drivers.cia402 import Cia402State
from app.drivers.contracts import (
    CommunicationError,
    DeviceEventKind,
    DriverError,
    LifecycleError,
    LifecycleState,
    OutputImage,
)
from app.drivers.modbus.backend import create_backend
from app.drivers.modbus.emulator import ModbusEmulator
from tests.drivers.modbus.helpers import (
    SilentServer,
    bus_of,
    cycle,
    machine_table,
    run_until,
    tcp_modbus,
    tcp_rig,
    with_port,
)

S = Cia402State
START = {"X": 100.0, "Y": 50.0, "Z": 2.0}
BUSY, ILLEGAL_ADDRESS = 0x06, 0x02


def table(**modbus: object) -> dict[str, object]:
    return machine_table(tcp_modbus(**modbus), sim={"start_position": START})


def all_enabled(fb: dict) -> bool:  # type: ignore[type-arg]
    return all(f.enabled for f in fb.values())


def test_activation_reads_the_drives_and_nothing_jumps_on_enable() -> None:
    with tcp_rig(table()) as (emulator, backend):
        motion = backend.motion
        fb = motion.read_axes()
        assert {n: round(f.position, 3) for n, f in fb.items()} == START
        assert all(f.power_state is S.SWITCH_ON_DISABLED and f.homed for f in fb.values())
        # A setpoint far away while X is disabled is not passed on: the target follows X.
        cycle(backend, {"X": 500.0})
        for axis in motion.axis_names:
            motion.enable(axis)
        fb = run_until(backend, all_enabled, 20)
        fb = run_until(backend, lambda f: True, 5)
        assert fb["X"].position == pytest.approx(100.0, abs=1e-3)
        assert emulator.world.axis_positions()["X"] == pytest.approx(100.0, abs=1e-3)


def test_enable_walk_move_and_disable() -> None:
    with tcp_rig(table()) as (emulator, backend):
        motion = backend.motion
        for axis in motion.axis_names:
            motion.enable(axis)
        states = []
        fb = run_until(backend, lambda f: states.append(f["X"].power_state) or all_enabled(f), 20)
        assert [s for i, s in enumerate(states) if i == 0 or s is not states[i - 1]] == [
            S.SWITCH_ON_DISABLED,
            S.READY_TO_SWITCH_ON,
            S.SWITCHED_ON,
            S.OPERATION_ENABLED,
        ]

        def ramp(i: int, _fb: object) -> dict[str, float]:
            return {"X": min(100.0 + 0.2 * (i + 1), 110.0), "Z": max(2.0 - 0.01 * (i + 1), 1.0)}

        fb = run_until(
            backend,
            lambda f: abs(f["X"].position - 110.0) < 0.01 and abs(f["Z"].position - 1.0) < 0.001,
            400,
            setpoints=ramp,
        )
        assert emulator.world.axis_positions()["X"] == pytest.approx(110.0, abs=0.01)
        assert abs(fb["X"].following_error) < 0.05
        motion.disable("X")
        fb = run_until(backend, lambda f: f["X"].power_state is S.SWITCH_ON_DISABLED, 5)
        assert fb["Y"].enabled


def test_homing_an_incremental_axis() -> None:
    t = machine_table(
        tcp_modbus(), sim={"start_position": {"X": 30.0}}, axes={"X": {"encoder": "incremental"}}
    )
    with tcp_rig(t) as (emulator, backend):
        motion = backend.motion
        fb = motion.read_axes()
        assert not fb["X"].homed and fb["X"].position == pytest.approx(0.0)
        motion.enable("X")
        run_until(backend, lambda f: f["X"].enabled, 10)
        motion.start_homing("X")
        seen_active = []
        fb = run_until(
            backend,
            lambda f: (
                seen_active.append(f["X"].homing_active)
                or (not f["X"].homing_active and f["X"].homed)
            ),
            2000,
        )
        assert any(seen_active)
        assert fb["X"].position == pytest.approx(-5.0, abs=0.05)  # home_switch_position
        assert emulator.world.axis_positions()["X"] == pytest.approx(-5.0, abs=0.05)
        assert fb["X"].enabled and motion.events() == []
        # Back in position mode: the axis follows setpoints again.
        fb = run_until(
            backend,
            lambda f: abs(f["X"].position - 0.0) < 0.01,
            400,
            setpoints=lambda i, _f: {"X": min(-5.0 + 0.05 * (i + 1), 0.0)},
        )


def test_a_drive_fault_is_an_event_and_only_a_reset_clears_it() -> None:
    with tcp_rig(table()) as (emulator, backend):
        motion = backend.motion
        for axis in motion.axis_names:
            motion.enable(axis)
        run_until(backend, all_enabled, 20)
        emulator.world.drives["Y"].inject_power_stage_fault(True)
        fb = run_until(backend, lambda f: f["Y"].power_state is S.FAULT, 20)
        assert fb["Y"].fault_code == 0x2310 and fb["Y"].faulted
        events = motion.events()
        assert [(e.kind, e.device, e.code) for e in events] == [
            (DeviceEventKind.EMERGENCY, "Y", 0x2310)
        ]
        emulator.world.drives["Y"].inject_power_stage_fault(False)
        fb = run_until(backend, lambda f: True, 10)
        assert fb["Y"].power_state is S.FAULT  # nothing resets or re-enables by itself
        motion.fault_reset("Y")
        fb = run_until(backend, lambda f: f["Y"].power_state is S.SWITCH_ON_DISABLED, 10)
        assert fb["Y"].fault_code == 0
        fb = run_until(backend, lambda f: True, 5)
        assert fb["Y"].power_state is S.SWITCH_ON_DISABLED  # reset ends disabled
        assert fb["X"].enabled


def test_estop_opens_the_chain_and_the_drives_lose_torque() -> None:
    with tcp_rig(table()) as (emulator, backend):
        motion = backend.motion
        for axis in motion.axis_names:
            motion.enable(axis)
        run_until(backend, all_enabled, 20)
        emulator.world.set_estop(True)
        assert not backend.io.read_inputs().estop_ok
        fb = run_until(
            backend, lambda f: all(x.power_state is S.SWITCH_ON_DISABLED for x in f.values()), 400
        )
        assert not any(f.enabled for f in fb.values())


def test_coupler_outputs_move_the_devices_and_inputs_follow() -> None:
    with tcp_rig(table()) as (emulator, backend):
        io = backend.io
        assert not io.read_inputs().part_present
        emulator.world.load_board(150.0)
        assert io.read_inputs().part_present
        close = OutputImage(clamps_close=True, lamp_green=True)
        periods = round(0.6 / 0.004) + 5  # clamp_time_s 0.6 at 4 ms
        inputs = None
        for _ in range(periods):
            cycle(backend, outputs=close)
            inputs = io.read_inputs()
            if inputs.clamps_closed:
                break
        assert inputs is not None and inputs.clamps_closed and not inputs.clamps_open
        assert emulator.world.outputs.lamp_green
        for device in reversed(backend.devices()):
            device.deactivate()
        assert emulator.world.outputs == OutputImage()  # deactivation switches outputs off


def test_inverted_inputs_are_inverted_on_the_wire() -> None:
    t = table(io={"inverted": ["estop_ok", "guard_closed"]})
    with tcp_rig(t) as (emulator, backend):
        assert backend.io.read_inputs().estop_ok
        port = bus_of(backend).settings.endpoint.port  # type: ignore[union-attr]
        client = ModbusTcpClient("127.0.0.1", port=port, timeout=1.0)
        try:
            assert client.connect()
            bits = client.read_discrete_inputs(0, count=11, device_id=10).bits
        finally:
            client.close()
        assert bits[7] is False and bits[6] is False  # NC contacts: healthy = open circuit
        emulator.world.set_estop(True)
        assert not backend.io.read_inputs().estop_ok


def test_word_order_and_float_map_on_the_wire() -> None:
    t = table(
        drives={
            "Z": {
                "counts_per_unit": 100.0,
                "map": {"word_order": "little", "position_type": "float32"},
            }
        }
    )
    with tcp_rig(t) as (_emulator, backend):
        assert backend.motion.read_axes()["Z"].position == pytest.approx(2.0)
        port = bus_of(backend).settings.endpoint.port  # type: ignore[union-attr]
        client = ModbusTcpClient("127.0.0.1", port=port, timeout=1.0)
        try:
            assert client.connect()
            registers = client.read_holding_registers(1, count=2, device_id=3).registers
        finally:
            client.close()
        assert (
            ModbusTcpClient.convert_from_registers(
                registers, ModbusTcpClient.DATATYPE.FLOAT32, word_order="little"
            )
            == 200.0
        )


def test_one_block_read_and_one_block_write_per_device_and_period() -> None:
    with tcp_rig(table()) as (emulator, backend):
        before = dict(emulator.requests)
        for _ in range(10):
            cycle(backend)
        assert {k: v - before[k] for k, v in emulator.requests.items()} == {
            "X": 20,
            "Y": 20,
            "Z": 20,
            "io": 20,
        }


def test_a_busy_reply_is_retried_within_the_period() -> None:
    with tcp_rig(table()) as (emulator, backend):
        emulator.inject_exception("X", BUSY)
        cycle(backend)
        stats = bus_of(backend).statistics
        assert stats.retries == 1 and stats.failures == 0


def test_other_exception_replies_are_raised_at_once_with_their_code() -> None:
    with tcp_rig(table()) as (emulator, backend):
        before = emulator.requests["Y"]
        emulator.inject_exception("Y", ILLEGAL_ADDRESS)
        with pytest.raises(DriverError, match="illegal data address") as info:
            backend.motion.read_axes()
        assert info.value.code == ILLEGAL_ADDRESS and info.value.device == "Y"
        assert not isinstance(info.value, CommunicationError)
        assert emulator.requests["Y"] == before + 1  # not retried
        cycle(backend)  # the link is fine
        assert not bus_of(backend).lost


def test_busy_beyond_the_retries_counts_and_n_failures_lose_the_link() -> None:
    with tcp_rig(table(retries=1, max_consecutive_failures=3)) as (emulator, backend):
        motion = backend.motion
        healthy = motion.read_axes()["Z"]
        emulator.inject_exception("Z", BUSY, count=100)
        for _ in range(2):  # two failed exchanges: tolerated, last feedback kept
            assert motion.read_axes()["Z"] == healthy
        with pytest.raises(CommunicationError, match="3 failed exchanges in a row"):
            motion.read_axes()
        events = motion.events()
        assert [(e.kind, e.device) for e in events] == [(DeviceEventKind.COMMUNICATION_LOST, "Z")]
        assert "server device busy" in events[0].text
        requests = dict(emulator.requests)
        for call in (
            motion.read_axes,
            backend.io.read_inputs,
            lambda: motion.write_setpoints({}),
            lambda: backend.io.write_outputs(OutputImage()),
        ):
            with pytest.raises(CommunicationError, match="reset must reconfigure"):
                call()
        assert emulator.requests == requests  # nothing more on the wire
        assert motion.lifecycle_state is LifecycleState.ERROR
        assert backend.io.lifecycle_state is LifecycleState.ERROR


def test_a_silent_drive_is_tolerated_then_declares_the_link_lost() -> None:
    with tcp_rig(table(timeout_ms=150.0, retries=1, max_consecutive_failures=3)) as (
        emulator,
        backend,
    ):
        motion = backend.motion
        healthy = motion.read_axes()["Z"]
        emulator.mute("Z")
        assert motion.read_axes()["Z"] == healthy  # failure 1: last feedback kept
        assert motion.read_axes()["Z"] == healthy  # failure 2
        emulator.mute("Z", muted=False)
        cycle(backend)  # one valid reply resets the count
        assert not bus_of(backend).lost
        emulator.mute("Z")
        motion.read_axes()
        motion.write_setpoints({})  # a write counts too: the next period sends it again
        with pytest.raises(CommunicationError, match="no reply") as info:
            motion.read_axes()
        assert info.value.device == "Z"
        assert bus_of(backend).statistics.failures == 5
        assert [e.kind for e in motion.events()] == [DeviceEventKind.COMMUNICATION_LOST]


def test_a_silent_server_fails_configure_in_bounded_time() -> None:
    server = SilentServer()
    try:
        backend = create_backend(with_port(table(timeout_ms=40.0, retries=1), server.port))
        with pytest.raises(
            CommunicationError,
            match="no reply to reading 7 holding registers from 0x0000 \\(unit 1\\) within 40 ms",
        ) as info:
            backend.motion.configure()
        assert info.value.device == "X"
        assert backend.motion.lifecycle_state is LifecycleState.ERROR
        backend.motion.shutdown()
    finally:
        server.close()


def test_nothing_listening_is_one_clear_message() -> None:
    server = SilentServer()
    port = server.port
    server.close()  # the port is free now: connection refused
    backend = create_backend(with_port(table(), port))
    with pytest.raises(
        CommunicationError, match=f"cannot connect to tcp 127.0.0.1:{port}: connection refused"
    ):
        backend.motion.configure()
    backend.motion.shutdown()


def _spawn_emulator(config_path: Path, port: int) -> tuple[subprocess.Popen[str], int]:
    process = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "app.drivers.modbus.emulator",
            "--config",
            str(config_path),
            "--port",
            str(port),
        ],
        stdout=subprocess.PIPE,
        text=True,
        cwd=Path(__file__).resolve().parents[3],
    )
    assert process.stdout is not None
    line = process.stdout.readline()
    assert line.startswith("listening tcp 127.0.0.1:"), line
    return process, int(line.rsplit(":", 1)[1])


def test_a_killed_server_is_a_lost_link_and_nothing_reconnects(tmp_path: Path) -> None:
    config_path = tmp_path / "machine.toml"
    config_path.write_text(
        '[backend]\nname = "modbus"\n[backend.modbus]\nhost = "127.0.0.1"\n'
        "timeout_ms = 1000.0\n[backend.sim.start_position]\nX = 100.0\n"
    )
    process, port = _spawn_emulator(config_path, 0)
    try:
        backend = create_backend(with_port(table(), port))
        for device in backend.devices():
            device.configure()
            device.activate()
        cycle(backend)
    finally:
        os.kill(process.pid, signal.SIGKILL)
        process.wait(timeout=10)
        assert process.stdout is not None
        process.stdout.close()
    with pytest.raises(CommunicationError, match="connection"):
        cycle(backend)  # the peer is gone: lost at once, no waiting for N timeouts
    assert [e.kind for e in backend.motion.events()] == [DeviceEventKind.COMMUNICATION_LOST]

    # A server is back on the same port: the backend does not go there by itself...
    emulator = ModbusEmulator(parse_config(table()))
    try:
        assert emulator.serve_tcp(port=port) == port
        for _ in range(3):
            with pytest.raises(CommunicationError):
                cycle(backend)
        assert emulator.connections == 0 and sum(emulator.requests.values()) == 0
        # ...only the operator's reset brings it back, as the machine layer does it:
        # deactivate everything, then configure and activate each device.
        for device in backend.devices():
            device.deactivate()
        assert backend.io.lifecycle_state is LifecycleState.ERROR
        for device in backend.devices():
            device.configure()
            device.activate()
        assert cycle(backend)["X"].position == pytest.approx(100.0)
        assert emulator.connections == 1
    finally:
        for device in backend.devices():
            device.shutdown()
        emulator.stop()


def test_devices_on_their_own_servers() -> None:
    config = parse_config(table())
    emulator = ModbusEmulator(config)
    try:
        main_port = emulator.serve_tcp(devices=["X", "Y", "io"])
        z_port = emulator.serve_tcp(devices=["Z"])
        t = table(drives={"Z": {"host": "127.0.0.1", "port": z_port}})
        backend = create_backend(with_port(t, main_port))
        try:
            for device in backend.devices():
                device.configure()
                device.activate()
            assert bus_of(backend).link_names == [
                f"tcp 127.0.0.1:{main_port}",
                f"tcp 127.0.0.1:{z_port}",
            ]
            assert cycle(backend)["Z"].position == pytest.approx(2.0)
        finally:
            for device in backend.devices():
                device.shutdown()
    finally:
        emulator.stop()


def test_lifecycle_rules() -> None:
    with tcp_rig(table(), activate=False) as (_emulator, backend):
        motion, io = backend.motion, backend.io
        with pytest.raises(LifecycleError):
            motion.read_axes()
        motion.configure()
        io.configure()
        assert motion.read_axes()["X"].position == pytest.approx(100.0)  # INACTIVE may read
        assert io.read_inputs().estop_ok
        with pytest.raises(LifecycleError):
            motion.write_setpoints({"X": 1.0})
        with pytest.raises(LifecycleError):
            motion.enable("X")
        with pytest.raises(LifecycleError):
            io.write_outputs(OutputImage())
        motion.activate()
        io.activate()
        with pytest.raises(DriverError, match="no such axis"):
            motion.enable("W")
        with pytest.raises(DriverError, match="homing needs OPERATION ENABLED"):
            motion.start_homing("X")
        with pytest.raises(DriverError, match="does not fit int32"):
            motion.write_setpoints({"X": 1e9})
        motion.shutdown()
        motion.shutdown()
        assert motion.lifecycle_state is LifecycleState.FINALIZED
        assert bus_of(backend).is_open  # the I/O still holds the link
        io.shutdown()
        assert not bus_of(backend).is_open
