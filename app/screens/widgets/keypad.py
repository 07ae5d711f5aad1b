"""The touch keypad: numbers (with the allowed range), fractions, and PINs, one key layout.

Why the keypad validates: a touch panel has no keyboard to correct a typo with, so the keypad
shows the allowed range before anything is typed, marks the display red while the value is
outside it, and refuses OK with a message naming the value and the range. The caller can add a
rule of its own (``check``), for example a recipe's cross-field limits, and the keypad shows
its message the same way. A physical keyboard works too (digits, point, minus, Backspace,
Delete, Enter, Escape), for commissioning with a USB keyboard.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable

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


class KeypadMode(enum.Enum):
    """What the keypad enters; each mode shows its own display above the one key block."""

    PIN = "pin"  # digits shown as dots
    NUMBER = "number"  # one number in a range
    FRACTION = "fraction"  # numerator / denominator


# The keys left and right of the 0 in each mode (None: an empty place).
SIDE_KEYS: dict[KeypadMode, tuple[tuple[str, str] | None, tuple[str, str] | None]] = {
    KeypadMode.PIN: (None, None),
    KeypadMode.NUMBER: (("±", "key_±"), (".", "key_.")),
    KeypadMode.FRACTION: (("/", "key_slash"), None),
}


class ClickableLabel(QLabel):
    """A label that reports a tap (the fraction's two displays)."""

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


class Keypad(Overlay):
    """The one touch keypad: a PIN, a number in a range, or a fraction (``KeypadMode``).

    Why one widget: the finger finds every key in the same place whatever is entered, and
    the key block, the error line and the keyboard handling exist once. The key block:
    digits 7-8-9 / 4-5-6 / 1-2-3 from the top, 0 below the 2 with the mode's own keys on
    each side of it (sign and point, the fraction's slash), and down the right ⌫, C, Cancel,
    OK. Open one with :meth:`for_number`, :meth:`for_fraction` or :meth:`for_pin`.

    Signals, by mode: ``valueAccepted(float)`` (and ``cleared()`` for an optional number
    emptied), ``fractionAccepted(int, int)``, ``pinEntered(str)`` (the caller checks the PIN
    and answers with :meth:`show_error` or ``accept()``)."""

    valueAccepted = Signal(float)  # noqa: N815 (Qt signal naming)
    cleared = Signal()
    fractionAccepted = Signal(int, int)  # noqa: N815 (Qt signal naming)
    pinEntered = Signal(str)  # noqa: N815 (Qt signal naming)

    # The mode's display, made by its constructor: the typed number or the PIN's dots ...
    display: QLabel
    # ... or a fraction's two parts (tap one to type into it) and its decimal value.
    numerator_display: ClickableLabel
    denominator_display: ClickableLabel
    decimal_label: QLabel

    def __init__(self, mode: KeypadMode, title: str, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.mode = mode
        self.setObjectName(OBJECT_NAMES[mode])
        self.title_label = _label(title, "title")
        self.range_label = _label("", "caption")
        self.range_label.setObjectName("rangeLabel")
        self.error_label = error_label()
        self.grid = QGridLayout()
        self.grid.setSpacing(8)
        self.keys = digit_keys(self.grid, DIGIT_ROWS, self.press)
        self.keys["0"] = typing_key("0", "0", self.press)
        self.grid.addWidget(self.keys["0"], 3, 1)
        for side, column in zip(SIDE_KEYS[mode], (0, 2), strict=True):
            if side is not None:
                key, name = side
                self.keys[key] = typing_key(key, key, self.press, name)
                self.grid.addWidget(self.keys[key], 3, column)
        self.backspace_button = typing_key("⌫", "back", self.press, "key_backspace")
        self.clear_button = typing_key("C", "clear", self.press, "key_clear")
        self.cancel_button, self.ok_button = answer_keys(self, self.confirm)
        for row, button in enumerate(
            (self.backspace_button, self.clear_button, self.cancel_button, self.ok_button)
        ):
            self.grid.addWidget(button, row, 3)
        # Every mode's state, so no attribute is missing in any mode.
        self.text = ""  # a number as typed
        self.pin = ""
        self.parts = ["", ""]  # a fraction's numerator and denominator as typed
        self.active = 0  # the fraction's part the keys type into
        self._fresh = [True, True]  # the first key replaces the shown value (per part)
        self.minimum = self.maximum = 0.0
        self.unit = ""
        self.decimals = 0
        self.integer = self.optional = False
        self._number_check: NumberCheck | None = None
        self._fraction_check: FractionCheck | None = None
        self.max_digits = 0

    # -- the three modes ----------------------------------------------------------------------

    @classmethod
    def for_number(
        cls,
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
    ) -> Keypad:
        """Enter one number between ``minimum`` and ``maximum`` (inclusive); ``check`` is
        the caller's own rule ("" or why not); ``optional`` allows an empty entry."""
        pad = cls(KeypadMode.NUMBER, title, parent)
        pad.optional = optional
        pad.minimum, pad.maximum = minimum, maximum
        pad.unit = unit
        pad.decimals = 0 if integer else decimals
        pad.integer = integer
        pad._number_check = check
        pad.text = "" if value is None else format_number(value, pad.decimals)
        pad.display = _label(pad.text, "display")
        pad.display.setObjectName("display")
        pad.display.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        pad.display.setMinimumWidth(360)
        pad.keys["±"].setEnabled(minimum < 0)
        pad.keys["."].setEnabled(not integer)
        pad._lay_out(pad.title_label, pad.range_label, pad.display)
        return pad

    @classmethod
    def for_fraction(
        cls,
        title: str,
        numerator: int,
        denominator: int,
        allowed_text: str,
        check: FractionCheck,
        parent: QWidget | None = None,
    ) -> Keypad:
        """Enter a ratio as numerator / denominator (how coopers give them); ``check`` returns
        "" or why the ratio is not allowed; the decimal value is shown live."""
        pad = cls(KeypadMode.FRACTION, title, parent)
        pad._fraction_check = check
        pad.parts = [str(numerator), str(denominator)]
        pad.range_label.setText(allowed_text)
        pad.range_label.setWordWrap(True)
        pad.numerator_display = ClickableLabel("", "display")
        pad.numerator_display.setObjectName("numeratorDisplay")
        pad.denominator_display = ClickableLabel("", "display")
        pad.denominator_display.setObjectName("denominatorDisplay")
        for index, display in enumerate((pad.numerator_display, pad.denominator_display)):
            display.setAlignment(Qt.AlignmentFlag.AlignCenter)
            display.setMinimumWidth(140)
            display.clicked.connect(lambda i=index: pad.select(i))
        pad.decimal_label = _label("", "value")
        pad.decimal_label.setObjectName("decimalLabel")
        row = QHBoxLayout()
        row.addWidget(pad.numerator_display)
        row.addWidget(_label("/", "bigvalue"))
        row.addWidget(pad.denominator_display)
        row.addWidget(pad.decimal_label, 1)
        pad._lay_out(pad.title_label, pad.range_label, row)
        return pad

    @classmethod
    def for_pin(cls, title: str, max_digits: int = 8, parent: QWidget | None = None) -> Keypad:
        """Enter a PIN, shown as dots."""
        pad = cls(KeypadMode.PIN, title, parent)
        pad.max_digits = max_digits
        pad.display = _label(" ", "display")
        pad.display.setObjectName("display")
        pad.display.setAlignment(Qt.AlignmentFlag.AlignCenter)
        pad.display.setMinimumWidth(320)
        pad._lay_out(pad.title_label, pad.display)
        return pad

    def _lay_out(self, *parts: QWidget | QHBoxLayout) -> None:
        """The mode's display above the error line and the key block."""
        if self.range_label not in parts:  # a PIN has no range
            self.range_label.setParent(self.panel)
            self.range_label.hide()
        for part in parts:
            if isinstance(part, QHBoxLayout):
                self.panel_layout.addLayout(part)
            else:
                self.panel_layout.addWidget(part)
        self.panel_layout.addWidget(self.error_label)
        self.panel_layout.addLayout(self.grid)
        self.retranslate()
        self._refresh()

    def retranslate(self) -> None:
        self.cancel_button.setText(self.tr("Cancel"))
        self.ok_button.setText(self.tr("OK"))
        if self.mode is KeypadMode.NUMBER:
            self.range_label.setText(self.allowed_text())

    def allowed_text(self) -> str:
        """A number's allowed range in words."""
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
        """One key: a digit, "back", "clear", or the mode's own ("±", ".", "/")."""
        if self.mode is KeypadMode.PIN:
            self._press_pin(key)
        elif self.mode is KeypadMode.NUMBER:
            self._press_number(key)
        else:
            self._press_fraction(key)

    def _press_pin(self, key: str) -> None:
        if key == "clear":
            self.pin = ""
        elif key == "back":
            self.pin = self.pin[:-1]
        elif key.isdigit() and len(self.pin) < self.max_digits:
            self.pin += key
        self.error_label.setText("")
        self._refresh()

    def _press_number(self, key: str) -> None:
        fresh = self._fresh[0]
        if key == "clear":
            self.text = ""
        elif key == "back":
            self.text = "" if fresh else self.text[:-1]
        elif key == "±":
            if self.minimum < 0:
                self.text = self.text[1:] if self.text.startswith("-") else "-" + self.text
        elif key == ".":
            if not self.integer:
                base = "" if fresh else self.text
                if "." not in base:
                    self.text = (base if base not in ("", "-") else base + "0") + "."
        elif key.isdigit():
            base = "" if fresh else self.text
            digits = sum(ch.isdigit() for ch in base)
            fraction = base.split(".", 1)[1] if "." in base else None
            if digits >= MAX_DIGITS or (fraction is not None and len(fraction) >= self.decimals):
                return
            self.text = base + key
        else:
            return
        self._fresh[0] = False
        self.error_label.setText("")
        self._refresh()

    def _press_fraction(self, key: str) -> None:
        if key == "/":
            self.select(1 - self.active)
            return
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

    def select(self, index: int) -> None:
        """A fraction: make the numerator (0) or the denominator (1) the part typed into."""
        self.active = index
        self._fresh[index] = True
        self._refresh()

    def keyPressEvent(self, event: QKeyEvent) -> None:
        """A USB keyboard: digits, Backspace, Enter everywhere; Delete clears a number or a
        fraction; point or comma and minus for a number; slash, colon or Tab switch a
        fraction's part."""
        text = event.text()
        key = event.key()
        number = self.mode is KeypadMode.NUMBER
        fraction = self.mode is KeypadMode.FRACTION
        if text and text.isdigit():
            self.press(text)
        elif number and text in (".", ","):
            self.press(".")
        elif number and text == "-":
            self.press("±")
        elif fraction and (text in ("/", ":") or key == Qt.Key.Key_Tab):
            self.press("/")
        elif key == Qt.Key.Key_Backspace:
            self.press("back")
        elif key == Qt.Key.Key_Delete and (number or fraction):
            self.press("clear")
        elif key in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
            self.confirm()
        else:
            super().keyPressEvent(event)

    # -- validation -----------------------------------------------------------------------------

    def values(self) -> tuple[int, int] | None:
        """A fraction's numerator and denominator, or None while one is empty."""
        if not self.parts[0] or not self.parts[1]:
            return None
        return int(self.parts[0]), int(self.parts[1])

    def problem(self) -> str:
        """Why the typed number or fraction cannot be accepted, or "" when it can."""
        if self.mode is KeypadMode.FRACTION:
            return self._fraction_problem()
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
        if self._number_check is not None:
            return self._number_check(value)
        return ""

    def _fraction_problem(self) -> str:
        values = self.values()
        if values is None:
            return self.tr("Enter both the numerator and the denominator.")
        if values[1] == 0:
            return self.tr("The denominator must not be 0.")
        assert self._fraction_check is not None
        return self._fraction_check(*values)

    def _refresh(self) -> None:
        if self.mode is KeypadMode.PIN:
            self.display.setText("●" * len(self.pin) or " ")
        elif self.mode is KeypadMode.NUMBER:
            self.display.setText(self.text or " ")
            value = parse_number(self.text)
            invalid = value is not None and not self.minimum <= value <= self.maximum
            set_style_property(self.display, "invalid", "true" if invalid else "false")
        else:
            self._refresh_fraction()

    def _refresh_fraction(self) -> None:
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
        """OK: accept a valid entry (emit the mode's signal), or show why not and stay open."""
        if self.mode is KeypadMode.PIN:
            if not self.pin:
                self.error_label.setText(self.tr("Enter your PIN."))
                return
            self.pinEntered.emit(self.pin)
            return
        if self.mode is KeypadMode.NUMBER and self.optional and not self.text.strip():
            self.cleared.emit()
            self.accept()
            return
        problem = self.problem()
        if problem:
            self.error_label.setText(problem)
            if self.mode is KeypadMode.NUMBER:
                set_style_property(self.display, "invalid", "true")
            return
        if self.mode is KeypadMode.FRACTION:
            values = self.values()
            assert values is not None
            self.fractionAccepted.emit(values[0], values[1])
        else:
            value = parse_number(self.text)
            assert value is not None
            self.valueAccepted.emit(float(int(value)) if self.integer else value)
        self.accept()

    # -- a PIN being checked by the caller -----------------------------------------------------

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


OBJECT_NAMES: dict[KeypadMode, str] = {
    KeypadMode.PIN: "pinPad",
    KeypadMode.NUMBER: "numberKeypad",
    KeypadMode.FRACTION: "fractionKeypad",
}
"""The name each mode's keypad has (the style sheet, the tests and the screenshots find it)."""
