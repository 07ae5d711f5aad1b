"""The ``[backend.canopen]`` settings: read, checked and cross-checked against the machine.

Why strict: these values decide which node a setpoint goes to and how many encoder counts a
millimetre is. A wrong default would move an axis ten times too far, so node ids, scaling
and the I/O wiring have no defaults; everything else has a safe one. The controller's own
node id (``master_node_id``, for the heartbeat the drives watch) defaults to 127, the usual
id of a CANopen manager, and must differ from every drive's and the I/O node's id. Every bad
value raises ``ConfigError`` with the dotted key (``backend.canopen.axes.X.node_id``), the
value and what is allowed, like the rest of the configuration.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from app.config import AxisConfig, ConfigError, MachineConfig, Section
from app.drivers.canopen.busload import MAX_BUS_LOAD, BusLoad, bus_load
from app.drivers.canopen.master_heartbeat import CONSUMER_TIMEOUT_MAX_MS
from app.drivers.canopen.pdo import cyclic_frames
from app.drivers.contracts import ANALOG_INPUTS, DIGITAL_INPUTS, PENDANT_INPUTS, OutputImage

ROOT = "backend.canopen"
BITRATES: tuple[int, ...] = (10_000, 20_000, 50_000, 125_000, 250_000, 500_000, 800_000, 1_000_000)
# python-can interfaces (can.interfaces.VALID_INTERFACES of python-can 4.6) minus
# udp_multicast, which is no CAN bus and sends to a non-loopback multicast address.
INTERFACES: tuple[str, ...] = (
    "canalystii",
    "cantact",
    "etas",
    "gs_usb",
    "iscan",
    "ixxat",
    "kvaser",
    "neousys",
    "neovi",
    "nican",
    "nixnet",
    "pcan",
    "robotell",
    "seeedstudio",
    "serial",
    "slcan",
    "socketcan",
    "socketcand",
    "systec",
    "usb2can",
    "vector",
    "virtual",
)
# CiA 402 homing methods: 1-14 with index pulse, 17-30 without, 33/34 index only,
# 35 and 37 current position; negative values are manufacturer specific.
HOMING_METHODS: frozenset[int] = frozenset(
    [*range(1, 15), *range(17, 31), 33, 34, 35, 37, *range(-128, 0)]
)
INPUT_FUNCTIONS: tuple[str, ...] = tuple(n for n in DIGITAL_INPUTS if n not in PENDANT_INPUTS)
"""The inputs every machine wires (required in the map)."""
OPTIONAL_INPUT_FUNCTIONS: tuple[str, ...] = PENDANT_INPUTS
"""The handwheel's and the joystick's switches: -1 (the default) when not wired."""
OUTPUT_FUNCTIONS: tuple[str, ...] = tuple(f.name for f in dataclasses.fields(OutputImage))
IO_BITS = 32  # a CiA 401 node with up to four bytes of inputs and four of outputs
DEFAULT_MASTER_NODE_ID = 127  # the usual node id of a CANopen manager (NMT master)


@dataclass(frozen=True)
class AxisNodeSettings:
    """One CiA 402 drive: its node, its scaling and its homing method."""

    axis: str
    node_id: int
    counts_per_unit: float  # encoder increments per mm (X, Y) or per degree (Z)
    invert: bool  # the drive counts positive where the machine axis runs negative
    homing_method: int

    def to_counts(self, position: float) -> int:
        sign = -1.0 if self.invert else 1.0
        return round(position * self.counts_per_unit * sign)

    def from_counts(self, counts: int) -> float:
        sign = -1.0 if self.invert else 1.0
        return counts * sign / self.counts_per_unit


@dataclass(frozen=True)
class IoNodeSettings:
    """The CiA 401 digital I/O node and which terminal bit each machine function uses."""

    node_id: int
    inputs: Mapping[str, int]  # InputImage field -> input bit (0x6000, bit 0 = sub 1 bit 0)
    outputs: Mapping[str, int]  # OutputImage field -> output bit (0x6200)
    inverted_inputs: frozenset[str]  # functions whose terminal reads 0 when the function is on
    # ANALOG_INPUTS name -> sub-index of 0x6401 (read analog input 16-bit); unwired absent
    analog: Mapping[str, int] = field(default_factory=dict)

    @property
    def input_bytes(self) -> int:
        return max(self.inputs.values()) // 8 + 1

    @property
    def output_bytes(self) -> int:
        return max(self.outputs.values()) // 8 + 1


@dataclass(frozen=True)
class CanopenSettings:
    interface: str
    channel: str | int
    bitrate: int
    period_s: float  # SYNC period: one SYNC per write_setpoints, i.e. backend.period_ms
    heartbeat_ms: int  # producer heartbeat time of every node (0x1017) and of ours
    heartbeat_timeout_ms: int  # our consumer: a node silent this long is lost
    master_node_id: int  # the controller's node id: its heartbeat is 0x700 + this
    master_heartbeat_timeout_ms: int  # the drives' consumer (0x1016): controller silent
    sdo_timeout_ms: int
    startup_timeout_ms: int  # wait for first heartbeat / first TPDO at start-up
    pdo_miss_limit: int  # consecutive SYNCs without a drive's TPDO1 before it is lost
    slow_feedback_every_n_sync: int  # TPDO2 (digital inputs, error code) transmission type
    axes: Mapping[str, AxisNodeSettings]
    io: IoNodeSettings

    @property
    def node_ids(self) -> list[int]:
        return [a.node_id for a in self.axes.values()] + [self.io.node_id]

    def bus_load(self) -> BusLoad:
        frames = cyclic_frames(
            len(self.axes),
            self.slow_feedback_every_n_sync,
            self.io.input_bytes,
            len(self.node_ids) + 1,  # and the controller's own heartbeat
            self.heartbeat_ms,
            self.period_s,
        )
        return bus_load(frames, self.period_s, self.bitrate)


_MISSING = object()


class _Table(Section):
    """:class:`app.config.Section` plus what these settings need beyond it: values without a
    default (``_MISSING``: refused with "(required)"), a note on what a whole number means in
    its message, positive numbers, choices of any type, and required sub-tables.

    The messages name no file (source ""), as these settings' messages always have."""

    def __init__(self, data: object, path: str) -> None:
        super().__init__(data, path, "")

    def value(self, name: str, default: object, allowed: str) -> object:
        self._used.add(name)
        value = self._data.get(name, default)
        if value is _MISSING:
            raise self.error(name, None, f"{allowed} (required)")
        return value

    def integer(
        self, name: str, default: object, minimum: int, maximum: int, what: str = ""
    ) -> int:
        allowed = f"a whole number from {minimum} to {maximum}{what}"
        value = self.value(name, default, allowed)
        if isinstance(value, bool) or not isinstance(value, int) or not minimum <= value <= maximum:
            raise self.error(name, value, allowed)
        return value

    def positive(self, name: str, default: object, what: str = "") -> float:
        allowed = f"a number > 0{what}"
        value = self.value(name, default, allowed)
        if (
            isinstance(value, bool)
            or not isinstance(value, int | float)
            or not math.isfinite(value)
            or value <= 0
        ):
            raise self.error(name, value, allowed)
        return float(value)

    def choice(self, name: str, default: object, choices: tuple[Any, ...]) -> Any:
        allowed = "one of " + ", ".join(repr(c) for c in choices)
        value = self.value(name, default, allowed)
        if isinstance(value, bool) or value not in choices:
            raise self.error(name, value, allowed)
        return value

    def table(self, name: str, *, required: bool = False) -> _Table:
        value = self.value(name, _MISSING if required else {}, "a table")
        return _Table(value, self._key(name))


def _read_axis(table: _Table, axis: AxisConfig) -> AxisNodeSettings:
    node_id = table.integer("node_id", _MISSING, 1, 127, " (the drive's CANopen node id)")
    counts = table.positive(
        "counts_per_unit", _MISSING, f" (encoder increments per {axis.unit} of axis {axis.name})"
    )
    invert = table.boolean("invert", False)
    default_method = 21 if axis.homing_direction < 0 else 19  # home switch, no index pulse
    method = table.integer(
        "homing_method",
        default_method,
        -128,
        37,
        ", a CiA 402 homing method (1-14, 17-30, 33-35, 37 or < 0)",
    )
    if method not in HOMING_METHODS:
        raise table.error(
            "homing_method", method, "a CiA 402 homing method (1-14, 17-30, 33-35, 37 or < 0)"
        )
    table.finish()
    reach = max(abs(axis.min_position), abs(axis.max_position)) + axis.limit_switch_margin
    if reach * counts >= 2**31:
        raise table.error(
            "counts_per_unit",
            counts,
            f"at most {(2**31 - 1) / reach:.6g}: position {reach:g} {axis.unit} "
            "must fit in the drive's 32-bit position",
        )
    return AxisNodeSettings(axis.name, node_id, counts, invert, method)


def _read_bits(
    table: _Table, functions: tuple[str, ...], kind: str, optional: tuple[str, ...] = ()
) -> dict[str, int]:
    bits: dict[str, int] = {}
    for name in (*functions, *optional):
        wired = name in functions
        bit = table.integer(
            name,
            _MISSING if wired else -1,
            0 if wired else -1,
            IO_BITS - 1,
            f" (the {kind} bit of this function on the I/O node{'' if wired else ', -1: none'})",
        )
        if bit < 0:
            continue
        clash = [other for other, used in bits.items() if used == bit]
        if clash:
            raise table.error(name, bit, f"a bit no other {kind} uses ({clash[0]} has {bit})")
        bits[name] = bit
    table.finish()
    return bits


def _read_io(table: _Table) -> IoNodeSettings:
    node_id = table.integer("node_id", _MISSING, 1, 127, " (the I/O node's CANopen node id)")
    inputs = _read_bits(
        table.table("inputs", required=True), INPUT_FUNCTIONS, "input", OPTIONAL_INPUT_FUNCTIONS
    )
    outputs = _read_bits(table.table("outputs", required=True), OUTPUT_FUNCTIONS, "output")
    inverted = table.value("inverted_inputs", [], "a list of input functions")
    if not isinstance(inverted, list) or any(n not in inputs for n in inverted):
        raise table.error(
            "inverted_inputs", inverted, "a list of input functions: " + ", ".join(INPUT_FUNCTIONS)
        )
    analog = _read_analog(table.table("analog"))
    table.finish()
    return IoNodeSettings(node_id, inputs, outputs, frozenset(inverted), analog)


ANALOG_SUBS = 4  # sub-indices of 0x6401 on the I/O node


def _read_analog(table: _Table) -> dict[str, int]:
    """``[backend.canopen.io.analog]``: the 0x6401 sub-index of the handwheel's counter and
    of each joystick axis, -1 (the default) when not wired."""
    subs: dict[str, int] = {}
    for name in ANALOG_INPUTS:
        sub = table.integer(name, -1, -1, ANALOG_SUBS, " (0x6401 sub-index, -1: none)")
        if sub == 0:
            raise table.error(name, sub, "a sub-index from 1 (0 holds the number of inputs)")
        if sub < 0:
            continue
        clash = [other for other, used in subs.items() if used == sub]
        if clash:
            raise table.error(name, sub, f"a sub-index no other input uses ({clash[0]} has {sub})")
        subs[name] = sub
    table.finish()
    return subs


def parse_settings(raw: Mapping[str, Any], config: MachineConfig) -> CanopenSettings:
    """Check ``config.backend_settings["canopen"]`` against the machine configuration."""
    root = _Table(raw, ROOT)
    interface = root.choice("interface", "socketcan", INTERFACES)
    channel = root.value("channel", "can0", "a channel name or number")
    if isinstance(channel, bool) or not isinstance(channel, str | int) or channel == "":
        raise root.error("channel", channel, 'a channel name ("can0") or number')
    bitrate = root.choice("bitrate", 1_000_000, BITRATES)
    heartbeat_ms = root.integer("heartbeat_ms", 100, 10, 10_000)
    timeout_ms = root.integer("heartbeat_timeout_ms", round(2.5 * heartbeat_ms), 15, 60_000)
    if timeout_ms < 1.5 * heartbeat_ms:
        raise root.error(
            "heartbeat_timeout_ms",
            timeout_ms,
            f"at least 1.5 x heartbeat_ms ({1.5 * heartbeat_ms:g})",
        )
    master_node_id = root.integer(
        "master_node_id", DEFAULT_MASTER_NODE_ID, 1, 127, " (the controller's own node id)"
    )
    master_timeout_ms = root.integer(
        "master_heartbeat_timeout_ms",
        round(2.5 * heartbeat_ms),
        15,
        CONSUMER_TIMEOUT_MAX_MS,
        " (the drives stop when the controller's heartbeat is silent this long)",
    )
    if master_timeout_ms < 1.5 * heartbeat_ms:
        raise root.error(
            "master_heartbeat_timeout_ms",
            master_timeout_ms,
            f"at least 1.5 x heartbeat_ms ({1.5 * heartbeat_ms:g}): the controller's heartbeat "
            "is sent every heartbeat_ms",
        )
    sdo_timeout_ms = root.integer("sdo_timeout_ms", 300, 10, 10_000)
    startup_ms = root.integer("startup_timeout_ms", max(1000, 2 * timeout_ms), 10, 60_000)
    miss_limit = root.integer("pdo_miss_limit", 5, 1, 1000)
    slow_every = root.integer("slow_feedback_every_n_sync", 5, 1, 240)

    axes_table = root.table("axes", required=True)
    axes = {
        name: _read_axis(axes_table.table(name, required=True), axis)
        for name, axis in config.axes.items()
    }
    axes_table.finish()
    io = _read_io(root.table("io", required=True))
    root.finish()

    seen: dict[int, str] = {}
    for key, node_id in [
        *((f"axes.{n}.node_id", a.node_id) for n, a in axes.items()),
        ("io.node_id", io.node_id),
        ("master_node_id", master_node_id),
    ]:
        if node_id in seen:
            raise ConfigError(
                f"{ROOT}.{key}",
                node_id,
                f"a node id no other node uses ({seen[node_id]} has {node_id})",
            )
        seen[node_id] = key

    settings = CanopenSettings(
        interface,
        channel,
        bitrate,
        config.period_s,
        heartbeat_ms,
        timeout_ms,
        master_node_id,
        master_timeout_ms,
        sdo_timeout_ms,
        startup_ms,
        miss_limit,
        slow_every,
        axes,
        io,
    )
    load = settings.bus_load()
    if load.maximum > MAX_BUS_LOAD:
        raise ConfigError(
            f"{ROOT}.bitrate",
            bitrate,
            f"a bitrate that keeps the cyclic bus load under "
            f"{100 * MAX_BUS_LOAD:.0f} % (now {load.describe()}: raise the "
            "bitrate or backend.period_ms)",
        )
    return settings


def settings_from_config(config: MachineConfig) -> CanopenSettings:
    return parse_settings(config.backend_settings.get("canopen", {}), config)
