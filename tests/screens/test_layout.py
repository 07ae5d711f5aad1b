"""Nothing is cut off: every screen fits 1024x768 with the alarm banner shown, in English and
Slovenian, and no button or single-line label shows less than its whole text."""

from __future__ import annotations

from dataclasses import replace

import pytest
from PySide6.QtCore import QSize
from PySide6.QtWidgets import QApplication, QLabel, QPushButton, QSizePolicy, QWidget

from app.machine.commands import InjectFault, SelectRecipe
from app.screens.main_window import SCREEN_KEYS
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.keypad import Keypad
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
        Keypad.for_number("Thickness H", 27, 25, 90, "mm"),
        Keypad.for_fraction("Width ratio W1 : W", 3, 4, "above 0, below 1", lambda n, d: ""),
        Keypad.for_pin("Log in: enter your PIN"),
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


PRIMARY_BUTTONS = ("startButton", "stopButton", "homeButton", "resetButton")


def primary_geometry(window) -> dict[str, tuple[int, int, int, int]]:  # type: ignore[no-untyped-def]
    QApplication.processEvents()
    found: dict[str, tuple[int, int, int, int]] = {}
    for name in PRIMARY_BUTTONS:
        button = window.findChild(QPushButton, name)
        corner = button.mapTo(window, button.rect().topLeft())
        found[name] = (corner.x(), corner.y(), button.width(), button.height())
    return found


def test_start_stop_home_reset_never_move(qtbot, window, machine, database) -> None:
    """The banner appearing and a recipe name of many lines leave the four primary buttons
    exactly where they were (they moved by up to 74 px, so a tap meant for Home hit Reset)."""
    window.show_screen("main")
    recipe = database.list_recipes()[0]
    machine.send(SelectRecipe(recipe.id))
    wait_for(qtbot, window, lambda s: s.recipe_id == recipe.id)
    before = primary_geometry(window)
    long_name = "Pièce 228 l Bourgogne, chêne de Tronçais"  # 40 characters, the most allowed
    operator = database.list_users()[0]
    long_recipe = database.save_recipe(replace(recipe, id=None, name=long_name), operator)
    window.page("main").reload_recipes()
    machine.send(SelectRecipe(long_recipe.id))
    wait_for(qtbot, window, lambda s: s.recipe_id == long_recipe.id)
    assert window.page("main").name_label.text() == long_recipe.name
    assert primary_geometry(window) == before
    machine.send(InjectFault("drive_fault", "X"))
    wait_for(qtbot, window, lambda s: bool(s.alarms))
    assert window.banner.isVisible()
    assert primary_geometry(window) == before


def test_a_keypad_keeps_its_size_when_it_shows_an_error(qtbot, host) -> None:
    pad = Keypad.for_number("Thickness H", 27, 25, 90, "mm")
    pad.open_on(host)
    QApplication.processEvents()
    size = pad.panel.size()
    pad.error_label.setText("120 is out of range: allowed 25 to 90 mm " * 3)
    QApplication.processEvents()
    assert pad.panel.size() == size
    pad.reject()
