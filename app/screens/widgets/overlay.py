"""Modal overlays drawn inside the main window (keypads, keyboard, confirmations, choices).

Why overlays and not top-level dialogs: in a frameless full-screen kiosk a separate dialog
window can end up behind the main window or be placed by a window manager that is not there;
an overlay is a child of the window, covers it (so nothing behind it can be touched: that
makes it modal), never blocks the event loop (the machine snapshot keeps refreshing behind
it), and ``QWidget.grab()`` of the window includes it, so screenshots show it.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, Qt, Signal
from PySide6.QtGui import QColor, QKeyEvent, QPainter, QPaintEvent
from PySide6.QtWidgets import QFrame, QVBoxLayout, QWidget


class Overlay(QWidget):
    """A dimmed backdrop over its host with a centred panel; subclasses fill ``panel``.

    ``finished(bool)`` is emitted once, with True when the user confirmed; the overlay then
    removes itself."""

    finished = Signal(bool)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("overlay")
        self.setAttribute(Qt.WidgetAttribute.WA_StyledBackground, False)
        self.setFocusPolicy(Qt.FocusPolicy.StrongFocus)
        self.panel = QFrame(self)
        self.panel.setObjectName("overlayPanel")
        self.panel_layout = QVBoxLayout(self.panel)
        self.panel_layout.setContentsMargins(18, 14, 18, 14)
        self.panel_layout.setSpacing(10)
        outer = QVBoxLayout(self)
        outer.setContentsMargins(0, 0, 0, 0)
        outer.addStretch(1)
        outer.addWidget(self.panel, 0, Qt.AlignmentFlag.AlignHCenter)
        outer.addStretch(1)
        self._host: QWidget | None = None
        self._done = False

    def open_on(self, host: QWidget) -> None:
        """Show over ``host`` (the window's central widget), on top of everything in it."""
        self._host = host
        self.setParent(host)
        self.setGeometry(host.rect())
        host.installEventFilter(self)
        self.show()
        self.raise_()
        self.setFocus(Qt.FocusReason.PopupFocusReason)
        # A fixed size from the moment it opens: an error line or a longer text inside it
        # never makes it grow or jump under the finger (its lines are reserved).
        if self.panel.minimumSize() != self.panel.maximumSize():  # not fixed by its maker
            self.panel.setFixedSize(self.panel.sizeHint().boundedTo(host.size()))

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        if watched is self._host and event.type() == QEvent.Type.Resize and self._host:
            self.setGeometry(self._host.rect())
        return False

    def paintEvent(self, event: QPaintEvent) -> None:
        painter = QPainter(self)
        painter.fillRect(self.rect(), QColor(0, 0, 0, 170))
        painter.end()

    def keyPressEvent(self, event: QKeyEvent) -> None:
        if event.key() == Qt.Key.Key_Escape:
            self.reject()
            return
        super().keyPressEvent(event)

    def accept(self) -> None:
        self._finish(True)

    def reject(self) -> None:
        self._finish(False)

    def _finish(self, accepted: bool) -> None:
        if self._done:
            return
        self._done = True
        if self._host is not None:
            self._host.removeEventFilter(self)
        self.hide()
        self.finished.emit(accepted)
        self.deleteLater()

    @property
    def is_open(self) -> bool:
        return not self._done and self.isVisible()


def open_overlays(host: QWidget) -> list[Overlay]:
    """The overlays currently open over ``host``, the top-most last."""
    return [w for w in host.findChildren(Overlay) if w.is_open]


def top_overlay(host: QWidget) -> Overlay | None:
    overlays = open_overlays(host)
    return overlays[-1] if overlays else None
