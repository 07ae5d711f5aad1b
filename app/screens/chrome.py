"""The frame around every screen: the status line on top, the alarm banner, the navigation.

Why always visible: the state of the machine, the newest alarm and the way to the other
screens must be readable from any screen at arm's length (the most asked-for thing on CNC
touch panels is "a readable status line").
"""

from __future__ import annotations

from PySide6.QtCore import QDateTime, Qt, Signal
from PySide6.QtWidgets import QButtonGroup, QFrame, QHBoxLayout, QPushButton, QSizePolicy, QWidget

from app.machine.snapshot import AlarmState, MachineSnapshot
from app.screens.texts import alarm_line, state_text
from app.screens.theme import set_style_property
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.lamp import StatusLamp, lamp_color
from app.screens.widgets.readouts import ElidedLinesLabel, set_text, styled_label


class TopBar(QFrame):
    """Lamp, state in words, the newest message, user level, language and clock."""

    userClicked = Signal()  # noqa: N815 (Qt signal naming)
    languageClicked = Signal()  # noqa: N815 (Qt signal naming)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("topBar")
        self.lamp = StatusLamp(40)
        self.lamp.setObjectName("statusLamp")
        self.state_label = styled_label("", "state", "stateLabel")
        self.state_label.setMinimumWidth(170)
        # Two lines at most, then an ellipsis: a long message never makes the top bar taller
        # (that pushed every screen, and its buttons, down).
        self.message_label = ElidedLinesLabel("message", "messageLabel")
        self.message_label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Fixed)
        self.user_button = touch_button("userButton", "bar")
        self.user_button.clicked.connect(self.userClicked)
        self.language_button = touch_button("languageButton", "bar")
        self.language_button.clicked.connect(self.languageClicked)
        self.clock_label = styled_label("", "value", "clockLabel")
        layout = QHBoxLayout(self)
        # 2 px above and below: the buttons are finger-sized (theme.TOUCH_PX) and the bar
        # stays as high as it was with smaller ones, so the screens below keep their room.
        layout.setContentsMargins(10, 2, 10, 2)
        layout.setSpacing(12)
        layout.addWidget(self.lamp)
        layout.addWidget(self.state_label)
        layout.addWidget(self.message_label, 1)
        layout.addWidget(self.user_button)
        layout.addWidget(self.language_button)
        layout.addWidget(self.clock_label)
        self.tick_clock()

    def show_snapshot(self, snapshot: MachineSnapshot | None, message: str) -> None:
        state = snapshot.state if snapshot is not None else None
        self.lamp.set_color(lamp_color(state))
        set_text(self.state_label, state_text(state))
        set_text(self.message_label, message)

    def show_user(self, text: str) -> None:
        set_text(self.user_button, text)

    def show_language(self, code: str) -> None:
        set_text(self.language_button, code.upper())

    def tick_clock(self) -> None:
        set_text(self.clock_label, QDateTime.currentDateTime().toString("HH:mm"))


class AlarmBanner(QPushButton):
    """The newest alarm across the window; hidden when there is none. Tapping it opens the
    Alarms screen."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("alarmBanner")
        self.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.setVisible(False)
        self._key: tuple[object, ...] = ()

    def show_alarms(
        self, snapshot: MachineSnapshot | None, more_text: str, force: bool = False
    ) -> None:
        alarms = snapshot.alarms if snapshot is not None else ()
        key = tuple((a.alarm_id, a.state, a.text) for a in alarms)
        if key == self._key and not force:
            return
        self._key = key
        if not alarms:
            self.setVisible(False)
            return
        newest = alarms[0]
        unacked = any(
            a.state in (AlarmState.ACTIVE_UNACKED, AlarmState.RTN_UNACKED) for a in alarms
        )
        if not unacked:
            severity = "acked"
        else:
            severity = "warning" if newest.severity == "warning" else "fault"
        set_style_property(self, "severity", severity)
        text = f"⚠  {newest.code}  {alarm_line(newest)}"
        if len(alarms) > 1:
            text += "   " + more_text.replace("%1", str(len(alarms) - 1))
        self.setText(text)
        self.setVisible(True)


class NavBar(QFrame):
    """The screen buttons and Shut down. ``navigate(str)`` carries the screen key."""

    navigate = Signal(str)
    shutdownClicked = Signal()  # noqa: N815 (Qt signal naming)

    def __init__(self, keys: tuple[str, ...], parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("navBar")
        self.buttons: dict[str, QPushButton] = {}
        self.group = QButtonGroup(self)
        self.group.setExclusive(True)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(8, 4, 8, 4)
        layout.setSpacing(8)
        for key in keys:
            button = touch_button(f"nav_{key}", "nav")
            button.setCheckable(True)
            button.clicked.connect(lambda _=False, k=key: self.navigate.emit(k))
            self.group.addButton(button)
            self.buttons[key] = button
            layout.addWidget(button, 1)
        self.shutdown_button = touch_button("nav_shutdown", "danger")
        self.shutdown_button.clicked.connect(self.shutdownClicked)
        layout.addSpacing(12)
        layout.addWidget(self.shutdown_button, 1)

    def set_current(self, key: str) -> None:
        """Mark the button of screen ``key``; none for a screen reached from another one
        (the I/O page), so no button claims a screen it does not show."""
        button = self.buttons.get(key)
        if button is None:
            self.group.setExclusive(False)
            for other in self.buttons.values():
                other.setChecked(False)
            self.group.setExclusive(True)
        elif not button.isChecked():
            button.setChecked(True)
