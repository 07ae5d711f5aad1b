"""Read-outs: an axis position and a captioned value.

Why ``set_*`` methods that compare first: the screens refresh at 30 Hz, and a ``setText`` with
the same text still costs a relayout; comparing first keeps an idle screen nearly free.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, Qt
from PySide6.QtWidgets import (
    QAbstractButton,
    QFrame,
    QHBoxLayout,
    QLabel,
    QVBoxLayout,
    QWidget,
)

from app.screens.formatting import format_position
from app.screens.theme import set_style_property


def set_text(label: QLabel | QAbstractButton, text: str) -> None:
    """``setText`` only when the text changed."""
    if label.text() != text:
        label.setText(text)


def styled_label(text: str, role: str, name: str = "") -> QLabel:
    label = QLabel(text)
    label.setProperty("role", role)
    if name:
        label.setObjectName(name)
    return label


REASON_LINES = 2


class ReasonLabel(QLabel):
    """Why the control above it is refused, in words on the screen (a touch screen shows
    no tooltips). Its height is kept for two lines whether it is empty or not, so that the
    controls below never move when a reason appears; it follows the font the theme gives."""

    def __init__(self, name: str, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName(name)
        self.setProperty("role", "reason")
        self.setWordWrap(True)
        self._fit()

    def changeEvent(self, event: QEvent) -> None:
        super().changeEvent(event)
        if event.type() in (QEvent.Type.FontChange, QEvent.Type.StyleChange):
            self._fit()

    def _fit(self) -> None:
        height = REASON_LINES * self.fontMetrics().lineSpacing()
        if self.minimumHeight() != height or self.maximumHeight() != height:
            self.setFixedHeight(height)


def reason_label(name: str) -> ReasonLabel:
    return ReasonLabel(name)


class AxisReadout(QFrame):
    """One axis: name, position in big digits, unit, and a tag when not homed.

    An unhomed position is drawn in yellow italics with a "not homed" tag: the number is only
    the encoder's count since power-up, and an operator must not trust it for a cut."""

    def __init__(
        self, axis: str, unit: str, decimals: int = 2, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.setObjectName("panel")
        self.axis = axis
        self.decimals = decimals
        self.name_label = styled_label(axis, "axis")
        self.value_label = styled_label(
            format_position(0.0, decimals), "position", f"position{axis}"
        )
        self.value_label.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        self.value_label.setProperty("homed", "true")
        self.unit_label = styled_label(unit, "caption")
        self.tag_label = styled_label("", "tag", f"homedTag{axis}")
        self.tag_label.setVisible(False)
        top = QHBoxLayout()
        top.setContentsMargins(0, 0, 0, 0)
        top.addWidget(self.name_label)
        top.addStretch(1)
        top.addWidget(self.tag_label)
        bottom = QHBoxLayout()
        bottom.setContentsMargins(0, 0, 0, 0)
        bottom.addWidget(self.value_label, 1)
        bottom.addWidget(self.unit_label, 0, Qt.AlignmentFlag.AlignBottom)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(10, 4, 10, 4)
        layout.setSpacing(0)
        layout.addLayout(top)
        layout.addLayout(bottom)
        self.homed = True
        self.not_homed_text = "NOT HOMED"

    def set_position(self, value: float, homed: bool, faulted: bool = False) -> None:
        set_text(self.value_label, format_position(value, self.decimals))
        if homed != self.homed:
            self.homed = homed
            set_style_property(self.value_label, "homed", "true" if homed else "false")
            self.tag_label.setVisible(not homed)
        set_style_property(self.value_label, "faulted", "true" if faulted else "false")

    def set_not_homed_text(self, text: str) -> None:
        self.not_homed_text = text
        self.tag_label.setText(text)


class ValueTile(QFrame):
    """A caption over a value (counters, last width, cycle times)."""

    def __init__(
        self, caption: str = "", name: str = "", role: str = "value", parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.setObjectName("panel")
        self.caption_label = styled_label(caption, "caption")
        self.value_label = styled_label("—", role, name)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(10, 4, 10, 6)
        layout.setSpacing(0)
        layout.addWidget(self.caption_label)
        layout.addWidget(self.value_label)

    def set_caption(self, caption: str) -> None:
        set_text(self.caption_label, caption)

    def set_value(self, text: str) -> None:
        set_text(self.value_label, text)
