"""The one factory for the panel's push buttons.

Why one place: every button on the panel is made the same way, and the two things it sets are
rules of the whole panel, not of one screen. ``kind`` is the property the theme's style sheet
picks the look by (primary, danger, nav, key, ...), so a button without it looks plain on
purpose; and no button ever takes keyboard focus, because a tap must not move a focus frame
around a touch screen nor steal the keys a USB keyboard sends to an open keypad or overlay.
A screen that made its own buttons could forget either; this module cannot.
"""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QPaintEvent
from PySide6.QtWidgets import QPushButton, QStyle, QStyleOptionButton, QStylePainter


def touch_button(name: str = "", kind: str = "", text: str = "") -> QPushButton:
    """A push button named ``name`` (tests and the style sheet find it by that), styled as
    ``kind`` (empty: the plain look), showing ``text``, that never takes keyboard focus."""
    button = QPushButton(text)
    if name:
        button.setObjectName(name)
    if kind:
        button.setProperty("kind", kind)
    button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
    return button


class ElidedButton(QPushButton):
    """A button whose text ends in an ellipsis when it does not fit (a long recipe name, a
    note): cut text without a sign looks like the whole value. ``text()`` stays the whole
    text; a tap opens what shows it whole (the keyboard, the recipe)."""

    # Where the ellipsis goes: at the end by default; in the middle where names differ only
    # at their ends (recipes of one barrel in several thicknesses).
    elide_mode = Qt.TextElideMode.ElideRight

    def shown_text(self) -> str:
        """The text as drawn: whole, or cut with an ellipsis to the button's width."""
        option = QStyleOptionButton()
        self.initStyleOption(option)
        style = self.style()
        contents = style.subElementRect(QStyle.SubElement.SE_PushButtonContents, option, self)
        width = contents.width() - 2 * ELIDE_MARGIN_PX
        return self.fontMetrics().elidedText(self.text(), self.elide_mode, width)

    def paintEvent(self, event: QPaintEvent) -> None:
        option = QStyleOptionButton()
        self.initStyleOption(option)
        option.text = self.shown_text()
        painter = QStylePainter(self)
        painter.drawControl(QStyle.ControlElement.CE_PushButton, option)
        painter.end()


ELIDE_MARGIN_PX = 6
"""Room kept inside the button's padding so the ellipsis never touches its border."""


def elided_button(
    name: str = "",
    kind: str = "",
    text: str = "",
    mode: Qt.TextElideMode = Qt.TextElideMode.ElideRight,
) -> ElidedButton:
    """A :func:`touch_button` that elides its text (same look, never takes focus)."""
    button = ElidedButton(text)
    button.elide_mode = mode
    if name:
        button.setObjectName(name)
    if kind:
        button.setProperty("kind", kind)
    button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
    return button
