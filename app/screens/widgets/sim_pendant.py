"""The System screen's simulation controls for the simulated handwheel and joystick.

Why on the screen at all: on the simulated machine there is no wheel to turn and no stick to
push, yet the handwheel's rules (exact to the count, the enable button, one jog source at a
time, manual mode only) are what a technician wants to try before the real pendant is wired.
Every control only sends the machine's simulation commands (``SelectHandwheel``,
``TurnHandwheel``, ``HoldJogEnable``, ``PushJoystick``); what the axes then do is the machine
layer's, and the panel only shows it (the selector's position comes back in the snapshot).
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtGui import QHideEvent
from PySide6.QtWidgets import QButtonGroup, QGridLayout, QLabel, QPushButton, QWidget

from app.machine.commands import (
    Command,
    EnterManual,
    HoldJogEnable,
    LeaveManual,
    PushJoystick,
    SelectHandwheel,
    TurnHandwheel,
)
from app.machine.snapshot import MachineSnapshot
from app.machine.states import MachineState
from app.screens.base import refusal
from app.screens.formatting import format_position
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.pendant_status import PendantStatus
from app.screens.widgets.readouts import set_text, styled_label

WHEEL_AXES = ("", "X", "Y", "Z")  # "" is the selector's off position
WHEEL_MULTIPLIERS = (1, 10, 100)
WHEEL_TURNS = (-100, -10, 10, 100)  # counts per tap, as a hand turns the wheel
STICK_FRACTION = 0.5  # of full deflection while a push button is held
STICK_PUSHES = (("X", -1), ("X", 1), ("Y", -1), ("Y", 1))
TOUCH_MIN_PX = 60


def _touch(name: str, kind: str = "") -> QPushButton:
    button = touch_button(name, kind)
    button.setMinimumSize(TOUCH_MIN_PX, TOUCH_MIN_PX)
    return button


class SimPendantPanel(QWidget):
    """Selector, multiplier, enable, turns and stick pushes for the simulated machine."""

    def __init__(self, send: Callable[[Command], None], parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("simPendant")
        self._send = send
        self._axis = ""
        self._multiplier = 1
        self._stick_held = False
        self._pending: tuple[str, int] | None = None  # a choice the machine has not shown yet
        self.title = styled_label("", "value")
        self.status = PendantStatus()
        self.positions = styled_label("", "caption", "simPendantPositions")
        self.manual_button = _touch("simManualButton", "primary")
        self.manual_button.clicked.connect(self._toggle_manual)

        self.axis_buttons: dict[str, QPushButton] = {}
        axis_group = QButtonGroup(self)
        for axis in WHEEL_AXES:
            button = _touch(f"simWheelAxis_{axis or 'off'}", "tab")
            button.setCheckable(True)
            button.clicked.connect(lambda _=False, a=axis: self._select(a, self._multiplier))
            axis_group.addButton(button)
            self.axis_buttons[axis] = button
        self.multiplier_buttons: dict[int, QPushButton] = {}
        multiplier_group = QButtonGroup(self)
        for multiplier in WHEEL_MULTIPLIERS:
            button = _touch(f"simWheelX{multiplier}", "tab")
            button.setText(f"×{multiplier}")
            button.setCheckable(True)
            button.clicked.connect(lambda _=False, m=multiplier: self._select(self._axis, m))
            multiplier_group.addButton(button)
            self.multiplier_buttons[multiplier] = button
        self.enable_button = _touch("simJogEnable", "tab")
        self.enable_button.setCheckable(True)
        self.enable_button.toggled.connect(lambda held: self._send(HoldJogEnable(held)))
        self.turn_buttons: dict[int, QPushButton] = {}
        for counts in WHEEL_TURNS:
            button = _touch(f"simWheelTurn_{'minus' if counts < 0 else 'plus'}{abs(counts)}")
            button.setText(f"{counts:+d}")
            button.clicked.connect(lambda _=False, n=counts: self._send(TurnHandwheel(n)))
            self.turn_buttons[counts] = button
        self.stick_buttons: dict[tuple[str, int], QPushButton] = {}
        for axis, direction in STICK_PUSHES:
            button = _touch(f"simStick_{axis}{'plus' if direction > 0 else 'minus'}")
            button.setText(f"{axis}{'+' if direction > 0 else '−'}")
            button.pressed.connect(lambda a=axis, d=direction: self._push(a, d))
            button.released.connect(self._let_go)
            self.stick_buttons[(axis, direction)] = button
        self.axis_buttons[""].setChecked(True)  # the simulated selector starts off, x1
        self.multiplier_buttons[1].setChecked(True)
        self.wheel_label = QLabel()
        self.stick_label = QLabel()

        grid = QGridLayout(self)
        grid.setContentsMargins(0, 6, 0, 0)
        grid.setSpacing(6)
        grid.addWidget(self.title, 0, 0, 1, 4)
        grid.addWidget(self.manual_button, 0, 4, 1, 3)
        grid.addWidget(self.status, 1, 0, 1, 7)
        grid.addWidget(self.positions, 2, 0, 1, 7)
        grid.addWidget(self.wheel_label, 3, 0)
        for column, axis in enumerate(WHEEL_AXES):
            grid.addWidget(self.axis_buttons[axis], 3, 1 + column)
        for column, multiplier in enumerate(WHEEL_MULTIPLIERS):
            grid.addWidget(self.multiplier_buttons[multiplier], 4, 1 + column)
        grid.addWidget(self.enable_button, 4, 4, 1, 3)
        for column, counts in enumerate(WHEEL_TURNS):
            grid.addWidget(self.turn_buttons[counts], 5, 1 + column)
        grid.addWidget(self.stick_label, 6, 0)
        for column, key in enumerate(STICK_PUSHES):
            grid.addWidget(self.stick_buttons[key], 6, 1 + column)
        self.retranslate()

    # -- commands --------------------------------------------------------------------------------

    def _select(self, axis: str, multiplier: int) -> None:
        """The page's buttons are the simulated wheel's switches: they keep their position
        (the snapshot comes a poll later, and a second tap must not undo the first)."""
        self._axis, self._multiplier = axis, multiplier
        self._pending = (axis, multiplier)
        self._send(SelectHandwheel(axis, multiplier))

    def _follow_selector(self, axis: str, multiplier: int, simulation: bool) -> None:
        """Show the wheel's switches as the machine reads them, except while the page's
        own last choice is still on its way there."""
        if self._pending == (axis, multiplier) or not simulation:
            self._pending = None
        if self._pending is not None:
            return
        self._axis, self._multiplier = axis, multiplier
        if axis in self.axis_buttons:
            self.axis_buttons[axis].setChecked(True)
        if multiplier in self.multiplier_buttons:
            self.multiplier_buttons[multiplier].setChecked(True)

    def _push(self, axis: str, direction: int) -> None:
        self._stick_held = True
        deflection = direction * STICK_FRACTION
        self._send(PushJoystick(x=deflection) if axis == "X" else PushJoystick(y=deflection))

    def _let_go(self) -> None:
        if self._stick_held:
            self._stick_held = False
            self._send(PushJoystick())

    def _toggle_manual(self) -> None:
        manual = self.manual_button.property("manual") is True
        self._send(LeaveManual() if manual else EnterManual())

    def hideEvent(self, event: QHideEvent) -> None:
        """A stick held while the page goes away is let go (the release would be lost)."""
        self._let_go()
        super().hideEvent(event)

    # -- texts and machine -----------------------------------------------------------------------

    def retranslate(self) -> None:
        self.title.setText(self.tr("Handwheel and joystick"))
        self.wheel_label.setText(self.tr("Handwheel"))
        self.stick_label.setText(self.tr("Joystick (hold)"))
        self.axis_buttons[""].setText(self.tr("Off"))
        for axis in WHEEL_AXES[1:]:
            self.axis_buttons[axis].setText(axis)
        self.enable_button.setText(self.tr("Hold enable"))
        self._manual_text()
        self.status.retranslate()

    def _manual_text(self) -> None:
        manual = self.manual_button.property("manual") is True
        self.manual_button.setText(
            self.tr("Leave manual mode") if manual else self.tr("Enter manual mode")
        )

    def update_snapshot(self, snapshot: MachineSnapshot, simulation: bool) -> None:
        view = snapshot.pendant
        self._follow_selector(view.wheel_axis, view.wheel_multiplier, simulation)
        self.status.show_view(view)
        set_text(
            self.positions,
            "   ".join(
                f"{axis.name} {format_position(axis.position)} {axis.unit}"
                for axis in snapshot.axes
            ),
        )
        manual = snapshot.state is MachineState.MANUAL
        if self.manual_button.property("manual") is not manual:
            self.manual_button.setProperty("manual", manual)
            self._manual_text()
        reason = refusal(snapshot, "LeaveManual" if manual else "EnterManual")
        self.manual_button.setEnabled(simulation and not reason)
        self.manual_button.setToolTip(reason)
        wheel = simulation and view.handwheel_fitted
        stick = simulation and view.joystick_fitted
        for button in (*self.axis_buttons.values(), *self.multiplier_buttons.values()):
            button.setEnabled(wheel)
        for button in self.turn_buttons.values():
            button.setEnabled(wheel)
        self.enable_button.setEnabled(wheel or stick)
        for button in self.stick_buttons.values():
            button.setEnabled(stick)
