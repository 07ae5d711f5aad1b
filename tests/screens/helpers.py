"""Helpers the screen tests share: tap a button, find one, wait for the machine."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton, QWidget

from app.machine.snapshot import MachineSnapshot
from app.machine.states import MachineState
from app.screens.main_window import MainWindow
from app.screens.widgets.keypad import Keypad, KeypadMode

WAIT_MS = 60_000


def click(qtbot, button: QPushButton) -> None:
    """Tap a button as a finger would (press and release inside it)."""
    assert button.isVisible(), f"{button.objectName()} is not visible"
    assert button.isEnabled(), f"{button.objectName()} is disabled: {button.toolTip()}"
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def find_button(parent: QWidget, name: str) -> QPushButton:
    button = parent.findChild(QPushButton, name)
    assert button is not None, f"no button {name!r}"
    return button


def is_keypad(widget: object, mode: KeypadMode) -> bool:
    """Whether ``widget`` is the keypad, open for ``mode`` (a PIN, a number, a fraction)."""
    return isinstance(widget, Keypad) and widget.mode is mode


def wait_for(
    qtbot, window: MainWindow, done: Callable[[MachineSnapshot], bool], timeout_ms: int = WAIT_MS
) -> MachineSnapshot:
    """Let the screen poll the machine until ``done`` holds for its snapshot."""
    qtbot.waitUntil(
        lambda: window.poller.snapshot is not None and done(window.poller.snapshot),
        timeout=timeout_ms,
    )
    snapshot = window.poller.snapshot
    assert snapshot is not None
    return snapshot


def home_from_main_screen(qtbot, window: MainWindow, tap) -> MachineSnapshot:
    """Press Home on the main screen if the axes are not homed, and wait until ready."""
    snapshot = window.poller.snapshot
    assert snapshot is not None
    if not snapshot.all_homed:
        window.show_screen("main")
        home = find_button(window, "homeButton")
        wait_for(qtbot, window, lambda s: not s.allowed.get("Home"))
        tap(home)
        snapshot = wait_for(qtbot, window, lambda s: s.state is MachineState.READY and s.all_homed)
    return snapshot


def enter_pin(qtbot, window: MainWindow, tap, pin: str) -> None:
    """Type a PIN on the open PIN pad, press OK and wait for the check (a worker thread)."""
    pad = window.overlay()
    assert pad is not None and pad.objectName() == "pinPad"
    for key in pin:
        tap(find_button(pad, f"key_{key}"))
    tap(find_button(pad, "okButton"))
    qtbot.waitUntil(lambda: not window.pin_checker.busy, timeout=10_000)


def open_pin_pad(qtbot, window: MainWindow, tap) -> None:
    """At operator level the user button offers a PIN login or naming the operator: the
    PIN pad."""
    tap(window.top_bar.user_button)
    choice = window.overlay()
    assert choice is not None and choice.objectName() == "choiceOverlay"
    tap(find_button(choice, "choice_0"))  # Log in with a PIN
