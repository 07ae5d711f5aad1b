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
from PySide6.QtWidgets import QPushButton


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
