"""The simulated world seen through CANopen: drive and I/O nodes whose devices are the
world's (``app.drivers.sim``), as ``app.drivers.modbus.emulation`` is for Modbus.

Why a view and not another model: the CiA 402 drives of :mod:`app.drivers.sim.drive` (power
state machine on the controlword, CSP with finite acceleration, homing on a switch, fault
codes, limit switches, safe torque off), the pneumatics, the spindle, the board and the
E-stop chain are the machine the simulation backend and the Modbus emulator drive; the
CANopen backend meets exactly that machine here, only through SDOs, PDOs, EMCY and
heartbeats (the node infrastructure of :mod:`tests.drivers.canopen.sim_nodes`). So the fault
matrix and the CANopen unit tests inject the same faults into the same world on every
backend, and there is no second drive model with its own power state machine.

Time: the X drive is the world's clock: at every SYNC, before any node samples its TPDOs,
the world advances by one period. While the bus is silent (a lost link, after which the
backend sends no SYNC) world time must still pass so that the drives' and the I/O's
watchdogs and fault reactions act, as on the machine, where every drive runs on its own
clock. Two ways, for the two kinds of test: :meth:`WorldBus.follow_clock` follows the
machine runtime's simulated clock (the runtime calls it every tick); with ``own_clock`` a
thread lets world time follow real time once no SYNC came for :data:`SILENT_AFTER_S`, for
the tests that drive the backend by hand against the real-time heartbeats. A link the world
cuts (a comms_loss injected) silences its nodes: no PDO, no heartbeat.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Collection, Mapping
from dataclasses import dataclass, field

from canopen.sdo import SdoAbortedError

from app.drivers.canopen import objects as obj
from app.drivers.cia402 import Cia402State, OperationMode
from app.drivers.contracts import OutputImage
from app.drivers.sim.drive import SimDrive
from app.drivers.sim.world import SimWorld
from tests.drivers.canopen.sim_nodes import NodeThread, SimIoNode, SimNetwork, SimNode

_MODES = {int(mode): mode for mode in OperationMode}
# RPDO1 carries controlword, target, mode; a drive applies the mode first (it decides what
# controlword bit 4 means), then the controlword, then the target.
_APPLY_ORDER = (obj.MODES_OF_OPERATION, obj.CONTROLWORD, obj.TARGET_POSITION)
# The homing methods (0x6098) the drives accept; another is refused with an SDO abort.
SUPPORTED_HOMING_METHODS = frozenset({17, 18, 19, 20, 21, 22, 33, 34, 35, 37})
ABORT_VALUE_RANGE = 0x06090030
# Real time without a SYNC after which the drives' own clock runs the world (``own_clock``):
# well above a period's round trip on a loaded machine, well below the consumer times.
SILENT_AFTER_S = 0.1
OWN_CLOCK_TICK_S = 0.01
# CiA 301 error register (0x1001) bits by the EMCY code's class (its top hex digit): current,
# voltage, temperature, communication; any other class is manufacturer specific. Bit 0
# (generic error) is set with every one.
_REGISTER_BITS = {0x2: 0x02, 0x3: 0x04, 0x4: 0x08, 0x8: 0x10}


def error_register(code: int) -> int:
    """The error register a drive shows (and sends in its EMCY) while ``code`` is active."""
    if not code:
        return 0
    return _REGISTER_BITS.get(code >> 12, 0x80) | 0x01


@dataclass
class DriveRecord:
    """What a test may check afterwards: the controlwords the drive took (while OPERATIONAL),
    the targets it followed (enabled, in CSP), both with the SYNC count, and the EMCY codes
    it sent."""

    controlwords: list[tuple[int, int]] = field(default_factory=list)  # (sync, controlword)
    targets: list[tuple[int, int]] = field(default_factory=list)  # (sync, counts)
    emcy_sent: list[int] = field(default_factory=list)


class WorldBus:
    """The world, its lock (the bus's notifier thread and the test's thread both touch it)
    and the nodes that show it on one virtual CAN channel."""

    def __init__(
        self,
        world: SimWorld,
        channel: str,
        node_ids: Mapping[str, int],
        counts_per_unit: Mapping[str, float],
        io_node: int,
        input_bits: Mapping[str, int],
        output_bits: Mapping[str, int],
        analog: Mapping[str, int] | None = None,
        *,
        without_consumer: Collection[str] = (),
        inverted_inputs: Collection[str] = (),
        own_clock: bool = False,
    ) -> None:
        """``without_consumer``: drives whose dictionary has no 0x1016 (no heartbeat
        consumer); ``inverted_inputs``: functions whose terminal reads 0 when they are on;
        ``own_clock``: world time follows real time while no SYNC comes."""
        self.world = world
        self.lock = threading.RLock()
        self._links = (True, True)  # the drives' and the I/O's link as last seen
        self._synced = (time.monotonic(), world.time_s)  # real and world time of the last SYNC
        self.network = SimNetwork(channel)
        self.drives = {
            name: WorldDrive(
                self,
                node,
                world.drives[name],
                counts_per_unit[name],
                heartbeat_consumer=name not in without_consumer,
            )
            for name, node in node_ids.items()
        }
        self.clock = self.drives[next(iter(node_ids))]
        self.io = WorldIo(self, io_node, input_bits, output_bits, analog or {}, inverted_inputs)
        for node in self.network.nodes:
            node.boot()
        self._own_clock = _OwnClock(self) if own_clock else None

    def follow_clock(self, time_s: float) -> None:
        """Let world time pass while no SYNC comes (more than two periods behind)."""
        world = self.world
        with self.lock:
            while world.time_s < time_s - 2 * world.period_s:
                world.advance(world.period_s)
            self._silence_cut_links()

    def tick(self) -> None:
        """One SYNC's worth of world time (called by the clock node)."""
        with self.lock:
            self.world.advance(self.world.period_s)
            self._synced = (time.monotonic(), self.world.time_s)
            self._silence_cut_links()

    def run_while_silent(self) -> None:
        """One look of the drives' own clock: after :data:`SILENT_AFTER_S` of real time
        without a SYNC, world time catches up with the real time since the last SYNC; what
        the drives did meanwhile (a fault reaction ending, an EMCY) shows on the bus."""
        with self.lock:
            synced_real_s, synced_world_s = self._synced
            silent_s = time.monotonic() - synced_real_s
            if silent_s < SILENT_AFTER_S:
                return
            self.follow_clock(synced_world_s + silent_s)
        for drive in self.drives.values():  # outside the world's lock: see WorldDrive
            drive.publish()

    def _silence_cut_links(self) -> None:
        """Silence the nodes of a link the world cut, and hear them again when it is
        restored; only on a change, so that a test may silence one node by itself."""
        links = (self.world.link_ok("drives"), self.world.link_ok("io"))
        if links == self._links:
            return
        self._links = links
        for drive in self.drives.values():
            drive.silence_heartbeat(not links[0])
        self.io.silence_heartbeat(not links[1])

    def close(self) -> None:
        if self._own_clock is not None:
            self._own_clock.close()
        self.network.close()


class _OwnClock(NodeThread):
    """The thread that runs :meth:`WorldBus.run_while_silent` every
    :data:`OWN_CLOCK_TICK_S`."""

    def __init__(self, bus: WorldBus) -> None:
        super().__init__()
        self._bus = bus
        self.start("world own clock")

    def _run(self) -> None:
        while True:
            with self._cond:
                if self._cond.wait_for(lambda: self._stopped, OWN_CLOCK_TICK_S):
                    return
            self._bus.run_while_silent()


class WorldDrive(SimNode):
    """A CiA 402 drive node over one of the world's drives."""

    link = "drives"

    def __init__(
        self,
        bus: WorldBus,
        node_id: int,
        drive: SimDrive,
        counts: float,
        *,
        heartbeat_consumer: bool = True,
    ) -> None:
        self.bus = bus
        self.drive = drive
        self.counts = counts
        self.record = DriveRecord()
        self._powered = False  # the first reset_application is the node's start-up
        self._buffer: dict[int, int] | None = None
        self._emcy_seen = len(bus.world.emcy_log)
        od = obj.build_drive_od(node_id)
        if not heartbeat_consumer:
            del od[obj.CONSUMER_HEARTBEAT_TIME]
        super().__init__(bus.network, node_id, od)

    def reset_application(self) -> None:
        """A reboot of the node is a power cycle of the world's drive (not at start-up: the
        world powered it up already)."""
        if self._powered:
            with self.bus.lock:
                self.drive.power_cycle()
        self._powered = True

    def move_by_hand(self, counts: int) -> None:
        """The axis pushed to ``counts`` on its encoder while its drive is not powered."""
        with self.bus.lock:
            self.drive.move_by_hand(counts / self.counts)

    def _on_sync(self, can_id: int, data: bytearray, timestamp: float) -> None:
        if self is self.bus.clock:
            self.bus.tick()
        if not self.bus.world.link_ok(self.link):
            return  # the cut cable: nothing heard, nothing sent
        with self.bus.lock:
            super()._on_sync(can_id, data, timestamp)

    def _apply_rpdo(self, number: int, data: bytes) -> None:
        self._buffer = {}
        try:
            super()._apply_rpdo(number, data)
            values = self._buffer
        finally:
            self._buffer = None
        for index in _APPLY_ORDER:
            if index in values:
                self._write(index, values[index])

    def on_write(self, index: int, subindex: int, value: object) -> None:
        assert isinstance(value, int)
        if index == obj.HOMING_METHOD and value not in SUPPORTED_HOMING_METHODS:
            raise SdoAbortedError(ABORT_VALUE_RANGE)
        if self._buffer is not None:
            self._buffer[index] = value
        else:
            self._write(index, value)

    def _write(self, index: int, value: int) -> None:
        drive = self.drive
        if index == obj.CONTROLWORD:
            if self.nmt_state == "OPERATIONAL":
                self.record.controlwords.append((self.sync_count, value))
            drive.write_controlword(value)
        elif index == obj.TARGET_POSITION:
            if (
                drive.state is Cia402State.OPERATION_ENABLED
                and drive.mode is OperationMode.CYCLIC_SYNC_POSITION
            ):
                self.record.targets.append((self.sync_count, value))
            drive.write_target(value / self.counts)
        elif index == obj.MODES_OF_OPERATION and value in _MODES:
            drive.set_mode(_MODES[value])

    def on_read(self, index: int, subindex: int) -> int | None:
        drive = self.drive
        inputs = (
            obj.DI_NEGATIVE_LIMIT * drive.limit_negative
            | obj.DI_POSITIVE_LIMIT * drive.limit_positive
            | obj.DI_HOME_SWITCH * drive.home_switch
        )
        return {
            obj.STATUSWORD: drive.statusword,
            obj.POSITION_ACTUAL: round(drive.position * self.counts),
            obj.MODES_DISPLAY: int(drive.mode),
            obj.ERROR_CODE: drive.fault_code,
            obj.DIGITAL_INPUTS: inputs,
            obj.ERROR_REGISTER: error_register(drive.fault_code),
            obj.CONTROLWORD: drive.controlword,
        }.get(index)

    def on_sync(self) -> None:
        self.publish()

    def publish(self) -> None:
        """The drive's EMCY messages not sent yet go out on the bus, and whoever waits on
        this node looks again (the world moved)."""
        with self.lock:
            log = self.bus.world.emcy_log
            for record in log[self._emcy_seen :]:
                if record.device == self.drive.name:
                    self.record.emcy_sent.append(record.code)
                    self.node.emcy.send(record.code, error_register(record.code))
            self._emcy_seen = len(log)
            self.changed.notify_all()

    def on_heartbeat_event(self) -> None:
        """The drive reacts under the world's lock and its EMCY goes out at once. The two
        locks are taken one after the other, never one inside the other: a SYNC takes the
        world's then this node's, a reboot this node's then the world's."""
        with self.bus.lock:
            self.drive.heartbeat_lost()
        self.publish()


class WorldIo(SimIoNode):
    """A CiA 401 node over the world's inputs and outputs, wired bit by bit."""

    link = "io"

    def __init__(
        self,
        bus: WorldBus,
        node_id: int,
        input_bits: Mapping[str, int],
        output_bits: Mapping[str, int],
        analog: Mapping[str, int],
        inverted: Collection[str] = (),
    ) -> None:
        self.bus = bus
        self.inverted = frozenset(inverted)
        self.input_bits = dict(input_bits)
        self.output_bits = dict(output_bits)
        self.analog = {sub: name for name, sub in analog.items()}  # 0x6401 sub -> input
        super().__init__(bus.network, node_id)

    def _on_sync(self, can_id: int, data: bytearray, timestamp: float) -> None:
        if not self.bus.world.link_ok(self.link):
            return
        with self.bus.lock:
            super()._on_sync(can_id, data, timestamp)

    def on_read(self, index: int, subindex: int) -> int | None:
        if index == obj.READ_ANALOG_INPUT_16BIT and subindex in self.analog:
            value = getattr(self.bus.world.inputs(), self.analog[subindex]) or 0
            return value - 0x10000 if value >= 0x8000 else value  # INTEGER16 on the wire
        if index == obj.READ_INPUT_8BIT and subindex >= 1:
            image = self.bus.world.inputs()
            self.inputs = sum(
                1 << bit
                for name, bit in self.input_bits.items()
                if bool(getattr(image, name)) is not (name in self.inverted)
            )
        return super().on_read(index, subindex)

    def on_write(self, index: int, subindex: int, value: object) -> None:
        if not self.bus.world.link_ok(self.link):
            return  # a cut link delivers nothing: a late refresh must not switch outputs on
        super().on_write(index, subindex, value)
        if index == obj.WRITE_OUTPUT_8BIT and subindex >= 1:
            image = OutputImage(
                **{name: bool(self.outputs >> bit & 1) for name, bit in self.output_bits.items()}
            )
            self.bus.world.write_outputs(image)
