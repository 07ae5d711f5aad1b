"""The I/O page for technicians: every digital input and output with its name, its state
and where it is wired on the configured backend, live.

Why the address beside the state: chasing a clamp, centering or guard alarm means comparing
what the software reads with the lamp on the terminal; the page names the unit and the
discrete input or coil (Modbus) or the node, object and bit (CANopen), so a technician goes
from the screen to the terminal without the configuration file. The table comes from the
machine (the snapshot's ``io_points``), the same mapping the drivers use.
"""

from __future__ import annotations

from dataclasses import asdict

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QFrame,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QScrollArea,
    QVBoxLayout,
    QWidget,
)

from app.machine.snapshot import IoPoint, MachineSnapshot
from app.screens.base import Screen, ScreenContext
from app.screens.io_status import signal_text
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.kinetic import kinetic_scroll
from app.screens.widgets.lamp import LampColor, StatusLamp
from app.screens.widgets.readouts import set_text, styled_label

LAMP_PX = 20


class IoRow:
    """One signal: lamp, name, state in words, address."""

    def __init__(self, point: IoPoint) -> None:
        self.point = point
        self.lamp = StatusLamp(LAMP_PX)
        self.name = styled_label("", "field", f"ioName_{point.signal}")
        self.state = styled_label("", "field", f"ioState_{point.signal}")
        self.address = styled_label("", "caption", f"ioAddress_{point.signal}")
        self.on: bool | None = None


class IoScreen(Screen):
    key = "io"

    def __init__(self, context: ScreenContext, parent: QWidget | None = None) -> None:
        super().__init__(context, parent)
        self.title_label = styled_label("", "title")
        self.backend_label = styled_label("", "caption", "ioBackend")
        self.back_button = touch_button("ioBack", "primary")
        self.back_button.clicked.connect(lambda: self.context.navigate("main"))
        header = QHBoxLayout()
        header.addWidget(self.title_label)
        header.addWidget(self.backend_label, 1)
        header.addWidget(self.back_button)

        self.inputs_panel, self.inputs_grid, self.inputs_title = self._panel()
        self.outputs_panel, self.outputs_grid, self.outputs_title = self._panel()
        body = QWidget()
        columns = QHBoxLayout(body)
        columns.setContentsMargins(0, 0, 0, 0)
        columns.setSpacing(10)
        columns.addWidget(self.inputs_panel, 3, Qt.AlignmentFlag.AlignTop)
        columns.addWidget(self.outputs_panel, 2, Qt.AlignmentFlag.AlignTop)
        # Every signal of every backend (the pendant's too) may not fit the panel's height:
        # the columns scroll by dragging instead of making the window grow.
        self.signals_scroll = QScrollArea()
        self.signals_scroll.setObjectName("ioScroll")
        self.signals_scroll.setWidget(body)
        self.signals_scroll.setWidgetResizable(True)
        self.signals_scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        kinetic_scroll(self.signals_scroll)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(8, 8, 8, 8)
        layout.addLayout(header)
        layout.addWidget(self.signals_scroll, 1)
        self.rows: dict[str, IoRow] = {}
        self._points: tuple[IoPoint, ...] = ()
        self.retranslate()

    def _panel(self) -> tuple[QFrame, QGridLayout, QLabel]:
        panel = QFrame()
        panel.setObjectName("panel")
        title = styled_label("", "value")
        grid = QGridLayout()
        grid.setHorizontalSpacing(10)
        grid.setVerticalSpacing(4)
        grid.setColumnStretch(1, 1)
        box = QVBoxLayout(panel)
        box.setContentsMargins(10, 6, 10, 6)
        box.addWidget(title)
        box.addLayout(grid)
        box.addStretch(1)
        return panel, grid, title

    def title(self) -> str:
        return self.tr("Inputs and outputs")

    def retranslate(self) -> None:
        self.title_label.setText(self.tr("Inputs and outputs"))
        self.inputs_title.setText(self.tr("Inputs"))
        self.outputs_title.setText(self.tr("Outputs"))
        self.back_button.setText(self.tr("Back"))
        for row in self.rows.values():
            row.name.setText(signal_text(row.point.signal))
            row.address.setText(self._address_text(row.point))
            row.on = None  # the state words again, in the new language

    def _address_text(self, point: IoPoint) -> str:
        if not point.address:
            return self.tr("not wired")
        if point.address == "simulated":
            return self.tr("simulated")
        return point.address

    def _build(self, points: tuple[IoPoint, ...]) -> None:
        """The rows, once per table (the table is fixed while the machine runs)."""
        self._points = points
        for point in points:
            if point.signal in self.rows:
                continue
            row = IoRow(point)
            grid = self.outputs_grid if point.output else self.inputs_grid
            line = grid.rowCount()
            grid.addWidget(row.lamp, line, 0)
            grid.addWidget(row.name, line, 1)
            grid.addWidget(row.state, line, 2)
            grid.addWidget(row.address, line, 3, Qt.AlignmentFlag.AlignRight)
            self.rows[point.signal] = row
        self.retranslate()

    def update_snapshot(self, snapshot: MachineSnapshot, force: bool = False) -> None:
        self.snapshot = snapshot
        if snapshot.io_points != self._points:
            self._build(snapshot.io_points)
        set_text(self.backend_label, self.tr("Backend: %1").replace("%1", snapshot.backend))
        states = {**asdict(snapshot.inputs), **asdict(snapshot.outputs)}
        for signal, row in self.rows.items():
            on = bool(states.get(signal, False))
            if on == row.on and not force:
                continue
            row.on = on
            row.lamp.set_color(LampColor.GREEN if on else LampColor.OFF)
            set_text(row.state, self.tr("ON") if on else self.tr("off"))
