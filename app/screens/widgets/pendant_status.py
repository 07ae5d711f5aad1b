"""The Manual screen's line about the machine's own jog controls: who jogs now (the screen,
the handwheel, the joystick or a USB pendant), and the handwheel's selected axis and
multiplier, as the technician set them on the wheel's switches."""

from __future__ import annotations

from PySide6.QtWidgets import QLabel, QWidget

from app.machine.snapshot import JogSource, PendantView
from app.screens.widgets.readouts import set_text


class PendantStatus(QLabel):
    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("pendantStatus")
        self.setProperty("role", "caption")
        self.setWordWrap(True)
        self._view = PendantView()

    def _source(self, source: JogSource | None) -> str:
        names = {
            JogSource.SCREEN: self.tr("the screen"),
            JogSource.HANDWHEEL: self.tr("the handwheel"),
            JogSource.JOYSTICK: self.tr("the joystick"),
            JogSource.PENDANT: self.tr("the USB pendant"),
        }
        return names[source] if source is not None else self.tr("nobody (all at rest)")

    def show_view(self, view: PendantView) -> None:
        self._view = view
        parts = [self.tr("Jogging: %1").replace("%1", self._source(view.jog_source))]
        if view.handwheel_fitted:
            if view.wheel_axis:
                wheel = self.tr("Handwheel: %1 ×%2")
                wheel = wheel.replace("%1", view.wheel_axis).replace(
                    "%2", str(view.wheel_multiplier)
                )
            else:
                wheel = self.tr("Handwheel: off")
            parts.append(wheel)
        if view.pendant_connected:
            parts.append(self.tr("USB pendant connected"))
        set_text(self, "   ·   ".join(parts))
        self.setVisible(view.handwheel_fitted or view.joystick_fitted or view.pendant_connected)

    def retranslate(self) -> None:
        self.show_view(self._view)
