"""Simulated CANopen nodes for the tests: CiA 402 servo drives and a CiA 401 I/O node.

Each node is a canopen ``LocalNode`` (its SDO server answers the backend's configuration)
with an object dictionary built in code (``app.drivers.canopen.objects``), plus what a
LocalNode lacks and a real node does, as the engineering guide says:

- NMT state handling: PDOs are processed and produced only in OPERATIONAL, SDO is refused in
  STOPPED, reset node/communication sends a boot-up message and goes to PRE-OPERATIONAL;
- a heartbeat producer (0x1017) on a thread of our own, so that a test can silence it and
  ``close()`` can join it before the bus goes away;
- a heartbeat consumer (0x1016 sub 1, in the drives' dictionary) on a thread of our own, as
  CiA 301 has it: it starts watching the named producer at the first heartbeat it hears after
  being configured (or after its last event), and a silence longer than the configured time
  is one heartbeat event (``on_heartbeat_event``), after which it waits for the next
  heartbeat; writing 0 switches it off. A drive faults on the event while its power stage is
  on (0x8130, EMCY), like a real drive with abort-connection option "fault" (0x6007 = 1); its
  NMT state does not change (0x1029 "no state change");
- PDOs driven by the communication and mapping objects the master downloads (CiA 301
  procedure checked: mapping only while the PDO is invalid and its count is 0), RPDOs taken
  at the next SYNC (types 0-240) or at once (254/255), TPDOs sent on every n-th SYNC;
- remote frames (RTR) for TPDOs and node guarding, which canopen's listener drops;
- the CiA 402 power state machine following the controlword (table below), CSP motion,
  homing, EMCY on a fault, fault reset on the rising edge of bit 7.

All nodes of one test share one ``canopen.Network`` on python-can's ``virtual`` interface;
the backend under test has its own Network on the same channel name.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import can
import canopen
from canopen.nmt import NmtSlave
from canopen.objectdictionary import ObjectDictionary, ODVariable
from canopen.sdo import SdoAbortedError

from app.drivers.canopen import objects as obj
from app.drivers.canopen.master_heartbeat import HEARTBEAT_COB_BASE, split_consumer_heartbeat_entry
from app.drivers.cia402 import CW_HOMING_START, Cia402State, OperationMode

S = Cia402State
MODE_CSP = int(OperationMode.CYCLIC_SYNC_POSITION)
MODE_HOMING = int(OperationMode.HOMING)
NOTIFIER_CYCLE_S = 0.02
NMT_RESET_NODE = 0x81
NMT_RESET_COMMUNICATION = 0x82
NMT_STATE_CODES = {
    "INITIALISING": 0x00,
    "STOPPED": 0x04,
    "OPERATIONAL": 0x05,
    "PRE-OPERATIONAL": 0x7F,
}
SUPPORTED_HOMING_METHODS = frozenset({17, 18, 19, 20, 21, 22, 33, 34, 35, 37})
ABORT_VALUE_RANGE = 0x06090030
ABORT_UNSUPPORTED_ACCESS = 0x06010000
ABORT_NOT_MAPPABLE = 0x06040041
ABORT_PDO_LENGTH = 0x06040042
EMCY_HEARTBEAT = 0x8130  # CiA 301: life guard or heartbeat error
POWERED = (Cia402State.OPERATION_ENABLED, Cia402State.QUICK_STOP_ACTIVE)


class _HeartbeatProducer:
    """Sends the node's NMT state every period; joinable, can be silenced by a test."""

    def __init__(self, send: Callable[[], None]) -> None:
        self._send = send
        self._cond = threading.Condition()
        self._period_s = 0.0
        self._silenced = False
        self._stopped = False
        self._thread = threading.Thread(target=self._run, name="sim heartbeat", daemon=True)
        self._thread.start()

    def set_period_ms(self, period_ms: int) -> None:
        with self._cond:
            self._period_s = period_ms / 1000.0
            self._cond.notify_all()

    def silence(self, silenced: bool) -> None:
        with self._cond:
            self._silenced = silenced
            self._cond.notify_all()

    def close(self) -> None:
        with self._cond:
            self._stopped = True
            self._cond.notify_all()
        self._thread.join()

    def _run(self) -> None:
        while True:
            with self._cond:
                self._cond.wait_for(
                    lambda: self._stopped or (self._period_s > 0 and not self._silenced)
                )
                if self._stopped:
                    return
                if self._cond.wait_for(lambda: self._stopped, self._period_s):
                    return
                due = self._period_s > 0 and not self._silenced
            if due:
                self._send()


class _HeartbeatConsumer:
    """Watches one producer's heartbeat (CiA 301 consumer); joinable, its own thread.

    Off until configured with a time; then idle until a heartbeat is heard, watching from
    that heartbeat on; a silence longer than the time calls ``on_event`` once (outside this
    object's lock) and makes it idle again until the next heartbeat."""

    def __init__(self, on_event: Callable[[], None]) -> None:
        self._on_event = on_event
        self._cond = threading.Condition()
        self._timeout_s = 0.0  # 0: off
        self._last: float | None = None  # monotonic time of the last heartbeat; None: idle
        self._stopped = False
        self.events = 0  # heartbeat events so far (for the tests' assertions)
        self._thread = threading.Thread(target=self._run, name="sim hb consumer", daemon=True)
        self._thread.start()

    def configure(self, timeout_ms: int) -> None:
        with self._cond:
            self._timeout_s = timeout_ms / 1000.0
            self._last = None
            self._cond.notify_all()

    def heard(self) -> None:
        """A heartbeat of the watched producer arrived (receive thread)."""
        with self._cond:
            if self._timeout_s > 0:
                self._last = time.monotonic()
                self._cond.notify_all()

    @property
    def watching(self) -> bool:
        with self._cond:
            return self._timeout_s > 0 and self._last is not None

    def wait_events(self, count: int, timeout_s: float) -> bool:
        with self._cond:
            return self._cond.wait_for(lambda: self.events >= count, timeout_s)

    def close(self) -> None:
        with self._cond:
            self._stopped = True
            self._cond.notify_all()
        self._thread.join()

    def _run(self) -> None:
        while True:
            with self._cond:
                self._cond.wait_for(
                    lambda: self._stopped or (self._timeout_s > 0 and self._last is not None)
                )
                if self._stopped:
                    return
                assert self._last is not None
                remaining_s = self._last + self._timeout_s - time.monotonic()
                if remaining_s > 0:
                    self._cond.wait(remaining_s)  # a heartbeat, a new time or close: re-check
                    continue
                self._last = None  # the event: idle until the next heartbeat
                self.events += 1
                self._cond.notify_all()
            self._on_event()


class _SimNmt(NmtSlave):
    """canopen's NMT slave with the heartbeat handed to our producer."""

    def __init__(
        self, node_id: int, local_node: canopen.LocalNode, producer: _HeartbeatProducer
    ) -> None:
        super().__init__(node_id, local_node)
        self._producer = producer

    def start_heartbeat(self, heartbeat_time_ms: int) -> None:
        self._heartbeat_time_ms = heartbeat_time_ms
        self._producer.set_period_ms(heartbeat_time_ms)

    def stop_heartbeat(self) -> None:
        self._producer.set_period_ms(0)

    def update_heartbeat(self) -> None:
        """The producer reads the state at every beat."""


@dataclass
class _Tpdo:
    sync_count: int = 0


class SimNode:
    """A LocalNode with NMT states, heartbeat, PDO processing and RTR."""

    def __init__(self, network: SimNetwork, node_id: int, od: ObjectDictionary) -> None:
        self.network = network
        self.node_id = node_id
        self.lock = threading.RLock()
        self.changed = threading.Condition(self.lock)
        self.reject: dict[tuple[int, int], int] = {}  # (index, sub) -> SDO abort code
        self.rpdos_dropped = False  # test control: a receive path that loses every RPDO
        self.node = canopen.LocalNode(node_id, od)
        self._producer = _HeartbeatProducer(self._beat)
        self.consumer = _HeartbeatConsumer(self._on_heartbeat_event)
        self._consumer_cob: int | None = None  # heartbeat COB-ID the consumer listens to
        old_nmt = self.node.nmt
        self.node.nmt = _SimNmt(node_id, self.node, self._producer)
        self.node._write_callbacks.remove(old_nmt.on_write)  # private: the NMT slave was replaced
        self.node.add_write_callback(self.node.nmt.on_write)
        self.node.add_write_callback(self._on_write)
        self.node.add_read_callback(self._on_read)
        self._defaults = od
        self._rpdo_cobs: dict[int, int] = {}  # RPDO number -> subscribed COB-ID
        self._rpdo_pending: dict[int, bytes] = {}
        self._tpdos = {n: _Tpdo() for n in range(1, obj.PDO_SLOTS + 1)}
        self.sync_count = 0
        self.heartbeats_sent = 0
        self.guard_toggle = 0
        self.reset_application()  # device state exists before the first frame can arrive
        raw = network.network
        raw.add_node(self.node)
        raw.unsubscribe(0x600 + node_id, self.node.sdo.on_request)
        raw.subscribe(0x600 + node_id, self._on_sdo)
        raw.subscribe(0, self._on_nmt)
        raw.subscribe(0x80, self._on_sync)
        network.nodes.append(self)

    # ---- NMT ----
    @property
    def nmt_state(self) -> str:
        return str(self.node.nmt.state)

    def boot(self) -> None:
        """Power-on: boot-up message, then PRE-OPERATIONAL with the stored heartbeat time."""
        with self.lock:
            self.node.nmt.send_command(NMT_RESET_NODE)  # state INITIALISING: boot-up sent
            self.node.nmt.send_command(0x80)  # PRE-OPERATIONAL, heartbeat from 0x1017
            self.changed.notify_all()

    def reboot(self) -> None:
        """A power cycle: every object back to its default, then boot."""
        with self.lock:
            self.node.data_store.clear()
            self._reset_pdo_subscriptions()
            self._set_consumer(0)
            self.reset_application()
            self.boot()

    def reset_application(self) -> None:
        """Hook: device-profile state back to power-on."""

    def _reset_pdo_subscriptions(self) -> None:
        for number, cob_id in list(self._rpdo_cobs.items()):
            self.network.network.unsubscribe(cob_id, self._on_rpdo)
            del self._rpdo_cobs[number]
        self._rpdo_pending.clear()

    def _on_nmt(self, can_id: int, data: bytearray, timestamp: float) -> None:
        command, target = data[0], data[1]
        if target not in (0, self.node_id):
            return
        with self.lock:
            if command == NMT_RESET_NODE:
                self.reboot()
            elif command == NMT_RESET_COMMUNICATION:
                for index in list(self.node.data_store):
                    if 0x1000 <= index < 0x2000:
                        del self.node.data_store[index]
                self._reset_pdo_subscriptions()
                self._set_consumer(0)
                self.boot()
            self.changed.notify_all()

    def _beat(self) -> None:
        state = NMT_STATE_CODES.get(self.nmt_state, 0x7F)
        self.network.send(0x700 + self.node_id, bytes([state]))
        with self.lock:
            self.heartbeats_sent += 1
            self.changed.notify_all()

    def silence_heartbeat(self, silenced: bool = True) -> None:
        self._producer.silence(silenced)

    # ---- heartbeat consumer (0x1016 sub 1) ----
    def _set_consumer(self, entry: int) -> None:
        """Watch the producer an 0x1016 entry names, for its time; 0 switches it off."""
        producer, timeout_ms = split_consumer_heartbeat_entry(entry)
        if self._consumer_cob is not None:
            self.network.network.unsubscribe(self._consumer_cob, self._on_consumed_heartbeat)
            self._consumer_cob = None
        if producer and timeout_ms:
            self._consumer_cob = HEARTBEAT_COB_BASE + producer
            self.network.network.subscribe(self._consumer_cob, self._on_consumed_heartbeat)
        self.consumer.configure(timeout_ms if producer else 0)

    def _on_consumed_heartbeat(self, can_id: int, data: bytearray, timestamp: float) -> None:
        self.consumer.heard()

    def _on_heartbeat_event(self) -> None:
        with self.lock:
            self.on_heartbeat_event()
            self.changed.notify_all()

    def on_heartbeat_event(self) -> None:
        """Hook: the watched producer was silent longer than the consumer time."""

    # ---- SDO ----
    def _on_sdo(self, can_id: int, data: bytearray, timestamp: float) -> None:
        if self.nmt_state == "STOPPED":
            return
        with self.lock:
            self.node.sdo.on_request(can_id, data, timestamp)

    def read(self, index: int, subindex: int = 0) -> int:
        """The value of an object, decoded (for the tests' assertions)."""
        with self.lock:
            var = self._variable(index, subindex)
            value = var.decode_raw(self.node.get_data(index, subindex))
        assert isinstance(value, int)
        return value

    def _variable(self, index: int, subindex: int) -> ODVariable:
        entry = self._defaults[index]
        return entry if isinstance(entry, ODVariable) else entry[subindex]

    # ---- object access hooks ----
    def _on_write(self, index: int, subindex: int, od: ODVariable, data: bytes) -> None:
        code = self.reject.get((index, subindex))
        if code is not None:
            raise SdoAbortedError(code)
        value = od.decode_raw(data)
        self._check_pdo_write(index, subindex, value)
        self.on_write(index, subindex, value)
        if index == obj.CONSUMER_HEARTBEAT_TIME and subindex == 1:
            self._set_consumer(int(value))
        if subindex == 1 and obj.RPDO_COMM <= index < obj.RPDO_COMM + obj.PDO_SLOTS:
            self._subscribe_rpdo(index - obj.RPDO_COMM + 1, int(value))
        self.changed.notify_all()

    def _on_read(self, index: int, subindex: int, od: ODVariable) -> int | None:
        return self.on_read(index, subindex)

    def on_write(self, index: int, subindex: int, value: object) -> None:
        """Hook: the device reacts to an object written by SDO or RPDO."""

    def on_read(self, index: int, subindex: int) -> int | None:
        """Hook: live value of an object, None for the stored one."""
        return None

    # ---- PDO ----
    def _check_pdo_write(self, index: int, subindex: int, value: object) -> None:
        for base, comm in ((obj.RPDO_MAPPING, obj.RPDO_COMM), (obj.TPDO_MAPPING, obj.TPDO_COMM)):
            if not base <= index < base + obj.PDO_SLOTS:
                continue
            cob_id = self._stored(comm + index - base, 1)
            if not cob_id & (1 << 31):
                raise SdoAbortedError(ABORT_UNSUPPORTED_ACCESS)  # PDO still valid
            if subindex != 0:
                if self._stored(index, 0) != 0:
                    raise SdoAbortedError(ABORT_UNSUPPORTED_ACCESS)  # count not 0 first
                return
            assert isinstance(value, int)
            bits = 0
            for sub in range(1, value + 1):
                entry = self._stored(index, sub)
                mapped = self._mapped_variable(entry)
                if mapped is None or not mapped.pdo_mappable:
                    raise SdoAbortedError(ABORT_NOT_MAPPABLE)
                bits += entry & 0xFF
            if bits > 64:
                raise SdoAbortedError(ABORT_PDO_LENGTH)

    def _mapped_variable(self, entry: int) -> ODVariable | None:
        index, sub = entry >> 16, (entry >> 8) & 0xFF
        if index not in self._defaults:
            return None
        item = self._defaults[index]
        if isinstance(item, ODVariable):
            return item
        return item.get(sub)

    def _stored(self, index: int, subindex: int) -> int:
        var = self._variable(index, subindex)
        value = var.decode_raw(self.node.get_data(index, subindex))
        assert isinstance(value, int)
        return value

    def _mapping(self, map_index: int) -> list[tuple[int, int, int]]:
        count = self._stored(map_index, 0)
        entries = [self._stored(map_index, sub) for sub in range(1, count + 1)]
        return [(e >> 16, (e >> 8) & 0xFF, e & 0xFF) for e in entries]

    def _subscribe_rpdo(self, number: int, cob_word: int) -> None:
        old = self._rpdo_cobs.pop(number, None)
        if old is not None:
            self.network.network.unsubscribe(old, self._on_rpdo)
        if not cob_word & (1 << 31):
            cob_id = cob_word & 0x7FF
            self._rpdo_cobs[number] = cob_id
            self.network.network.subscribe(cob_id, self._on_rpdo)

    def _on_rpdo(self, can_id: int, data: bytearray, timestamp: float) -> None:
        with self.lock:
            if self.nmt_state != "OPERATIONAL" or self.rpdos_dropped:
                return
            for number, cob_id in self._rpdo_cobs.items():
                if cob_id != can_id:
                    continue
                if self._stored(obj.RPDO_COMM + number - 1, 2) <= 240:
                    self._rpdo_pending[number] = bytes(data)  # taken at the next SYNC
                else:
                    self._apply_rpdo(number, bytes(data))

    def _apply_rpdo(self, number: int, data: bytes) -> None:
        mapping = self._mapping(obj.RPDO_MAPPING + number - 1)
        if sum(bits for _, _, bits in mapping) != 8 * len(data):
            self.node.emcy.send(0x8210, 0x11)  # PDO not processed due to length error
            return
        offset = 0
        for index, sub, bits in mapping:
            self.node.set_data(index, sub, data[offset : offset + bits // 8])
            offset += bits // 8

    def _tpdo_payload(self, number: int) -> bytes:
        mapping = self._mapping(obj.TPDO_MAPPING + number - 1)
        return b"".join(self.node.get_data(index, sub)[: bits // 8] for index, sub, bits in mapping)

    def _send_tpdo(self, number: int) -> None:
        cob_id = self._stored(obj.TPDO_COMM + number - 1, 1) & 0x7FF
        self.network.send(cob_id, self._tpdo_payload(number))

    def _on_sync(self, can_id: int, data: bytearray, timestamp: float) -> None:
        with self.lock:
            if self.nmt_state != "OPERATIONAL":
                return
            self.sync_count += 1
            for number, tpdo in self._tpdos.items():  # inputs are sampled at the SYNC
                comm = obj.TPDO_COMM + number - 1
                cob_word = self._stored(comm, 1)
                kind = self._stored(comm, 2)
                if cob_word & (1 << 31) or not 1 <= kind <= 240:
                    continue
                tpdo.sync_count += 1
                if tpdo.sync_count % kind == 0:
                    self._send_tpdo(number)
            pending, self._rpdo_pending = self._rpdo_pending, {}
            for number, payload in sorted(pending.items()):  # then outputs are actuated
                self._apply_rpdo(number, payload)
            self.on_sync()
            self.changed.notify_all()

    def on_sync(self) -> None:
        """Hook: one cycle of the device, after the SYNC's RPDOs were taken."""

    def on_remote_frame(self, can_id: int) -> None:
        """RTR: a TPDO on request, or the node guarding answer."""
        with self.lock:
            if can_id == 0x700 + self.node_id:
                state = NMT_STATE_CODES.get(self.nmt_state, 0x7F)
                self.network.send(can_id, bytes([state | self.guard_toggle]))
                self.guard_toggle ^= 0x80
                return
            if self.nmt_state != "OPERATIONAL":
                return
            for number in self._tpdos:
                cob_word = self._stored(obj.TPDO_COMM + number - 1, 1)
                if cob_word & 0x7FF == can_id and not cob_word & (3 << 30):
                    self._send_tpdo(number)

    def wait(self, predicate: Callable[[], bool], timeout_s: float = 2.0) -> bool:
        with self.changed:
            return self.changed.wait_for(predicate, timeout_s)

    def close(self) -> None:
        self._producer.close()
        self.consumer.close()


class _RemoteFrameListener(can.Listener):
    """canopen's MessageListener drops remote frames; this one hands them to the nodes."""

    def __init__(self, network: SimNetwork) -> None:
        self._network = network

    def on_message_received(self, msg: can.Message) -> None:
        if msg.is_remote_frame:
            for node in list(self._network.nodes):
                node.on_remote_frame(msg.arbitration_id)

    def stop(self) -> None:
        """Nothing to release."""


class SimNetwork:
    """One canopen Network on the virtual channel, holding every simulated node."""

    def __init__(self, channel: str) -> None:
        self.nodes: list[SimNode] = []
        self.network = canopen.Network()
        self.network.NOTIFIER_CYCLE = NOTIFIER_CYCLE_S
        self.network.listeners.append(_RemoteFrameListener(self))
        self.network.connect(interface="virtual", channel=channel)

    def send(self, cob_id: int, data: bytes) -> None:
        self.network.send_message(cob_id, data)

    def close(self) -> None:
        for node in self.nodes:
            node.close()
        self.network.disconnect()


# ---- CiA 402 drive ---------------------------------------------------------------------------


def _command(controlword: int) -> str:
    """Device control command of a controlword (bit 7 clear), CiA 402 table."""
    if controlword & 0x82 == 0x00:
        return "disable voltage"
    if controlword & 0x86 == 0x02:
        return "quick stop"
    if controlword & 0x87 == 0x06:
        return "shutdown"
    if controlword & 0x8F == 0x07:
        return "switch on"
    if controlword & 0x8F == 0x0F:
        return "enable operation"
    return "none"


# (state, command) -> next state; CiA 402 transition numbers in the comments.
DRIVE_TRANSITIONS: dict[tuple[Cia402State, str], Cia402State] = {
    (S.SWITCH_ON_DISABLED, "shutdown"): S.READY_TO_SWITCH_ON,  # 2
    (S.READY_TO_SWITCH_ON, "switch on"): S.SWITCHED_ON,  # 3
    (S.READY_TO_SWITCH_ON, "enable operation"): S.OPERATION_ENABLED,  # 3 + 4
    (S.SWITCHED_ON, "enable operation"): S.OPERATION_ENABLED,  # 4
    (S.OPERATION_ENABLED, "switch on"): S.SWITCHED_ON,  # 5
    (S.SWITCHED_ON, "shutdown"): S.READY_TO_SWITCH_ON,  # 6
    (S.READY_TO_SWITCH_ON, "disable voltage"): S.SWITCH_ON_DISABLED,  # 7
    (S.READY_TO_SWITCH_ON, "quick stop"): S.SWITCH_ON_DISABLED,  # 7
    (S.OPERATION_ENABLED, "shutdown"): S.READY_TO_SWITCH_ON,  # 8
    (S.OPERATION_ENABLED, "disable voltage"): S.SWITCH_ON_DISABLED,  # 9
    (S.SWITCHED_ON, "disable voltage"): S.SWITCH_ON_DISABLED,  # 10
    (S.SWITCHED_ON, "quick stop"): S.SWITCH_ON_DISABLED,  # 10
    (S.OPERATION_ENABLED, "quick stop"): S.QUICK_STOP_ACTIVE,  # 11
    (S.QUICK_STOP_ACTIVE, "disable voltage"): S.SWITCH_ON_DISABLED,  # 12
    (S.QUICK_STOP_ACTIVE, "enable operation"): S.OPERATION_ENABLED,  # 16
}

STATE_BITS: dict[Cia402State, int] = {
    S.NOT_READY_TO_SWITCH_ON: 0x00,
    S.SWITCH_ON_DISABLED: 0x40,
    S.READY_TO_SWITCH_ON: 0x31,  # + voltage enabled (bit 4)
    S.SWITCHED_ON: 0x33,
    S.OPERATION_ENABLED: 0x37,
    S.QUICK_STOP_ACTIVE: 0x17,
    S.FAULT_REACTION_ACTIVE: 0x0F,
    S.FAULT: 0x08,
}


@dataclass
class DriveRecord:
    """What a test may check afterwards: the controlword and target taken at each SYNC."""

    controlwords: list[tuple[int, int]] = field(default_factory=list)  # (sync, controlword)
    targets: list[tuple[int, int]] = field(default_factory=list)  # (sync, target) when moving
    emcy_sent: list[int] = field(default_factory=list)


class SimDrive(SimNode):
    """A CiA 402 servo drive: power state machine, CSP and homing, faults and EMCY."""

    def __init__(
        self,
        network: SimNetwork,
        node_id: int,
        position_counts: int = 0,
        max_counts_per_sync: int = 10**9,
        homing_syncs: int = 5,
        homing_overshoot_counts: int = 0,
        *,
        heartbeat_consumer: bool = True,
    ) -> None:
        """``heartbeat_consumer=False``: a drive without object 0x1016."""
        self.initial_position = position_counts
        self.homing_overshoot_counts = homing_overshoot_counts  # stops past the switch edge
        self.max_counts_per_sync = max_counts_per_sync
        self.homing_syncs = homing_syncs
        self.record = DriveRecord()
        od = obj.build_drive_od(node_id)
        if not heartbeat_consumer:
            del od[obj.CONSUMER_HEARTBEAT_TIME]
        super().__init__(network, node_id, od)

    def reset_application(self) -> None:
        with self.lock:
            self.state = S.SWITCH_ON_DISABLED  # transitions 0 and 1 are immediate here
            self.position = self.initial_position
            self.target = self.initial_position
            self.controlword = 0
            self.mode = MODE_CSP
            self.mode_display = MODE_CSP
            self.error_code = 0
            self.fault_cause_active = False
            self.digital_inputs = 0
            self.homing_left = -1  # SYNCs until homing completes; -1 not running
            self.homing_attained = False
            self.homing_error = False
            self.inject_homing_error = False
            self.following_error = False

    # ---- test controls ----
    def inject_fault(self, code: int, *, persistent: bool = False) -> None:
        """A fault: FAULT REACTION ACTIVE now, FAULT at the next SYNC, EMCY at once."""
        with self.lock:
            self.state = S.FAULT_REACTION_ACTIVE
            self.error_code = code
            self.fault_cause_active = persistent
            self.homing_left = -1
            self._emcy(code)
            self.changed.notify_all()

    def on_heartbeat_event(self) -> None:
        """The controller is silent: with the power stage on, fault (0x8130, EMCY). The fault
        reaction ends on the drive's own clock: no SYNC will come to finish it."""
        if self.state in POWERED:
            self.inject_fault(EMCY_HEARTBEAT)
            self.state = S.FAULT  # 14

    def clear_fault_cause(self) -> None:
        with self.lock:
            self.fault_cause_active = False

    def _emcy(self, code: int) -> None:
        register = {0x2: 0x02, 0x3: 0x04, 0x4: 0x08, 0x8: 0x10}.get(code >> 12, 0x80) | 0x01
        self.record.emcy_sent.append(code)
        self.node.emcy.send(code, register)

    @property
    def statusword(self) -> int:
        word = STATE_BITS[self.state] | 0x0200  # remote
        if self.mode_display == MODE_CSP and self.state is S.OPERATION_ENABLED:
            word |= 1 << 12  # drive follows the command value
            if self.following_error:
                word |= 1 << 13
        if self.mode_display == MODE_HOMING:
            if self.homing_left < 0:
                word |= 1 << 10  # target reached: homing done, interrupted or not started
            if self.homing_attained:
                word |= 1 << 12
            if self.homing_error:
                word |= 1 << 13
        return word

    # ---- object hooks ----
    def on_read(self, index: int, subindex: int) -> int | None:
        return {
            obj.STATUSWORD: self.statusword,
            obj.POSITION_ACTUAL: self.position,
            obj.MODES_DISPLAY: self.mode_display,
            obj.ERROR_CODE: self.error_code,
            obj.DIGITAL_INPUTS: self.digital_inputs,
            obj.ERROR_REGISTER: 0x01 if self.error_code else 0,
            obj.CONTROLWORD: self.controlword,
            obj.TARGET_POSITION: self.target,
            obj.MODES_OF_OPERATION: self.mode,
        }.get(index)

    def on_write(self, index: int, subindex: int, value: object) -> None:
        assert isinstance(value, int)
        if index == obj.HOMING_METHOD and value not in SUPPORTED_HOMING_METHODS:
            raise SdoAbortedError(ABORT_VALUE_RANGE)
        if index == obj.CONTROLWORD:
            self._controlword(value)
        elif index == obj.TARGET_POSITION:
            self.target = value
        elif index == obj.MODES_OF_OPERATION:
            self.mode = value
            self.mode_display = value

    def _controlword(self, controlword: int) -> None:
        rising_reset = controlword & 0x80 and not self.controlword & 0x80
        self.controlword = controlword
        if self.nmt_state == "OPERATIONAL":
            self.record.controlwords.append((self.sync_count, controlword))
        if self.state is S.FAULT:
            if rising_reset and not self.fault_cause_active:
                self.state = S.SWITCH_ON_DISABLED  # 15
                self.error_code = 0
                self.node.emcy.reset()
            return
        if controlword & 0x80 or self.state is S.FAULT_REACTION_ACTIVE:
            return
        command = _command(controlword)
        new_state = DRIVE_TRANSITIONS.get((self.state, command))
        if new_state is None:
            return
        if new_state is S.OPERATION_ENABLED and self.state is not S.OPERATION_ENABLED:
            self.target = self.position  # CSP: a freshly enabled drive holds where it is
        self.state = new_state
        if self.mode_display == MODE_HOMING and controlword & CW_HOMING_START:
            self._maybe_start_homing()

    def _maybe_start_homing(self) -> None:
        if self.state is S.OPERATION_ENABLED and self.homing_left < 0 and not self.homing_attained:
            self.homing_left = self.homing_syncs
            self.homing_error = False

    def on_sync(self) -> None:
        if self.state is S.FAULT_REACTION_ACTIVE:
            self.state = S.FAULT  # 14
            return
        if self.state is not S.OPERATION_ENABLED:
            return
        if self.mode_display == MODE_CSP:
            self.homing_attained = False
            self.record.targets.append((self.sync_count, self.target))
            step = max(
                -self.max_counts_per_sync,
                min(self.max_counts_per_sync, self.target - self.position),
            )
            self.position += step
            window = self.read(obj.FOLLOWING_ERROR_WINDOW)
            if abs(self.target - self.position) > window:
                self.following_error = True
                self.inject_fault(0x8611)
        elif self.mode_display == MODE_HOMING:
            if not self.controlword & CW_HOMING_START:
                self.homing_left = -1
                self.homing_attained = False
            elif self.homing_left < 0 and not self.homing_attained:
                self._maybe_start_homing()
            elif self.homing_left > 0:
                self.homing_left -= 1
                if self.homing_left == 0:
                    self.homing_left = -1
                    if self.inject_homing_error:
                        self.homing_error = True
                    else:
                        self.position = self.read(obj.HOME_OFFSET) + self.homing_overshoot_counts
                        self.target = self.position
                        self.homing_attained = True


# ---- CiA 401 I/O node --------------------------------------------------------------------


class SimIoNode(SimNode):
    """16 digital inputs (0x6000) a test sets, 16 outputs (0x6200) the master writes."""

    def __init__(self, network: SimNetwork, node_id: int) -> None:
        self.inputs = 0
        self.outputs = 0
        super().__init__(network, node_id, obj.build_io_od(node_id))

    def set_inputs(self, bits: int) -> None:
        with self.lock:
            self.inputs = bits

    def on_read(self, index: int, subindex: int) -> int | None:
        if index == obj.READ_INPUT_8BIT and subindex >= 1:
            return (self.inputs >> (8 * (subindex - 1))) & 0xFF
        if index == obj.WRITE_OUTPUT_8BIT and subindex >= 1:
            return (self.outputs >> (8 * (subindex - 1))) & 0xFF
        return None

    def on_write(self, index: int, subindex: int, value: object) -> None:
        if index == obj.WRITE_OUTPUT_8BIT and subindex >= 1:
            assert isinstance(value, int)
            shift = 8 * (subindex - 1)
            self.outputs = (self.outputs & ~(0xFF << shift)) | (value << shift)


class SimStationIo(SimIoNode):
    """The I/O node wired to a simulated station: centering device, clamps and spindle answer
    their outputs with their sensors after a travel time counted in SYNCs (machine periods),
    and a board is put on the table by the test (``part_present``)."""

    def __init__(
        self,
        network: SimNetwork,
        node_id: int,
        inputs: dict[str, int],
        outputs: dict[str, int],
        travel_syncs: int = 10,
    ) -> None:
        self.input_bits = inputs
        self.output_bits = outputs
        self.travel_syncs = travel_syncs
        self.part_present = False
        self._moving: dict[str, int] = {}  # output name -> SYNCs since it changed
        self._last: dict[str, bool] = {}
        super().__init__(network, node_id)
        self.inputs = self._sensor_bits(centering=False, clamps=False, spindle=False)

    def _on(self, name: str) -> bool:
        return bool(self.outputs >> self.output_bits[name] & 1)

    def _sensor_bits(self, *, centering: bool | None, clamps: bool | None, spindle: bool) -> int:
        values = {
            "part_present": self.part_present,
            "guard_closed": True,
            "estop_ok": True,
            "centering_extended": centering is True,
            "centering_retracted": centering is False,
            "clamps_closed": clamps is True,
            "clamps_open": clamps is False,
            "spindle_running": spindle,
        }
        return sum(1 << self.input_bits[n] for n, on in values.items() if on)

    def on_sync(self) -> None:
        state: dict[str, bool | None] = {}
        for name in ("centering_extend", "clamps_close", "spindle_on"):
            on = self._on(name)
            if self._last.get(name) != on:
                self._last[name] = on
                self._moving[name] = 0
            self._moving[name] = self._moving.get(name, 0) + 1
            arrived = self._moving[name] >= self.travel_syncs
            state[name] = on if arrived else None  # None: travelling, both sensors off
        self.inputs = self._sensor_bits(
            centering=state["centering_extend"],
            clamps=state["clamps_close"],
            spindle=state["spindle_on"] is True,
        )
