"""Touch on every panel: drag-scrolling by finger or by a mouse-type touch controller on
every scrolling area, scroll bars a finger can hold, touch targets of at least 60 px, one key
layout for every keypad, the accents of the sample recipes on the keyboard, readable text
everywhere."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QMetaMethod, QPoint, Qt
from PySide6.QtGui import QFontInfo
from PySide6.QtWidgets import (
    QAbstractButton,
    QAbstractItemView,
    QAbstractScrollArea,
    QAbstractSpinBox,
    QApplication,
    QComboBox,
    QGraphicsView,
    QGridLayout,
    QLabel,
    QLineEdit,
    QListWidget,
    QPushButton,
    QScroller,
    QTableWidget,
    QWidget,
)

from app.machine.commands import InjectFault
from app.screens.main_window import SCREEN_KEYS
from app.screens.theme import TOUCH_PX, scaled_px
from app.screens.widgets.dialogs import ChoiceOverlay, ConfirmOverlay, MessageOverlay
from app.screens.widgets.file_chooser import FileChooser
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.keypad import Keypad
from tests.screens.helpers import find_button, wait_for

MIN_TEXT_PX = 14
MIN_SCROLL_BAR_PX = 40
MIN_TARGET_PX = 60


def visible(root: QWidget, kind: type) -> list:  # type: ignore[type-arg]
    return [w for w in root.findChildren(kind) if w.isVisible()]


def every_view(qtbot, window) -> Iterator[tuple[str, QWidget]]:  # type: ignore[no-untyped-def]
    """Each screen, each page of the System screen, the I/O page and every kind of overlay,
    shown in turn at 1024x768 with the alarm banner up, as ``(name, root to search)``."""
    window.link.send(InjectFault("drive_fault", "X"))
    wait_for(qtbot, window, lambda s: bool(s.alarms))
    window.session.set_user(window.database.authenticate("1234"))  # System unlocked
    for key in (*SCREEN_KEYS, "io"):
        window.show_screen(key)
        QApplication.processEvents()
        yield key, window
    system = window.page("system")
    window.show_screen("system")
    for group, button in system.group_buttons.items():
        button.click()
        QApplication.processEvents()
        yield f"system/{group}", window
    window.show_screen("main")
    overlays = [
        Keypad.for_number("Thickness H", 27, 25, 90, "mm"),
        Keypad.for_fraction("Width ratio", 3, 4, "above 0, below 1", lambda n, d: ""),
        Keypad.for_pin("PIN"),
        TextKeyboard("Name", "Barrique"),
        ChoiceOverlay("Choose", [(f"{n}  Barrique", n) for n in range(12)], columns=2),
        ConfirmOverlay("Delete?", "Delete the recipe?", "Delete"),
        MessageOverlay("Saved", "The recipe is saved."),
        FileChooser("Import", Path(__file__).parent),
    ]
    for overlay in overlays:
        overlay.open_on(window.host)
        QApplication.processEvents()
        yield overlay.objectName(), overlay
        overlay.reject()
    window.session.logout()


def test_every_screen_scrolls_by_dragging_and_reads_at_arms_length(qtbot, window) -> None:
    small: list[str] = []
    for key, root in every_view(qtbot, window):
        for area in visible(root, QAbstractScrollArea):
            if isinstance(area, QGraphicsView):
                continue  # the plan view pans and zooms by itself
            grabbed = QScroller.grabbedGesture(area.viewport())
            assert grabbed != Qt.GestureType(0), f"{key}: {area.objectName()} does not drag"
            bar = area.verticalScrollBar()
            if bar.isVisible():
                assert bar.width() >= MIN_SCROLL_BAR_PX, f"{key}: {area.objectName()}"
        for widget in [*visible(root, QLabel), *visible(root, QAbstractButton)]:
            if not widget.text():
                continue
            size = QFontInfo(widget.font()).pixelSize()
            if size < MIN_TEXT_PX:
                small.append(f"{key}: {widget.objectName()} {widget.text()!r} {size} px")
    assert small == []


def tapped_rows(view: QAbstractItemView) -> bool:
    """Whether tapping a row of ``view`` does something (a read-only log's rows do not)."""
    signal = view.cellClicked if isinstance(view, QTableWidget) else view.itemClicked
    return view.isSignalConnected(QMetaMethod.fromSignal(signal))


def small_targets(root: QWidget) -> list[str]:
    """Visible buttons, inputs and tapped list or table rows less than 60 px high or wide."""
    problems: list[str] = []
    inputs = (QAbstractButton, QLineEdit, QComboBox, QAbstractSpinBox)
    for widget in [w for kind in inputs for w in visible(root, kind)]:
        if min(widget.width(), widget.height()) < MIN_TARGET_PX:
            text = widget.text() if isinstance(widget, QAbstractButton) else ""
            problems.append(
                f"{type(widget).__name__} {widget.objectName()!r} {text!r}: "
                f"{widget.width()}x{widget.height()} px"
            )
    for view in [*visible(root, QListWidget), *visible(root, QTableWidget)]:
        if not tapped_rows(view):
            continue
        if isinstance(view, QTableWidget):
            heights = [view.rowHeight(row) for row in range(view.rowCount())]
            heights.append(view.verticalHeader().defaultSectionSize())
        else:
            heights = [view.visualItemRect(view.item(row)).height() for row in range(view.count())]
        if heights and min(heights) < MIN_TARGET_PX:
            problems.append(f"rows of {view.objectName()!r}: {min(heights)} px")
    return problems


def test_every_touch_target_is_at_least_60_px(qtbot, window) -> None:
    """Buttons, inputs and the rows a finger opens, on every screen and overlay, with the
    alarm banner shown (it is a button too) and rows in the alarm tables."""
    problems: list[str] = []
    for key, root in every_view(qtbot, window):
        problems += [f"{key}: {p}" for p in small_targets(root)]
    assert problems == []


def test_the_target_check_sees_a_small_button_and_short_rows(qtbot) -> None:
    host = QWidget()  # unthemed: the theme would make both big enough
    qtbot.addWidget(host)
    host.show()
    small = QPushButton("OK", host)
    small.setFixedSize(120, 50)
    rows = QListWidget(host)
    rows.setObjectName("rows")
    rows.addItems(["one", "two"])
    rows.itemClicked.connect(lambda _item: None)
    log = QListWidget(host)
    log.addItems(["read only"])  # rows nobody taps are no target
    for widget in (small, rows, log):
        widget.show()
    problems = small_targets(host)
    assert len(problems) == 2
    assert "'OK': 120x50 px" in problems[0] and "rows of 'rows'" in problems[1]


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
        Keypad.for_pin("PIN"),
        Keypad.for_number("Thickness H", 27, 25, 90, "mm"),
        Keypad.for_fraction("Width ratio", 3, 4, "above 0, below 1", lambda n, d: ""),
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
    assert TOUCH_PX >= MIN_TARGET_PX
