"""The status lamp: a coloured disc that mirrors the machine's state at a glance.

Why colours from a pure function: the mapping (IEC 60073: red = fault, yellow = attention,
green = running, blue = mandatory action, white = neutral) is a rule an operator relies on
across the hall; it is tested without Qt widgets and used by the lamp and the state text.
"""

from __future__ import annotations

import enum

from PySide6.QtCore import QRectF, QSize, Qt
from PySide6.QtGui import QBrush, QColor, QPainter, QPaintEvent, QPen, QRadialGradient
from PySide6.QtWidgets import QSizePolicy, QWidget

from app.machine.states import MachineState


class LampColor(enum.Enum):
    OFF = "#39414d"
    GREEN = "#3cd066"
    YELLOW = "#ffc21a"
    RED = "#ff3030"
    BLUE = "#4d94ff"
    WHITE = "#f2f4f8"


_STATE_COLORS: dict[MachineState, LampColor] = {
    MachineState.POWER_UP: LampColor.OFF,
    MachineState.NOT_HOMED: LampColor.BLUE,  # mandatory action: home the machine
    MachineState.HOMING: LampColor.GREEN,
    MachineState.READY: LampColor.WHITE,
    MachineState.AUTOMATIC: LampColor.GREEN,
    MachineState.MANUAL: LampColor.YELLOW,
    MachineState.STOPPING: LampColor.YELLOW,
    MachineState.ERROR: LampColor.RED,
    MachineState.EMERGENCY_STOP: LampColor.RED,
}


def lamp_color(state: MachineState | None) -> LampColor:
    """The lamp's colour for a machine state; None (no machine) is red."""
    if state is None:
        return LampColor.RED
    return _STATE_COLORS[state]


class StatusLamp(QWidget):
    """A round lamp; ``color`` is one of :class:`LampColor`."""

    def __init__(self, diameter_px: int = 40, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._color = LampColor.OFF
        self._diameter_px = diameter_px
        self.setSizePolicy(QSizePolicy.Policy.Fixed, QSizePolicy.Policy.Fixed)
        self.setFixedSize(QSize(diameter_px + 4, diameter_px + 4))

    @property
    def color(self) -> LampColor:
        return self._color

    def set_color(self, color: LampColor) -> None:
        if color is not self._color:
            self._color = color
            self.update()

    def set_diameter(self, diameter_px: int) -> None:
        self._diameter_px = diameter_px
        self.setFixedSize(QSize(diameter_px + 4, diameter_px + 4))

    def paintEvent(self, event: QPaintEvent) -> None:
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        rect = QRectF(2, 2, self._diameter_px, self._diameter_px)
        base = QColor(self._color.value)
        gradient = QRadialGradient(
            rect.center().x() - rect.width() * 0.2,
            rect.center().y() - rect.height() * 0.2,
            rect.width() * 0.7,
        )
        gradient.setColorAt(0.0, base.lighter(150))
        gradient.setColorAt(1.0, base)
        painter.setBrush(QBrush(gradient))
        painter.setPen(QPen(QColor("#05070a"), 2))
        painter.drawEllipse(rect)
        painter.setPen(Qt.PenStyle.NoPen)
        painter.end()
