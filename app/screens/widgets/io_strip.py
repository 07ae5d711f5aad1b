"""The main screen's I/O strip: spindle, clamps, centering, board, guard and E-stop chain,
each a lamp with words.

Why one button: the whole strip is one touch target that opens the I/O page, so a
technician chasing a clamp or guard alarm goes from the symptom to every terminal in one tap;
the lamps inside do not take touches of their own.
"""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QHBoxLayout, QLabel, QPushButton, QWidget

from app.drivers.contracts import InputImage
from app.screens.io_status import (
    Device,
    DeviceStatus,
    condition_text,
    device_statuses,
    device_text,
)
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.lamp import StatusLamp
from app.screens.widgets.readouts import set_text, styled_label

LAMP_PX = 18


class IoStrip(QWidget):
    """``button`` is the touch target; ``show_inputs`` draws the latest input image."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.button: QPushButton = touch_button("ioStrip", "strip")
        self.lamps: dict[Device, StatusLamp] = {}
        self.labels: dict[Device, QLabel] = {}
        self.statuses: tuple[DeviceStatus, ...] = ()
        self.inputs = InputImage()
        inside = QHBoxLayout(self.button)
        inside.setContentsMargins(8, 0, 8, 0)
        inside.setSpacing(6)
        for device in Device:
            lamp = StatusLamp(LAMP_PX)
            lamp.setAttribute(Qt.WidgetAttribute.WA_TransparentForMouseEvents)
            label = styled_label("", "iolamp", f"io_{device.name.lower()}")
            label.setAttribute(Qt.WidgetAttribute.WA_TransparentForMouseEvents)
            self.lamps[device] = lamp
            self.labels[device] = label
            inside.addWidget(lamp)
            inside.addWidget(label, 1)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.button)
        self.show_inputs(InputImage(), force=True)

    def show_inputs(self, inputs: InputImage, force: bool = False) -> None:
        self.inputs = inputs
        statuses = device_statuses(inputs)
        if statuses == self.statuses and not force:
            return
        self.statuses = statuses
        for status in statuses:
            self.lamps[status.device].set_color(status.color)
            set_text(
                self.labels[status.device],
                f"{device_text(status.device)}\n{condition_text(status.condition)}",
            )

    def retranslate(self) -> None:
        self.show_inputs(self.inputs, force=True)

    def set_lamp_diameter(self, diameter_px: int) -> None:
        for lamp in self.lamps.values():
            lamp.set_diameter(diameter_px)
