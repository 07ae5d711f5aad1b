"""The last cycle's seconds as one bar: a segment per step, as long as the step took.

Why a bar and not a table: the operator (and the technician tuning the machine) should see
at a glance where the time of a board goes (mostly cutting, or standing still waiting for
something). The machine reports the seconds (``MachineSnapshot.last_step_times_s``); this
widget only draws them.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QRectF, QSize, Qt
from PySide6.QtGui import QColor, QPainter, QPaintEvent, QPen
from PySide6.QtWidgets import QSizePolicy, QWidget

from app.machine.states import TimedStep
from app.screens import theme
from app.screens.texts import QT_TRANSLATE_NOOP

CONTEXT = "StepTimes"

_NAMES: dict[str, str] = {
    TimedStep.WAITING.value: QT_TRANSLATE_NOOP("StepTimes", "Waiting"),
    TimedStep.CENTERING.value: QT_TRANSLATE_NOOP("StepTimes", "Centering"),
    TimedStep.CLAMPING.value: QT_TRANSLATE_NOOP("StepTimes", "Clamping"),
    TimedStep.MEASURING.value: QT_TRANSLATE_NOOP("StepTimes", "Measuring"),
    TimedStep.SPINDLE.value: QT_TRANSLATE_NOOP("StepTimes", "Spindle"),
    TimedStep.RETRACTING.value: QT_TRANSLATE_NOOP("StepTimes", "Moving clear"),
    TimedStep.APPROACH.value: QT_TRANSLATE_NOOP("StepTimes", "Approach"),
    TimedStep.SIDE_A.value: QT_TRANSLATE_NOOP("StepTimes", "Side A"),
    TimedStep.REPOSITIONING.value: QT_TRANSLATE_NOOP("StepTimes", "Repositioning"),
    TimedStep.SIDE_B.value: QT_TRANSLATE_NOOP("StepTimes", "Side B"),
    TimedStep.RETURN.value: QT_TRANSLATE_NOOP("StepTimes", "Return"),
    TimedStep.UNCLAMPING.value: QT_TRANSLATE_NOOP("StepTimes", "Unclamping"),
}

# Cutting in green (the work), motion in blue, the devices in grey, waits in amber.
_COLOURS: dict[str, str] = {
    TimedStep.WAITING.value: theme.YELLOW,
    TimedStep.CENTERING.value: theme.GREY,
    TimedStep.CLAMPING.value: "#59626f",
    TimedStep.MEASURING.value: theme.GREY,
    TimedStep.SPINDLE.value: theme.ACCENT,
    TimedStep.RETRACTING.value: theme.BLUE,
    TimedStep.APPROACH.value: theme.BLUE,
    TimedStep.SIDE_A.value: theme.GREEN,
    TimedStep.REPOSITIONING.value: "#3f7fd8",
    TimedStep.SIDE_B.value: "#2fa653",
    TimedStep.RETURN.value: theme.BLUE,
    TimedStep.UNCLAMPING.value: "#59626f",
}

BAR_HEIGHT_PX = 26


def step_name(step: str) -> str:
    """The step's name in the current language (the key itself if unknown)."""
    text = _NAMES.get(step)
    return step if text is None else QCoreApplication.translate(CONTEXT, text)


class StepTimesBar(QWidget):
    """A horizontal bar split by the last cycle's step times."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._steps: tuple[tuple[str, float], ...] = ()
        self._height_px = BAR_HEIGHT_PX
        self.setObjectName("stepTimesBar")
        self.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Fixed)
        self.setFixedHeight(self._height_px)

    def sizeHint(self) -> QSize:
        return QSize(400, self._height_px)

    def set_scale(self, scale: float) -> None:
        self._height_px = round(BAR_HEIGHT_PX * scale)
        self.setFixedHeight(self._height_px)

    @property
    def steps(self) -> tuple[tuple[str, float], ...]:
        return self._steps

    def set_step_times(self, steps: tuple[tuple[str, float], ...]) -> None:
        shown = tuple((name, seconds) for name, seconds in steps if seconds > 0.0)
        if shown == self._steps:
            return
        self._steps = shown
        self.setToolTip("\n".join(f"{step_name(n)}: {s:.1f} s" for n, s in shown))
        self.update()

    def paintEvent(self, event: QPaintEvent) -> None:
        del event
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing, False)
        area = QRectF(self.rect()).adjusted(0.5, 0.5, -0.5, -0.5)
        painter.fillRect(area, QColor(theme.BACKGROUND))
        total_s = sum(seconds for _name, seconds in self._steps)
        if total_s <= 0.0:
            painter.setPen(QColor(theme.DIM_TEXT))
            painter.drawText(area, Qt.AlignmentFlag.AlignCenter, "—")
            painter.end()
            return
        font = painter.font()
        font.setPixelSize(max(round(area.height() * 0.5), 9))
        painter.setFont(font)
        metrics = painter.fontMetrics()
        x = area.left()
        for name, seconds in self._steps:
            width = area.width() * seconds / total_s
            segment = QRectF(x, area.top(), width, area.height())
            painter.fillRect(segment, QColor(_COLOURS.get(name, theme.GREY)))
            label = f"{step_name(name)} {seconds:.1f} s"
            if metrics.horizontalAdvance(label) + 6 > width:
                label = f"{seconds:.1f}"
            if metrics.horizontalAdvance(label) + 4 <= width:
                painter.setPen(QColor(theme.BACKGROUND))
                painter.drawText(segment, Qt.AlignmentFlag.AlignCenter, label)
            x += width
        painter.setPen(QPen(QColor(theme.DIM_TEXT), 1))
        painter.drawRect(area)
        painter.end()
