"""The one way the panel makes a vertically scrolling area.

Why one place: a touch panel has no mouse wheel, so a scroll area that forgets the kinetic
drag (``kinetic_scroll``) cannot be scrolled by a finger at all; and a horizontal bar on a
page laid out to the screen's width only steals height.
"""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QScrollArea, QWidget

from app.screens.widgets.kinetic import kinetic_scroll


def touch_scroll_area(content: QWidget) -> QScrollArea:
    """``content`` in a scroll area a finger drags (kinetic), vertical only."""
    scroll = QScrollArea()
    scroll.setWidgetResizable(True)
    scroll.setWidget(content)
    scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
    kinetic_scroll(scroll)
    return scroll
