"""Touch on every panel: drag-scrolling by finger or by a mouse-type touch controller on
every scrolling area, scroll bars a finger can hold, one key layout for every keypad, the
accents of the sample recipes on the keyboard, readable text everywhere."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtGui import QFontInfo
from PySide6.QtWidgets import (
    QAbstractButton,
    QAbstractScrollArea,
    QApplication,
    QGraphicsView,
    QGridLayout,
    QLabel,
    QScroller,
    QWidget,
)

from app.screens.main_window import SCREEN_KEYS
from app.screens.theme import scaled_px
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.keypad import FractionKeypad, NumberKeypad, PinPad
from tests.screens.helpers import find_button

MIN_TEXT_PX = 14
MIN_SCROLL_BAR_PX = 40


def visible(root: QWidget, kind: type) -> list:  # type: ignore[type-arg]
    return [w for w in root.findChildren(kind) if w.isVisible()]


def test_every_screen_scrolls_by_dragging_and_reads_at_arms_length(qtbot, window) -> None:
    window.session.set_user(window.database.authenticate("1234"))  # System unlocked
    small: list[str] = []
    for key in SCREEN_KEYS:
        window.show_screen(key)
        QApplication.processEvents()
        for area in visible(window, QAbstractScrollArea):
            if isinstance(area, QGraphicsView):
                continue  # the plan view pans and zooms by itself
            grabbed = QScroller.grabbedGesture(area.viewport())
            assert grabbed != Qt.GestureType(0), f"{key}: {area.objectName()} does not drag"
            bar = area.verticalScrollBar()
            if bar.isVisible():
                assert bar.width() >= MIN_SCROLL_BAR_PX, f"{key}: {area.objectName()}"
        for widget in [*visible(window, QLabel), *visible(window, QAbstractButton)]:
            if not widget.text():
                continue
            size = QFontInfo(widget.font()).pixelSize()
            if size < MIN_TEXT_PX:
                small.append(f"{key}: {widget.objectName()} {widget.text()!r} {size} px")
    window.session.logout()
    assert small == []


def test_a_mouse_drag_scrolls_a_list(qtbot, window) -> None:
    """A resistive panel reports a finger as a mouse: dragging the alarm history scrolls."""
    window.show_screen("alarms")
    table = window.page("alarms").history_table
    table.setRowCount(200)
    QApplication.processEvents()
    viewport = table.viewport()
    start = QPoint(viewport.width() // 2, viewport.height() - 10)
    qtbot.mousePress(viewport, Qt.MouseButton.LeftButton, pos=start)
    for step in range(1, 11):
        qtbot.mouseMove(viewport, start - QPoint(0, 20 * step))
        qtbot.wait(10)
    qtbot.mouseRelease(viewport, Qt.MouseButton.LeftButton, pos=start - QPoint(0, 200))
    qtbot.waitUntil(lambda: table.verticalScrollBar().value() > 0, timeout=3000)


def positions(pad) -> dict[str, tuple[int, int]]:  # type: ignore[no-untyped-def]
    grid = next(g for g in pad.panel.findChildren(QGridLayout) if g.indexOf(pad.keys["1"]) >= 0)
    found: dict[str, tuple[int, int]] = {}
    for name in ("1", "5", "9", "0", "key_backspace", "cancelButton", "okButton"):
        button = pad.keys.get(name) or find_button(pad, name)
        row, column, _rows, _columns = grid.getItemPosition(grid.indexOf(button))
        found[name] = (row, column)
    return found


def test_pin_number_and_fraction_keys_are_in_the_same_places(qtbot, host) -> None:
    pads = [
        PinPad("PIN"),
        NumberKeypad("Thickness H", 27, 25, 90, "mm"),
        FractionKeypad("Width ratio", 3, 4, "above 0, below 1", lambda n, d: ""),
    ]
    layouts = [positions(pad) for pad in pads]
    assert layouts[0] == layouts[1] == layouts[2]


@pytest.mark.parametrize("layout", ["qwerty", "qwertz"])
def test_the_keyboard_types_the_sample_recipes_and_the_slovenian_letters(
    qtbot, host, tap, layout: str
) -> None:
    keyboard = TextKeyboard("Name", layout=layout)
    keyboard.open_on(host)
    for char in "čšž":
        tap(find_button(keyboard, f"key_{char}"))
    tap(find_button(keyboard, "key_space"))
    for char in "Pi":
        if char.isupper():
            tap(find_button(keyboard, "key_shift"))
        tap(find_button(keyboard, f"key_{char.lower()}"))
    tap(find_button(keyboard, "key_accent"))  # grave: è
    assert find_button(keyboard, "key_e").text() == "è"
    tap(find_button(keyboard, "key_e"))
    assert find_button(keyboard, "key_e").text() == "e"  # one accented letter, then plain
    for char in "ce":
        tap(find_button(keyboard, f"key_{char}"))
    assert keyboard.text == "čšž Pièce"
    keyboard.reject()


def test_scroll_bars_are_wide_enough_for_a_finger() -> None:
    assert scaled_px("scroll_w", 1.0) >= MIN_SCROLL_BAR_PX
