"""A press-and-hold button for continuous jogging.

Why it repeats while held: the machine stops a jog by itself when the refresh stops
(``JOG_DEADMAN_S``), so a lost release event, a frozen screen or a dead link cannot leave an
axis running. The button therefore sends ``holdStarted`` on press, ``holdRefresh`` every
``JOG_REFRESH_S`` while held, and ``holdEnded`` on release, and also when it is disabled,
hidden or the application loses focus while held (the finger may still be on the glass, but
the screen can no longer tell).
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QTimer, Signal
from PySide6.QtGui import QHideEvent
from PySide6.QtWidgets import QPushButton, QWidget

from app.machine.commands import JOG_REFRESH_S


class HoldButton(QPushButton):
    holdStarted = Signal()  # noqa: N815 (Qt signal naming)
    holdRefresh = Signal()  # noqa: N815 (Qt signal naming)
    holdEnded = Signal()  # noqa: N815 (Qt signal naming)

    def __init__(self, text: str = "", parent: QWidget | None = None) -> None:
        super().__init__(text, parent)
        self._held = False
        self._timer = QTimer(self)
        self._timer.setInterval(round(JOG_REFRESH_S * 1000))
        self._timer.timeout.connect(self.holdRefresh)
        self.pressed.connect(self._start)
        self.released.connect(self._end)

    @property
    def held(self) -> bool:
        return self._held

    @property
    def refreshing(self) -> bool:
        """True while the refresh timer runs (only while held)."""
        return self._timer.isActive()

    def _start(self) -> None:
        if self._held:
            return
        self._held = True
        self._timer.start()
        self.holdStarted.emit()

    def _end(self) -> None:
        if not self._held:
            return
        self._held = False
        self._timer.stop()
        self.holdEnded.emit()

    def release_hold(self) -> None:
        """End a hold from outside (the screen is left, the machine refused the jog)."""
        if self.isDown():
            self.setDown(False)
        self._end()

    def changeEvent(self, event: QEvent) -> None:
        if (event.type() == QEvent.Type.EnabledChange and not self.isEnabled()) or (
            event.type() == QEvent.Type.ActivationChange and not self.isActiveWindow()
        ):
            self.release_hold()
        super().changeEvent(event)

    def hideEvent(self, event: QHideEvent) -> None:
        self.release_hold()
        super().hideEvent(event)
