"""Production at a glance: a shift or the last days in four charts and five figures, and the
range written to a CSV file on a USB stick.

Why this screen reads the database and not the snapshot: the snapshot says what the machine
does now; a shift's production is in the records the machine wrote (the screens' second
channel). The figures are SQL aggregates (``app.data.production_stats``) computed on a worker
thread with a connection of its own, so a month of records never holds up the panel; the
charts are redrawn when the answer arrives, and once a minute while the screen is shown.
The export writes exactly the range shown, with the safe file writer and the CSV cell
escaping of every export (``app.data.exchange.export_production_csv``).
"""

from __future__ import annotations

from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import (
    QButtonGroup,
    QGridLayout,
    QHBoxLayout,
    QPushButton,
    QSizePolicy,
    QVBoxLayout,
    QWidget,
)

from app.data.database import Database
from app.data.exchange import export_production_csv
from app.data.production_stats import ProductionStats, StatsRange, production_stats, range_window
from app.data.records import PieceResult
from app.data.shifts import ShiftPlan
from app.screens.base import Screen, ScreenContext
from app.screens.database_jobs import DatabaseJobs
from app.screens.formatting import format_number, format_time_range
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.dialogs import MessageOverlay
from app.screens.widgets.file_chooser import FileChooser, default_exchange_dir
from app.screens.widgets.production_charts import (
    ALARMS_COLOR,
    BOUND_COLOR,
    CYCLE_COLOR,
    PIECES_COLOR,
    WIDTHS_COLOR,
    ProductionCharts,
)
from app.screens.widgets.readouts import set_text, styled_label

REFRESH_MS = 60_000
"""How often the shown range is read again while the screen is shown (new boards come in)."""
SHOWN_CODES = 5
"""Alarm codes named beside the alarm chart, the most frequent first."""
STATS_JOB = "stats"
EXPORT_JOB = "export"


def _stats_job(choice: StatsRange, now: datetime) -> Callable[[Database], ProductionStats]:
    """The worker's read: the range on the shift plan of the parameters now, then its figures."""

    def job(db: Database) -> ProductionStats:
        start, end = range_window(choice, now, ShiftPlan.from_parameters(db.get_parameters()))
        return production_stats(db, start, end)

    return job


class ProductionScreen(Screen):
    key = "production"

    def __init__(self, context: ScreenContext, parent: QWidget | None = None) -> None:
        super().__init__(context, parent)
        self.clock: Callable[[], datetime] = lambda: datetime.now(UTC)
        self.jobs = DatabaseJobs(context.database.path, parent=self)
        self.choice = StatsRange.THIS_SHIFT
        self.stats: ProductionStats | None = None
        self.loading = False

        self.range_group = QButtonGroup(self)
        self.range_group.setExclusive(True)
        self.range_buttons: dict[StatsRange, QPushButton] = {}
        header = QHBoxLayout()
        header.setSpacing(8)
        for choice in StatsRange:
            button = touch_button(f"range_{choice.value}", "range")
            button.setCheckable(True)
            button.clicked.connect(lambda _=False, c=choice: self.show_range(c))
            self.range_group.addButton(button)
            self.range_buttons[choice] = button
            header.addWidget(button)
        self.range_buttons[self.choice].setChecked(True)
        header.addSpacing(12)
        self.export_button = touch_button("exportProduction", "range")
        self.export_button.clicked.connect(lambda _=False: self.export())
        header.addWidget(self.export_button)

        self.range_label = styled_label("", "field", "productionRange")
        self.status_label = styled_label("", "caption", "productionStatus")
        self.count_labels = {
            result: styled_label("", "value", f"count_{result.value}") for result in PieceResult
        }
        self.rate_label = styled_label("", "value", "piecesPerHour")
        self.alarm_count_label = styled_label("", "value", "alarmCount")
        # The status may be long (an error): it takes what is left, never the window's width.
        self.status_label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        figures = QHBoxLayout()
        figures.setSpacing(16)
        figures.addWidget(self.range_label)
        for label in (*self.count_labels.values(), self.rate_label, self.alarm_count_label):
            figures.addWidget(label)
        figures.addWidget(self.status_label, 1)

        self.charts = ProductionCharts(self)
        self.chart_titles = {
            name: styled_label("", "field", f"chartTitle_{name}") for name in self.charts.widgets()
        }
        self.codes_label = styled_label("", "field", "alarmCodes")
        grid = QGridLayout()
        grid.setHorizontalSpacing(10)
        grid.setVerticalSpacing(4)
        for index, (name, widget) in enumerate(self.charts.widgets().items()):
            row, column = divmod(index, 2)
            cell = QVBoxLayout()
            cell.setSpacing(2)
            title_row = QHBoxLayout()
            title_row.addWidget(self.chart_titles[name], 1)
            if name == "alarms":
                title_row.addWidget(self.codes_label)
            cell.addLayout(title_row)
            cell.addWidget(widget, 1)
            grid.addLayout(cell, row, column)
        grid.setRowStretch(0, 1)
        grid.setRowStretch(1, 1)

        layout = QVBoxLayout(self)
        layout.setContentsMargins(8, 8, 8, 8)
        layout.setSpacing(6)
        layout.addLayout(header)
        layout.addLayout(figures)
        layout.addLayout(grid, 1)

        self.refresh_timer = QTimer(self)
        self.refresh_timer.setInterval(REFRESH_MS)
        self.refresh_timer.timeout.connect(self.reload)
        self.retranslate()
        self._show_figures()

    # -- texts -------------------------------------------------------------------------------

    def title(self) -> str:
        return self.tr("Production")

    def retranslate(self) -> None:
        names = {
            StatsRange.THIS_SHIFT: self.tr("This shift"),
            StatsRange.LAST_SHIFT: self.tr("Last shift"),
            StatsRange.TODAY: self.tr("Today"),
            StatsRange.LAST_7_DAYS: self.tr("7 days"),
            StatsRange.LAST_30_DAYS: self.tr("30 days"),
        }
        for choice, button in self.range_buttons.items():
            button.setText(names[choice])
        self.export_button.setText(self.tr("Export CSV…"))
        self.chart_titles["pieces"].setText(
            self._coloured(self.tr("Staves per hour"), PIECES_COLOR)
        )
        self.chart_titles["cycles"].setText(
            self.tr("Cycle time per stave, s:")
            + " "
            + self._coloured("● " + self.tr("cycle"), CYCLE_COLOR)
            + " "
            + self._coloured("— " + self.tr("bound"), BOUND_COLOR)
        )
        self.chart_titles["widths"].setText(
            self._coloured(self.tr("Board widths, mm"), WIDTHS_COLOR)
        )
        self.chart_titles["alarms"].setText(
            self._coloured(self.tr("Alarms per hour"), ALARMS_COLOR)
        )
        self._show_figures()

    @staticmethod
    def _coloured(text: str, color: str) -> str:
        escaped = text.replace("&", "&amp;").replace("<", "&lt;")
        return f'<span style="color:{color}">{escaped}</span>'

    def _show_figures(self) -> None:
        stats = self.stats
        names = {
            PieceResult.OK: self.tr("Good"),
            PieceResult.ABORTED: self.tr("Aborted"),
            PieceResult.REJECTED: self.tr("Rejected"),
        }
        for result, label in self.count_labels.items():
            count = "—" if stats is None else str(stats.counts[result.value])
            set_text(label, f"{names[result]} {count}")
        rate = "—" if stats is None else self._rate_text(stats)
        set_text(self.rate_label, self.tr("%1 per hour").replace("%1", rate))
        alarms = "—" if stats is None else str(sum(n for _code, n in stats.alarm_codes))
        set_text(self.alarm_count_label, self.tr("Alarms %1").replace("%1", alarms))
        set_text(
            self.range_label, "" if stats is None else format_time_range(stats.start, stats.end)
        )
        if stats is None or not stats.alarm_codes:
            codes = ""
        else:
            shown = [f"{code} ×{n}" for code, n in stats.alarm_codes[:SHOWN_CODES]]
            rest = len(stats.alarm_codes) - SHOWN_CODES
            codes = "  ".join(shown) + (f"  +{rest}" if rest > 0 else "")
        set_text(self.codes_label, codes)
        if self.loading:
            status = self.tr("Reading…")
        elif stats is not None and not any(stats.counts.values()) and not stats.alarm_codes:
            status = self.tr("Nothing produced in this range.")
        else:
            status = ""
        set_text(self.status_label, status)
        self.export_button.setEnabled(stats is not None)
        # The figures arrive from the worker between two layout passes: lay them out now, so
        # no label is drawn clipped at its empty size until the next pass.
        layout = self.layout()
        if layout is not None:
            layout.activate()

    def _rate_text(self, stats: ProductionStats) -> str:
        """Finished staves per hour over the part of the range that has passed."""
        now = self.clock()
        hours = (min(stats.end, now) - stats.start).total_seconds() / 3600.0
        if hours <= 0:
            return "—"
        return format_number(stats.counts[PieceResult.OK.value] / hours, 0)

    # -- reading -----------------------------------------------------------------------------

    def show_range(self, choice: StatsRange) -> None:
        """Show ``choice`` (read on the worker; the charts follow when it answers)."""
        self.choice = choice
        button = self.range_buttons[choice]
        if not button.isChecked():
            button.setChecked(True)
        self.reload()

    def reload(self) -> None:
        self.loading = True
        self._show_figures()
        self.jobs.run(STATS_JOB, _stats_job(self.choice, self.clock()), self._stats_read)

    def _stats_read(self, stats: object, error: str) -> None:
        self.loading = False
        if isinstance(stats, ProductionStats):
            self.stats = stats
            self.charts.show_stats(stats)
            self._show_figures()
        else:
            self._show_figures()
            set_text(self.status_label, self.tr("Not read: %1").replace("%1", error))

    def activated(self) -> None:
        self.reload()
        self.refresh_timer.start()

    def deactivated(self) -> None:
        self.refresh_timer.stop()

    # -- export ------------------------------------------------------------------------------

    def export(self, directory: Path | None = None) -> FileChooser | None:
        """Write the range shown to a CSV file chosen on the touch file chooser."""
        stats = self.stats
        if stats is None:
            return None
        name = f"production-{stats.start.astimezone().strftime('%Y%m%d-%H%M')}.csv"
        chooser = FileChooser(
            self.tr("Export production"),
            directory or default_exchange_dir(),
            save_name=name,
            keyboard_layout=self.context.keyboard_layout(),
            suffixes=(".csv",),
        )
        chooser.fileChosen.connect(lambda path: self.export_file(Path(path)))
        self.context.open(chooser)
        return chooser

    def export_file(self, path: Path) -> None:
        """Write the shown range to ``path`` on the worker; say so when it is written."""
        stats = self.stats
        if stats is None:
            return
        start, end = stats.start, stats.end

        def done(count: object, error: str) -> None:
            if error:
                self.context.open(MessageOverlay(self.tr("Export failed"), error))
                return
            self.context.notify(
                self.tr("%1 production records written to %2.")
                .replace("%1", str(count))
                .replace("%2", str(path))
            )

        self.jobs.run(EXPORT_JOB, lambda db: export_production_csv(db, path, start, end), done)

    # -- size --------------------------------------------------------------------------------

    def apply_scale(self, scale: float) -> None:
        self.charts.set_scale(scale)
