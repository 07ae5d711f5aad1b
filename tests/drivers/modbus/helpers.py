"""Configurations and a rig for the Modbus backend's tests against the emulator."""

from __future__ import annotations

import copy
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from app.config import MachineConfig, parse_config
from app.drivers.contracts import AxisFeedback, MachineBackend, OutputImage
from app.drivers.modbus.backend import create_backend
from app.drivers.modbus.bus import ModbusBus
from app.drivers.modbus.emulator import ModbusEmulator

# Normal exchanges get a generous timeout (a loaded CI machine must not trip them); tests of
# silence use short ones.
SAFE_TIMEOUT_MS = 1000.0


def machine_table(
    modbus: dict[str, Any],
    *,
    period_ms: float = 4.0,
    sim: dict[str, Any] | None = None,
    axes: dict[str, Any] | None = None,
) -> dict[str, Any]:
    table: dict[str, Any] = {
        "backend": {
            "name": "modbus",
            "period_ms": period_ms,
            "modbus": copy.deepcopy(modbus),
            "sim": copy.deepcopy(sim or {}),
        },
        "axes": copy.deepcopy(axes or {}),
    }
    return table


def tcp_modbus(port: int = 502, **extra: Any) -> dict[str, Any]:
    table: dict[str, Any] = {
        "transport": "tcp",
        "host": "127.0.0.1",
        "port": port,
        "timeout_ms": SAFE_TIMEOUT_MS,
    }
    table.update(extra)
    return table


def with_port(table: dict[str, Any], port: int) -> MachineConfig:
    copied = copy.deepcopy(table)
    copied["backend"]["modbus"]["port"] = port
    return parse_config(copied)


@contextmanager
def tcp_rig(
    table: dict[str, Any], *, activate: bool = True
) -> Iterator[tuple[ModbusEmulator, MachineBackend]]:
    """An emulator serving the table's machine on an ephemeral port, and a backend connected
    to it (configured and, by default, active); everything closed afterwards."""
    emulator = ModbusEmulator(parse_config(table))
    backend: MachineBackend | None = None
    try:
        port = emulator.serve_tcp()
        backend = create_backend(with_port(table, port))
        if activate:
            for device in backend.devices():
                device.configure()
            for device in backend.devices():
                device.activate()
        yield emulator, backend
    finally:
        if backend is not None:
            for device in backend.devices():
                device.shutdown()
        emulator.stop()


def bus_of(backend: MachineBackend) -> ModbusBus:
    bus = backend.extras["modbus_bus"]
    assert isinstance(bus, ModbusBus)
    return bus


def cycle(
    backend: MachineBackend,
    setpoints: dict[str, float] | None = None,
    outputs: OutputImage | None = None,
) -> dict[str, AxisFeedback]:
    """One machine period: read everything, then write everything."""
    feedback = dict(backend.motion.read_axes())
    backend.io.read_inputs()
    backend.motion.write_setpoints(setpoints or {})
    backend.io.write_outputs(outputs or OutputImage())
    return feedback


def run_until(
    backend: MachineBackend,
    done: Any,
    periods: int,
    setpoints: Any = None,
    outputs: OutputImage | None = None,
) -> dict[str, AxisFeedback]:
    """Cycle until ``done(feedback)``; fails the test after ``periods``."""
    feedback: dict[str, AxisFeedback] = {}
    for i in range(periods):
        feedback = cycle(
            backend, setpoints(i, feedback) if callable(setpoints) else setpoints, outputs
        )
        if done(feedback):
            return feedback
    raise AssertionError(f"not done after {periods} periods: {feedback}")


class SilentServer:
    """Accepts TCP connections and never answers (a device that hangs, a wrong port on a
    gateway): the client must time out, not hang."""

    def __init__(self) -> None:
        import socket
        import threading

        self._socket = socket.create_server(("127.0.0.1", 0))
        self._socket.settimeout(0.05)
        self.port: int = self._socket.getsockname()[1]
        self._stop = threading.Event()
        self._connections: list[socket.socket] = []
        self._thread = threading.Thread(target=self._serve, name="silent-server", daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        import select

        while not self._stop.is_set():
            try:
                connection, _ = self._socket.accept()
                self._connections.append(connection)
            except TimeoutError:
                pass
            readable = [c for c in self._connections if c.fileno() >= 0]
            if readable:
                ready, _, _ = select.select(readable, [], [], 0.01)
                for connection in ready:
                    if not connection.recv(4096):  # read and drop the requests
                        connection.close()

    def close(self) -> None:
        self._stop.set()
        self._thread.join(timeout=5.0)
        for connection in self._connections:
            connection.close()
        self._socket.close()
