"""CANopen node infrastructure for the tests: what a canopen ``LocalNode`` lacks and a real
node does, with no device model of its own (the devices are the simulated world's, seen
through :mod:`tests.drivers.canopen.world_nodes`).

Each node is a canopen ``LocalNode`` (its SDO server answers the backend's configuration)
with an object dictionary built in code (``app.drivers.canopen.objects``), plus:

- NMT state handling: PDOs are processed and produced only in OPERATIONAL, SDO is refused in
  STOPPED, reset node/communication sends a boot-up message and goes to PRE-OPERATIONAL;
- a heartbeat producer (0x1017) on a thread of our own, so that a test can silence it and
  ``close()`` can join it before the bus goes away;
- a heartbeat consumer (0x1016 sub 1, in the drives' dictionary) on a thread of our own, as
  CiA 301 has it: it starts watching the named producer at the first heartbeat it hears after
  being configured (or after its last event), and a silence longer than the configured time
  is one heartbeat event (``on_heartbeat_event``), after which it waits for the next
  heartbeat; writing 0 switches it off;
- PDOs driven by the communication and mapping objects the master downloads (CiA 301
  procedure checked: mapping only while the PDO is invalid and its count is 0), RPDOs taken
  at the next SYNC (types 0-240) or at once (254/255), TPDOs sent on every n-th SYNC;
- remote frames (RTR) for TPDOs and node guarding, which canopen's listener drops;
- a CiA 401 I/O node (:class:`SimIoNode`): 16 inputs and 16 outputs as process images.

All nodes of one test share one ``canopen.Network`` on python-can's ``virtual`` interface;
the backend under test has its own Network on the same channel name.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass

import can
import canopen
from canopen.nmt import NmtSlave
from canopen.objectdictionary import ObjectDictionary, ODVariable
from canopen.sdo import SdoAbortedError

from app.drivers.canopen import objects as obj
from app.drivers.canopen.master_heartbeat import HEARTBEAT_COB_BASE, split_consumer_heartbeat_entry

NOTIFIER_CYCLE_S = 0.02
NMT_RESET_NODE = 0x81
NMT_RESET_COMMUNICATION = 0x82
NMT_STATE_CODES = {
    "INITIALISING": 0x00,
    "STOPPED": 0x04,
    "OPERATIONAL": 0x05,
    "PRE-OPERATIONAL": 0x7F,
}
ABORT_UNSUPPORTED_ACCESS = 0x06010000
ABORT_NOT_MAPPABLE = 0x06040041
ABORT_PDO_LENGTH = 0x06040042


class NodeThread:
    """A thread of a simulated node: one condition its state and ``close`` share, so that
    ``close()`` wakes it wherever it waits and joins it before the bus goes away. A subclass
    sets its state, then calls ``start``; its ``_run`` returns once ``_stopped`` is set."""

    def __init__(self) -> None:
        self._cond = threading.Condition()
        self._stopped = False

    def start(self, name: str) -> None:
        self._thread = threading.Thread(target=self._run, name=name, daemon=True)
        self._thread.start()

    def _run(self) -> None:
        raise NotImplementedError

    def close(self) -> None:
        with self._cond:
            self._stopped = True
            self._cond.notify_all()
        self._thread.join()


class _HeartbeatProducer(NodeThread):
    """Sends the node's NMT state every period; can be silenced by a test."""

    def __init__(self, send: Callable[[], None]) -> None:
        super().__init__()
        self._send = send
        self._period_s = 0.0
        self._silenced = False
        self.start("sim heartbeat")

    def set_period_ms(self, period_ms: int) -> None:
        with self._cond:
            self._period_s = period_ms / 1000.0
            self._cond.notify_all()

    def silence(self, silenced: bool) -> None:
        with self._cond:
            self._silenced = silenced
            self._cond.notify_all()

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


class _HeartbeatConsumer(NodeThread):
    """Watches one producer's heartbeat (CiA 301 consumer), on its own thread.

    Off until configured with a time; then idle until a heartbeat is heard, watching from
    that heartbeat on; a silence longer than the time calls ``on_event`` once (outside this
    object's lock) and makes it idle again until the next heartbeat."""

    def __init__(self, on_event: Callable[[], None]) -> None:
        super().__init__()
        self._on_event = on_event
        self._timeout_s = 0.0  # 0: off
        self._last: float | None = None  # monotonic time of the last heartbeat; None: idle
        self.events = 0  # heartbeat events so far (for the tests' assertions)
        self.start("sim hb consumer")

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
        self.on_heartbeat_event()
        with self.lock:
            self.changed.notify_all()

    def on_heartbeat_event(self) -> None:
        """Hook: the watched producer was silent longer than the consumer time (on the
        consumer's thread, no lock held: the hook takes the ones it needs)."""

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
