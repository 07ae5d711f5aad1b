"""System screen: every system parameter, grouped, with units and ranges, behind a PIN.

Why generated from the catalogue (``app.data.parameters``): one table says each parameter's
unit, range, default, meaning and the least role allowed to change it; the screen shows
exactly that, so a parameter added there appears here with its limits, and a value is
checked the same way here as in the database. Every change is stored with who and when
(the database logs it) and the machine is told to reload. Parameters above the logged-in
level are shown but locked, with the level they need.
"""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QAbstractItemView,
    QButtonGroup,
    QFrame,
    QGridLayout,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QPushButton,
    QStackedWidget,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from app.data.errors import DataError, FieldValidationError
from app.data.parameters import (
    CONFIGURATION_GROUPS,
    PARAMETERS,
    UNUSED_PARAMETERS,
    ParameterSpec,
    check_parameter_set,
    check_parameter_value,
)
from app.data.users import Role
from app.drivers.contracts import FAULT_KINDS
from app.machine.commands import (
    ClearFaults,
    InjectFault,
    LoadBoard,
    ReloadParameters,
    RemoveBoard,
)
from app.machine.snapshot import MachineSnapshot
from app.plant.status import PlantStatus, PlantStatusSource
from app.screens.base import Screen, ScreenContext, refusal
from app.screens.formatting import format_clock, format_number
from app.screens.opcua_page import OpcuaPage
from app.screens.pin_lockout import PinLockoutBar
from app.screens.texts import parameter_text, role_text
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.keypad import Keypad
from app.screens.widgets.kinetic import kinetic_scroll
from app.screens.widgets.readouts import set_text, styled_label
from app.screens.widgets.sim_pendant import SimPendantPanel
from app.screens.widgets.touch_scroll import touch_scroll_area

GROUP_ORDER = ("home", "tool", "start", "motion", "path", "limits", "jog", "production")
UNIT_SYMBOLS = {"deg": "°", "deg/s": "°/s", "deg/s²": "°/s²"}
HISTORY_LIMIT = 200


def unit_text(unit: str) -> str:
    return UNIT_SYMBOLS.get(unit, unit)


def groups() -> list[str]:
    """The catalogue's groups, in the screen's order (unknown groups at the end)."""
    found = list(dict.fromkeys(spec.group for spec in PARAMETERS))
    return sorted(found, key=lambda g: GROUP_ORDER.index(g) if g in GROUP_ORDER else 99)


class SystemScreen(Screen):
    key = "system"

    def __init__(self, context: ScreenContext, parent: QWidget | None = None) -> None:
        super().__init__(context, parent)
        self.values: dict[str, float] = {}
        self.group = groups()[0]
        self.unlocked = False

        # -- locked page ---------------------------------------------------------------------
        locked = QFrame()
        locked.setObjectName("panel")
        self.locked_label = styled_label("", "title", "lockedLabel")
        self.locked_label.setWordWrap(True)
        self.locked_label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.unlock_button = touch_button("unlockButton", "primary")
        self.unlock_button.clicked.connect(self.unlock)
        locked_layout = QVBoxLayout(locked)
        locked_layout.addStretch(1)
        locked_layout.addWidget(self.locked_label)
        locked_layout.addWidget(self.unlock_button, 0, Qt.AlignmentFlag.AlignHCenter)
        locked_layout.addStretch(2)

        # -- settings page -----------------------------------------------------------------------
        settings = QWidget()
        self.group_buttons: dict[str, QPushButton] = {}
        group_grid = QGridLayout()
        group_grid.setSpacing(6)
        button_group = QButtonGroup(self)
        keys = [*groups(), "log", "opcua", "simulation"]
        columns = (len(keys) + 2) // 2
        for index, key in enumerate(keys):
            button = touch_button(f"group_{key}", "tab")
            button.setCheckable(True)
            button.clicked.connect(lambda _=False, k=key: self.show_group(k))
            button_group.addButton(button)
            group_grid.addWidget(button, index // columns, index % columns)
            self.group_buttons[key] = button
        self.lock_button = touch_button("lockButton", "tab")
        self.lock_button.clicked.connect(self.context.session.logout)
        group_grid.addWidget(self.lock_button, 1, columns - 1)

        self.pages = QStackedWidget()
        # parameter page
        self.param_title = styled_label("", "title", "groupTitle")
        self.param_grid_host = QWidget()
        self.param_grid = QGridLayout(self.param_grid_host)
        self.param_grid.setHorizontalSpacing(10)
        self.param_grid.setVerticalSpacing(4)
        scroll = touch_scroll_area(self.param_grid_host)
        self.param_buttons: dict[str, QPushButton] = {}
        self.param_labels: dict[str, tuple[QLabel, QLabel]] = {}
        param_page = QFrame()
        param_page.setObjectName("panel")
        param_layout = QVBoxLayout(param_page)
        param_layout.setContentsMargins(10, 6, 10, 8)
        param_layout.addWidget(self.param_title)
        param_layout.addWidget(scroll, 1)
        # change log page
        log_page = QFrame()
        log_page.setObjectName("panel")
        self.log_title = styled_label("", "title")
        self.log_table = QTableWidget(0, 5)
        self.log_table.setObjectName("parameterLog")
        self.log_table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.log_table.setSelectionMode(QAbstractItemView.SelectionMode.NoSelection)
        self.log_table.verticalHeader().setVisible(False)
        self.log_table.setAlternatingRowColors(True)
        self.log_table.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        kinetic_scroll(self.log_table)
        log_layout = QVBoxLayout(log_page)
        log_layout.setContentsMargins(10, 6, 10, 8)
        log_layout.addWidget(self.log_title)
        log_layout.addWidget(self.log_table, 1)
        # simulation page
        sim_page = QFrame()
        sim_page.setObjectName("panel")
        sim_content = QWidget()  # taller than the page at 1024x768: it scrolls
        self.sim_title = styled_label("", "title")
        self.sim_note = styled_label("", "caption")
        self.sim_note.setWordWrap(True)
        self.fault_buttons: dict[str, QPushButton] = {}
        sim_grid = QGridLayout()
        sim_grid.setSpacing(6)
        for index, kind in enumerate(FAULT_KINDS):
            button = touch_button(f"inject_{kind}")
            button.setText(kind.replace("_", " "))
            button.clicked.connect(lambda _=False, k=kind: self.inject(k))
            sim_grid.addWidget(button, index // 3, index % 3)
            self.fault_buttons[kind] = button
        self.clear_faults_button = touch_button("clearFaults", "primary")
        self.clear_faults_button.clicked.connect(lambda: self.context.send(ClearFaults()))
        self.load_board_button = touch_button("simLoadBoard")
        self.load_board_button.clicked.connect(self.load_board)
        self.remove_board_button = touch_button("simRemoveBoard")
        self.remove_board_button.clicked.connect(lambda: self.context.send(RemoveBoard()))
        self.replace_board_button = touch_button("simReplaceBoard")
        self.replace_board_button.clicked.connect(self.load_board)  # LoadBoard takes it off first
        sim_actions = QHBoxLayout()
        sim_actions.addWidget(self.clear_faults_button)
        sim_actions.addWidget(self.load_board_button)
        sim_actions.addWidget(self.remove_board_button)
        sim_actions.addWidget(self.replace_board_button)
        sim_layout = QVBoxLayout(sim_content)
        sim_layout.setContentsMargins(10, 6, 10, 8)
        sim_layout.addWidget(self.sim_title)
        sim_layout.addWidget(self.sim_note)
        sim_layout.addLayout(sim_grid)
        sim_layout.addLayout(sim_actions)
        self.sim_pendant = SimPendantPanel(self.context.send)
        sim_layout.addWidget(self.sim_pendant)
        sim_layout.addStretch(1)
        self.sim_scroll = touch_scroll_area(sim_content)
        sim_page_layout = QVBoxLayout(sim_page)
        sim_page_layout.setContentsMargins(0, 0, 0, 0)
        sim_page_layout.addWidget(self.sim_scroll)
        self.pages.addWidget(param_page)
        self.pages.addWidget(log_page)
        self.pages.addWidget(sim_page)
        self.param_page, self.log_page, self.sim_page = param_page, log_page, sim_page
        self.opcua_page = OpcuaPage(context, self.plant_status)
        self.pages.addWidget(self.opcua_page)

        settings_layout = QVBoxLayout(settings)
        settings_layout.setContentsMargins(0, 0, 0, 0)
        settings_layout.setSpacing(8)
        self.pin_lockout = PinLockoutBar(context)
        settings_layout.addWidget(self.pin_lockout)
        settings_layout.addLayout(group_grid)
        settings_layout.addWidget(self.pages, 1)

        self.body = QStackedWidget()
        self.body.addWidget(locked)
        self.body.addWidget(settings)
        self.locked_page, self.settings_page = locked, settings
        layout = QVBoxLayout(self)
        layout.setContentsMargins(8, 8, 8, 8)
        layout.addWidget(self.body)
        self.retranslate()
        self.user_changed()

    # -- texts -----------------------------------------------------------------------------------

    def title(self) -> str:
        return self.tr("System")

    def group_title(self, key: str) -> str:
        titles = {
            "home": self.tr("Home position"),
            "tool": self.tr("Tool and machine"),
            "start": self.tr("Start position P0"),
            "motion": self.tr("Automatic speeds"),
            "path": self.tr("Tool path"),
            "limits": self.tr("Axis limits"),
            "jog": self.tr("Jogging"),
            "production": self.tr("Shifts"),
            "log": self.tr("Change log"),
            "opcua": self.tr("OPC UA"),
            "simulation": self.tr("Simulation"),
        }
        return titles.get(key, key)

    def retranslate(self) -> None:
        self.locked_label.setText(
            self.tr(
                "The system settings are locked.\nLog in as technician or service to change them."
            )
        )
        self.unlock_button.setText(self.tr("Unlock with PIN"))
        self.lock_button.setText(self.tr("Lock (log out)"))
        self.pin_lockout.retranslate()
        for key, button in self.group_buttons.items():
            button.setText(self.group_title(key))
        self.log_title.setText(self.tr("Change log of the system parameters"))
        self.log_table.setHorizontalHeaderLabels(
            [self.tr("Time"), self.tr("Parameter"), self.tr("Old"), self.tr("New"), self.tr("User")]
        )
        header = self.log_table.horizontalHeader()
        for column in range(5):
            header.setSectionResizeMode(
                column,
                QHeaderView.ResizeMode.Stretch
                if column == 1
                else QHeaderView.ResizeMode.ResizeToContents,
            )
        self.sim_title.setText(self.tr("Simulation"))
        self.sim_note.setText(
            self.tr(
                "Only on the simulated machine: inject a fault to test the alarms, clear the "
                "injected faults (the machine stays latched until Reset), put a board in, take "
                "it off or replace it, and work the handwheel and the joystick (in manual mode)."
            )
        )
        self.clear_faults_button.setText(self.tr("Clear injected faults"))
        self.load_board_button.setText(self.tr("Put a board in"))
        self.remove_board_button.setText(self.tr("Take the board off"))
        self.replace_board_button.setText(self.tr("Replace the board"))
        self.sim_pendant.retranslate()
        self.opcua_page.retranslate()
        if self.unlocked:
            self.show_group(self.group)

    # -- lock -----------------------------------------------------------------------------------

    def unlock(self) -> None:
        self.context.require(Role.TECHNICIAN, self.user_changed)

    def user_changed(self) -> None:
        self.unlocked = self.context.session.can(Role.TECHNICIAN)
        self.body.setCurrentWidget(self.settings_page if self.unlocked else self.locked_page)
        if self.unlocked:
            self.pin_lockout.refresh()
            self.show_group(self.group)

    def activated(self) -> None:
        self.user_changed()

    # -- groups -----------------------------------------------------------------------------------

    def show_group(self, key: str) -> None:
        self.group = key
        self.group_buttons[key].setChecked(True)
        if key == "log":
            self.pages.setCurrentWidget(self.log_page)
            self.refresh_log()
        elif key == "simulation":
            self.pages.setCurrentWidget(self.sim_page)
        elif key == "opcua":
            self.pages.setCurrentWidget(self.opcua_page)
            self.opcua_page.refresh()
        else:
            self.pages.setCurrentWidget(self.param_page)
            self.fill_parameters(key)

    def fill_parameters(self, group: str) -> None:
        """(Re)build the rows of one group from the catalogue and the stored values."""
        self.values = self.context.database.get_parameters()
        set_text(self.param_title, self.group_title(group))
        while self.param_grid.count():
            item = self.param_grid.takeAt(0)
            widget = item.widget() if item is not None else None
            if widget is not None:
                widget.hide()  # at once: deleteLater waits for the event loop
                widget.setParent(None)
                widget.deleteLater()
        self.param_buttons.clear()
        self.param_labels.clear()
        row = 0
        for spec in PARAMETERS:
            if spec.group != group or spec.name in UNUSED_PARAMETERS:
                continue
            description = styled_label(parameter_text(spec.description), "value")
            description.setWordWrap(True)
            description.setStyleSheet("font-weight: normal;")
            unit = f" {unit_text(spec.unit)}" if spec.unit else ""
            allowed = self.context.session.can(spec.required_role)
            caption_text = (
                f"{spec.name} · {format_number(spec.minimum, 9)} … "
                f"{format_number(spec.maximum, 9)}{unit}"
            )
            if not allowed:
                caption_text += " · " + self.tr("needs %1").replace(
                    "%1", role_text(spec.required_role)
                )
            value = self.values[spec.name]
            if spec.group in CONFIGURATION_GROUPS:
                # What the machine enforces comes from its configuration: shown, not edited.
                value = getattr(self.context.database.limits, spec.name)
                caption_text = f"{spec.name} · " + self.tr(
                    "enforced by the machine, set in its configuration file"
                )
                allowed = False
            caption = styled_label(caption_text, "caption")
            caption.setWordWrap(True)
            button = touch_button(f"param_{spec.name}", "field")
            button.setMinimumWidth(190)
            button.setText("—" if value is None else f"{format_number(value, 6)}{unit}")
            button.setEnabled(allowed)
            button.clicked.connect(lambda _=False, s=spec: self.edit_parameter(s))
            labels = QVBoxLayout()
            labels.setSpacing(0)
            labels.addWidget(description)
            labels.addWidget(caption)
            holder = QWidget()
            holder.setLayout(labels)
            self.param_grid.addWidget(holder, row, 0)
            self.param_grid.addWidget(button, row, 1)
            holder.show()  # now, not when the layout gets round to it
            button.show()
            self.param_buttons[spec.name] = button
            self.param_labels[spec.name] = (description, caption)
            row += 1
        self.param_grid.setColumnStretch(0, 1)
        self.param_grid.setRowStretch(row, 1)

    def edit_parameter(self, spec: ParameterSpec) -> None:
        current = self.values.get(spec.name, spec.default)

        def check(value: float) -> str:
            error = check_parameter_value(spec, value)
            if error is None:
                proposed = {**self.values, spec.name: value}
                problems = check_parameter_set(proposed)
                error = problems[0] if problems else None
            return error.message if error is not None else ""

        keypad = Keypad.for_number(
            parameter_text(spec.description),
            current,
            spec.minimum,
            spec.maximum,
            unit_text(spec.unit),
            decimals=9 if spec.maximum <= 0.1 else 3,
            integer=spec.integer,
            check=check,
        )
        keypad.valueAccepted.connect(lambda value: self.set_parameter(spec, value))
        self.context.open(keypad)

    def set_parameter(self, spec: ParameterSpec, value: float) -> None:
        user = self.context.session.user
        if user is None:
            self.context.notify(self.tr("Log in to change parameters."))
            return
        try:
            self.context.database.set_parameter(spec.name, value, user)
        except (FieldValidationError, DataError) as exc:
            self.context.notify(str(exc))
            self.fill_parameters(self.group)
            return
        self.context.send(ReloadParameters())
        self.fill_parameters(self.group)
        self.context.notify(
            self.tr("%1 set to %2 (logged).")
            .replace("%1", spec.name)
            .replace("%2", format_number(value, 9))
        )

    def refresh_log(self) -> None:
        changes = self.context.database.parameter_history(limit=HISTORY_LIMIT)
        self.log_table.setRowCount(len(changes))
        for row, change in enumerate(changes):
            old = "—" if change.old_value is None else format_number(change.old_value, 9)
            values = (
                format_clock(change.time),
                change.name,
                old,
                format_number(change.new_value, 9),
                f"{change.user_name} ({change.user_role})",
            )
            for column, text in enumerate(values):
                self.log_table.setItem(row, column, QTableWidgetItem(text))

    def plant_status(self) -> PlantStatus | None:
        """The plant connection's state (None: the panel runs without one)."""
        link = self.context.link
        return link.plant_status() if isinstance(link, PlantStatusSource) else None

    # -- simulation -------------------------------------------------------------------------------

    def inject(self, kind: str) -> None:
        target = "X" if kind in ("drive_fault", "following_error", "limit_switch") else ""
        self.context.send(InjectFault(kind, target))
        self.context.notify(self.tr("Fault injected: %1").replace("%1", kind))

    def load_board(self) -> None:
        self.context.send(LoadBoard())

    # -- machine ----------------------------------------------------------------------------------

    def update_snapshot(self, snapshot: MachineSnapshot, force: bool = False) -> None:
        self.snapshot = snapshot
        if self.pages.currentWidget() is self.opcua_page and self.opcua_page.isVisible():
            self.opcua_page.refresh_now_and_then()
        simulation = not refusal(snapshot, "InjectFault")
        button = self.group_buttons["simulation"]
        if button.isHidden() == simulation:
            button.setHidden(not simulation)
        for fault_button in self.fault_buttons.values():
            fault_button.setEnabled(simulation)
        self.clear_faults_button.setEnabled(simulation)
        board_reason = refusal(snapshot, "LoadBoard")
        on_table = snapshot.inputs.part_present
        self.load_board_button.setEnabled(simulation and not on_table)
        for button in (self.remove_board_button, self.replace_board_button):
            button.setEnabled(simulation and on_table and not board_reason)
            button.setToolTip(board_reason)
        if self.pages.currentWidget() is self.sim_page:
            self.sim_pendant.update_snapshot(snapshot, simulation)
