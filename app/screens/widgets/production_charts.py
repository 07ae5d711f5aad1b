"""The Production screen's four charts: staves per hour, cycle time per stave against its
bound, board widths, alarms per hour.

Why a fixed set of items updated with ``setData``: as with the plan view (see
``plan_view.py``), items are created once and only their data changes, which is what keeps
pyqtgraph alive over hours of updates. Bars are step curves filled to zero (one item per
chart, however many bars), hours without production are drawn as zero bars so that a gap in
production is a gap in the chart. Mouse panning and zooming are off: on a touch panel a stray
swipe must not lose the view.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from datetime import datetime, timedelta

import numpy as np
import pyqtgraph as pg
from PySide6.QtGui import QFont
from PySide6.QtWidgets import QWidget

from app.data.production_stats import HourCount, ProductionStats
from app.screens import theme

TICK_FONT_PX = 15
"""Axis figures: at least 14 px at arm's length, like every text of the panel."""
HOUR_S = 3600.0
SMALL_COUNT = 6
"""Up to this many a bar's axis is labelled 1, 2, 3 (no halves of an alarm)."""
CYCLE_SYMBOL_PX = 7
CYCLE_COLOR = theme.GREEN
BOUND_COLOR = theme.ACCENT
PIECES_COLOR = theme.GREEN
ALARMS_COLOR = theme.RED
WIDTHS_COLOR = theme.BLUE


def hour_bars(
    counts: Sequence[HourCount], start: datetime, end: datetime
) -> tuple[np.ndarray, np.ndarray]:
    """Bar edges (epoch seconds, one more than bars) and heights for every hour from the
    one ``start`` falls in to the one before ``end``, zero where nothing was counted."""
    first_s = math.floor(start.timestamp() / HOUR_S) * HOUR_S
    hours = max(math.ceil((end.timestamp() - first_s) / HOUR_S), 1)
    edges = first_s + HOUR_S * np.arange(hours + 1, dtype=float)
    heights = np.zeros(hours)
    for item in counts:
        index = round((item.hour.timestamp() - first_s) / HOUR_S)
        if 0 <= index < hours:
            heights[index] = item.count
    return edges, heights


def width_bars(stats: ProductionStats) -> tuple[np.ndarray, np.ndarray]:
    """Bar edges (mm) and heights from the lowest to the highest bin, zero between."""
    if not stats.widths:
        return np.zeros(0), np.zeros(0)
    size = stats.width_bin_mm
    first = stats.widths[0].low_mm
    count = round((stats.widths[-1].low_mm - first) / size) + 1
    edges = first + size * np.arange(count + 1, dtype=float)
    heights = np.zeros(count)
    for item in stats.widths:
        heights[round((item.low_mm - first) / size)] = item.count
    return edges, heights


TICK_STEPS_H = (1, 2, 3, 4, 6, 12, 24, 48, 72, 120, 168)
MAX_TIME_TICKS = 9


def time_ticks(start: datetime, end: datetime) -> list[tuple[float, str]]:
    """Labelled ticks from ``start`` on at a round step of hours (local clock times under a
    day, local dates above), at most ``MAX_TIME_TICKS``: the ranges start on a shift or a
    day, so every label is a round time."""
    span_h = (end - start).total_seconds() / HOUR_S
    step_h = next((h for h in TICK_STEPS_H if span_h / h <= MAX_TIME_TICKS), TICK_STEPS_H[-1])
    form = "%H:%M" if step_h < 24 else "%d.%m."
    ticks: list[tuple[float, str]] = []
    moment = start
    while moment <= end:
        ticks.append((moment.timestamp(), moment.astimezone().strftime(form)))
        moment += timedelta(hours=step_h)
    return ticks


def _plot() -> pg.PlotWidget:
    widget = pg.PlotWidget(background="#05070a")
    plot = widget.getPlotItem()
    plot.setMenuEnabled(False)
    plot.hideButtons()
    plot.setMouseEnabled(x=False, y=False)
    plot.showGrid(x=False, y=True, alpha=0.25)
    for name in ("left", "bottom"):
        axis = plot.getAxis(name)
        axis.setTextPen(pg.mkPen(theme.DIM_TEXT))
        axis.setPen(pg.mkPen("#4f5b6d"))
        axis.enableAutoSIPrefix(False)
    return widget


def _bars(color: str) -> pg.PlotDataItem:
    return pg.PlotDataItem(
        stepMode="center",
        fillLevel=0,
        brush=pg.mkBrush(color),
        pen=pg.mkPen(color, width=1),
    )


class ProductionCharts:
    """The four plot widgets (placed by the screen) and their items."""

    def __init__(self, parent: QWidget | None = None) -> None:
        self.pieces = _plot()
        self.cycles = _plot()
        self.widths = _plot()
        self.alarms = _plot()
        for name, widget in self.widgets().items():
            widget.setObjectName(f"chart_{name}")
            if parent is not None:
                widget.setParent(parent)
        self.pieces_item = _bars(PIECES_COLOR)
        self.widths_item = _bars(WIDTHS_COLOR)
        self.alarms_item = _bars(ALARMS_COLOR)
        self.bound_item = pg.PlotDataItem(pen=pg.mkPen(BOUND_COLOR, width=2), connect="finite")
        self.cycle_item = pg.PlotDataItem(
            pen=None,
            symbol="o",
            symbolSize=CYCLE_SYMBOL_PX,
            symbolBrush=pg.mkBrush(CYCLE_COLOR),
            symbolPen=None,
        )
        self.pieces.addItem(self.pieces_item)
        self.widths.addItem(self.widths_item)
        self.alarms.addItem(self.alarms_item)
        self.cycles.addItem(self.bound_item)
        self.cycles.addItem(self.cycle_item)
        self.updates = 0  # how many times data was set (a test counts them)
        self.set_scale(1.0)

    def widgets(self) -> dict[str, pg.PlotWidget]:
        return {
            "pieces": self.pieces,
            "cycles": self.cycles,
            "widths": self.widths,
            "alarms": self.alarms,
        }

    def set_scale(self, scale: float) -> None:
        font = QFont("DejaVu Sans")
        font.setPixelSize(round(TICK_FONT_PX * scale))
        for widget in self.widgets().values():
            plot = widget.getPlotItem()
            for name in ("left", "bottom"):
                plot.getAxis(name).setTickFont(font)
                plot.getAxis(name).setStyle(tickTextOffset=round(4 * scale))
            plot.getAxis("left").setWidth(round(44 * scale))

    def show_stats(self, stats: ProductionStats) -> None:
        """Draw ``stats``: the time charts span the whole range."""
        start_s, end_s = stats.start.timestamp(), stats.end.timestamp()
        edges, heights = hour_bars(stats.pieces_per_hour, stats.start, stats.end)
        self.pieces_item.setData(edges, heights, stepMode="center", fillLevel=0)
        edges, heights = hour_bars(stats.alarms_per_hour, stats.start, stats.end)
        self.alarms_item.setData(edges, heights, stepMode="center", fillLevel=0)
        edges, heights = width_bars(stats)
        self.widths_item.setData(edges, heights, stepMode="center", fillLevel=0)
        times = np.array([p.time.timestamp() for p in stats.cycles], dtype=float)
        cycle_s = np.array([p.cycle_s for p in stats.cycles], dtype=float)
        bound_s = np.array(
            [math.nan if p.bound_s is None else p.bound_s for p in stats.cycles], dtype=float
        )
        self.cycle_item.setData(times, cycle_s)
        self.bound_item.setData(times, bound_s, connect="finite")
        self.updates += 5
        ticks = time_ticks(stats.start, stats.end)
        for widget in (self.pieces, self.cycles, self.alarms):
            widget.setXRange(start_s, end_s, padding=0.01)
            widget.getPlotItem().getAxis("bottom").setTicks([ticks, []])
        self._y_from_zero(self.pieces, self.pieces_item)
        self._y_from_zero(self.alarms, self.alarms_item)
        self._y_from_zero(self.widths, self.widths_item)
        finite = cycle_s[np.isfinite(cycle_s)]
        top = float(finite.max()) if len(finite) else 1.0
        self.cycles.setYRange(0.0, top * 1.08 or 1.0, padding=0)
        if len(edges):
            self.widths.setXRange(float(edges[0]), float(edges[-1]), padding=0.02)

    @staticmethod
    def _y_from_zero(widget: pg.PlotWidget, item: pg.PlotDataItem) -> None:
        """Counts from zero; whole numbers only while the counts are small."""
        _x, y = item.getData()
        top = float(np.max(y)) if y is not None and len(y) else 0.0
        widget.setYRange(0.0, max(top * 1.1, 1.0), padding=0)
        axis = widget.getPlotItem().getAxis("left")
        if top <= SMALL_COUNT:
            axis.setTickSpacing(1.0, 1.0)
        else:
            axis.setTickSpacing()
