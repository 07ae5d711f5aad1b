"""A Modbus server emulating the machine's drives and I/O coupler, on TCP or RTU.

What it is for: the Modbus backend's tests meet a real pymodbus server on 127.0.0.1 (or on a
pty pair for RTU) instead of mocks; and at commissioning a technician can try ``stave probe``
and the whole application against it before the cabinet is wired::

    python -m app.drivers.modbus.emulator --config my-machine.toml --port 5020

serves every drive and the coupler of ``[backend.modbus]`` on 127.0.0.1:5020 (point
``backend.modbus.host``/``port`` of a copy of the file there). The devices behave as the
simulated machine does (:mod:`app.drivers.modbus.emulation`), with time running in lock-step
with the master.

Fault injection for the tests: :meth:`ModbusEmulator.inject_exception` makes a device answer
its next requests with a Modbus exception (the ``action=`` hook of pymodbus' ``SimDevice``);
:meth:`ModbusEmulator.mute` makes a device swallow its replies (a device that has gone
silent: the server's ``trace_packet`` hook drops the outgoing frame). Faults of the machine
itself (E-stop, a board on the table, a drive fault) go through :attr:`world`.

Why a private event-loop thread here (unlike the client): pymodbus' servers exist only as
asyncio servers. The thread is started by the first ``serve_*`` and ended by :meth:`stop`.
"""

from __future__ import annotations

import argparse
import asyncio
import signal
import sys
import threading
from collections.abc import Callable, Coroutine, Iterable, Sequence
from types import TracebackType
from typing import Any

from pymodbus.constants import ExcCodes
from pymodbus.server import ModbusSerialServer, ModbusTcpServer
from pymodbus.server.base import ModbusBaseServer
from pymodbus.simulator import DataType, SimData, SimDevice

from app.config import ConfigError, MachineConfig, load_config
from app.drivers.modbus.emulation import MachineEmulation
from app.drivers.modbus.settings import RegisterTable
from app.drivers.sim.world import SimWorld

READ_FUNCTIONS = {3: RegisterTable.HOLDING, 4: RegisterTable.INPUT}
WRITE_REGISTER_FUNCTIONS = (6, 16, 23)
WRITE_COIL_FUNCTIONS = (5, 15)
READ_DISCRETE_INPUTS = 2
READ_INPUT_REGISTERS = 4


def _round16(count: int) -> int:
    return max(16, (count + 15) // 16 * 16)


class ModbusEmulator:
    def __init__(self, config: MachineConfig, *, world: SimWorld | None = None) -> None:
        self.emulation = MachineEmulation(config, world)
        self.world = self.emulation.world
        self._injected: dict[str, list[int]] = {}
        self._muted_units: set[int] = set()
        self.requests: dict[str, int] = dict.fromkeys(self.emulation.device_names(), 0)
        self.connections = 0
        self._loop: asyncio.AbstractEventLoop | None = None
        self._thread: threading.Thread | None = None
        self._servers: list[ModbusBaseServer] = []

    # -- fault injection (any thread) -----------------------------------------------------
    def inject_exception(self, device: str, code: int, count: int = 1) -> None:
        """The device's next ``count`` requests are answered with exception ``code``."""
        self._check_device(device)
        with self.emulation.lock:
            self._injected.setdefault(device, []).extend([code] * count)

    def mute(self, device: str, muted: bool = True) -> None:
        """A muted device processes requests but its replies never leave the server."""
        unit = self.emulation.unit_of(self._check_device(device))
        with self.emulation.lock:
            if muted:
                self._muted_units.add(unit)
            else:
                self._muted_units.discard(unit)

    def _check_device(self, device: str) -> str:
        names = self.emulation.device_names()
        if device not in names:
            raise ValueError(f"device = {device!r} is not allowed: one of {', '.join(names)}")
        return device

    # -- register behaviour (server thread) -------------------------------------------------
    def _sim_device(self, name: str) -> SimDevice:
        emulation = self.emulation
        unit = emulation.unit_of(name)
        one_register = [SimData(0, count=1, values=0, datatype=DataType.REGISTERS)]
        sixteen_bits = [SimData(0, count=16, values=False, datatype=DataType.BITS)]
        if name == "io":
            c = emulation.settings.coupler
            coils = [
                SimData(
                    0,
                    count=_round16(c.outputs_address + c.output_count),
                    values=False,
                    datatype=DataType.BITS,
                )
            ]
            inputs = [
                SimData(
                    0,
                    count=_round16(c.inputs_address + c.input_count),
                    values=False,
                    datatype=DataType.BITS,
                )
            ]
            first, span = c.register_span
            input_registers = [
                SimData(0, count=first + span or 1, values=0, datatype=DataType.REGISTERS)
            ]
            blocks = (coils, inputs, one_register, input_registers)
        else:
            drive = emulation.drives[name]
            registers = [
                SimData(0, count=drive.last_address + 1, values=0, datatype=DataType.REGISTERS)
            ]
            input_registers = (
                list(registers) if drive.table is RegisterTable.INPUT else one_register
            )
            blocks = (sixteen_bits, list(sixteen_bits), registers, input_registers)

        async def action(
            function_code: int,
            start_address: int,
            address: int,
            count: int,
            registers: list[int],
            set_values: list[int] | list[bool] | None,
        ) -> ExcCodes | None:
            return self._act(
                name, function_code, start_address, address, count, registers, set_values
            )

        return SimDevice(id=unit, simdata=blocks, action=action)

    def _act(
        self,
        name: str,
        function_code: int,
        start_address: int,
        address: int,
        count: int,
        registers: list[int],
        set_values: list[int] | list[bool] | None,
    ) -> ExcCodes | None:
        emulation = self.emulation
        with emulation.lock:
            self.requests[name] += 1
            queue = self._injected.get(name)
            if queue:
                return ExcCodes(queue.pop(0))
            if name == "io":
                coupler = emulation.coupler
                if function_code == READ_DISCRETE_INPUTS:
                    emulation.on_status_read(name)
                    base = coupler.settings.inputs_address
                    for bit, level in coupler.input_bits().items():
                        index, shift = divmod(base + bit, 16)
                        index -= start_address
                        if 0 <= index < len(registers):
                            mask = 1 << shift
                            registers[index] = (
                                registers[index] | mask if level else registers[index] & ~mask
                            )
                elif function_code in WRITE_COIL_FUNCTIONS and set_values is not None:
                    coupler.write_coils(address, [bool(v) for v in set_values])
                elif function_code == READ_INPUT_REGISTERS:
                    for register, value in coupler.input_registers().items():
                        index = register - start_address
                        if 0 <= index < len(registers):
                            registers[index] = value
                return None
            drive = emulation.drives[name]
            table = READ_FUNCTIONS.get(function_code)
            if table is not None and set_values is None:
                if drive.covers_status(table, address, count):
                    emulation.on_status_read(name)
                if table is drive.table:
                    for register, value in drive.status_registers().items():
                        index = register - start_address
                        if 0 <= index < len(registers):
                            registers[index] = value
            elif function_code in WRITE_REGISTER_FUNCTIONS and set_values is not None:
                drive.write(address, [int(v) for v in set_values])
        return None

    def _trace_packet(self, unit_offset: int) -> Callable[[bool, bytes], bytes]:
        """Replies of a muted unit, or of a unit whose link the simulated world has cut (a
        comms_loss injected into the world), never leave the server."""
        links = {
            self.emulation.unit_of(name): "io" if name == "io" else "drives"
            for name in self.emulation.device_names()
        }
        world = self.world

        def trace(sending: bool, data: bytes) -> bytes:
            if sending and len(data) > unit_offset:
                unit = data[unit_offset]
                if unit in self._muted_units or not world.link_ok(links.get(unit, "drives")):
                    return b""
            return data

        return trace

    def _trace_connect(self, connected: bool) -> None:
        if connected:
            self.connections += 1

    # -- serving ---------------------------------------------------------------------------
    def _devices(self, names: Iterable[str] | None) -> list[SimDevice]:
        chosen = list(names) if names is not None else self.emulation.device_names()
        units = [self.emulation.unit_of(self._check_device(n)) for n in chosen]
        if len(set(units)) < len(units):
            raise ValueError(f"devices {chosen} share unit ids {units}: serve them apart")
        return [self._sim_device(n) for n in chosen]

    def _run(
        self, coroutine_factory: Callable[[], Coroutine[Any, Any, ModbusBaseServer]]
    ) -> ModbusBaseServer:
        if self._loop is None:
            loop = asyncio.new_event_loop()
            thread = threading.Thread(target=loop.run_forever, name="modbus-emulator", daemon=True)
            thread.start()
            self._loop, self._thread = loop, thread
        future = asyncio.run_coroutine_threadsafe(coroutine_factory(), self._loop)
        server: ModbusBaseServer = future.result(timeout=10.0)
        self._servers.append(server)
        return server

    def serve_tcp(
        self, host: str = "127.0.0.1", port: int = 0, devices: Iterable[str] | None = None
    ) -> int:
        """Serve ``devices`` (default: all) on a TCP port; returns the port (0: ephemeral)."""
        sim_devices = self._devices(devices)

        async def start() -> ModbusTcpServer:
            server = ModbusTcpServer(
                sim_devices,
                address=(host, port),
                trace_packet=self._trace_packet(6),
                trace_connect=self._trace_connect,
            )
            await server.serve_forever(background=True)
            return server

        server = self._run(start)
        sockets = getattr(server.transport, "sockets", None)
        if not sockets:
            raise OSError(f"cannot listen on {host}:{port}")
        bound: int = sockets[0].getsockname()[1]
        return bound

    def serve_rtu(
        self,
        port: str,
        *,
        baudrate: int = 115200,
        parity: str = "E",
        stopbits: int = 1,
        devices: Iterable[str] | None = None,
    ) -> None:
        """Serve ``devices`` (default: all) as RTU slaves on the serial device ``port``."""
        sim_devices = self._devices(devices)

        async def start() -> ModbusSerialServer:
            server = ModbusSerialServer(
                sim_devices,
                port=port,
                baudrate=baudrate,
                parity=parity,
                stopbits=stopbits,
                trace_packet=self._trace_packet(0),
                trace_connect=self._trace_connect,
            )
            await server.serve_forever(background=True)
            return server

        self._run(start)

    def stop(self) -> None:
        """Close every server and end the loop thread; safe to call twice."""
        loop, thread = self._loop, self._thread
        if loop is None or thread is None:
            return
        servers, self._servers = self._servers, []

        async def shutdown() -> None:
            for server in servers:
                await server.shutdown()  # type: ignore[no-untyped-call]
            await asyncio.sleep(0)  # let the transports' close callbacks run

        asyncio.run_coroutine_threadsafe(shutdown(), loop).result(timeout=10.0)
        loop.call_soon_threadsafe(loop.stop)
        thread.join(timeout=10.0)
        loop.close()
        self._loop = self._thread = None

    def __enter__(self) -> ModbusEmulator:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.stop()


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m app.drivers.modbus.emulator",
        description="Serve the drives and I/O coupler of a Modbus machine configuration, "
        "emulated on the simulated machine.",
    )
    parser.add_argument("--config", help="machine configuration (TOML) with [backend.modbus]")
    parser.add_argument("--host", default="127.0.0.1", help="TCP address to listen on")
    parser.add_argument("--port", type=int, default=5020, help="TCP port (0: any free one)")
    parser.add_argument(
        "--rtu",
        metavar="DEVICE",
        help="serve Modbus RTU on this serial "
        "device instead of TCP (line settings from the configuration)",
    )
    parser.add_argument("--board-mm", type=float, help="put a board of this width on the table")
    args = parser.parse_args(argv)
    try:
        config = load_config(args.config)
        emulator = ModbusEmulator(config)
    except ConfigError as exc:
        print(f"emulator: {exc}", file=sys.stderr)
        return 2
    if args.board_mm is not None:
        emulator.world.load_board(args.board_mm)
    done = threading.Event()
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda *_: done.set())
    try:
        if args.rtu:
            line = emulator.emulation.settings.link.serial
            emulator.serve_rtu(
                args.rtu,
                baudrate=line.baudrate if line else 115200,
                parity=line.parity if line else "E",
                stopbits=line.stopbits if line else 1,
            )
            print(f"listening rtu {args.rtu}", flush=True)
        else:
            port = emulator.serve_tcp(args.host, args.port)
            print(f"listening tcp {args.host}:{port}", flush=True)
        done.wait()
    except OSError as exc:
        print(f"emulator: {exc}", file=sys.stderr)
        return 1
    finally:
        emulator.stop()
    return 0


if __name__ == "__main__":
    sys.exit(main())
