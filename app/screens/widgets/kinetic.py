"""Kinetic drag-scrolling for every scrolling list and page on the panel.

Why the left-mouse-button gesture: many panel PCs have a resistive or USB touch controller
that reports a finger as a mouse, not as touch events; Qt's touch gesture never sees those,
so a list could only be scrolled by its thin scroll bar. The mouse gesture works for both:
a real touch screen's touches reach the widget as synthesised mouse events too. A tap that
does not move still reaches the row or button under it.
"""

from __future__ import annotations

from PySide6.QtWidgets import QAbstractItemView, QAbstractScrollArea, QScroller


def kinetic_scroll(area: QAbstractScrollArea) -> None:
    """Drag anywhere in ``area`` to scroll it, with momentum, by finger or by mouse."""
    if isinstance(area, QAbstractItemView):
        area.setVerticalScrollMode(QAbstractItemView.ScrollMode.ScrollPerPixel)
        area.setHorizontalScrollMode(QAbstractItemView.ScrollMode.ScrollPerPixel)
    QScroller.grabGesture(area.viewport(), QScroller.ScrollerGestureType.LeftMouseButtonGesture)
