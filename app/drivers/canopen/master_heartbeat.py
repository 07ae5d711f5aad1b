"""The controller's own heartbeat (CiA 301 producer), which every drive consumes (0x1016).

Why: a drive that only watches SYNC notices a dead controller through its SYNC-loss
monitoring, if it has one and it is switched on. A CANopen drive has a standard watchdog for
this instead: its heartbeat consumer (0x1016). We write into each drive's 0x1016 sub 1 our
node id (bits 16-23) and a timeout in ms (bits 0-15); once the drive has heard our heartbeat,
a silence longer than that timeout is a heartbeat event: EMCY 0x8130 ("life guard or
heartbeat error") and the drive's abort-connection reaction (CiA 402 0x6007, usually a
fault), so an enabled drive stops on its own when the machine process dies or the
controller's CAN connection is lost.

Why python-can's periodic send and not the machine loop: the beat must not depend on the
loop's timing (a long step or a pause of the loop must not make every drive fault), and it
must end when the process ends. On ``socketcan`` python-can hands the frame to the kernel's
broadcast manager (BCM): the kernel sends it on time whatever the process does, and drops
the task when the process dies and its socket is closed. On the other interfaces python-can
sends it from a daemon thread of its own, which dies with the process.

What it does not cover: a machine process that hangs but stays alive keeps the heartbeat
going; the loop's own timing and the drives' SYNC monitoring (cycle period 0x1006) are what
notice that.

The frame: COB-ID 0x700 + node id, one byte, the NMT state 0x05 (OPERATIONAL).
"""

from __future__ import annotations

import threading

import can

HEARTBEAT_COB_BASE = 0x700  # heartbeat COB-ID = 0x700 + producer node id
NMT_STATE_OPERATIONAL = 0x05  # the one data byte of our heartbeat
CONSUMER_TIMEOUT_MAX_MS = 0xFFFF  # 0x1016 entries carry the time in 16 bits
STOP_JOIN_MAX_S = 0.2  # how long stop() waits for a sleeping sender thread to notice


def consumer_heartbeat_entry(producer_node_id: int, timeout_ms: int) -> int:
    """One 0x1016 entry: bits 16-23 the producer's node id, bits 0-15 the timeout in ms.

    0 (what deactivation writes) switches the consumer off."""
    if not 1 <= producer_node_id <= 127:
        raise ValueError(f"producer node id {producer_node_id} is not 1 to 127")
    if not 1 <= timeout_ms <= CONSUMER_TIMEOUT_MAX_MS:
        raise ValueError(f"consumer heartbeat time {timeout_ms} ms is not 1 to 65535")
    return producer_node_id << 16 | timeout_ms


def split_consumer_heartbeat_entry(entry: int) -> tuple[int, int]:
    """(producer node id, timeout ms) of a 0x1016 entry; (0, 0) or a 0 time means off."""
    return (entry >> 16) & 0xFF, entry & 0xFFFF


class MasterHeartbeat:
    """Our heartbeat on one python-can bus: ``start(bus)``, ``stop()``, ``failure()``.

    Only the machine loop's thread calls these (the backend's lifecycle and supervision)."""

    def __init__(self, node_id: int, period_ms: int) -> None:
        self.node_id = node_id
        self.period_s = period_ms / 1000.0
        self._task: can.broadcastmanager.CyclicSendTaskABC | None = None

    @property
    def cob_id(self) -> int:
        return HEARTBEAT_COB_BASE + self.node_id

    @property
    def running(self) -> bool:
        """Started and not stopped by us (it may still have died: see :meth:`failure`)."""
        return self._task is not None

    def start(self, bus: can.BusABC) -> None:
        """Send the heartbeat every period from now on (no-op while it is sent; a sender that
        died is replaced). Raises python-can's errors (CanError, OSError, ValueError) when
        the bus refuses."""
        if self._task is not None and not self.failure():
            return
        self.stop()
        message = can.Message(
            arbitration_id=self.cob_id, data=bytes([NMT_STATE_OPERATIONAL]), is_extended_id=False
        )
        self._task = bus.send_periodic(message, self.period_s)

    def stop(self) -> None:
        """Stop sending (no-op when stopped). A thread-based sender is given up to one
        period (at most ``STOP_JOIN_MAX_S``) to end, so that it is not in the middle of a
        send when the bus is closed right after; one still asleep then ends by itself when
        it wakes up, without sending."""
        task, self._task = self._task, None
        if task is None:
            return
        task.stop()
        thread = getattr(task, "thread", None)
        if isinstance(thread, threading.Thread) and thread is not threading.current_thread():
            thread.join(min(self.period_s, STOP_JOIN_MAX_S) + 0.05)

    def failure(self) -> str:
        """Why the heartbeat is no longer sent although :meth:`stop` was not called ("" while
        it is sent): python-can's sender thread ends on a send error, or when the bus is
        shut down under it. The kernel's BCM task has no such thread and cannot die alone."""
        task = self._task
        thread = getattr(task, "thread", None) if task is not None else None
        if isinstance(thread, threading.Thread) and not thread.is_alive():
            return (
                f"the controller's heartbeat (COB-ID 0x{self.cob_id:03X}) is no longer sent: "
                "its sender thread ended; the drives stop with heartbeat error 0x8130"
            )
        return ""
