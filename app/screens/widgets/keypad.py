"""Touch keypads: numbers (with the allowed range), fractions, and PINs.

Why the keypad validates: a touch panel has no keyboard to correct a typo with, so the keypad
shows the allowed range before anything is typed, marks the display red while the value is
outside it, and refuses OK with a message naming the value and the range. The caller can add a
rule of its own (``check``), for example a recipe's cross-field limits, and the keypad shows
its message the same way. A physical keyboard works too (digits, point, minus, Backspace,
Delete, Enter, Escape), for commissioning with a USB keyboard.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from PySide6.QtCore import Qt, Signal
from PySide6.QtGui import QKeyEvent, QMouseEvent
from PySide6.QtWidgets import QGridLayout, QHBoxLayout, QLabel, QPushButton, QWidget

from app.screens.formatting import format_number
from app.screens.theme import set_style_property
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.overlay import Overlay
from app.screens.widgets.readouts import FixedLinesLabel

NumberCheck = Callable[[float], str]
FractionCheck = Callable[[int, int], str]

MAX_DIGITS = 12
DIGIT_ROWS: tuple[tuple[str, ...], ...] = (("7", "8", "9"), ("4", "5", "6"), ("1", "2", "3"))


def key_button(text: str, kind: str = "key", name: str = "") -> QPushButton:
    """A keypad key: never takes keyboard focus (the overlay keeps it for a USB keyboard)."""
    button = touch_button(name, kind, text)
    button.setAutoDefault(False)
    return button


def _label(text: str, role: str) -> QLabel:
    label = QLabel(text)
    label.setProperty("role", role)
    return label


def error_label() -> QLabel:
    """The red line under an entry that says why OK was refused (empty while all is well);
    its two lines are kept while it is empty, so the keypad does not grow when it speaks."""
    return FixedLinesLabel("error", "errorLabel")


def typing_key(text: str, key: str, press: Callable[[str], None], name: str = "") -> QPushButton:
    """A key that calls ``press(key)`` when tapped (digits, "back", "clear")."""
    button = key_button(text, name=name or f"key_{key}")
    button.clicked.connect(lambda _=False: press(key))
    return button


def digit_keys(
    grid: QGridLayout, rows: tuple[tuple[str, ...], ...], press: Callable[[str], None]
) -> dict[str, QPushButton]:
    """The digit block, ``rows`` from the top, placed in ``grid`` from column 0."""
    keys: dict[str, QPushButton] = {}
    for row, row_keys in enumerate(rows):
        for column, key in enumerate(row_keys):
            keys[key] = typing_key(key, key, press)
            grid.addWidget(keys[key], row, column)
    return keys


def answer_keys(overlay: Overlay, confirm: Callable[[], None]) -> tuple[QPushButton, QPushButton]:
    """Cancel (rejects the overlay) and OK (``confirm``), without texts: the overlay's own
    ``retranslate`` sets them, so they are translated in that overlay's context."""
    cancel = key_button("", "smallkey", name="cancelButton")
    cancel.clicked.connect(overlay.reject)
    ok = key_button("", "primary", name="okButton")
    ok.clicked.connect(confirm)
    return cancel, ok


@dataclass
class KeyBlock:
    """The one key layout of every keypad (PIN, number, fraction), so that a key is always
    in the same place under the finger: digits 7-8-9 / 4-5-6 / 1-2-3 from the top, 0 below
    the 2 with the keypad's own key on each side of it (sign and point, the fraction's
    slash), and down the right ⌫, C, Cancel, OK."""

    grid: QGridLayout
    keys: dict[str, QPushButton]
    backspace_button: QPushButton
    clear_button: QPushButton
    cancel_button: QPushButton
    ok_button: QPushButton


def key_block(
    overlay: Overlay,
    press: Callable[[str], None],
    confirm: Callable[[], None],
    left: QPushButton | None = None,
    right: QPushButton | None = None,
) -> KeyBlock:
    grid = QGridLayout()
    grid.setSpacing(8)
    keys = digit_keys(grid, DIGIT_ROWS, press)
    keys["0"] = typing_key("0", "0", press)
    grid.addWidget(keys["0"], 3, 1)
    for button, column in ((left, 0), (right, 2)):
        if button is not None:
            grid.addWidget(button, 3, column)
    backspace = typing_key("⌫", "back", press, "key_backspace")
    clear = typing_key("C", "clear", press, "key_clear")
    cancel, ok = answer_keys(overlay, confirm)
    for row, button in enumerate((backspace, clear, cancel, ok)):
        grid.addWidget(button, row, 3)
    return KeyBlock(grid, keys, backspace, clear, cancel, ok)


class ClickableLabel(QLabel):
    """A label that reports a tap (the fraction keypad's two displays)."""

    clicked = Signal()

    def __init__(self, text: str, role: str) -> None:
        super().__init__(text)
        self.setProperty("role", role)

    def mousePressEvent(self, event: QMouseEvent) -> None:
        self.clicked.emit()
        event.accept()


def parse_number(text: str) -> float | None:
    """The typed text as a finite number, or None (empty, lone sign or point)."""
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


class NumberKeypad(Overlay):
    """Enter one number between ``minimum`` and ``maximum`` (inclusive).

    ``valueAccepted(float)`` is emitted when OK is pressed on a valid value; with
    ``optional`` an empty entry is allowed too and emits ``cleared()``."""

    valueAccepted = Signal(float)  # noqa: N815 (Qt signal naming)
    cleared = Signal()

    def __init__(
        self,
        title: str,
        value: float | None,
        minimum: float,
        maximum: float,
        unit: str = "",
        *,
        decimals: int = 3,
        integer: bool = False,
        check: NumberCheck | None = None,
        optional: bool = False,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("numberKeypad")
        self.optional = optional
        self.minimum = minimum
        self.maximum = maximum
        self.unit = unit
        self.decimals = 0 if integer else decimals
        self.integer = integer
        self._check = check
        self._fresh = True  # the first key replaces the shown value
        self.text = "" if value is None else format_number(value, self.decimals)

        self.title_label = _label(title, "title")
        self.range_label = _label("", "caption")
        self.range_label.setObjectName("rangeLabel")
        self.display = _label(self.text, "display")
        self.display.setObjectName("display")
        self.display.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        self.display.setMinimumWidth(360)
        self.error_label = error_label()

        sign = typing_key("±", "±", self.press)
        point = typing_key(".", ".", self.press)
        block = key_block(self, self.press, self.confirm, sign, point)
        grid = block.grid
        self.keys = {**block.keys, "±": sign, ".": point}
        self.backspace_button, self.clear_button = block.backspace_button, block.clear_button
        self.cancel_button, self.ok_button = block.cancel_button, block.ok_button
        self.keys["±"].setEnabled(minimum < 0)
        self.keys["."].setEnabled(not integer)

        self.panel_layout.addWidget(self.title_label)
        self.panel_layout.addWidget(self.range_label)
        self.panel_layout.addWidget(self.display)
        self.panel_layout.addWidget(self.error_label)
        self.panel_layout.addLayout(grid)
        self.retranslate()
        self._refresh()

    def retranslate(self) -> None:
        self.cancel_button.setText(self.tr("Cancel"))
        self.ok_button.setText(self.tr("OK"))
        self.range_label.setText(self.allowed_text())

    def allowed_text(self) -> str:
        unit = f" {self.unit}" if self.unit else ""
        low = format_number(self.minimum, max(self.decimals, 6))
        high = format_number(self.maximum, max(self.decimals, 6))
        if self.integer:
            text = self.tr("Allowed: whole number from %1 to %2%3")
        elif self.optional:
            text = self.tr("Allowed: %1 to %2%3, or empty")
        else:
            text = self.tr("Allowed: %1 to %2%3")
        return text.replace("%1", low).replace("%2", high).replace("%3", unit)

    # -- typing --------------------------------------------------------------------------------

    def press(self, key: str) -> None:
        """One key of the keypad: a digit, ".", "±", "back" or "clear"."""
        if key == "clear":
            self.text = ""
        elif key == "back":
            self.text = "" if self._fresh else self.text[:-1]
        elif key == "±":
            if self.minimum < 0:
                self.text = self.text[1:] if self.text.startswith("-") else "-" + self.text
        elif key == ".":
            if not self.integer:
                base = "" if self._fresh else self.text
                if "." not in base:
                    self.text = (base if base not in ("", "-") else base + "0") + "."
        elif key.isdigit():
            base = "" if self._fresh else self.text
            digits = sum(ch.isdigit() for ch in base)
            fraction = base.split(".", 1)[1] if "." in base else None
            if digits >= MAX_DIGITS or (fraction is not None and len(fraction) >= self.decimals):
                return
            self.text = base + key
        else:
            return
        self._fresh = False
        self.error_label.setText("")
        self._refresh()

    def keyPressEvent(self, event: QKeyEvent) -> None:
        key = event.key()
        text = event.text()
        if text and (text.isdigit() or text in ".,"):
            self.press("." if text == "," else text)
        elif text == "-":
            self.press("±")
        elif key == Qt.Key.Key_Backspace:
            self.press("back")
        elif key == Qt.Key.Key_Delete:
            self.press("clear")
        elif key in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
            self.confirm()
        else:
            super().keyPressEvent(event)

    # -- validation -----------------------------------------------------------------------------

    def problem(self) -> str:
        """Why the typed value cannot be accepted, or "" when it can."""
        value = parse_number(self.text)
        if value is None:
            return self.tr("Enter a number. %1").replace("%1", self.allowed_text())
        if value < self.minimum or value > self.maximum:
            unit = f" {self.unit}" if self.unit else ""
            return (
                self.tr("%1%2 is outside the allowed range.")
                .replace("%1", format_number(value, self.decimals))
                .replace("%2", unit)
                + " "
                + self.allowed_text()
            )
        if self._check is not None:
            return self._check(value)
        return ""

    def _refresh(self) -> None:
        self.display.setText(self.text or " ")
        value = parse_number(self.text)
        invalid = value is not None and not self.minimum <= value <= self.maximum
        set_style_property(self.display, "invalid", "true" if invalid else "false")

    def confirm(self) -> None:
        """OK: accept a valid value, or show why not and stay open."""
        if self.optional and not self.text.strip():
            self.cleared.emit()
            self.accept()
            return
        problem = self.problem()
        if problem:
            self.error_label.setText(problem)
            set_style_property(self.display, "invalid", "true")
            return
        value = parse_number(self.text)
        assert value is not None
        self.valueAccepted.emit(float(int(value)) if self.integer else value)
        self.accept()


class FractionKeypad(Overlay):
    """Enter a ratio as numerator / denominator (how coopers give them).

    ``check(numerator, denominator)`` returns "" or why the ratio is not allowed; the decimal
    value is shown live. ``fractionAccepted(int, int)`` is emitted on OK."""

    fractionAccepted = Signal(int, int)  # noqa: N815 (Qt signal naming)

    def __init__(
        self,
        title: str,
        numerator: int,
        denominator: int,
        allowed_text: str,
        check: FractionCheck,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("fractionKeypad")
        self._check = check
        self.parts = [str(numerator), str(denominator)]
        self.active = 0
        self._fresh = [True, True]

        self.title_label = _label(title, "title")
        self.range_label = _label(allowed_text, "caption")
        self.range_label.setObjectName("rangeLabel")
        self.range_label.setWordWrap(True)
        self.numerator_display = ClickableLabel("", "display")
        self.numerator_display.setObjectName("numeratorDisplay")
        self.denominator_display = ClickableLabel("", "display")
        self.denominator_display.setObjectName("denominatorDisplay")
        for index, display in enumerate((self.numerator_display, self.denominator_display)):
            display.setAlignment(Qt.AlignmentFlag.AlignCenter)
            display.setMinimumWidth(140)
            display.clicked.connect(lambda i=index: self.select(i))
        slash = _label("/", "bigvalue")
        self.decimal_label = _label("", "value")
        self.decimal_label.setObjectName("decimalLabel")
        row = QHBoxLayout()
        row.addWidget(self.numerator_display)
        row.addWidget(slash)
        row.addWidget(self.denominator_display)
        row.addWidget(self.decimal_label, 1)
        self.error_label = error_label()

        self.slash_button = key_button("/", name="key_slash")
        self.slash_button.clicked.connect(lambda: self.select(1 - self.active))
        block = key_block(self, self.press, self.confirm, self.slash_button)
        grid = block.grid
        self.keys = block.keys
        self.backspace_button, self.clear_button = block.backspace_button, block.clear_button
        self.cancel_button, self.ok_button = block.cancel_button, block.ok_button

        self.panel_layout.addWidget(self.title_label)
        self.panel_layout.addWidget(self.range_label)
        self.panel_layout.addLayout(row)
        self.panel_layout.addWidget(self.error_label)
        self.panel_layout.addLayout(grid)
        self.retranslate()
        self._refresh()

    def retranslate(self) -> None:
        self.cancel_button.setText(self.tr("Cancel"))
        self.ok_button.setText(self.tr("OK"))

    def select(self, index: int) -> None:
        """Make the numerator (0) or the denominator (1) the part the keys type into."""
        self.active = index
        self._fresh[index] = True
        self._refresh()

    def press(self, key: str) -> None:
        part = self.parts[self.active]
        fresh = self._fresh[self.active]
        if key == "clear":
            part = ""
        elif key == "back":
            part = "" if fresh else part[:-1]
        elif key.isdigit():
            base = "" if fresh else part
            if len(base) >= 6:
                return
            part = (base + key).lstrip("0") or "0"
        else:
            return
        self.parts[self.active] = part
        self._fresh[self.active] = False
        self.error_label.setText("")
        self._refresh()

    def keyPressEvent(self, event: QKeyEvent) -> None:
        text = event.text()
        key = event.key()
        if text and text.isdigit():
            self.press(text)
        elif text in ("/", ":") or key == Qt.Key.Key_Tab:
            self.select(1 - self.active)
        elif key == Qt.Key.Key_Backspace:
            self.press("back")
        elif key == Qt.Key.Key_Delete:
            self.press("clear")
        elif key in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
            self.confirm()
        else:
            super().keyPressEvent(event)

    def values(self) -> tuple[int, int] | None:
        if not self.parts[0] or not self.parts[1]:
            return None
        return int(self.parts[0]), int(self.parts[1])

    def problem(self) -> str:
        values = self.values()
        if values is None:
            return self.tr("Enter both the numerator and the denominator.")
        if values[1] == 0:
            return self.tr("The denominator must not be 0.")
        return self._check(*values)

    def _refresh(self) -> None:
        self.numerator_display.setText(self.parts[0] or " ")
        self.denominator_display.setText(self.parts[1] or " ")
        set_style_property(self.numerator_display, "active", str(self.active == 0).lower())
        set_style_property(self.denominator_display, "active", str(self.active == 1).lower())
        values = self.values()
        if values is not None and values[1] != 0:
            self.decimal_label.setText(f"= {values[0] / values[1]:.4f}")
        else:
            self.decimal_label.setText("= ?")
        invalid = "true" if values is not None and self.problem() else "false"
        set_style_property(self.numerator_display, "invalid", invalid)
        set_style_property(self.denominator_display, "invalid", invalid)

    def confirm(self) -> None:
        problem = self.problem()
        if problem:
            self.error_label.setText(problem)
            return
        values = self.values()
        assert values is not None
        self.fractionAccepted.emit(values[0], values[1])
        self.accept()


class PinPad(Overlay):
    """Enter a PIN (digits shown as dots). ``pinEntered(str)`` is emitted on OK."""

    pinEntered = Signal(str)  # noqa: N815 (Qt signal naming)

    def __init__(self, title: str, max_digits: int = 8, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("pinPad")
        self.max_digits = max_digits
        self.pin = ""
        self.title_label = _label(title, "title")
        self.display = _label(" ", "display")
        self.display.setObjectName("display")
        self.display.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.display.setMinimumWidth(320)
        self.error_label = error_label()
        block = key_block(self, self.press, self.confirm)
        grid = block.grid
        self.keys = block.keys
        self.backspace_button = block.backspace_button
        self.cancel_button, self.ok_button = block.cancel_button, block.ok_button
        self.panel_layout.addWidget(self.title_label)
        self.panel_layout.addWidget(self.display)
        self.panel_layout.addWidget(self.error_label)
        self.panel_layout.addLayout(grid)
        self.retranslate()

    def retranslate(self) -> None:
        self.cancel_button.setText(self.tr("Cancel"))
        self.ok_button.setText(self.tr("OK"))

    def press(self, key: str) -> None:
        if key == "clear":
            self.pin = ""
        elif key == "back":
            self.pin = self.pin[:-1]
        elif key.isdigit() and len(self.pin) < self.max_digits:
            self.pin += key
        self.error_label.setText("")
        self.display.setText("●" * len(self.pin) or " ")

    def keyPressEvent(self, event: QKeyEvent) -> None:
        text = event.text()
        key = event.key()
        if text and text.isdigit():
            self.press(text)
        elif key == Qt.Key.Key_Backspace:
            self.press("back")
        elif key in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
            self.confirm()
        else:
            super().keyPressEvent(event)

    def set_busy(self, busy: bool, text: str = "") -> None:
        """While the PIN is being checked: keys off, a word on what is happening."""
        for button in (*self.keys.values(), self.ok_button, self.backspace_button):
            button.setEnabled(not busy)
        self.error_label.setText(text if busy else "")

    def show_error(self, message: str) -> None:
        """The caller refused the PIN: say why, clear it, stay open."""
        self.pin = ""
        self.display.setText(" ")
        self.error_label.setText(message)

    def confirm(self) -> None:
        if not self.pin:
            self.error_label.setText(self.tr("Enter your PIN."))
            return
        self.pinEntered.emit(self.pin)
