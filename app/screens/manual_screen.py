"""Manual screen: jog X-Y with a cross and the tilt with two buttons, continuous or by steps,
jog speed and acceleration, homing, clamps and spindle by hand (docs/MACHINE.md sections 4 and 5).

Why opening the screen enters manual mode and leaving it leaves: that is how the original
panel worked, and it means no jog button is ever live on a screen the operator is not looking
at. Continuous jog runs only while a button is held: press sends ``JogContinuous`` and repeats
it every ``JOG_REFRESH_S``, release sends ``JogRelease``; if the repeats stop (frozen screen,
lost link) the machine's dead-man timer stops the axis by itself.
"""

from __future__ import annotations

import itertools
import random

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QButtonGroup,
    QFrame,
    QGridLayout,
    QHBoxLayout,
    QPushButton,
    QSizePolicy,
    QVBoxLayout,
    QWidget,
)

from app.data.errors import DataError
from app.data.parameters import parameter_spec
from app.machine.commands import (
    EnterManual,
    Home,
    JogContinuous,
    JogRelease,
    JogStep,
    LeaveManual,
    MoveTo,
    ReloadParameters,
    SetClamps,
    SetSpindle,
)
from app.machine.permissions import SPINDLE_ON
from app.machine.snapshot import MachineSnapshot
from app.machine.states import MachineState
from app.screens.base import Screen, ScreenContext, refusal
from app.screens.formatting import format_number
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.dialogs import ConfirmOverlay
from app.screens.widgets.hold_button import HoldButton
from app.screens.widgets.keypad import Keypad
from app.screens.widgets.pendant_status import PendantStatus
from app.screens.widgets.readouts import AxisReadout, reason_label, set_text, styled_label

STEP_SIZES: tuple[float, ...] = (0.01, 0.1, 1.0, 10.0)
TILT_STEP_RANGE_DEG = (0.1, 1.0)  # the tilt steps 0.1 or 1 degree: 0.01 is too fine, 10 too big


def tilt_step_deg(step_size: float) -> float:
    """The tilt step for the selected step size: 0.01 and 0.1 -> 0.1 deg, 1 and 10 -> 1 deg."""
    low, high = TILT_STEP_RANGE_DEG
    return min(max(step_size, low), high)


# (axis, direction, symbol, grid row, grid column)
JOG_KEYS: tuple[tuple[str, int, str, int, int], ...] = (
    ("Y", +1, "Y+\n▲", 0, 1),
    ("X", -1, "◀\nX−", 1, 0),
    ("X", +1, "▶\nX+", 1, 2),
    ("Y", -1, "▼\nY−", 2, 1),
    ("Z", +1, "Z+\n↻", 0, 4),
    ("Z", -1, "Z−\n↺", 2, 4),
)

# group -> (speed parameter, acceleration parameter) whose ranges the keypads use
JOG_PARAMETERS: dict[str, tuple[str, str]] = {
    "XY": ("jog_xy_speed_mm_s", "jog_xy_accel_mm_s2"),
    "Z": ("jog_z_speed_deg_s", "jog_z_accel_deg_s2"),
}


class ManualScreen(Screen):
    key = "manual"

    def __init__(self, context: ScreenContext, parent: QWidget | None = None) -> None:
        super().__init__(context, parent)
        self.step_mode = False
        self.step_size = 1.0
        self.jog_buttons: dict[tuple[str, int], HoldButton] = {}
        # Each press is a new hold; its refreshes repeat its number (the machine refuses the
        # refreshes of a hold its dead-man ended). Numbered from a random start so that a
        # restarted screen does not repeat the numbers of the one before.
        self._hold_numbers = itertools.count(random.randrange(1, 2**31))
        self._holds: dict[str, int] = {}

        # -- jog cross ---------------------------------------------------------------------
        jog_panel = QFrame()
        jog_panel.setObjectName("panel")
        self.mode_label = styled_label("", "value", "manualModeLabel")
        self.mode_label.setWordWrap(True)
        self.enter_button = touch_button("enterManualButton", "primary")
        self.enter_button.clicked.connect(lambda: self.context.send(EnterManual()))
        cross = QGridLayout()
        cross.setSpacing(8)
        for axis, direction, symbol, row, column in JOG_KEYS:
            jog = HoldButton(symbol)
            jog.setObjectName(f"jog_{axis}{'plus' if direction > 0 else 'minus'}")
            jog.setProperty("kind", "jog")
            jog.setFocusPolicy(Qt.FocusPolicy.NoFocus)
            jog.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)
            jog.holdStarted.connect(lambda a=axis, d=direction: self.jog_pressed(a, d))
            jog.holdRefresh.connect(lambda a=axis, d=direction: self.jog_refresh(a, d))
            jog.holdEnded.connect(lambda a=axis: self.jog_released(a))
            cross.addWidget(jog, row, column)
            self.jog_buttons[(axis, direction)] = jog
        self.xy_label = styled_label("X-Y", "caption")
        self.xy_label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        cross.addWidget(self.xy_label, 1, 1)
        self.z_caption = styled_label("", "caption")
        self.z_caption.setAlignment(Qt.AlignmentFlag.AlignCenter)
        cross.addWidget(self.z_caption, 1, 4)
        cross.setColumnMinimumWidth(3, 24)

        self.continuous_button = touch_button("continuousMode")
        self.step_button = touch_button("stepMode")
        mode_group = QButtonGroup(self)
        for button in (self.continuous_button, self.step_button):
            button.setCheckable(True)
            mode_group.addButton(button)
        self.continuous_button.setChecked(True)
        self.continuous_button.clicked.connect(lambda: self.set_step_mode(False))
        self.step_button.clicked.connect(lambda: self.set_step_mode(True))
        self.go_to_button = touch_button("goToPosition")
        self.go_to_button.clicked.connect(self.go_to_position)
        modes = QHBoxLayout()
        modes.addWidget(self.continuous_button)
        modes.addWidget(self.step_button)
        modes.addWidget(self.go_to_button)

        self.step_caption = styled_label("", "caption")
        self.step_buttons: dict[float, QPushButton] = {}
        step_group = QButtonGroup(self)
        steps = QHBoxLayout()
        for size in STEP_SIZES:
            button = touch_button(f"step_{format_number(size)}")
            button.setText(format_number(size))
            button.setCheckable(True)
            button.setChecked(size == self.step_size)
            button.clicked.connect(lambda _=False, s=size: self.set_step_size(s))
            step_group.addButton(button)
            steps.addWidget(button)
            self.step_buttons[size] = button

        jog_layout = QVBoxLayout(jog_panel)
        jog_layout.setContentsMargins(12, 4, 12, 6)
        mode_row = QHBoxLayout()
        mode_row.addWidget(self.mode_label, 1)
        mode_row.addWidget(self.enter_button)
        jog_layout.addLayout(mode_row)
        self.pendant_status = PendantStatus()
        jog_layout.addWidget(self.pendant_status)
        jog_layout.addLayout(cross, 1)
        jog_layout.addLayout(modes)

        # -- right: positions, speeds, homing, clamps, spindle ------------------------------
        self.axis_x = AxisReadout("X", "mm")
        self.axis_y = AxisReadout("Y", "mm")
        self.axis_z = AxisReadout("Z", "°")
        positions = QHBoxLayout()
        positions.setSpacing(8)
        for readout in (self.axis_x, self.axis_y, self.axis_z):
            positions.addWidget(readout, 1)

        speed_panel = QFrame()
        speed_panel.setObjectName("panel")
        speeds = QGridLayout(speed_panel)
        speeds.setContentsMargins(10, 6, 10, 8)
        self.speed_fields: dict[tuple[str, int], QPushButton] = {}
        self.speed_headers = (styled_label("", "caption"), styled_label("", "caption"))
        speeds.addWidget(self.speed_headers[0], 1, 1)
        speeds.addWidget(self.speed_headers[1], 1, 2)
        for row, group in enumerate(("XY", "Z"), start=2):
            label = styled_label("X-Y" if group == "XY" else "Z", "value")
            speeds.addWidget(label, row, 0)
            for column in (0, 1):
                field = touch_button(f"jog{group}{'Speed' if column == 0 else 'Accel'}", "field")
                field.clicked.connect(lambda _=False, g=group, c=column: self.edit_speed(g, c))
                speeds.addWidget(field, row, column + 1)
                self.speed_fields[(group, column)] = field

        actions = QGridLayout()
        actions.setSpacing(8)
        # Homing: a caption and one button per axis (short labels fit every language).
        self.home_caption = styled_label("", "caption")
        self.home_buttons: dict[str, QPushButton] = {}
        for column, axis in enumerate(("X", "Y", "Z", "")):
            button = touch_button(f"home{axis or 'All'}", "primary")
            button.clicked.connect(lambda _=False, a=axis: self.context.send(Home(a)))
            actions.addWidget(button, 0, column)
            self.home_buttons[axis] = button
        self.clamps_button = touch_button("clampsButton")
        self.clamps_button.clicked.connect(self.toggle_clamps)
        self.spindle_button = touch_button("spindleButton")
        self.spindle_button.clicked.connect(self.toggle_spindle)
        actions.addWidget(self.clamps_button, 1, 0, 1, 2)
        actions.addWidget(self.spindle_button, 1, 2, 1, 2)
        # Why jogging, homing, clamps or spindle are refused, under them: a touch screen
        # shows no tooltips.
        self.reason_label = reason_label("manualReason")

        right = QVBoxLayout()
        right.setSpacing(4)
        right.addWidget(speed_panel)
        right.addWidget(self.step_caption)
        right.addLayout(steps)
        right.addWidget(self.home_caption)
        right.addLayout(actions)
        right.addWidget(self.reason_label)
        right.addStretch(1)

        below = QHBoxLayout()
        below.setSpacing(10)
        below.addWidget(jog_panel, 5)
        below.addLayout(right, 6)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(8, 8, 8, 8)
        layout.setSpacing(8)
        layout.addLayout(positions)
        layout.addLayout(below, 1)
        self.retranslate()
        self.set_step_mode(False)

    # -- texts ----------------------------------------------------------------------------------

    def title(self) -> str:
        return self.tr("Manual")

    def retranslate(self) -> None:
        self.enter_button.setText(self.tr("Enter manual mode"))
        self.z_caption.setText(self.tr("Tilt"))
        self.continuous_button.setText(self.tr("Continuous"))
        self.step_button.setText(self.tr("Step"))
        self.step_caption.setText(self.tr("Step size (mm for X-Y; tilt 0.1° or 1°)"))
        self.speed_headers[0].setText(self.tr("Jog speed"))
        self.speed_headers[1].setText(self.tr("Jog acceleration"))
        self.home_caption.setText(self.tr("Home (find the reference position)"))
        for axis in ("X", "Y", "Z"):
            self.home_buttons[axis].setText(axis)
            self.home_buttons[axis].setToolTip(self.tr("Home %1").replace("%1", axis))
        self.go_to_button.setText(self.tr("Go to…"))
        self.go_to_button.setToolTip(self.tr("Go to a position typed on the keypad"))
        self.home_buttons[""].setText(self.tr("All"))
        self.home_buttons[""].setToolTip(self.tr("Home all axes"))
        for readout in (self.axis_x, self.axis_y, self.axis_z):
            readout.set_not_homed_text(self.tr("NOT HOMED"))
        self.pendant_status.retranslate()
        if self.snapshot is None:
            self.mode_label.setText(self.tr("Waiting for the machine…"))

    # -- mode -----------------------------------------------------------------------------------

    def activated(self) -> None:
        if (
            self.snapshot is not None
            and self.snapshot.state is not MachineState.MANUAL
            and not refusal(self.snapshot, "EnterManual")
        ):
            self.context.send(EnterManual())

    def deactivated(self) -> None:
        for button in self.jog_buttons.values():
            button.release_hold()
        if self.snapshot is not None and self.snapshot.state is MachineState.MANUAL:
            self.context.send(LeaveManual())

    def set_step_mode(self, on: bool) -> None:
        self.step_mode = on
        self.step_button.setChecked(on)
        self.continuous_button.setChecked(not on)
        for button in self.step_buttons.values():
            button.setEnabled(on)

    def set_step_size(self, size: float) -> None:
        self.step_size = size
        self.step_buttons[size].setChecked(True)

    # -- jogging --------------------------------------------------------------------------------

    def jog_pressed(self, axis: str, direction: int) -> None:
        if self.step_mode:
            size = tilt_step_deg(self.step_size) if axis == "Z" else self.step_size
            self.context.send(JogStep(axis, direction * size))
        else:
            self._holds[axis] = next(self._hold_numbers)
            self.context.send(JogContinuous(axis, direction, self._holds[axis]))

    def jog_refresh(self, axis: str, direction: int) -> None:
        if not self.step_mode:
            self.context.send(JogContinuous(axis, direction, self._holds.get(axis, 0)))

    def jog_released(self, axis: str) -> None:
        if not self.step_mode:
            self.context.send(JogRelease(axis))

    def edit_speed(self, group: str, column: int) -> None:
        """Open the keypad for a jog speed (column 0) or acceleration (column 1)."""
        spec = parameter_spec(JOG_PARAMETERS[group][column])
        speed, accel = self._jog_values(group)
        current = speed if column == 0 else accel
        title = (
            self.tr("Jog speed %1") if column == 0 else self.tr("Jog acceleration %1")
        ).replace("%1", "X-Y" if group == "XY" else "Z")
        keypad = Keypad.for_number(
            title, current, spec.minimum, spec.maximum, spec.unit, decimals=2
        )

        def accepted(value: float) -> None:
            # The System screen's Jogging parameter: one value, logged, kept across a restart.
            user = self.context.session.acting_user()
            if user is None:
                self.context.notify(self.tr("Log in to change parameters."))
                return
            try:
                self.context.database.set_parameter(spec.name, value, user)
            except DataError as exc:
                self.context.notify(str(exc))
                return
            self.context.send(ReloadParameters())

        keypad.valueAccepted.connect(accepted)
        self.context.open(keypad)

    def _jog_values(self, group: str) -> tuple[float, float]:
        if self.snapshot is None:
            return (0.0, 0.0)
        return self.snapshot.jog_xy if group == "XY" else self.snapshot.jog_z

    def go_to_position(self) -> None:
        """X, Y and the tilt typed on the keypad, one after the other; the machine plans the
        move around the board on the table, or says why not."""
        if self.snapshot is None:
            return
        limits = self.context.database.limits
        fields = (
            ("X", self.tr("Go to X"), limits.x_min_mm, limits.x_max_mm, "mm"),
            ("Y", self.tr("Go to Y"), limits.y_min_mm, limits.y_max_mm, "mm"),
            ("Z", self.tr("Go to tilt"), limits.z_min_deg, limits.z_max_deg, "°"),
        )
        chosen: list[float] = []

        def ask(index: int) -> None:
            if index == len(fields):
                self.context.send(MoveTo(chosen[0], chosen[1], chosen[2]))
                return
            axis, title, low, high, unit = fields[index]
            keypad = Keypad.for_number(
                title,
                self.snapshot.axis(axis).position if self.snapshot is not None else 0.0,
                -1e6 if low is None else low,
                1e6 if high is None else high,
                unit,
                decimals=2,
            )

            def accepted(value: float) -> None:
                chosen.append(value)
                ask(index + 1)

            keypad.valueAccepted.connect(accepted)
            self.context.open(keypad)

        ask(0)

    def toggle_clamps(self) -> None:
        if self.snapshot is not None:
            self.context.send(SetClamps(not self.snapshot.outputs.clamps_close))

    def toggle_spindle(self) -> None:
        """Spindle off at once; Spindle on only after the operator confirms (a cutter that
        starts turning by hand is the one moment nobody expects it)."""
        if self.snapshot is None:
            return
        if self.snapshot.outputs.spindle_on:
            self.context.send(SetSpindle(False))
            return
        overlay = ConfirmOverlay(
            self.tr("Start the spindle?"),
            self.tr("The cutter starts turning. Keep clear of it."),
            self.tr("Spindle ON"),
            danger=True,
        )
        overlay.finished.connect(lambda ok: self.context.send(SetSpindle(True)) if ok else None)
        self.context.open(overlay)

    # -- machine --------------------------------------------------------------------------------

    def update_snapshot(self, snapshot: MachineSnapshot, force: bool = False) -> None:
        self.snapshot = snapshot
        manual = snapshot.state is MachineState.MANUAL
        jog_reason = refusal(snapshot, "JogContinuous")
        if manual:
            set_text(self.mode_label, self.tr("Manual mode: hold a button to jog."))
        else:
            reason = refusal(snapshot, "EnterManual")
            set_text(
                self.mode_label, self.tr("Not in manual mode.") + (" " + reason if reason else "")
            )
        self.enter_button.setVisible(not manual)
        self.enter_button.setEnabled(not refusal(snapshot, "EnterManual"))
        self.pendant_status.show_view(snapshot.pendant)

        for button in self.jog_buttons.values():
            if button.isEnabled() == bool(jog_reason):
                button.setEnabled(not jog_reason)

        for readout in (self.axis_x, self.axis_y, self.axis_z):
            try:
                axis = snapshot.axis(readout.axis)
            except KeyError:
                continue
            readout.set_position(axis.position, axis.homed, axis.faulted)

        units = {"XY": ("mm/s", "mm/s²"), "Z": ("°/s", "°/s²")}
        for group, values in (("XY", snapshot.jog_xy), ("Z", snapshot.jog_z)):
            for column in (0, 1):
                text = f"{format_number(values[column], 2)} {units[group][column]}"
                set_text(self.speed_fields[(group, column)], text)

        home_reason = refusal(snapshot, "Home")
        for home in self.home_buttons.values():
            home.setEnabled(not home_reason)

        move_reason = refusal(snapshot, "MoveTo")
        self.go_to_button.setEnabled(not move_reason)
        self.go_to_button.setToolTip(move_reason)

        clamps_reason = refusal(snapshot, "SetClamps")
        self.clamps_button.setEnabled(not clamps_reason)
        closed = snapshot.outputs.clamps_close
        set_text(self.clamps_button, self.tr("Open clamps") if closed else self.tr("Close clamps"))
        spindle_reason = refusal(snapshot, SPINDLE_ON)
        spindle_on = snapshot.outputs.spindle_on
        # Switching the spindle off is always offered while it runs.
        self.spindle_button.setEnabled(spindle_on or not spindle_reason)
        reasons = (
            jog_reason if manual else "",
            home_reason,
            clamps_reason,
            "" if spindle_on else spindle_reason,
        )
        set_text(self.reason_label, "; ".join(dict.fromkeys(r for r in reasons if r)))
        set_text(
            self.spindle_button, self.tr("Spindle OFF") if spindle_on else self.tr("Spindle ON")
        )
