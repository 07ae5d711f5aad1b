"""Samples the machine's latest snapshot on a timer and announces only real changes.

Why polling and not callbacks from the machine: the machine runs in its own process (or, in
tests, on a simulated clock advanced by each ``latest()`` call); the GUI must never wait for
it. ``latest()`` returns at once, so a 30 Hz timer costs nothing when nothing changed, and a
slow frame drops snapshots rather than delaying the machine.
"""

from __future__ import annotations

from PySide6.QtCore import QObject, QTimer, Signal

from app.machine.link import MachineLink
from app.machine.snapshot import MachineSnapshot

REFRESH_HZ = 30.0


class SnapshotPoller(QObject):
    """``snapshotChanged(MachineSnapshot)`` when a newer snapshot arrives; ``linkLost()``
    once when the machine has ended or died."""

    snapshotChanged = Signal(object)  # noqa: N815 (Qt signal naming)
    linkLost = Signal()  # noqa: N815 (Qt signal naming)

    def __init__(
        self, link: MachineLink, refresh_hz: float = REFRESH_HZ, parent: QObject | None = None
    ) -> None:
        super().__init__(parent)
        self.link = link
        self.snapshot: MachineSnapshot | None = None
        self.lost = False
        self.polls = 0
        self._timer = QTimer(self)
        self._timer.setInterval(max(1, round(1000.0 / refresh_hz)))
        self._timer.timeout.connect(self.poll)

    def set_interval_ms(self, interval_ms: int) -> None:
        """Poll every ``interval_ms`` (0: whenever the event loop is idle, for tests and
        benchmarks that run the simulated machine as fast as it goes)."""
        self._timer.setInterval(max(0, interval_ms))

    def start(self) -> None:
        self._timer.start()

    def stop(self) -> None:
        self._timer.stop()

    @property
    def active(self) -> bool:
        return self._timer.isActive()

    def poll(self) -> None:
        """One sample: emit the snapshot if it is new, and notice a dead machine."""
        self.polls += 1
        snapshot = self.link.latest()
        if snapshot is not None and (self.snapshot is None or snapshot.seq != self.snapshot.seq):
            self.snapshot = snapshot
            self.snapshotChanged.emit(snapshot)
        if not self.lost and not self.link.alive():
            self.lost = True
            self.linkLost.emit()
