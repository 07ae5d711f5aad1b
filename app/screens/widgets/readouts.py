"""Read-outs: an axis position and a captioned value.

Why ``set_*`` methods that compare first: the screens refresh at 30 Hz, and a ``setText`` with
the same text still costs a relayout; comparing first keeps an idle screen nearly free.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QRect, Qt
from PySide6.QtGui import QPainter, QPaintEvent, QPalette, QTextLayout
from PySide6.QtWidgets import (
    QAbstractButton,
    QFrame,
    QHBoxLayout,
    QLabel,
    QSizePolicy,
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


class FixedLinesLabel(QLabel):
    """A wrapped label whose height is kept for ``lines`` lines whether it is empty or not,
    so that nothing below it moves when a text appears (a refusal's reason, an error under
    a keypad's entry); it follows the font the theme gives it."""

    def __init__(self, role: str, name: str, lines: int = 2, parent: QWidget | None = None):
        super().__init__(parent)
        self.setObjectName(name)
        self.setProperty("role", role)
        self.setWordWrap(True)
        self.lines = lines
        self._fit()

    def changeEvent(self, event: QEvent) -> None:
        super().changeEvent(event)
        if event.type() in (QEvent.Type.FontChange, QEvent.Type.StyleChange):
            self._fit()

    def _fit(self) -> None:
        height = self.lines * self.fontMetrics().lineSpacing()
        if self.minimumHeight() != height or self.maximumHeight() != height:
            self.setFixedHeight(height)


class ElidedLinesLabel(FixedLinesLabel):
    """A FixedLinesLabel that ends its last line with an ellipsis when the text needs more
    lines (a long recipe name): ``text()`` stays the whole text."""

    def never_widen(self) -> None:
        """Take the width the layout gives and never ask for more (nor for a height from the
        width: the height is fixed), so that a long text cannot widen its screen."""
        policy = self.sizePolicy()
        policy.setHorizontalPolicy(QSizePolicy.Policy.Ignored)
        policy.setHeightForWidth(False)
        self.setSizePolicy(policy)

    def paintEvent(self, event: QPaintEvent) -> None:
        text = self.text()
        area = self.contentsRect()
        metrics = self.fontMetrics()
        layout = QTextLayout(text, self.font())
        layout.beginLayout()
        spans: list[tuple[int, int]] = []
        while len(spans) <= self.lines:
            line = layout.createLine()
            if not line.isValid():
                break
            line.setLineWidth(area.width())
            spans.append((line.textStart(), line.textLength()))
        layout.endLayout()
        shown: list[str] = []
        for index, (start, length) in enumerate(spans[: self.lines]):
            if index == self.lines - 1 and len(spans) > self.lines:
                shown.append(
                    metrics.elidedText(text[start:], Qt.TextElideMode.ElideRight, area.width())
                )
            else:
                shown.append(text[start : start + length].strip())
        painter = QPainter(self)
        painter.setPen(self.palette().color(QPalette.ColorRole.WindowText))
        painter.setFont(self.font())
        step = metrics.lineSpacing()
        top = area.top() + (area.height() - step * len(shown)) // 2
        for index, line_text in enumerate(shown):
            row = QRect(area.left(), top + index * step, area.width(), step)
            painter.drawText(row, int(self.alignment()), line_text)
        painter.end()


def reason_label(name: str) -> FixedLinesLabel:
    """Why the control above it is refused, in words on the screen (a touch screen shows
    no tooltips)."""
    return FixedLinesLabel("reason", name)


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
        # The degree sign belongs at the top of the digits, in their size (a small caption
        # on the baseline read as a stray circle); mm is a caption beside them.
        degree = unit == "°"
        self.unit_label = styled_label(unit, "position" if degree else "caption")
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
        unit_at = Qt.AlignmentFlag.AlignTop if degree else Qt.AlignmentFlag.AlignBottom
        bottom.addWidget(self.unit_label, 0, unit_at)
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
        self._value_row = QHBoxLayout()
        self._value_row.setSpacing(8)
        self._value_row.addWidget(self.value_label)
        self._value_row.addStretch(1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(10, 4, 10, 6)
        layout.setSpacing(0)
        layout.addWidget(self.caption_label)
        layout.addLayout(self._value_row)

    def add_note(self, note: QLabel) -> None:
        """A small text beside the value (what the value leaves out), on its baseline."""
        self._value_row.insertWidget(1, note, 0, Qt.AlignmentFlag.AlignBottom)

    def set_caption(self, caption: str) -> None:
        set_text(self.caption_label, caption)

    def set_value(self, text: str) -> None:
        set_text(self.value_label, text)
