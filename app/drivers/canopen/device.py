"""Lifecycle and supervision shared by the CANopen motion backend and the CANopen I/O.

Why one base: both roles go through the same start-up (NMT pre-operational, SDO
configuration, heartbeat, NMT start) and the same rules when a node is lost. Those rules:

- A node is lost when its heartbeat stops (our consumer watchdog), when its heartbeat says it
  left OPERATIONAL (a reboot: its PDO mapping is gone), when its cyclic TPDO misses
  ``pdo_miss_limit`` SYNCs in a row, or when the receive thread died.
- The loss is latched: the device goes to LifecycleState.ERROR, queues COMMUNICATION_LOST,
  and every read and write raises CommunicationError until ``configure()`` and
  ``activate()`` are called again (the machine layer does that on an operator's reset). A
  heartbeat heard again gives COMMUNICATION_RESTORED, never a silent recovery.
- ``deactivate()`` never raises for a dead link: the machine layer calls it before it
  reconnects, and a dead node cannot be reached anyway.

The controller's heartbeat (``consumes_master_heartbeat``: the drives): ``configure()``
writes each node's consumer heartbeat time 0x1016 sub 1 (``master_node_id`` << 16 |
``master_heartbeat_timeout_ms``), and a node that refuses fails the configuration: a drive
that cannot watch the controller would not stop by itself if the controller died.
``activate()`` starts the heartbeat before NMT start (a CiA 301 consumer starts watching at
the first heartbeat it hears). ``deactivate()`` first switches the consumer off (0x1016 sub 1
= 0) in every node that is reachable and known to be safe (its power stage off), then stops
the heartbeat, so that a deactivated, disabled drive does not fault for a silence it was
meant to have; a node left watching (unreachable, or not confirmed disabled) faults on its
own once the heartbeat stops, which is the safe direction. ``activate()`` switches those
consumers on again. Losing a node does not stop the heartbeat: the drives keep watching the
controller (a quick-stopped drive holds with its power stage on) until deactivation, or
``shutdown()``, which from ERROR stops the heartbeat without switching any consumer off, or
until the process ends.

Time: every wait here is on a condition (frames arriving), bounded by a timeout from the
settings; nothing sleeps.
"""

from __future__ import annotations

import logging
import time
from abc import abstractmethod
from collections.abc import Callable

from app.drivers.canopen.bus import NMT_STATE_NAMES, CanopenBus
from app.drivers.canopen.master_heartbeat import consumer_heartbeat_entry
from app.drivers.canopen.objects import (
    CONSUMER_HEARTBEAT_TIME,
    DEVICE_TYPE,
    PRODUCER_HEARTBEAT_TIME,
)
from app.drivers.canopen.settings import CanopenSettings
from app.drivers.canopen.watchdog import NMT_OPERATIONAL
from app.drivers.contracts import (
    CommunicationError,
    DeviceEvent,
    DriverError,
    LifecycleError,
    LifecycleState,
)
from app.drivers.lifecycle import ManagedLifecycle

log = logging.getLogger(__name__)


class CanopenDevice(ManagedLifecycle):
    """The hooks of the one lifecycle for a group of nodes on a shared bus."""

    owner = ""  # "motion" or "io": the bus routes this group's events by it
    profile = 0  # CiA device profile the nodes must report in 0x1000 (402, 401)
    consumes_master_heartbeat = False  # the nodes watch the controller's heartbeat (0x1016)

    def __init__(self, bus: CanopenBus, settings: CanopenSettings) -> None:
        super().__init__(type(self).__name__)
        self._bus = bus
        self._settings = settings
        self._fault = ""  # latched reason of a loss; cleared only by configure()
        self._fault_device = ""
        self._acquired = False
        self._read_seq = -1
        self._checked_seq = -1
        self._missed: dict[int, int] = {}
        self._disarmed: set[int] = set()  # consumers deactivate() switched off

    # ---- what a group provides ----
    @property
    @abstractmethod
    def device_label(self) -> str: ...

    @property
    def lifecycle_label(self) -> str:
        return self.device_label

    @abstractmethod
    def _nodes(self) -> dict[int, str]:
        """node id -> label, for every node of this group."""

    @abstractmethod
    def _add_nodes(self) -> None:
        """Add the nodes to the network and subscribe their TPDOs."""

    @abstractmethod
    def _configure_node(self, node_id: int) -> None:
        """SDO configuration of one node (it is PRE-OPERATIONAL)."""

    @abstractmethod
    def _latest_seq(self, node_id: int) -> int:
        """The SYNC number of the node's latest cyclic TPDO, -1 if none (under the lock)."""

    @abstractmethod
    def _start_exchange(self) -> None:
        """After NMT start: first feedback, command = measured, first RPDOs."""

    @abstractmethod
    def _stop_exchange(self) -> None:
        """Before NMT pre-operational: drives disabled, outputs off (may raise)."""

    def _on_lost(self) -> None:
        """Best effort when a node is lost: bring the reachable nodes to a safe state."""

    # ---- lifecycle hooks ----
    def _on_configure(self) -> None:
        self._release()
        try:
            self._bus.acquire()
            self._acquired = True
            self._bus.add_answer_source(self._answered)
            self._add_nodes()
            with self._bus.condition:
                beats = {n: self._bus.beats(n) for n in self._nodes()}
            for node_id in self._nodes():
                self._bus.nmt(node_id, "PRE-OPERATIONAL")
                self._check_profile(node_id)
                self._bus.sdo_download(
                    node_id,
                    PRODUCER_HEARTBEAT_TIME,
                    0,
                    self._settings.heartbeat_ms.to_bytes(2, "little"),
                    "producer heartbeat time",
                )
                if self.consumes_master_heartbeat:
                    self._write_consumer(node_id, armed=True)
                self._configure_node(node_id)
            self._wait_nodes(lambda n: self._bus.beats(n) > beats[n], "no heartbeat")
        except DriverError:
            self._release()
            raise
        self._fault = ""
        self._missed = {n: 0 for n in self._nodes()}
        self._disarmed.clear()
        log.info("%s configured", self.device_label)

    def _on_activate(self) -> None:
        try:
            if self.consumes_master_heartbeat:
                for node_id in sorted(self._disarmed):
                    self._write_consumer(node_id, armed=True)
                    self._disarmed.discard(node_id)
                self._bus.start_master_heartbeat()
            self._bus.watchdog.watch(self._nodes())
            for node_id in self._nodes():
                self._bus.nmt(node_id, "OPERATIONAL")
            self._wait_nodes(
                lambda n: self._bus.watchdog.nmt_state(n) == NMT_OPERATIONAL,
                "did not report OPERATIONAL after NMT start",
            )
            self._read_seq = -1
            self._checked_seq = -1
            self._missed = {n: 0 for n in self._nodes()}
            self._start_exchange()
        except DriverError as exc:
            self._fault, self._fault_device = str(exc), exc.device
            raise
        log.info("%s active", self.device_label)

    def _on_deactivate(self) -> None:
        """Drives disabled (outputs off), nodes PRE-OPERATIONAL, the consumers that are safe
        switched off, the heartbeat stopped; a failure leaves the drives watching it."""
        try:
            self._stop_nodes()
        except DriverError as exc:
            self._fault, self._fault_device = str(exc), exc.device
            raise
        log.info("%s deactivated", self.device_label)

    def _on_error(self) -> None:
        """After a loss: the same safe stop for the nodes that can still hear us."""
        if self._acquired:
            self._stop_nodes()

    def _stop_nodes(self) -> None:
        try:
            self._stop_exchange()
            for node_id in self._nodes():
                self._bus.nmt(node_id, "PRE-OPERATIONAL")
        except DriverError:
            self._end_master_heartbeat(disarm=False)  # the drives stop on their own
            raise
        self._end_master_heartbeat(disarm=True)

    def _on_shutdown(self) -> None:
        if self._acquired:  # from ERROR: the heartbeat may still run, with nodes watching
            self._end_master_heartbeat(disarm=False)
        self._release()

    def _pending_events(self) -> list[DeviceEvent]:
        if not self._acquired:
            return []
        self._bus.supervise()  # heartbeats, and a receive thread that died meanwhile
        return self._bus.events(self.owner)

    # ---- the controller's heartbeat ----
    def _write_consumer(self, node_id: int, *, armed: bool) -> None:
        """0x1016 sub 1: watch the controller's heartbeat (``armed``) or stop watching (0)."""
        settings = self._settings
        value = (
            consumer_heartbeat_entry(settings.master_node_id, settings.master_heartbeat_timeout_ms)
            if armed
            else 0
        )
        what = (
            f"consumer heartbeat time (controller node {settings.master_node_id}, "
            f"{settings.master_heartbeat_timeout_ms} ms)"
            if armed
            else "consumer heartbeat time (off)"
        )
        try:
            self._bus.sdo_download(
                node_id, CONSUMER_HEARTBEAT_TIME, 1, value.to_bytes(4, "little"), what
            )
        except CommunicationError:
            raise
        except DriverError as exc:
            if not armed:
                raise
            reason = str(exc).removeprefix(f"{exc.device}: ")
            raise DriverError(
                exc.device,
                f"{reason}: the node cannot watch the controller's heartbeat, so it would "
                "not stop by itself if the controller died",
                exc.code,
            ) from exc

    def _disarmable(self, node_id: int) -> bool:
        """May deactivate() switch this node's consumer off? Only if it can be reached;
        subclasses add what makes it safe (a drive's power stage is off)."""
        return not self._bus.lost_reason(node_id)

    def _end_master_heartbeat(self, *, disarm: bool) -> None:
        """Switch the safe nodes' consumers off (``disarm``), then stop the heartbeat."""
        if not self.consumes_master_heartbeat:
            return
        running = self._bus.master_heartbeat.running
        for node_id, label in self._nodes().items():
            if node_id in self._disarmed or not running:
                continue
            if not disarm or not self._disarmable(node_id):
                log.warning(
                    "%s still watches the controller's heartbeat, which stops now: "
                    "it faults (0x8130) if its power stage is on",
                    label,
                )
                continue
            try:
                self._write_consumer(node_id, armed=False)
            except DriverError as exc:
                log.warning("%s: deactivate: %s", self.device_label, exc)
                continue
            self._disarmed.add(node_id)
        self._bus.stop_master_heartbeat()

    # ---- helpers for the subclasses ----
    def _answered(self, seq: int) -> bool:
        return all(self._latest_seq(n) >= seq for n in self._nodes())

    def _release(self) -> None:
        if self._acquired:
            self._bus.remove_answer_source(self._answered)
            self._bus.remove_nodes(list(self._nodes()))
            self._bus.release()
            self._acquired = False

    def _check_profile(self, node_id: int) -> None:
        data = self._bus.sdo_upload(node_id, DEVICE_TYPE, 0, "device type")
        device_type = int.from_bytes(data[:4], "little")
        if device_type & 0xFFFF != self.profile:
            raise DriverError(
                self._nodes()[node_id],
                f"device type 0x{device_type:08X} is not a CiA {self.profile} "
                "device: check the node id",
            )

    def _wait_nodes(self, ready: Callable[[int], bool], what: str) -> None:
        """Wait (bounded by startup_timeout_ms) until ``ready(node_id)`` for every node."""
        timeout_s = self._settings.startup_timeout_ms / 1000.0
        nodes = self._nodes()
        if self._bus.wait(lambda: all(ready(n) for n in nodes), timeout_s):
            return
        with self._bus.condition:
            missing = [n for n in nodes if not ready(n)]
        raise CommunicationError(
            nodes[missing[0]], f"{what} within {self._settings.startup_timeout_ms} ms"
        )

    def _ensure_active(self) -> None:
        if self._state is LifecycleState.ACTIVE:
            return
        if self._state is LifecycleState.ERROR and self._fault:
            raise CommunicationError(
                self._fault_device or self.device_label,
                f"stopped after: {self._fault}; reset to reconnect",
            )
        raise LifecycleError(self.device_label, f"not active ({self._state.value})")

    def _lose(self, device: str, reason: str) -> CommunicationError:
        """Latch a loss; returns the error for the caller to raise."""
        self._latch_error()
        self._fault, self._fault_device = reason, device
        try:
            self._on_lost()
        except DriverError as exc:
            log.warning("%s: safe stop after a loss: %s", self.device_label, exc)
        return CommunicationError(device, reason)

    def _supervise_cycle(self) -> None:
        """Once per read: receive thread alive, every node heard and OPERATIONAL."""
        try:
            self._bus.check()
            if self.consumes_master_heartbeat:
                self._bus.check_master_heartbeat(self.owner)
        except CommunicationError as exc:
            raise self._lose(exc.device, str(exc)) from exc
        self._bus.supervise()
        for node_id, label in self._nodes().items():
            reason = self._bus.lost_reason(node_id)
            if not reason:
                state = self._bus.watchdog.nmt_state(node_id)
                if state is not None and state != NMT_OPERATIONAL:
                    name = NMT_STATE_NAMES.get(state, f"state 0x{state:02X}")
                    reason = f"left OPERATIONAL (heartbeat says {name}): rebooted or stopped"
                    self._bus.report_lost(node_id, reason)
            if reason:
                raise self._lose(label, reason)

    def _refresh(self) -> None:
        """Make sure the answers to the latest SYNC are in, and count missed TPDOs.

        In the machine loop the previous ``write`` sent the SYNC about one period ago and its
        answers are normally in; a late answer is waited for until 1.5 periods after that
        SYNC, no longer, so a lost frame costs the loop at most half a period. A tool that
        only reads gets a SYNC of its own here and waits for its answers."""
        bus = self._bus
        if bus.sync_seq == self._read_seq:
            bus.sync(feedback=True)
        seq = bus.sync_seq
        nodes = self._nodes()
        period_s = self._settings.period_s
        if bus.sync_is_feedback:
            wait_s = max(0.05, 10 * period_s)
        else:
            wait_s = max(0.0, bus.sync_time_s + 1.5 * period_s - time.monotonic())
        bus.wait(lambda: self._answered(seq), wait_s)
        self._read_seq = seq
        if self._checked_seq == seq:
            return
        self._checked_seq = seq
        with bus.condition:
            late = [n for n in nodes if self._latest_seq(n) < seq]
        for node_id in nodes:
            self._missed[node_id] = self._missed.get(node_id, 0) + 1 if node_id in late else 0
            if self._missed[node_id] >= self._settings.pdo_miss_limit:
                reason = (
                    f"no cyclic TPDO for {self._missed[node_id]} SYNCs in a row "
                    f"(limit {self._settings.pdo_miss_limit})"
                )
                self._bus.report_lost(node_id, reason)
                raise self._lose(nodes[node_id], reason)
