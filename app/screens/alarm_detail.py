"""The whole story of one alarm, opened by tapping its row: what it means, what was found,
why it usually happens, what to do, and who did what when.

Why a separate view: a table row has room for a title and a few words; at three in the
morning the operator needs the remedy, and the technician the measured value, the axis and
the device's own words, without a manual. The times and users come from the ISA-18.2
history in the database (every transition is stored with the user who made it).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from datetime import UTC, datetime

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QHBoxLayout,
    QLabel,
    QScrollArea,
    QVBoxLayout,
    QWidget,
)

from app.data.records import AlarmEvent, AlarmEventFilter, AlarmState
from app.machine.snapshot import AlarmView
from app.screens.formatting import format_table_time
from app.screens.texts import (
    alarm_help,
    alarm_title,
    history_found,
    history_state_text,
    machine_text,
    severity_text,
)
from app.screens.theme import scale_for_size
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.kinetic import kinetic_scroll
from app.screens.widgets.overlay import Overlay

EPISODE_LIMIT = 200
DETAIL_SIZE_PX = (760, 560)  # fixed: the panel never grows with a long text (it scrolls)


@dataclass(frozen=True)
class AlarmFacts:
    """What the view shows of one alarm, from the live alarm or from a history row."""

    code: str
    source: str
    found: str  # what was found, in the user's language
    technical: str  # a device's own words (English), "" when none
    severity: str
    at: datetime


def facts_of_view(alarm: AlarmView) -> AlarmFacts:
    return AlarmFacts(
        alarm.code,
        alarm.source,
        machine_text(alarm.detail),
        alarm.technical,
        alarm.severity,
        datetime.fromtimestamp(alarm.raised_at, tz=UTC),
    )


def facts_of_event(event: AlarmEvent) -> AlarmFacts:
    """A history row, in the user's language as far as it was stored coded."""
    return AlarmFacts(event.code, event.source, history_found(event), "", "", event.time)


def episode(events: Sequence[AlarmEvent], at: datetime) -> list[AlarmEvent]:
    """The transitions of the one occurrence that was active at ``at``: from its last
    activation out of NORMAL at or before ``at`` up to its return to NORMAL, oldest first.
    ``events`` are one alarm's (code and source), in any order."""
    ordered = sorted(events, key=lambda e: (e.time, e.id or 0))
    start = 0
    for index, event in enumerate(ordered):
        if event.time > at:
            break
        if event.from_state is AlarmState.NORMAL:
            start = index
    chosen: list[AlarmEvent] = []
    for event in ordered[start:]:
        if chosen and event.from_state is AlarmState.NORMAL:
            break
        chosen.append(event)
        if event.to_state is AlarmState.NORMAL:
            break
    return chosen


def _paragraph(text: str, name: str, role: str = "") -> QLabel:
    label = QLabel(text)
    label.setObjectName(name)
    label.setWordWrap(True)
    label.setTextInteractionFlags(Qt.TextInteractionFlag.NoTextInteraction)
    if role:
        label.setProperty("role", role)
    return label


class AlarmDetailOverlay(Overlay):
    """One alarm's whole text, causes, remedy, details and history; Acknowledge when the
    alarm waits for one (``acknowledge`` is then the action), Close always."""

    def __init__(
        self,
        facts: AlarmFacts,
        events: Sequence[AlarmEvent],
        *,
        acknowledge: bool = False,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("alarmDetailOverlay")
        self.title_label = _paragraph(
            f"{facts.code}  {alarm_title(facts.code)}", "alarmDetailTitle", "title"
        )
        content = QWidget()
        body = QVBoxLayout(content)
        body.setContentsMargins(0, 0, 8, 0)
        body.setSpacing(8)
        help_ = alarm_help(facts.code)
        if help_ is not None:
            body.addWidget(_paragraph(help_.description, "alarmDescription"))
        body.addWidget(_paragraph(self.tr("What was found"), "foundCaption", "caption"))
        found = [facts.found] if facts.found else []
        if facts.source:
            found.append(self.tr("Source: %1").replace("%1", facts.source))
        if facts.severity:
            found.append(self.tr("Kind: %1").replace("%1", severity_text(facts.severity)))
        if facts.technical:
            found.append(self.tr("Device reports: %1").replace("%1", facts.technical))
        self.found_label = _paragraph("\n".join(found) or "—", "alarmFound")
        body.addWidget(self.found_label)
        if help_ is not None:
            body.addWidget(_paragraph(self.tr("Probable causes"), "causesCaption", "caption"))
            self.causes_label = _paragraph(
                "\n".join(f"•  {cause}" for cause in help_.causes), "alarmCauses"
            )
            body.addWidget(self.causes_label)
            body.addWidget(_paragraph(self.tr("What to do"), "remedyCaption", "caption"))
            self.remedy_label = _paragraph(help_.remedy, "alarmRemedy")
            body.addWidget(self.remedy_label)
        body.addWidget(_paragraph(self.tr("History"), "historyCaption", "caption"))
        lines = [
            "  ".join(
                part
                for part in (
                    format_table_time(event.time),
                    history_state_text(event.to_state.value),
                    event.user_name or "",
                )
                if part
            )
            for event in episode(events, facts.at)
        ]
        self.history_label = _paragraph("\n".join(lines) or "—", "alarmEpisode")
        body.addWidget(self.history_label)
        body.addStretch(1)
        scroll = QScrollArea()
        scroll.setObjectName("alarmDetailScroll")
        scroll.setWidget(content)
        scroll.setWidgetResizable(True)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        scroll.setFrameShape(QScrollArea.Shape.NoFrame)
        kinetic_scroll(scroll)
        self.ack_button = touch_button("detailAckButton", "primary", self.tr("Acknowledge"))
        self.ack_button.setVisible(acknowledge)
        self.ack_button.clicked.connect(self.accept)
        self.close_button = touch_button("detailCloseButton", text=self.tr("Close"))
        self.close_button.clicked.connect(self.reject)
        self.panel_layout.addWidget(self.title_label)
        self.panel_layout.addWidget(scroll, 1)
        buttons = QHBoxLayout()
        buttons.setSpacing(16)
        buttons.addWidget(self.close_button)
        buttons.addWidget(self.ack_button)
        self.panel_layout.addLayout(buttons)

    def open_on(self, host: QWidget) -> None:
        """A fixed size in the panel's scale (the fonts grow on a larger screen, so does
        the view), never larger than the window."""
        window = host.window()
        scale = scale_for_size(window.width(), window.height())
        width, height = (round(px * scale) for px in DETAIL_SIZE_PX)
        self.panel.setFixedSize(min(width, host.width()), min(height, host.height()))
        super().open_on(host)


def history_filter(facts: AlarmFacts) -> AlarmEventFilter:
    """The stored transitions of this alarm (its code at its source)."""
    return AlarmEventFilter(code=facts.code, source=facts.source, limit=EPISODE_LIMIT)
