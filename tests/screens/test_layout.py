"""Nothing is cut off: every screen fits 1024x768 with the alarm banner shown, in English and
Slovenian, and no button or single-line label shows less than its whole text."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QSize
from PySide6.QtWidgets import QApplication, QLabel, QPushButton, QSizePolicy, QWidget

from app.machine.commands import InjectFault
from app.screens.main_window import SCREEN_KEYS
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.keypad import FractionKeypad, NumberKeypad, PinPad
from tests.screens.helpers import wait_for


def cut_texts(root: QWidget) -> list[str]:
    """Visible buttons and one-line labels narrower than their text needs."""
    problems: list[str] = []
    for button in root.findChildren(QPushButton):
        if not button.isVisible() or not button.text():
            continue
        if button.sizePolicy().horizontalPolicy() is QSizePolicy.Policy.Ignored:
            continue  # values that may be long (names, notes) are cut on purpose
        if button.sizeHint().width() > button.width() + 1:
            problems.append(
                f"button {button.objectName()!r} {button.text()!r}: "
                f"needs {button.sizeHint().width()} px, has {button.width()}"
            )
    for label in root.findChildren(QLabel):
        if not label.isVisible() or not label.text() or label.wordWrap():
            continue
        if label.sizePolicy().horizontalPolicy() is QSizePolicy.Policy.Ignored:
            continue
        if label.sizeHint().width() > label.width() + 1:
            problems.append(
                f"label {label.objectName()!r} {label.text()!r}: "
                f"needs {label.sizeHint().width()} px, has {label.width()}"
            )
    return problems


@pytest.mark.parametrize("language", ["en", "sl"])
def test_every_screen_fits_1024x768_without_cutting_text(qtbot, window, machine, language) -> None:
    window.languages.set_language(language)
    machine.send(InjectFault("drive_fault", "X"))
    wait_for(qtbot, window, lambda s: bool(s.alarms))
    assert window.banner.isVisible()
    window.session.set_user(window.database.authenticate("1234"))  # System unlocked
    problems: list[str] = []
    for key in SCREEN_KEYS:
        window.show_screen(key)
        QApplication.processEvents()
        assert window.size() == QSize(1024, 768), f"{key} made the window grow"
        problems += [f"{key}: {p}" for p in cut_texts(window)]
    overlays = [
        NumberKeypad("Thickness H", 27, 25, 90, "mm"),
        FractionKeypad("Width ratio W1 : W", 3, 4, "above 0, below 1", lambda n, d: ""),
        PinPad("Log in: enter your PIN"),
        TextKeyboard("Name", "Barrique", layout="qwertz" if language == "sl" else "qwerty"),
    ]
    for overlay in overlays:
        overlay.open_on(window.host)
        QApplication.processEvents()
        problems += [f"{overlay.objectName()}: {p}" for p in cut_texts(overlay)]
        overlay.reject()
    window.session.logout()
    assert problems == []


def test_the_check_sees_a_cut_button_and_label(qtbot, host) -> None:
    narrow = QPushButton("Referenciraj vse osi", host)
    narrow.setFixedWidth(80)
    label = QLabel("Razmerje dolžin L1 : L", host)
    label.setFixedWidth(40)
    wide = QPushButton("OK", host)
    wide.setFixedWidth(200)
    for widget in (narrow, label, wide):
        widget.show()
    problems = cut_texts(host)
    assert len(problems) == 2
    assert "Referenciraj" in problems[0] and "Razmerje" in problems[1]
