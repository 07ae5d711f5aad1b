"""Heartbeat consumer: which nodes have gone silent, and which came back.

Why our own: canopen's ``NmtMaster`` records the last heartbeat but has no consumer timeout,
so a drive that loses power or its cable would simply stop updating, and the last statusword
would be shown for ever. Here every heartbeat is stamped on arrival (receive thread) and
:meth:`HeartbeatWatchdog.poll` (machine loop) reports each node whose silence exceeds the
timeout exactly once, and each lost node heard again exactly once. It never clears the
backend's error by itself: the backend latches the loss until it is configured again.

The clock is injected so that the rules are tested on simulated time.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass

NMT_OPERATIONAL = 0x05
NMT_PRE_OPERATIONAL = 0x7F
NMT_BOOT_UP = 0x00


@dataclass(frozen=True)
class HeartbeatChange:
    node_id: int
    lost: bool  # True: silent for longer than the timeout; False: heard again after a loss
    silent_s: float


class HeartbeatWatchdog:
    def __init__(self, timeout_s: float, clock: Callable[[], float] = time.monotonic) -> None:
        self._timeout_s = timeout_s
        self._clock = clock
        self._lock = threading.Lock()
        self._last: dict[int, float] = {}
        self._state: dict[int, int] = {}
        self._lost: set[int] = set()

    def watch(self, node_ids: Iterable[int]) -> None:
        """Start watching these nodes now, as if each had just been heard."""
        now = self._clock()
        with self._lock:
            for node_id in node_ids:
                self._last[node_id] = now
                self._lost.discard(node_id)

    def forget(self, node_ids: Iterable[int]) -> None:
        with self._lock:
            for node_id in node_ids:
                self._last.pop(node_id, None)
                self._lost.discard(node_id)

    def heard(self, node_id: int, nmt_state: int) -> None:
        """A heartbeat arrived (called from the receive thread)."""
        now = self._clock()
        with self._lock:
            if node_id in self._last:
                self._last[node_id] = now
            self._state[node_id] = nmt_state

    def nmt_state(self, node_id: int) -> int | None:
        with self._lock:
            return self._state.get(node_id)

    def poll(self) -> list[HeartbeatChange]:
        """Nodes lost since the last poll, and lost nodes heard again since then."""
        now = self._clock()
        changes: list[HeartbeatChange] = []
        with self._lock:
            for node_id, last in sorted(self._last.items()):
                silent_s = now - last
                if node_id not in self._lost and silent_s > self._timeout_s:
                    self._lost.add(node_id)
                    changes.append(HeartbeatChange(node_id, True, silent_s))
                elif node_id in self._lost and silent_s <= self._timeout_s:
                    self._lost.discard(node_id)
                    changes.append(HeartbeatChange(node_id, False, silent_s))
        return changes
