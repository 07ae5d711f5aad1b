"""Touch-sized confirmation, message and choice overlays.

Why a confirmation for deletes and shut down: on a touch panel a stray tap is easy, and those
actions cannot be undone from the panel.
"""

from __future__ import annotations

from typing import Any

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QScrollArea,
    QWidget,
)

from app.screens.widgets.buttons import touch_button
from app.screens.widgets.kinetic import kinetic_scroll
from app.screens.widgets.overlay import Overlay


def _title_label(title: str) -> QLabel:
    label = QLabel(title)
    label.setProperty("role", "title")
    return label


def _message_label(message: str) -> QLabel:
    """The wrapped text of a confirmation or message, wide enough to read at a glance."""
    label = QLabel(message)
    label.setWordWrap(True)
    label.setMinimumWidth(520)
    label.setObjectName("messageLabel")
    return label


class ConfirmOverlay(Overlay):
    """A question with two big answers; ``finished(True)`` when confirmed."""

    def __init__(
        self,
        title: str,
        message: str,
        confirm_text: str,
        *,
        danger: bool = False,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("confirmOverlay")
        title_label = _title_label(title)
        self.message_label = _message_label(message)
        self.confirm_button = touch_button(
            "confirm", "danger" if danger else "primary", confirm_text
        )
        self.cancel_button = touch_button("cancelButton", text=self.tr("Cancel"))
        self.confirm_button.clicked.connect(self.accept)
        self.cancel_button.clicked.connect(self.reject)
        row = QHBoxLayout()
        row.setSpacing(16)
        row.addWidget(self.cancel_button)
        row.addWidget(self.confirm_button)
        self.panel_layout.addWidget(title_label)
        self.panel_layout.addWidget(self.message_label)
        self.panel_layout.addSpacing(10)
        self.panel_layout.addLayout(row)


class MessageOverlay(Overlay):
    """A message the operator must see (an error on import, a refused save)."""

    def __init__(self, title: str, message: str, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("messageOverlay")
        title_label = _title_label(title)
        self.message_label = _message_label(message)
        self.ok_button = touch_button("okButton", "primary", self.tr("OK"))
        self.ok_button.clicked.connect(self.accept)
        self.panel_layout.addWidget(title_label)
        self.panel_layout.addWidget(self.message_label)
        self.panel_layout.addWidget(self.ok_button)


class ChoiceOverlay(Overlay):
    """Pick one of several items from big buttons (scrolls by dragging when there are many).

    ``chosen(object)`` carries the value of the picked item."""

    chosen = Signal(object)

    def __init__(
        self,
        title: str,
        choices: list[tuple[str, Any]],
        *,
        current: Any = None,
        columns: int = 1,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("choiceOverlay")
        title_label = _title_label(title)
        content = QWidget()
        grid = QGridLayout(content)
        grid.setSpacing(8)
        self.buttons: list[QPushButton] = []
        for index, (text, value) in enumerate(choices):
            button = touch_button(f"choice_{index}", text=text)
            button.setCheckable(True)
            button.setChecked(value == current and current is not None)
            button.clicked.connect(lambda _=False, v=value: self._pick(v))
            grid.addWidget(button, index // columns, index % columns)
            self.buttons.append(button)
        scroll = QScrollArea()
        scroll.setWidget(content)
        scroll.setWidgetResizable(True)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        scroll.setMinimumWidth(560)
        scroll.setMinimumHeight(min(440, 66 * max(1, (len(choices) + columns - 1) // columns)))
        kinetic_scroll(scroll)
        self.cancel_button = touch_button("cancelButton", text=self.tr("Cancel"))
        self.cancel_button.clicked.connect(self.reject)
        self.panel_layout.addWidget(title_label)
        self.panel_layout.addWidget(scroll)
        self.panel_layout.addWidget(self.cancel_button)

    def _pick(self, value: Any) -> None:
        self.chosen.emit(value)
        self.accept()
