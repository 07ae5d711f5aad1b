"""The barrel being raised, drawn as the belly's cross-section seen from the head.

The belly outline, each stave placed so far as its face (a chord between two joints, numbered,
alternating shades so neighbours stand apart), the stave being cut highlighted, and the gap
from the last joint back to the first as a dashed red line. Every point comes from the
machine (``app.machine.barrel_view``): this only scales them into the widget, with y up, so
the staves run counter-clockwise as the cooper sees them from the head.
"""

from __future__ import annotations

from PySide6.QtCore import QPointF, QRectF, Qt, Signal
from PySide6.QtGui import QColor, QFont, QMouseEvent, QPainter, QPaintEvent, QPen
from PySide6.QtWidgets import QSizePolicy, QWidget

from app.machine.barrel_view import BarrelView, Point

OUTLINE_COLOR = QColor("#6c7685")
STAVE_COLORS = (QColor("#c8a165"), QColor("#a87f45"))
CURRENT_COLOR = QColor("#ffb000")
GAP_COLOR = QColor("#ff3030")
TEXT_COLOR = QColor("#f2f4f8")
MARGIN_PX = 14.0
LABEL_FONT_PX = 11


class BarrelDrawing(QWidget):
    """``tapped`` when a finger lifts on it: the main screen's small drawing opens the big one."""

    tapped = Signal()

    def __init__(
        self, parent: QWidget | None = None, *, label_font_px: int = LABEL_FONT_PX
    ) -> None:
        super().__init__(parent)
        self.setObjectName("barrelDrawing")
        self.view: BarrelView | None = None
        self.label_font_px = label_font_px
        self.setMinimumSize(80, 40)  # on 1024x768 its height, not its width, limits it
        self.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)

    def set_view(self, view: BarrelView | None) -> None:
        if view != self.view:
            self.view = view
            self.update()

    def _scale(self, view: BarrelView) -> tuple[float, QPointF]:
        width = max(1.0, self.width() - 2 * MARGIN_PX)
        height = max(1.0, self.height() - 2 * MARGIN_PX)
        scale = min(width / (2 * view.a_mm), height / (2 * view.b_mm))
        return scale, QPointF(self.width() / 2.0, self.height() / 2.0)

    def paintEvent(self, event: QPaintEvent) -> None:
        view = self.view
        if view is None:
            return
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        scale, centre = self._scale(view)

        def at(point: Point) -> QPointF:
            return QPointF(centre.x() + point[0] * scale, centre.y() - point[1] * scale)

        painter.setPen(QPen(OUTLINE_COLOR, 1.0, Qt.PenStyle.DotLine))
        painter.drawEllipse(centre, view.a_mm * scale, view.b_mm * scale)
        font = QFont(painter.font())
        font.setPixelSize(self.label_font_px)
        painter.setFont(font)
        joints = view.joints_xy
        for index in range(1, len(joints)):
            start, end = at(joints[index - 1]), at(joints[index])
            painter.setPen(
                QPen(STAVE_COLORS[index % 2], 5.0, Qt.PenStyle.SolidLine, Qt.PenCapStyle.FlatCap)
            )
            painter.drawLine(start, end)
            self._number(painter, start, end, centre, str(index))
        if view.current_xy is not None:
            start, end = at(view.current_xy[0]), at(view.current_xy[1])
            painter.setPen(QPen(CURRENT_COLOR, 7.0, Qt.PenStyle.SolidLine, Qt.PenCapStyle.FlatCap))
            painter.drawLine(start, end)
            self._number(painter, start, end, centre, str(view.current_number))
        if len(joints) > 1 and not view.closed:
            painter.setPen(QPen(GAP_COLOR, 2.0, Qt.PenStyle.DashLine))
            painter.drawLine(at(joints[-1]), at(joints[0]))
        painter.end()

    def mouseReleaseEvent(self, event: QMouseEvent) -> None:
        if self.rect().contains(event.position().toPoint()):
            self.tapped.emit()
        super().mouseReleaseEvent(event)

    def _number(
        self, painter: QPainter, start: QPointF, end: QPointF, centre: QPointF, text: str
    ) -> None:
        """The stave's number just inside its face (towards the barrel's axis)."""
        size = float(self.label_font_px)
        middle = (start + end) / 2.0
        inward = centre - middle
        length = max(1.0, (inward.x() ** 2 + inward.y() ** 2) ** 0.5)
        spot = middle + inward * (1.3 * size / length)
        painter.setPen(TEXT_COLOR)
        box = QRectF(spot.x() - 1.1 * size, spot.y() - 0.75 * size, 2.2 * size, 1.5 * size)
        painter.drawText(box, Qt.AlignmentFlag.AlignCenter, text)
