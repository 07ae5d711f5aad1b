"""Alarms screen: the active alarms with acknowledge and reset, and the history with filters.

Why both on one screen: after a stop the operator wants to see what is wrong now and what
happened just before; the history (ISA-18.2: every transition is kept) comes from the
database, filtered by period, code and source, newest first.
"""

from __future__ import annotations

from datetime import UTC, datetime, timedelta

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QAbstractItemView,
    QButtonGroup,
    QFrame,
    QHBoxLayout,
    QHeaderView,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from app.data.records import AlarmEvent, AlarmEventFilter
from app.machine.alarms import CATALOGUE
from app.machine.commands import Acknowledge, Reset
from app.machine.snapshot import AlarmState, AlarmView, MachineSnapshot
from app.screens.alarm_detail import (
    AlarmDetailOverlay,
    AlarmFacts,
    facts_of_event,
    facts_of_view,
    history_filter,
)
from app.screens.base import Screen, ScreenContext, refusal
from app.screens.formatting import format_table_time
from app.screens.texts import (
    alarm_line,
    alarm_state_text,
    alarm_title,
    history_line,
    history_state_text,
)
from app.screens.theme import TOUCH_PX
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.dialogs import ChoiceOverlay
from app.screens.widgets.kinetic import kinetic_scroll
from app.screens.widgets.readouts import styled_label

HISTORY_LIMIT = 500
# period key -> length (None: everything)
PERIODS: tuple[tuple[str, timedelta | None], ...] = (
    ("hour", timedelta(hours=1)),
    ("day", timedelta(days=1)),
    ("week", timedelta(days=7)),
    ("all", None),
)
AXIS_SOURCES: tuple[str, ...] = ("X", "Y", "Z")


def _table(name: str, columns: int) -> QTableWidget:
    table = QTableWidget(0, columns)
    table.setObjectName(name)
    table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
    table.setSelectionMode(QAbstractItemView.SelectionMode.NoSelection)
    table.setFocusPolicy(Qt.FocusPolicy.NoFocus)
    table.setAlternatingRowColors(True)
    table.verticalHeader().setVisible(False)
    set_row_height(table, TOUCH_PX)  # a row is tapped to open the alarm
    table.setWordWrap(False)
    table.horizontalHeader().setHighlightSections(False)
    table.setVerticalScrollMode(QAbstractItemView.ScrollMode.ScrollPerPixel)
    kinetic_scroll(table)
    return table


def set_row_height(table: QTableWidget, height_px: int) -> None:
    """Rows a finger opens are at least ``height_px`` high, also after resizing to contents."""
    header = table.verticalHeader()
    header.setMinimumSectionSize(height_px)
    header.setDefaultSectionSize(height_px)
    table.resizeRowsToContents()


def _item(text: str) -> QTableWidgetItem:
    item = QTableWidgetItem(text)
    item.setToolTip(text)  # the whole text, where the column cuts it
    return item


class AlarmsScreen(Screen):
    key = "alarms"

    def __init__(self, context: ScreenContext, parent: QWidget | None = None) -> None:
        super().__init__(context, parent)
        self.period = "day"
        self.code_filter: str | None = None
        self.source_filter: str | None = None
        self._active_key: tuple[object, ...] = ()
        self.history_count = 0
        self.active_rows: tuple[AlarmView, ...] = ()
        self.history_rows: list[AlarmEvent] = []

        # -- active alarms -------------------------------------------------------------------
        active_panel = QFrame()
        active_panel.setObjectName("panel")
        self.active_title = styled_label("", "title")
        self.ack_all_button = touch_button("ackAllButton", "primary")
        self.ack_all_button.clicked.connect(lambda: self.context.send(Acknowledge(0)))
        self.reset_button = touch_button("alarmsResetButton", "primary")
        self.reset_button.clicked.connect(lambda: self.context.send(Reset()))
        header = QHBoxLayout()
        header.addWidget(self.active_title, 1)
        header.addWidget(self.ack_all_button)
        header.addWidget(self.reset_button)
        self.active_table = _table("activeAlarms", 6)
        self.active_table.cellClicked.connect(self.open_active)
        self.none_label = styled_label("", "caption", "noAlarmsLabel")
        active_layout = QVBoxLayout(active_panel)
        active_layout.setContentsMargins(10, 6, 10, 8)
        active_layout.addLayout(header)
        active_layout.addWidget(self.none_label)
        active_layout.addWidget(self.active_table, 1)

        # -- history -----------------------------------------------------------------------------
        history_panel = QFrame()
        history_panel.setObjectName("panel")
        self.history_title = styled_label("", "title")
        self.period_buttons: dict[str, QPushButton] = {}
        period_group = QButtonGroup(self)
        filters = QHBoxLayout()
        filters.addWidget(self.history_title, 1)
        for key, _length in PERIODS:
            button = touch_button(f"period_{key}")
            button.setCheckable(True)
            button.setChecked(key == self.period)
            button.clicked.connect(lambda _=False, k=key: self.set_period(k))
            period_group.addButton(button)
            filters.addWidget(button)
            self.period_buttons[key] = button
        self.code_button = touch_button("codeFilter")
        self.code_button.clicked.connect(self.choose_code)
        self.source_button = touch_button("sourceFilter")
        self.source_button.clicked.connect(self.choose_source)
        filters.addWidget(self.code_button)
        filters.addWidget(self.source_button)
        self.history_table = _table("alarmHistory", 6)
        self.history_table.cellClicked.connect(self.open_history)
        history_layout = QVBoxLayout(history_panel)
        history_layout.setContentsMargins(10, 6, 10, 8)
        history_layout.addLayout(filters)
        history_layout.addWidget(self.history_table, 1)

        layout = QVBoxLayout(self)
        layout.setContentsMargins(8, 8, 8, 8)
        layout.setSpacing(8)
        layout.addWidget(active_panel, 2)
        layout.addWidget(history_panel, 3)
        self.retranslate()

    def apply_scale(self, scale: float) -> None:
        for table in (self.active_table, self.history_table):
            set_row_height(table, round(TOUCH_PX * scale))

    # -- texts ----------------------------------------------------------------------------------

    def title(self) -> str:
        return self.tr("Alarms")

    def retranslate(self) -> None:
        self.active_title.setText(self.tr("Active alarms"))
        self.ack_all_button.setText(self.tr("Acknowledge all"))
        self.reset_button.setText(self.tr("Reset machine"))
        self.none_label.setText(self.tr("No active alarms."))
        self.history_title.setText(self.tr("History"))
        period_names = {
            "hour": self.tr("1 hour"),
            "day": self.tr("24 hours"),
            "week": self.tr("7 days"),
            "all": self.tr("All"),
        }
        for key, button in self.period_buttons.items():
            button.setText(period_names[key])
        self.code_button.setText(
            self.tr("Code: %1").replace("%1", self.code_filter or self.tr("all"))
        )
        self.source_button.setText(
            self.tr("Source: %1").replace("%1", self.source_filter or self.tr("all"))
        )
        self.active_table.setHorizontalHeaderLabels(
            [
                self.tr("Time"),
                self.tr("Code"),
                self.tr("Alarm"),
                self.tr("Source"),
                self.tr("State"),
                "",
            ]
        )
        self.history_table.setHorizontalHeaderLabels(
            [
                self.tr("Time"),
                self.tr("Code"),
                self.tr("Alarm"),
                self.tr("Source"),
                self.tr("New state"),
                self.tr("User"),
            ]
        )
        for table, stretch in ((self.active_table, 2), (self.history_table, 2)):
            header = table.horizontalHeader()
            for column in range(table.columnCount()):
                mode = (
                    QHeaderView.ResizeMode.Stretch
                    if column == stretch
                    else QHeaderView.ResizeMode.ResizeToContents
                )
                header.setSectionResizeMode(column, mode)
        self._active_key = ()
        if self.isVisible():
            self.refresh_history()

    # -- active alarms ----------------------------------------------------------------------

    def update_snapshot(self, snapshot: MachineSnapshot, force: bool = False) -> None:
        previous = self.snapshot
        self.snapshot = snapshot
        key = tuple((a.alarm_id, a.state) for a in snapshot.alarms)
        if key != self._active_key or force:
            changed = key != self._active_key
            self._active_key = key
            self._fill_active(snapshot.alarms)
            if changed and previous is not None and self.isVisible():
                self.refresh_history()
        self.ack_all_button.setEnabled(snapshot.unacknowledged_alarms > 0)
        reason = refusal(snapshot, "Reset")
        self.reset_button.setEnabled(not reason)
        self.reset_button.setToolTip(reason)

    def _fill_active(self, alarms: tuple[AlarmView, ...]) -> None:
        table = self.active_table
        self.active_rows = alarms
        table.setRowCount(len(alarms))
        self.none_label.setVisible(not alarms)
        for row, alarm in enumerate(alarms):
            moment = datetime.fromtimestamp(alarm.raised_at, tz=UTC)
            values = (
                format_table_time(moment),
                alarm.code,
                alarm_line(alarm),
                alarm.source,
                alarm_state_text(alarm.state),
            )
            for column, text in enumerate(values):
                table.setItem(row, column, _item(text))
            needs_ack = alarm.state in (AlarmState.ACTIVE_UNACKED, AlarmState.RTN_UNACKED)
            if needs_ack:
                button = touch_button(f"ack_{alarm.alarm_id}")
                button.setText(self.tr("Acknowledge"))
                button.clicked.connect(
                    lambda _=False, i=alarm.alarm_id: self.context.send(Acknowledge(i))
                )
                table.setCellWidget(row, 5, button)
            else:
                table.removeCellWidget(row, 5)
                table.setItem(row, 5, _item("✓"))
        table.resizeRowsToContents()

    def ack_button(self, alarm_id: int) -> QPushButton | None:
        """The Acknowledge button shown for one active alarm (None when it needs none).

        Looked up in the table's cells, not among its children: a button the table has just
        replaced stays a child until Qt deletes it later, and it must not count as shown.
        """
        table = self.active_table
        for row in range(table.rowCount()):
            widget = table.cellWidget(row, 5)
            if isinstance(widget, QPushButton) and widget.objectName() == f"ack_{alarm_id}":
                return widget
        return None

    # -- one alarm's details -----------------------------------------------------------------

    def open_active(self, row: int, _column: int = 0) -> AlarmDetailOverlay | None:
        """Tapping an active alarm's row: its whole text; Acknowledge there when it waits."""
        if not 0 <= row < len(self.active_rows):
            return None
        alarm = self.active_rows[row]
        needs_ack = alarm.state in (AlarmState.ACTIVE_UNACKED, AlarmState.RTN_UNACKED)
        overlay = self._open_detail(facts_of_view(alarm), needs_ack)
        overlay.finished.connect(
            lambda ok: self.context.send(Acknowledge(alarm.alarm_id)) if ok else None
        )
        return overlay

    def open_history(self, row: int, _column: int = 0) -> AlarmDetailOverlay | None:
        if not 0 <= row < len(self.history_rows):
            return None
        return self._open_detail(facts_of_event(self.history_rows[row]), False)

    def _open_detail(self, facts: AlarmFacts, acknowledge: bool) -> AlarmDetailOverlay:
        events = self.context.database.list_alarm_events(history_filter(facts))
        overlay = AlarmDetailOverlay(facts, events, acknowledge=acknowledge)
        self.context.open(overlay)
        return overlay

    # -- history -------------------------------------------------------------------------------

    def activated(self) -> None:
        self.refresh_history()

    def set_period(self, key: str) -> None:
        self.period = key
        self.period_buttons[key].setChecked(True)
        self.refresh_history()

    def choose_code(self) -> None:
        choices: list[tuple[str, str | None]] = [(self.tr("All codes"), None)]
        choices += [(f"{code}  {alarm_title(code)}", code) for code in sorted(CATALOGUE)]
        overlay = ChoiceOverlay(self.tr("Alarm code"), choices, current=self.code_filter)
        overlay.chosen.connect(self.set_code_filter)
        self.context.open(overlay)

    def choose_source(self) -> None:
        choices: list[tuple[str, str | None]] = [(self.tr("All sources"), None)]
        recent = self.context.database.list_alarm_events(AlarmEventFilter(limit=HISTORY_LIMIT))
        sources = sorted({*AXIS_SOURCES, *(event.source for event in recent)})
        choices += [(source, source) for source in sources]
        overlay = ChoiceOverlay(self.tr("Source"), choices, current=self.source_filter, columns=3)
        overlay.chosen.connect(self.set_source_filter)
        self.context.open(overlay)

    def set_code_filter(self, code: str | None) -> None:
        self.code_filter = code
        self.retranslate()
        self.refresh_history()

    def set_source_filter(self, source: str | None) -> None:
        self.source_filter = source
        self.retranslate()
        self.refresh_history()

    def current_filter(self) -> AlarmEventFilter:
        length = dict(PERIODS)[self.period]
        start = datetime.now(tz=UTC) - length if length is not None else None
        return AlarmEventFilter(
            start=start, code=self.code_filter, source=self.source_filter, limit=HISTORY_LIMIT
        )

    def refresh_history(self) -> None:
        events = self.context.database.list_alarm_events(self.current_filter())
        table = self.history_table
        self.history_rows = events
        table.setRowCount(len(events))
        for row, event in enumerate(events):
            values = (
                format_table_time(event.time),
                event.code,
                history_line(event),
                event.source,
                history_state_text(event.to_state.value),
                event.user_name or "",
            )
            for column, text in enumerate(values):
                table.setItem(row, column, _item(text))
        self.history_count = len(events)
