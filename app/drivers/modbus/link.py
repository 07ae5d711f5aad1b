"""One Modbus connection (a TCP socket to one server, or one RTU serial line), behind our own
small interface. This is the only module that touches pymodbus' client API.

Why pymodbus' synchronous clients and not the asyncio client on a private loop thread: the
machine loop reads and writes every device once per period, synchronously, in its own
process; a transaction is a request followed by its reply and nothing else can usefully
happen meanwhile. The sync clients do exactly that on the caller's thread: no second thread
whose death would have to be detected, no hand-over between threads each period (which costs
more than a local TCP round trip of ~0.3 ms), no event loop to shut down. Their one trap is
handled here: pymodbus' ``execute`` silently re-opens a closed connection, and a backend must
never reconnect on its own after a loss, so every request first checks that the connection
is still the one ``open`` made and raises :class:`LinkClosedError` otherwise.

Why our own exceptions: pymodbus reports an exception reply as a value, a silent device as
``ModbusIOException`` and a dead connection as ``ConnectionException`` (and these have moved
between releases). The supervisor (:mod:`app.drivers.modbus.bus`) needs exactly three cases:
no valid reply (retry), an exception reply (busy: retry; others: the device refuses), the
connection is gone (link lost).
"""

from __future__ import annotations

import logging
import socket
from collections.abc import Callable, Sequence
from typing import TypeVar

import serial
from pymodbus.client import ModbusSerialClient, ModbusTcpClient
from pymodbus.exceptions import ConnectionException, ModbusException, ModbusIOException
from pymodbus.pdu import ModbusPDU

from app.drivers.modbus.settings import Endpoint, RegisterTable, SerialLine

# pymodbus logs its own errors (a refused connection, a timeout) through the "pymodbus"
# logger. Without a handler Python would print them on stderr through logging.lastResort,
# beside our one clear line; with the application's logging configured they still propagate
# to its handlers and end up in the log file.
logging.getLogger("pymodbus").addHandler(logging.NullHandler())

T = TypeVar("T")

EXCEPTION_NAMES: dict[int, str] = {
    0x01: "illegal function",
    0x02: "illegal data address",
    0x03: "illegal data value",
    0x04: "server device failure",
    0x05: "acknowledge",
    0x06: "server device busy",
    0x08: "memory parity error",
    0x0A: "gateway path unavailable",
    0x0B: "gateway target device failed to respond",
}
BUSY = 0x06


class LinkError(Exception):
    """Base of what a transaction can end with instead of a valid reply."""


class NoReplyError(LinkError):
    """No valid reply within the timeout (silent device, garbled or mismatched frame)."""


class ExceptionReplyError(LinkError):
    """The device answered with a Modbus exception."""

    def __init__(self, code: int, what: str) -> None:
        self.code = code
        name = EXCEPTION_NAMES.get(code, "unknown exception")
        super().__init__(f"exception {code:#04x} ({name}) to {what}")


class LinkClosedError(LinkError):
    """The connection is gone (refused, reset, closed, serial port unplugged)."""


class ModbusLink:
    """One connection. ``open`` connects once; after a loss only ``close`` and a new ``open``
    bring it back (that is the operator's reset, through the backend's ``configure``)."""

    def __init__(
        self,
        name: str,
        timeout_s: float,
        *,
        endpoint: Endpoint | None = None,
        line: SerialLine | None = None,
    ) -> None:
        if (endpoint is None) == (line is None):
            raise ValueError("a link is either a TCP endpoint or a serial line")
        self.name = name
        self.timeout_s = timeout_s
        self._endpoint = endpoint
        self._line = line
        self._client: ModbusTcpClient | ModbusSerialClient | None = None

    @property
    def is_open(self) -> bool:
        return self._client is not None and self._client.connected

    def open(self) -> None:
        """Connect; raises LinkClosedError with the reason when the peer cannot be reached."""
        self.close()
        client: ModbusTcpClient | ModbusSerialClient
        if self._endpoint is not None:
            client = ModbusTcpClient(
                self._endpoint.host, port=self._endpoint.port, timeout=self.timeout_s, retries=0
            )
        else:
            assert self._line is not None
            client = ModbusSerialClient(
                self._line.port,
                baudrate=self._line.baudrate,
                bytesize=8,
                parity=self._line.parity,
                stopbits=self._line.stopbits,
                timeout=self.timeout_s,
                retries=0,
            )
        # Our supervisor counts failures; pymodbus' own "close after N silent requests" would
        # only muddle that count.
        client.set_max_no_responses(1_000_000)
        if not client.connect():
            _close_client(client)
            raise LinkClosedError(f"cannot connect to {self.name}: {self._why_not_connected()}")
        self._client = client

    def close(self) -> None:
        if self._client is not None:
            _close_client(self._client)
            self._client = None

    def _why_not_connected(self) -> str:
        """The reason a connect failed, found again for the message (pymodbus only logs it)."""
        try:
            if self._endpoint is not None:
                with socket.create_connection(
                    (self._endpoint.host, self._endpoint.port), timeout=self.timeout_s
                ):
                    return "the server accepted a second attempt; try again"
            assert self._line is not None
            with serial.Serial(self._line.port):
                return "the port opened on a second attempt; try again"
        except TimeoutError:
            return f"no answer within {self.timeout_s * 1000:.0f} ms (address or cable?)"
        except ConnectionRefusedError:
            return "connection refused (no Modbus server on that port)"
        except (OSError, serial.SerialException) as exc:
            text = getattr(exc, "strerror", None) or str(exc)
            return text

    # -- transactions ---------------------------------------------------------------------
    def _execute(
        self, what: str, request: Callable[[ModbusTcpClient | ModbusSerialClient], ModbusPDU]
    ) -> ModbusPDU:
        client = self._client
        if client is None or not client.connected:
            self._client = None
            raise LinkClosedError(f"{self.name}: connection closed")
        try:
            reply = request(client)
        except ConnectionException as exc:
            self.close()
            raise LinkClosedError(f"{self.name}: connection lost ({_short(exc)})") from None
        except ModbusIOException:
            if not client.connected:  # the socket closed while waiting
                self.close()
                raise LinkClosedError(f"{self.name}: connection lost") from None
            raise NoReplyError(
                f"no reply to {what} within {self.timeout_s * 1000:.0f} ms"
            ) from None
        except ModbusException as exc:
            raise NoReplyError(f"invalid reply to {what} ({_short(exc)})") from None
        except OSError as exc:
            self.close()
            raise LinkClosedError(f"{self.name}: {exc.strerror or exc}") from None
        if reply.isError():
            raise ExceptionReplyError(reply.exception_code, what)
        return reply

    def read_registers(
        self, table: RegisterTable, device_id: int, address: int, count: int
    ) -> list[int]:
        what = f"reading {count} {table.value} registers from {address:#06x} (unit {device_id})"
        if table is RegisterTable.HOLDING:
            reply = self._execute(
                what, lambda c: c.read_holding_registers(address, count=count, device_id=device_id)
            )
        else:
            reply = self._execute(
                what, lambda c: c.read_input_registers(address, count=count, device_id=device_id)
            )
        registers = list(reply.registers)
        if len(registers) != count:
            raise NoReplyError(f"{len(registers)} registers instead of {count} {what}")
        return registers

    def write_registers(self, device_id: int, address: int, values: Sequence[int]) -> None:
        what = f"writing {len(values)} registers from {address:#06x} (unit {device_id})"
        self._execute(what, lambda c: c.write_registers(address, list(values), device_id=device_id))

    def read_discrete_inputs(self, device_id: int, address: int, count: int) -> list[bool]:
        what = f"reading {count} discrete inputs from {address} (unit {device_id})"
        reply = self._execute(
            what, lambda c: c.read_discrete_inputs(address, count=count, device_id=device_id)
        )
        bits = list(reply.bits)
        if len(bits) < count:
            raise NoReplyError(f"{len(bits)} inputs instead of {count} {what}")
        return bits[:count]

    def write_coils(self, device_id: int, address: int, values: Sequence[bool]) -> None:
        what = f"writing {len(values)} coils from {address} (unit {device_id})"
        self._execute(what, lambda c: c.write_coils(address, list(values), device_id=device_id))


def _close_client(client: ModbusTcpClient | ModbusSerialClient) -> None:
    client.close()  # type: ignore[no-untyped-call]  # pymodbus leaves close() unannotated


def _short(exc: ModbusException) -> str:
    text = str(exc).replace("Modbus Error: ", "")
    return text if len(text) < 120 else text[:117] + "..."
