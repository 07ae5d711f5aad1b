"""The live plan view: the stave's outline, the tool path and the cutter, in machine X/Y.

Why a fixed set of items updated with ``setData``: creating and removing plot items at 30 Hz
leaks and is slow; four items are created once and only their data changes (the outline and
the path when a new plan arrives, the cutter every frame it moves). PySide6 is pinned below
6.12 because 6.12.0 on Python 3.11 crashes in exactly this call pattern (none_dealloc
after about 1,000 setData calls); a soak test keeps it
honest. Mouse panning and zooming are off: on a touch panel a stray swipe must not lose the
view.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pyqtgraph as pg
from PySide6.QtGui import QFont
from PySide6.QtWidgets import QWidget

from app.machine.snapshot import PlanPreview

Points = Sequence[tuple[float, float]]

OUTLINE_COLOR = "#f2f4f8"
CUT_COLOR = "#ffb000"
RAPID_COLOR = "#6c7685"
CUTTER_COLOR = "#ff3030"
MIN_CUTTER_MOVE_MM = 0.05
TICK_FONT_PX = 13


def split_toolpath(points: Points, mask: Sequence[bool]) -> tuple[np.ndarray, np.ndarray]:
    """Split a path into its cutting and its non-cutting parts, as (N, 2) arrays in which NaN
    rows separate the pieces (drawn with ``connect="finite"``).

    ``mask`` has one flag per segment (``len(points) - 1``) or one per point, where a point's
    flag says whether the segment that reaches it cuts."""
    xy = np.asarray(points, dtype=float).reshape(-1, 2)
    count = len(xy)
    if count < 2:
        empty = np.empty((0, 2))
        return empty, empty
    flags = np.asarray(mask, dtype=bool)
    if len(flags) == count:
        segment_cuts = flags[1:]
    elif len(flags) == count - 1:
        segment_cuts = flags
    else:
        segment_cuts = np.zeros(count - 1, dtype=bool)
    return _pieces(xy, segment_cuts), _pieces(xy, ~segment_cuts)


def _pieces(xy: np.ndarray, segment_on: np.ndarray) -> np.ndarray:
    rows: list[np.ndarray] = []
    nan_row = np.array([[np.nan, np.nan]])
    start: int | None = None
    for index, on in enumerate(segment_on):
        if on and start is None:
            start = index
        elif not on and start is not None:
            rows.extend((xy[start : index + 1], nan_row))
            start = None
    if start is not None:
        rows.append(xy[start:])
    elif rows:
        rows.pop()  # no separator after the last piece
    if not rows:
        return np.empty((0, 2))
    return np.vstack(rows)


class PlanView(pg.PlotWidget):  # type: ignore[misc]  # pyqtgraph ships no type information
    """Plan view of the table. ``set_plan`` draws a machine plan, ``set_paths`` a preview,
    ``set_cutter`` moves the cutter marker."""

    def __init__(self, parent: QWidget | None = None, *, show_cutter: bool = True) -> None:
        super().__init__(parent, background="#05070a")
        self.setObjectName("planView")
        plot = self.getPlotItem()
        plot.setMenuEnabled(False)
        plot.hideButtons()
        plot.setMouseEnabled(x=False, y=False)
        # No grid: with a grid the axes span the plot area and repaint (text and all) every
        # time the cutter moves; the axes alone are cheap and enough to read the plan.
        plot.showGrid(x=False, y=False)
        for name in ("left", "bottom"):
            axis = plot.getAxis(name)
            axis.setTextPen(pg.mkPen("#aab4c3"))
            axis.setPen(pg.mkPen("#4f5b6d"))
        self.set_scale(1.0)
        plot.getAxis("bottom").enableAutoSIPrefix(False)
        plot.getAxis("left").enableAutoSIPrefix(False)
        self.outline_item = pg.PlotDataItem(pen=pg.mkPen(OUTLINE_COLOR, width=2))
        self.rapid_item = pg.PlotDataItem(
            pen=pg.mkPen(RAPID_COLOR, width=1, style=pg.QtCore.Qt.PenStyle.DashLine),
            connect="finite",
        )
        self.cut_item = pg.PlotDataItem(pen=pg.mkPen(CUT_COLOR, width=3), connect="finite")
        self.cutter_item = pg.PlotDataItem(
            [],
            [],
            pen=None,
            symbol="o",
            symbolSize=18,
            symbolBrush=pg.mkBrush(CUTTER_COLOR),
            symbolPen=pg.mkPen("#ffffff", width=2),
        )
        for item in (self.outline_item, self.rapid_item, self.cut_item, self.cutter_item):
            plot.addItem(item)
        self.cutter_item.setVisible(show_cutter)
        self._cutter: tuple[float, float] | None = None
        self.plan_id = 0
        self.updates = 0  # how many times data was set (the soak test counts them)

    def set_scale(self, scale: float) -> None:
        """Axis fonts for the theme's scale (readable at arm's length on every panel)."""
        plot = self.getPlotItem()
        font = QFont("DejaVu Sans")
        font.setPixelSize(round(TICK_FONT_PX * scale))
        for name in ("left", "bottom"):
            plot.getAxis(name).setTickFont(font)
        style = {"color": "#aab4c3", "font-size": f"{round(TICK_FONT_PX * scale)}px"}
        plot.setLabel("bottom", "X", units="mm", **style)
        plot.setLabel("left", "Y", units="mm", **style)

    def set_plan(self, plan: PlanPreview | None) -> None:
        """Draw a machine plan (or clear the view for None)."""
        if plan is None:
            self.plan_id = 0
            self.set_paths((), (), ())
            return
        self.plan_id = plan.plan_id
        self.set_paths(plan.outline_xy, plan.toolpath_xy, plan.cutting_mask)

    def set_paths(self, outline: Points, toolpath: Points, mask: Sequence[bool]) -> None:
        """Draw an outline and a tool path (machine or preview coordinates)."""
        outline_xy = np.asarray(outline, dtype=float).reshape(-1, 2)
        cut, rapid = split_toolpath(toolpath, mask)
        self.outline_item.setData(outline_xy[:, 0], outline_xy[:, 1])
        self.cut_item.setData(cut[:, 0], cut[:, 1], connect="finite")
        self.rapid_item.setData(rapid[:, 0], rapid[:, 1], connect="finite")
        self.updates += 3
        # Frame the work: the stave and the cut (the travel from home may leave the view).
        everything = [a for a in (outline_xy, cut) if len(a)] or [a for a in (rapid,) if len(a)]
        if not everything:
            self.enableAutoRange()
            return
        stacked = np.vstack(everything)
        finite = stacked[np.isfinite(stacked).all(axis=1)]
        x_low, y_low = finite.min(axis=0)
        x_high, y_high = finite.max(axis=0)
        self.setRange(xRange=(x_low, x_high), yRange=(y_low, y_high), padding=0.08)

    def set_cutter(self, x_mm: float, y_mm: float) -> None:
        """Move the cutter marker (only when it moved enough to be seen)."""
        if self._cutter is not None:
            dx = abs(x_mm - self._cutter[0])
            dy = abs(y_mm - self._cutter[1])
            if dx < MIN_CUTTER_MOVE_MM and dy < MIN_CUTTER_MOVE_MM:
                return
        self._cutter = (x_mm, y_mm)
        self.cutter_item.setData([x_mm], [y_mm])
        self.updates += 1
