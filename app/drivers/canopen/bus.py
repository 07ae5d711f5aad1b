"""One CAN bus shared by the drives and the I/O node: the canopen Network and its watchmen.

Why shared: one fieldbus carries both device roles, so the motion backend and the digital
I/O share one ``canopen.Network`` (one python-can bus, one notifier thread). The first
``acquire()`` connects, the last ``release()`` disconnects.

What runs where: the notifier thread (python-can ``Notifier`` inside canopen's ``Network``)
calls our subscriptions: TPDO frames, heartbeats and EMCY messages. They only store data and
stamp it, under :attr:`CanopenBus.condition`. Everything else (sending RPDOs and SYNC,
deciding that a node is lost) runs in the machine loop's thread, in the backend's calls.

Failures are never silent: a dead notifier thread is found by ``Network.check()`` on every
read and send and becomes a RECEIVE_THREAD_DIED event plus a CommunicationError; a node
whose heartbeat stops becomes COMMUNICATION_LOST for the device that owns it.

The controller's own heartbeat (:mod:`app.drivers.canopen.master_heartbeat`, node
``master_node_id``) belongs to the bus too, since it is one frame for the whole network: the
motion backend starts it on activation and stops it on deactivation; disconnecting stops it
before the bus is closed. Its sender dying unasked is found by
:meth:`CanopenBus.check_master_heartbeat` on every read of the motion backend.
"""

from __future__ import annotations

import contextlib
import logging
import threading
import time
from collections import deque
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import can
import canopen
from canopen.emcy import EmcyError
from canopen.objectdictionary import ObjectDictionary

from app.drivers.canopen.master_heartbeat import MasterHeartbeat
from app.drivers.canopen.settings import CanopenSettings
from app.drivers.canopen.watchdog import HeartbeatChange, HeartbeatWatchdog
from app.drivers.contracts import CommunicationError, DeviceEvent, DeviceEventKind, DriverError
from app.drivers.emcy import emcy_text

log = logging.getLogger(__name__)

NOTIFIER_CYCLE_S = 0.05  # how long the receive thread blocks per wait: bounds shutdown time
FrameCallback = Callable[[bytes, int], None]  # (data, SYNC number current at receipt)

NMT_STATE_NAMES = {0x00: "boot-up", 0x04: "STOPPED", 0x05: "OPERATIONAL", 0x7F: "PRE-OPERATIONAL"}


def sdo_abort_text(code: int) -> str:
    return canopen.SdoAbortedError.CODES.get(code, "unknown abort code")


@dataclass
class _NodeEntry:
    node: canopen.RemoteNode
    owner: str  # "motion" or "io": whose event queue its events go to
    label: str  # device name in events and errors, e.g. "X (node 1)"
    last_emcy_code: int = 0
    beats: int = 0  # heartbeats received
    subscriptions: list[tuple[int, Callable[[int, bytearray, float], None]]] = field(
        default_factory=list
    )


class CanopenBus:
    """The connected network, the SYNC counter, the heartbeat watchdog and event queues."""

    def __init__(
        self, settings: CanopenSettings, clock: Callable[[], float] = time.monotonic
    ) -> None:
        self.settings = settings
        self.label = f"CAN {settings.interface}:{settings.channel}"
        self.condition = threading.Condition()
        self.watchdog = HeartbeatWatchdog(settings.heartbeat_timeout_ms / 1000.0, clock)
        self.master_heartbeat = MasterHeartbeat(settings.master_node_id, settings.heartbeat_ms)
        self._master_failure_reported = False
        self._network: canopen.Network | None = None
        self._users = 0
        self._nodes: dict[int, _NodeEntry] = {}
        self._queues: dict[str, deque[DeviceEvent]] = {"motion": deque(), "io": deque()}
        self._shared: deque[DeviceEvent] = deque()
        self._lost: dict[int, str] = {}
        self._thread_error: str = ""
        self._booted: set[int] = set()  # nodes whose boot-up message was seen
        self.sync_seq = 0
        self.sync_is_feedback = False  # the latest SYNC was sent to refresh feedback
        self.sync_time_s = 0.0  # monotonic time the latest SYNC was sent
        self._answer_sources: list[Callable[[int], bool]] = []

    # ---- connection ----
    def acquire(self) -> None:
        if self._network is not None and self._thread_error:
            self._disconnect()  # its receive thread is dead: only a new connection helps
        if self._network is None:
            network = canopen.Network()
            network.NOTIFIER_CYCLE = NOTIFIER_CYCLE_S
            try:
                network.connect(
                    interface=self.settings.interface,
                    channel=self.settings.channel,
                    bitrate=self.settings.bitrate,
                )
            except (can.CanError, OSError, ValueError, ImportError) as exc:
                raise CommunicationError(
                    self.label, f"cannot open the CAN interface: {exc}"
                ) from exc
            self._network = network
            self._thread_error = ""
            log.info("connected to %s", self.label)
        self._users += 1

    def release(self) -> None:
        self._users = max(0, self._users - 1)
        if self._users == 0:
            self._disconnect()

    def _disconnect(self) -> None:
        if self._network is None:
            return
        self.master_heartbeat.stop()  # before the bus closes under its sender
        network, self._network = self._network, None
        self._nodes.clear()
        try:
            network.disconnect()
        except Exception as exc:  # the notifier's stored exception is re-raised here
            log.warning("%s: disconnect: %s", self.label, exc)
        log.info("disconnected from %s", self.label)

    @property
    def network(self) -> canopen.Network:
        if self._network is None:
            raise CommunicationError(self.label, "not connected")
        return self._network

    # ---- nodes ----
    def add_node(
        self, node_id: int, od: ObjectDictionary, owner: str, label: str
    ) -> canopen.RemoteNode:
        network = self.network
        if node_id in network:
            del network[node_id]
        node = network.add_node(node_id, od)
        node.sdo.RESPONSE_TIMEOUT = self.settings.sdo_timeout_ms / 1000.0
        entry = _NodeEntry(node, owner, label)
        self._nodes[node_id] = entry
        self._lost.pop(node_id, None)
        node.nmt.add_heartbeat_callback(lambda state: self._on_heartbeat(node_id, state))
        node.emcy.add_callback(lambda emcy: self._on_emcy(entry, emcy))
        return node

    def remove_nodes(self, node_ids: list[int]) -> None:
        self.watchdog.forget(node_ids)
        for node_id in node_ids:
            entry = self._nodes.pop(node_id, None)
            self._lost.pop(node_id, None)
            if self._network is None:
                continue
            if entry is not None:
                for cob_id, on_frame in entry.subscriptions:
                    self._network.unsubscribe(cob_id, on_frame)
            if node_id in self._network:
                del self._network[node_id]

    def subscribe(self, node_id: int, cob_id: int, callback: FrameCallback) -> None:
        """Call ``callback(data, sync_seq)`` for every frame with this COB-ID (receive
        thread, under the condition)."""

        def on_frame(can_id: int, data: bytearray, timestamp: float) -> None:
            with self.condition:
                callback(bytes(data), self.sync_seq)
                self.condition.notify_all()

        self.network.subscribe(cob_id, on_frame)
        self._nodes[node_id].subscriptions.append((cob_id, on_frame))

    def beats(self, node_id: int) -> int:
        """Heartbeats received from this node so far (call under the condition)."""
        entry = self._nodes.get(node_id)
        return entry.beats if entry else 0

    # ---- receive-thread callbacks ----
    def _on_heartbeat(self, node_id: int, state: int) -> None:
        with self.condition:
            self.watchdog.heard(node_id, state)
            entry = self._nodes.get(node_id)
            if entry is not None:
                entry.beats += 1
            if state == 0x00:
                self._booted.add(node_id)
            self.condition.notify_all()

    def _on_emcy(self, entry: _NodeEntry, emcy: EmcyError) -> None:
        code = int(emcy.code)
        with self.condition:
            if code & 0xFF00 == 0:
                log.info("%s: EMCY error reset", entry.label)
                return
            entry.last_emcy_code = code
            text = f"{emcy_text(code)} (error register 0x{int(emcy.register):02X})"
            self._queues[entry.owner].append(
                DeviceEvent(DeviceEventKind.EMERGENCY, entry.label, code, text)
            )
            self.condition.notify_all()
        log.warning("%s: EMCY 0x%04X %s", entry.label, code, text)

    def last_emcy_code(self, node_id: int) -> int:
        with self.condition:
            entry = self._nodes.get(node_id)
            return entry.last_emcy_code if entry else 0

    def clear_emcy_code(self, node_id: int) -> None:
        with self.condition:
            entry = self._nodes.get(node_id)
            if entry:
                entry.last_emcy_code = 0

    def take_booted(self, node_id: int) -> bool:
        """True once after a boot-up message of this node (kept across re-configuration)."""
        with self.condition:
            if node_id not in self._booted:
                return False
            self._booted.discard(node_id)
            return True

    @property
    def receive_failed(self) -> bool:
        return bool(self._thread_error)

    # ---- sending (machine loop) ----
    def check(self) -> None:
        """Raise CommunicationError (once reported as RECEIVE_THREAD_DIED) when the receive
        thread has died."""
        if self._thread_error:
            raise CommunicationError(self.label, self._thread_error)
        try:
            self.network.check()
        except CommunicationError:
            raise
        except Exception as exc:  # Network.check re-raises whatever killed the thread
            self._thread_error = f"the CAN receive thread died: {type(exc).__name__}: {exc}"
            with self.condition:
                self._shared.append(
                    DeviceEvent(
                        DeviceEventKind.RECEIVE_THREAD_DIED, self.label, 0, self._thread_error
                    )
                )
            log.error("%s: %s", self.label, self._thread_error)
            raise CommunicationError(self.label, self._thread_error) from exc

    def send(self, cob_id: int, data: bytes) -> None:
        try:
            self.network.send_message(cob_id, data)
        except CommunicationError:
            raise
        except Exception as exc:
            self.check()  # a dead receive thread explains it best
            raise CommunicationError(self.label, f"sending 0x{cob_id:03X} failed: {exc}") from exc

    def start_master_heartbeat(self) -> None:
        """Start the controller's heartbeat (no-op while it runs)."""
        bus = self.network.bus
        if bus is None:
            raise CommunicationError(self.label, "not connected")
        if self.master_heartbeat.running and not self.master_heartbeat.failure():
            return
        try:
            self.master_heartbeat.start(bus)
            self._master_failure_reported = False
        except (can.CanError, OSError, ValueError, NotImplementedError) as exc:
            raise CommunicationError(
                self.label,
                f"cannot start the controller's heartbeat "
                f"(COB-ID 0x{self.master_heartbeat.cob_id:03X}): {exc}",
            ) from exc
        log.info(
            "%s: controller heartbeat 0x%03X every %g ms",
            self.label,
            self.master_heartbeat.cob_id,
            1000 * self.master_heartbeat.period_s,
        )

    def stop_master_heartbeat(self) -> None:
        """Stop the controller's heartbeat (no-op when stopped); never raises."""
        if self.master_heartbeat.running:
            self.master_heartbeat.stop()
            log.info("%s: controller heartbeat stopped", self.label)

    def check_master_heartbeat(self, owner: str) -> None:
        """Raise CommunicationError when the controller's heartbeat stopped although
        :meth:`stop_master_heartbeat` was not called; the first time it is also queued as
        COMMUNICATION_LOST (device: the bus) for ``owner``, the device whose nodes watch it."""
        text = self.master_heartbeat.failure()
        if not text:
            return
        with self.condition:
            first = not self._master_failure_reported
            self._master_failure_reported = True
            if first:
                self._queues[owner].append(
                    DeviceEvent(DeviceEventKind.COMMUNICATION_LOST, self.label, 0, text)
                )
        if first:
            log.error("%s: %s", self.label, text)
        raise CommunicationError(self.label, text)

    def sync(self, *, feedback: bool = False) -> int:
        """Send one SYNC; returns its number. ``feedback``: sent by a read (a tool that does
        not write setpoints), so the reads wait for the answers."""
        with self.condition:
            self.sync_seq += 1
            seq = self.sync_seq
            self.sync_is_feedback = feedback
            self.sync_time_s = time.monotonic()
        self.send(0x80, b"")  # SYNC, COB-ID 0x80, no counter
        return seq

    def nmt(self, node_id: int, command: str) -> None:
        try:
            self.network[node_id].nmt.state = command
        except Exception as exc:
            self.check()
            raise CommunicationError(self._label(node_id), f"NMT {command} failed: {exc}") from exc

    def _label(self, node_id: int) -> str:
        entry = self._nodes.get(node_id)
        return entry.label if entry else f"node {node_id}"

    # ---- SDO ----
    def sdo_upload(self, node_id: int, index: int, subindex: int, what: str) -> bytes:
        node = self._nodes[node_id].node
        try:
            return bytes(node.sdo.upload(index, subindex))
        except canopen.SdoAbortedError as exc:
            raise self._abort(node_id, exc, "reading", index, subindex, what) from exc
        except (canopen.SdoCommunicationError, can.CanError, RuntimeError) as exc:
            self.check()
            raise CommunicationError(
                self._label(node_id),
                f"no SDO answer reading 0x{index:04X}:{subindex:02X} {what}: {exc}",
            ) from exc

    def sdo_download(self, node_id: int, index: int, subindex: int, data: bytes, what: str) -> None:
        node = self._nodes[node_id].node
        try:
            node.sdo.download(index, subindex, data)
        except canopen.SdoAbortedError as exc:
            raise self._abort(node_id, exc, "writing", index, subindex, what) from exc
        except (canopen.SdoCommunicationError, can.CanError, RuntimeError) as exc:
            self.check()
            raise CommunicationError(
                self._label(node_id),
                f"no SDO answer writing 0x{index:04X}:{subindex:02X} {what}: {exc}",
            ) from exc

    def _abort(
        self,
        node_id: int,
        exc: canopen.SdoAbortedError,
        doing: str,
        index: int,
        subindex: int,
        what: str,
    ) -> DriverError:
        code = int(exc.code)
        return DriverError(
            self._label(node_id),
            f"SDO abort 0x{code:08X} ({sdo_abort_text(code)}) {doing} "
            f"0x{index:04X}:{subindex:02X} {what}",
            code,
        )

    # ---- supervision (machine loop) ----
    def supervise(self) -> None:
        """Turn heartbeat changes, and a receive thread that died, into events."""
        if self._network is not None and not self._thread_error:
            with contextlib.suppress(CommunicationError):
                self.check()
        for change in self.watchdog.poll():
            self._heartbeat_change(change)

    def _heartbeat_change(self, change: HeartbeatChange) -> None:
        entry = self._nodes.get(change.node_id)
        if entry is None:
            return
        with self.condition:
            if change.lost:
                text = (
                    f"heartbeat lost: nothing heard for {1000 * change.silent_s:.0f} ms "
                    f"(timeout {self.settings.heartbeat_timeout_ms} ms)"
                )
                self._lost[change.node_id] = text
                kind = DeviceEventKind.COMMUNICATION_LOST
            else:
                text = "heartbeat heard again (the backend stays stopped until reset)"
                kind = DeviceEventKind.COMMUNICATION_RESTORED
            self._queues[entry.owner].append(DeviceEvent(kind, entry.label, 0, text))
        log.log(logging.ERROR if change.lost else logging.WARNING, "%s: %s", entry.label, text)

    def lost_reason(self, node_id: int) -> str:
        with self.condition:
            return self._lost.get(node_id, "")

    def report_lost(self, node_id: int, text: str) -> None:
        """A device found a node lost by other means (NMT state, missing PDOs)."""
        entry = self._nodes.get(node_id)
        with self.condition:
            if node_id in self._lost:
                return
            self._lost[node_id] = text
            if entry is not None:
                self._queues[entry.owner].append(
                    DeviceEvent(DeviceEventKind.COMMUNICATION_LOST, entry.label, 0, text)
                )
        log.error("%s: %s", self._label(node_id), text)

    def events(self, owner: str) -> list[DeviceEvent]:
        with self.condition:
            events = list(self._queues[owner]) + list(self._shared)
            self._queues[owner].clear()
            self._shared.clear()
        return events

    def add_answer_source(self, answered: Callable[[int], bool]) -> None:
        """``answered(seq)``: True once every cyclic TPDO of a device answered SYNC ``seq``
        (evaluated under the condition)."""
        self._answer_sources.append(answered)

    def remove_answer_source(self, answered: Callable[[int], bool]) -> None:
        if answered in self._answer_sources:
            self._answer_sources.remove(answered)

    def wait_for_answers(self, timeout_s: float) -> bool:
        """Wait until every node answered the latest SYNC. The machine loop never needs it
        (a period passes between its write and its next read); tools and tests that run
        periods back to back call it to read the drives' answers to what they just wrote."""
        seq = self.sync_seq
        return self.wait(lambda: all(answered(seq) for answered in self._answer_sources), timeout_s)

    def probe_report(self) -> Mapping[str, object]:
        """What ``stave probe`` prints about the link (found in ``MachineBackend.extras``)."""
        settings = self.settings
        report: dict[str, object] = {
            "link": f"{settings.interface} {settings.channel} {settings.bitrate // 1000} kbit/s",
            "cyclic bus load (computed)": settings.bus_load().describe(),
            "heartbeat ms": f"{settings.heartbeat_ms} (timeout {settings.heartbeat_timeout_ms})",
            "controller heartbeat": (
                f"node {settings.master_node_id}, drives stop after "
                f"{settings.master_heartbeat_timeout_ms} ms of silence"
                + (", sending" if self.master_heartbeat.running else ", not sending")
            ),
            "SYNCs sent": self.sync_seq,
        }
        for node_id, entry in sorted(self._nodes.items()):
            state = self.watchdog.nmt_state(node_id)
            text = NMT_STATE_NAMES.get(state, "not heard") if state is not None else "not heard"
            if entry.last_emcy_code:
                text += f", last EMCY 0x{entry.last_emcy_code:04X}"
            report[entry.label] = text
        return report

    def wait(self, predicate: Callable[[], bool], timeout_s: float) -> bool:
        """Wait until ``predicate()`` (evaluated under the condition) holds; False on timeout."""
        with self.condition:
            return self.condition.wait_for(predicate, timeout_s)
