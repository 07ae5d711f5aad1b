"""The ``[backend.modbus]`` table: link, register map of the drives, I/O coupler.

Why the register map lives in the configuration: every drive maker puts the CiA 402 objects
at other Modbus addresses, with other 32-bit word orders and scalings. A technician must be
able to adapt the map from the drive's manual without a new software release, and a wrong
map must stop the start-up with one line naming the key (``backend.modbus.drive_map.target``),
the value and what is allowed, never be guessed.

Why the map is checked beyond types: the drives are read with one block read and written with
one block write per period (the least traffic Modbus allows), so the fields read together
must fit one request (at most 125 registers) and the fields written together must be
contiguous (a gap would overwrite registers the map does not know).

The defaults (:data:`DEFAULT_DRIVE_MAP`, :data:`DEFAULT_INPUT_BITS`,
:data:`DEFAULT_OUTPUT_BITS`) are the map documented in the README and in
``resources/machine-modbus.toml``.
"""

from __future__ import annotations

import enum
from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from itertools import pairwise
from typing import Any

from app.config import ConfigError, MachineConfig, Section
from app.drivers.cia402 import OperationMode
from app.drivers.contracts import ANALOG_INPUTS, DIGITAL_INPUTS, OutputImage

MAX_READ_REGISTERS = 125  # Modbus limit of one read holding/input registers request
MAX_WRITE_REGISTERS = 123  # Modbus limit of one write multiple registers request
MAX_BITS = 1968  # Modbus limit of one read discrete inputs / write coils request (rounded)


class Transport(enum.Enum):
    TCP = "tcp"
    RTU = "rtu"


class RegisterTable(enum.Enum):
    """Where a drive's status block is read from."""

    HOLDING = "holding"  # function 3, read holding registers
    INPUT = "input"  # function 4, read input registers


class DataType(enum.Enum):
    """Register data types; the value is the TOML spelling."""

    INT16 = "int16"
    UINT16 = "uint16"
    INT32 = "int32"
    UINT32 = "uint32"
    FLOAT32 = "float32"

    @property
    def registers(self) -> int:
        return 1 if self in (DataType.INT16, DataType.UINT16) else 2


class WordOrder(enum.Enum):
    """Order of the two 16-bit words of a 32-bit value (bytes within a word are always
    big-endian, as Modbus defines)."""

    BIG = "big"  # high word at the lower address (Modicon convention, most drives)
    LITTLE = "little"  # low word at the lower address ("word swapped")


@dataclass(frozen=True)
class Field:
    """One value in the register map."""

    address: int
    data_type: DataType

    @property
    def end(self) -> int:
        """One past the last register of the value."""
        return self.address + self.data_type.registers


@dataclass(frozen=True)
class Endpoint:
    """A Modbus TCP server: host name or IP address and port."""

    host: str
    port: int

    def __str__(self) -> str:
        return f"{self.host}:{self.port}"


@dataclass(frozen=True)
class SerialLine:
    """A Modbus RTU line (RTU is always 8 data bits)."""

    port: str
    baudrate: int
    parity: str  # "N", "E" or "O"
    stopbits: int

    @property
    def bits_per_character(self) -> int:
        """Start bit, 8 data bits, parity bit if any, stop bits."""
        return 1 + 8 + (0 if self.parity == "N" else 1) + self.stopbits


@dataclass(frozen=True)
class LinkSettings:
    transport: Transport
    endpoint: Endpoint | None  # TCP: the default server of every device
    serial: SerialLine | None  # RTU: the line every device hangs on
    timeout_s: float
    retries: int  # retries of a timed-out or busy request, within the same period
    max_consecutive_failures: int  # failed exchanges of one device before the link is lost
    rtu_turnaround_s: float  # a device's answer delay, for the RTU period estimate
    rtu_frame_gap_s: float  # silence between frames (t3.5), for the RTU period estimate

    @property
    def name(self) -> str:
        if self.serial is not None:
            return f"rtu {self.serial.port} {self.serial.baudrate} baud"
        return f"tcp {self.endpoint}"


@dataclass(frozen=True)
class DriveMap:
    """Where one drive keeps its CiA 402 objects (addresses are 0-based PDU addresses)."""

    status_table: RegisterTable
    statusword: Field  # 0x6041, uint16
    position: Field  # 0x6064 position actual value, counts
    velocity: Field | None  # 0x606C velocity actual value, counts/s
    fault_code: Field | None  # 0x603F error code, uint16
    inputs: Field | None  # 0x60FD digital inputs (low word), uint16
    limit_negative_bit: int
    limit_positive_bit: int
    home_switch_bit: int
    controlword: Field  # 0x6040, uint16
    mode: Field | None  # 0x6060 modes of operation, int16
    target: Field  # 0x607A target position, counts, same type as position
    word_order: WordOrder
    position_mode_value: int  # 8: cyclic synchronous position
    homing_mode_value: int  # 6: homing

    def mode_value(self, mode: OperationMode) -> int:
        """The register value this drive uses for ``mode`` (vendors may number them apart)."""
        if mode is OperationMode.HOMING:
            return self.homing_mode_value
        return self.position_mode_value

    def mode_of(self, value: int) -> OperationMode | None:
        """The mode a register value selects; None for a value this map does not use."""
        if value == self.position_mode_value:
            return OperationMode.CYCLIC_SYNC_POSITION
        if value == self.homing_mode_value:
            return OperationMode.HOMING
        return None

    def read_fields(self) -> list[Field]:
        return [
            f
            for f in (self.statusword, self.position, self.velocity, self.fault_code, self.inputs)
            if f is not None
        ]

    def write_fields(self) -> list[Field]:
        return [f for f in (self.controlword, self.mode, self.target) if f is not None]

    @property
    def read_block(self) -> tuple[int, int]:
        """(first address, count) of the one block read per period."""
        start = min(f.address for f in self.read_fields())
        return start, max(f.end for f in self.read_fields()) - start

    @property
    def write_block(self) -> tuple[int, int]:
        """(first address, count) of the one block written per period."""
        start = min(f.address for f in self.write_fields())
        return start, max(f.end for f in self.write_fields()) - start


@dataclass(frozen=True)
class DriveSettings:
    axis: str
    device_id: int
    endpoint: Endpoint | None  # TCP only: this drive's own server; None: the link's
    counts_per_unit: float  # position counts per mm (X, Y) or per degree (Z)
    velocity_counts_per_unit_s: float  # velocity counts per mm/s or degree/s
    map: DriveMap


@dataclass(frozen=True)
class CouplerSettings:
    device_id: int
    endpoint: Endpoint | None
    inputs_address: int  # first discrete input (function 2)
    outputs_address: int  # first coil (function 15)
    input_bits: Mapping[str, int]  # InputImage field -> bit offset; unwired inputs absent
    output_bits: Mapping[str, int]  # OutputImage field -> bit offset
    inverted: frozenset[str]  # inputs wired as normally-closed contacts
    # ANALOG_INPUTS name -> input register (function 4): the handwheel's 16-bit counter
    # (unsigned), the joystick's analog inputs (signed 16-bit); unwired ones absent
    registers: Mapping[str, int] = field(default_factory=dict)

    @property
    def input_count(self) -> int:
        return max(self.input_bits.values()) + 1

    @property
    def register_span(self) -> tuple[int, int]:
        """(first address, count) of the one input-register read per period; (0, 0): none."""
        if not self.registers:
            return 0, 0
        first = min(self.registers.values())
        return first, max(self.registers.values()) - first + 1

    @property
    def output_count(self) -> int:
        return max(self.output_bits.values(), default=-1) + 1


@dataclass(frozen=True)
class ModbusSettings:
    link: LinkSettings
    drives: Mapping[str, DriveSettings]
    coupler: CouplerSettings


# The default register map: CiA 402 objects laid out the way Modbus-capable servo drives
# commonly expose them, one drive per unit id. Documented in the README and the sample file.
DEFAULT_DRIVE_MAP: dict[str, Any] = {
    "status_table": "holding",
    "statusword": 0x0000,  # 0x6041 statusword, uint16
    "position": 0x0001,  # 0x6064 position actual value, 0x0001-0x0002
    "position_type": "int32",
    "velocity": 0x0003,  # 0x606C velocity actual value, 0x0003-0x0004
    "velocity_type": "int32",
    "fault_code": 0x0005,  # 0x603F error code, uint16
    "inputs": 0x0006,  # 0x60FD digital inputs, low word
    "limit_negative_bit": 0,  # 0x60FD bit 0: negative limit switch
    "limit_positive_bit": 1,  # 0x60FD bit 1: positive limit switch
    "home_switch_bit": 2,  # 0x60FD bit 2: home switch
    "controlword": 0x0010,  # 0x6040 controlword, uint16
    "mode": 0x0011,  # 0x6060 modes of operation, int16
    "target": 0x0012,  # 0x607A target position, 0x0012-0x0013, same type as position
    "word_order": "big",
    "position_mode_value": 8,  # cyclic synchronous position
    "homing_mode_value": 6,  # homing
}

DEFAULT_DEVICE_IDS: dict[str, int] = {"X": 1, "Y": 2, "Z": 3}
DEFAULT_COUPLER_ID = 10

DEFAULT_INPUT_BITS: dict[str, int] = {
    "part_present": 0,
    "centering_extended": 1,
    "centering_retracted": 2,
    "clamps_closed": 3,
    "clamps_open": 4,
    "spindle_running": 5,
    "guard_closed": 6,
    "estop_ok": 7,
    "start_button": 8,
    "stop_button": 9,
    "reset_button": 10,
}

DEFAULT_OUTPUT_BITS: dict[str, int] = {
    "centering_extend": 0,
    "clamps_close": 1,
    "spindle_on": 2,
    "lamp_green": 3,
    "lamp_yellow": 4,
    "lamp_red": 5,
}

INPUT_NAMES: tuple[str, ...] = DIGITAL_INPUTS
OUTPUT_NAMES: tuple[str, ...] = tuple(f.name for f in fields(OutputImage))
# The safety chain's state must come from a wire: unwired it would read "healthy" forever.
MUST_BE_WIRED: tuple[str, ...] = ("estop_ok", "guard_closed")

_DATA_TYPES = tuple(t.value for t in DataType)
_ADDRESS_MAX = 0xFFFF


def _address(section: Section, name: str, default: int, optional: bool) -> int | None:
    value = section.integer(name, default, -1 if optional else 0, _ADDRESS_MAX)
    if value < 0:
        return None
    return value


def _field(
    section: Section, name: str, d: Mapping[str, Any], data_type: DataType, optional: bool = False
) -> Field | None:
    address = _address(section, name, d[name], optional)
    return None if address is None else Field(address, data_type)


def _data_type(section: Section, name: str, d: Mapping[str, Any]) -> DataType:
    return DataType(section.text(name, d[name], _DATA_TYPES))


def _check_disjoint(section: Section, named: list[tuple[str, Field]]) -> None:
    ordered = sorted(named, key=lambda item: item[1].address)
    for (name_a, a), (name_b, b) in pairwise(ordered):
        if b.address < a.end:
            raise section.error(
                name_b,
                b.address,
                f"an address not inside {name_a} ({a.address:#06x}-{a.end - 1:#06x})",
            )


def parse_drive_map(raw: Mapping[str, Any], path: str, source: str) -> DriveMap:
    """Check one register map (``raw`` holds every key, defaults filled in by the caller
    or missing ones taken from :data:`DEFAULT_DRIVE_MAP`)."""
    s = Section(raw, path, source)
    d = DEFAULT_DRIVE_MAP
    table = RegisterTable(
        s.text("status_table", d["status_table"], tuple(t.value for t in RegisterTable))
    )
    position_type = _data_type(s, "position_type", d)
    velocity_type = _data_type(s, "velocity_type", d)
    statusword = _field(s, "statusword", d, DataType.UINT16)
    position = _field(s, "position", d, position_type)
    velocity = _field(s, "velocity", d, velocity_type, optional=True)
    fault_code = _field(s, "fault_code", d, DataType.UINT16, optional=True)
    inputs = _field(s, "inputs", d, DataType.UINT16, optional=True)
    bits = {
        name: s.integer(name, d[name], 0, 15)
        for name in ("limit_negative_bit", "limit_positive_bit", "home_switch_bit")
    }
    controlword = _field(s, "controlword", d, DataType.UINT16)
    mode = _field(s, "mode", d, DataType.INT16, optional=True)
    target = _field(s, "target", d, position_type)
    word_order = WordOrder(s.text("word_order", d["word_order"], tuple(w.value for w in WordOrder)))
    position_mode = s.integer("position_mode_value", d["position_mode_value"], -128, 127)
    homing_mode = s.integer("homing_mode_value", d["homing_mode_value"], -128, 127)
    s.finish()
    assert statusword and position and controlword and target  # mandatory: never None

    if inputs is not None and len(set(bits.values())) < len(bits):
        raise s.error(
            "home_switch_bit",
            bits["home_switch_bit"],
            "a bit different from limit_negative_bit and limit_positive_bit",
        )
    read = [
        (n, f)
        for n, f in (
            ("statusword", statusword),
            ("position", position),
            ("velocity", velocity),
            ("fault_code", fault_code),
            ("inputs", inputs),
        )
        if f is not None
    ]
    write = [
        (n, f)
        for n, f in (("controlword", controlword), ("mode", mode), ("target", target))
        if f is not None
    ]
    _check_disjoint(s, read)
    _check_disjoint(s, write)
    if table is RegisterTable.HOLDING:
        _check_disjoint(s, read + write)
    for name, f in read + write:
        if f.end - 1 > _ADDRESS_MAX:
            raise s.error(
                name,
                f.address,
                f"an address up to {_ADDRESS_MAX - 1:#06x} "
                f"(a {f.data_type.value} needs {f.data_type.registers} registers)",
            )
    read_start = min(f.address for _, f in read)
    read_end = max(f.end for _, f in read)
    if read_end - read_start > MAX_READ_REGISTERS:
        last = max(read, key=lambda item: item[1].end)
        raise s.error(
            last[0],
            last[1].address,
            f"an address within {MAX_READ_REGISTERS} registers of the first status "
            f"field ({read_start:#06x}): the status block is read in one request",
        )
    ordered = sorted(write, key=lambda item: item[1].address)
    for (name_a, a), (name_b, b) in pairwise(ordered):
        if b.address != a.end:
            raise s.error(
                name_b,
                b.address,
                f"{a.end:#06x}, right after {name_a}: controlword, mode and target "
                "are written in one request and must be contiguous",
            )
    if position_mode == homing_mode:
        raise s.error(
            "homing_mode_value",
            homing_mode,
            f"a value different from position_mode_value ({position_mode})",
        )
    return DriveMap(
        table,
        statusword,
        position,
        velocity,
        fault_code,
        inputs,
        bits["limit_negative_bit"],
        bits["limit_positive_bit"],
        bits["home_switch_bit"],
        controlword,
        mode,
        target,
        word_order,
        position_mode,
        homing_mode,
    )


def _refuse_keys(
    section: Section, raw: Mapping[str, Any], names: tuple[str, ...], allowed: str
) -> None:
    """Keys that do not belong in this set-up (the other transport's): the first one present
    is refused, naming it, rather than silently ignored."""
    for name in names:
        if name in raw:
            raise section.error(name, raw[name], allowed)


def _endpoint(section: Section, raw: Mapping[str, Any], link: LinkSettings) -> Endpoint | None:
    """A device's own TCP server (``host``/``port`` keys), or None to use the link's."""
    if not any(name in raw for name in ("host", "port")):
        return None
    if link.transport is Transport.RTU:
        _refuse_keys(
            section,
            raw,
            ("host", "port"),
            "absent: on Modbus RTU every device is on backend.modbus.serial_port",
        )
    assert link.endpoint is not None
    host = section.text("host", link.endpoint.host)
    if not host.strip():
        raise section.error("host", host, "a host name or IP address")
    port = section.integer("port", link.endpoint.port, 1, 65535)
    return Endpoint(host.strip(), port)


def _parse_link(s: Section, raw: Mapping[str, Any]) -> LinkSettings:
    transport = Transport(s.text("transport", "tcp", tuple(t.value for t in Transport)))
    timeout_s = s.number("timeout_ms", 50.0, 1.0, 5000.0) / 1000.0
    retries = s.integer("retries", 1, 0, 5)
    failures = s.integer("max_consecutive_failures", 3, 1, 100)
    turnaround_s = s.number("rtu_turnaround_ms", 1.0, 0.0, 1000.0) / 1000.0
    endpoint: Endpoint | None = None
    serial: SerialLine | None = None
    if transport is Transport.TCP:
        _refuse_keys(
            s,
            raw,
            ("serial_port", "baudrate", "parity", "stopbits", "rtu_frame_gap_ms"),
            'absent for transport = "tcp" (an RTU setting)',
        )
        host = s.text("host", "")
        if not host.strip():
            raise s.error(
                "host",
                host,
                'a host name or IP address of the Modbus TCP server (for transport = "tcp")',
            )
        endpoint = Endpoint(host.strip(), s.integer("port", 502, 1, 65535))
        gap_s = 0.0
    else:
        _refuse_keys(s, raw, ("host", "port"), 'absent for transport = "rtu" (a TCP setting)')
        port = s.text("serial_port", "")
        if not port.strip():
            raise s.error(
                "serial_port", port, 'a serial device such as /dev/ttyUSB0 (for transport = "rtu")'
            )
        baudrate = s.integer("baudrate", 115200, 1200, 4_000_000)
        serial = SerialLine(
            port.strip(),
            baudrate,
            s.text("parity", "E", ("N", "E", "O")),
            s.integer("stopbits", 1, 1, 2),
        )
        # Modbus over serial line V1.02, 2.5.1.1: t3.5 is 3.5 characters up to 19200 baud,
        # and a fixed 1.75 ms above.
        spec_gap_ms = (
            3.5 * serial.bits_per_character / baudrate * 1000.0 if baudrate <= 19200 else 1.75
        )
        gap_s = s.number("rtu_frame_gap_ms", spec_gap_ms, 0.0, 1000.0) / 1000.0
    return LinkSettings(
        transport, endpoint, serial, timeout_s, retries, failures, turnaround_s, gap_s
    )


def _sub(
    parent: Section, name: str, path: str, source: str, exclude: tuple[str, ...] = ()
) -> tuple[Section, dict[str, Any]]:
    """A sub-table as a checked section plus its raw values (``exclude``: keys the caller
    reads itself, such as lists)."""
    raw = parent.raw_table(name)
    section = Section({k: v for k, v in raw.items() if k not in exclude}, path, source)
    return section, raw


def _parse_drive(
    drives: Section,
    axis: str,
    link: LinkSettings,
    shared_map_raw: Mapping[str, Any],
    shared_map: DriveMap,
    source: str,
) -> DriveSettings:
    path = f"backend.modbus.drives.{axis}"
    s, raw = _sub(drives, axis, path, source, exclude=("map",))
    device_id = s.integer("device_id", DEFAULT_DEVICE_IDS.get(axis, 1), 1, 247)
    endpoint = _endpoint(s, raw, link)
    counts = s.number("counts_per_unit", 1000.0)
    if abs(counts) < 1e-9:
        raise s.error("counts_per_unit", counts, "a number other than 0 (negative inverts)")
    velocity_counts = s.number("velocity_counts_per_unit_s", counts)
    if abs(velocity_counts) < 1e-9:
        raise s.error("velocity_counts_per_unit_s", velocity_counts, "a number other than 0")
    s.finish()
    drive_map = shared_map
    if "map" in raw:
        overrides = raw["map"]
        if not isinstance(overrides, Mapping):
            raise ConfigError(f"{path}.map", overrides, "a table", source)
        drive_map = parse_drive_map({**shared_map_raw, **overrides}, f"{path}.map", source)
    return DriveSettings(axis, device_id, endpoint, counts, velocity_counts, drive_map)


def _bit_table(s: Section, names: tuple[str, ...], defaults: Mapping[str, int]) -> dict[str, int]:
    bits: dict[str, int] = {}
    used: dict[int, str] = {}
    for name in names:
        bit = s.integer(name, defaults.get(name, -1), -1, MAX_BITS - 1)
        if bit < 0:
            continue
        if bit in used:
            raise s.error(name, bit, f"a bit not already used by {used[bit]}")
        used[bit] = name
        bits[name] = bit
    s.finish()
    return bits


MAX_REGISTER_SPAN = 125  # the most registers one Modbus read returns


def _register_table(s: Section) -> dict[str, int]:
    """``[backend.modbus.io.registers]``: an input register per analog input, -1 (the
    default) when not wired; all within one read."""
    registers: dict[str, int] = {}
    for name in ANALOG_INPUTS:
        address = s.integer(name, -1, -1, _ADDRESS_MAX)
        if address < 0:
            continue
        if address in registers.values():
            other = next(n for n, a in registers.items() if a == address)
            raise s.error(name, address, f"a register not already used by {other}")
        registers[name] = address
        span = max(registers.values()) - min(registers.values()) + 1
        if span > MAX_REGISTER_SPAN:
            raise s.error(
                name, address, f"within {MAX_REGISTER_SPAN} registers of the others (one read)"
            )
    s.finish()
    return registers


def _parse_coupler(root: Section, link: LinkSettings, source: str) -> CouplerSettings:
    path = "backend.modbus.io"
    s, raw = _sub(root, "io", path, source, exclude=("inverted",))
    device_id = s.integer("device_id", DEFAULT_COUPLER_ID, 1, 247)
    endpoint = _endpoint(s, raw, link)
    inputs_address = s.integer("inputs_address", 0, 0, _ADDRESS_MAX)
    outputs_address = s.integer("outputs_address", 0, 0, _ADDRESS_MAX)
    inputs_section = s.table("inputs")
    input_bits = _bit_table(inputs_section, INPUT_NAMES, DEFAULT_INPUT_BITS)
    for name in MUST_BE_WIRED:
        if name not in input_bits:
            raise inputs_section.error(
                name, -1, "a bit from 0: the safety chain's state must be read from a wire"
            )
    output_bits = _bit_table(s.table("outputs"), OUTPUT_NAMES, DEFAULT_OUTPUT_BITS)
    registers = _register_table(s.table("registers"))
    s.finish()
    inverted_raw = raw.get("inverted", [])
    allowed = "a list of input names from: " + ", ".join(INPUT_NAMES)
    if not isinstance(inverted_raw, list):
        raise ConfigError(f"{path}.inverted", inverted_raw, allowed, source)
    for name in inverted_raw:
        if name not in INPUT_NAMES:
            raise ConfigError(f"{path}.inverted", name, allowed, source)
        if name not in input_bits:
            raise ConfigError(
                f"{path}.inverted", name, f"a wired input ({name} is set to -1)", source
            )
    for kind, count, address in (
        ("inputs", max(input_bits.values()) + 1, inputs_address),
        ("outputs", max(output_bits.values(), default=-1) + 1, outputs_address),
    ):
        if address + count - 1 > _ADDRESS_MAX:
            raise s.error(
                f"{kind}_address",
                address,
                f"an address up to {_ADDRESS_MAX + 1 - count:#06x} ({count} {kind} follow it)",
            )
    return CouplerSettings(
        device_id,
        endpoint,
        inputs_address,
        outputs_address,
        input_bits,
        output_bits,
        frozenset(inverted_raw),
        registers,
    )


def parse_modbus_settings(raw: object, config: MachineConfig) -> ModbusSettings:
    """Check ``[backend.modbus]``; raises ConfigError naming the ``backend.modbus.*`` key."""
    path = "backend.modbus"
    if not isinstance(raw, Mapping):
        raise ConfigError(path, raw, "a table", config.source)
    s = Section(raw, path, config.source)
    link = _parse_link(s, raw)
    map_raw = {**DEFAULT_DRIVE_MAP, **s.raw_table("drive_map")}
    shared_map = parse_drive_map(map_raw, f"{path}.drive_map", config.source)
    drives_section = s.table("drives")
    drives = {
        axis: _parse_drive(drives_section, axis, link, map_raw, shared_map, config.source)
        for axis in config.axes
    }
    drives_section.finish()
    coupler = _parse_coupler(s, link, config.source)
    s.finish()

    units: dict[tuple[Endpoint | None, int], str] = {}
    for name, (endpoint, device_id) in [
        (f"drives.{a}", (d.endpoint, d.device_id)) for a, d in drives.items()
    ] + [("io", (coupler.endpoint, coupler.device_id))]:
        other = units.get((endpoint, device_id))
        if other is not None:
            raise ConfigError(
                f"{path}.{name}.device_id",
                device_id,
                f"a unit id not already used by {path}.{other}",
                config.source,
            )
        units[(endpoint, device_id)] = name
    return ModbusSettings(link, drives, coupler)
