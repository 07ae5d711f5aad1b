"""A simple on-screen keyboard for short texts (recipe names, notes, filters).

Why QWERTZ with č, š, ž in Slovenian: that is the keyboard a Slovenian operator knows, and
recipe names use those letters; English gets QWERTY, and č, š, ž too (a Slovenian name typed
on the English interface). Why an accent key: the sample recipes are French ("Pièce 228 l
Bourgogne"); each tap of the accent key puts the next accent on the vowels and c, n, y
(grave, acute, circumflex, diaeresis, cedilla and tilde), the next letter typed takes it and
the keys return to plain letters.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import Qt, Signal
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QGridLayout, QHBoxLayout, QLabel, QPushButton, QWidget

from app.screens.widgets.keypad import answer_keys, error_label, key_button
from app.screens.widgets.overlay import Overlay

TextCheck = Callable[[str], str]

LAYOUTS: dict[str, tuple[str, ...]] = {
    "qwerty": ("1234567890", "qwertyuiopš", "asdfghjklčž", "zxcvbnm"),
    "qwertz": ("1234567890", "qwertzuiopš", "asdfghjklčž", "yxcvbnm"),
}

PUNCTUATION = "-_/.,()+#"

# The accents the accent key steps through, each as plain letter -> accented letter.
ACCENTS: tuple[dict[str, str], ...] = (
    dict(zip("aeiou", "àèìòù", strict=True)),
    dict(zip("aeiouyc", "áéíóúýć", strict=True)),
    dict(zip("aeiou", "âêîôû", strict=True)),
    dict(zip("aeiouy", "äëïöüÿ", strict=True)),
    dict(zip("cn", "çñ", strict=True)),
)


class TextKeyboard(Overlay):
    """Enter a line of text up to ``max_length`` characters.

    ``textAccepted(str)`` is emitted on OK with the text stripped of outer spaces, after
    ``check`` (if given) found nothing wrong."""

    textAccepted = Signal(str)  # noqa: N815 (Qt signal naming)

    def __init__(
        self,
        title: str,
        text: str = "",
        *,
        max_length: int = 40,
        layout: str = "qwerty",
        check: TextCheck | None = None,
        allow_empty: bool = False,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("textKeyboard")
        self.allow_empty = allow_empty  # a search: OK on an empty text clears it
        self.text = text
        self.max_length = max_length
        self.shift = False
        self.accent = -1  # index into ACCENTS, -1: plain letters
        self._check = check
        self.title_label = QLabel(title)
        self.title_label.setProperty("role", "title")
        self.display = QLabel()
        self.display.setProperty("role", "display")
        self.display.setObjectName("display")
        self.display.setMinimumWidth(560)
        self.error_label = error_label()
        self.letter_keys: dict[str, QPushButton] = {}

        grid = QGridLayout()
        grid.setSpacing(6)
        rows = LAYOUTS.get(layout, LAYOUTS["qwerty"])
        for row_index, row in enumerate(rows):
            for column, char in enumerate(row):
                button = key_button(char, "smallkey", name=f"key_{char}")
                button.clicked.connect(lambda _=False, c=char: self.type_char(c))
                grid.addWidget(button, row_index, column + (row_index >= 2))
                self.letter_keys[char] = button
        punctuation_row = QHBoxLayout()
        for char in PUNCTUATION:
            button = key_button(char, "smallkey", name=f"key_{char}")
            button.clicked.connect(lambda _=False, c=char: self.type_char(c))
            punctuation_row.addWidget(button)
        bottom = QHBoxLayout()
        self.shift_button = key_button("⇧", "smallkey", name="key_shift")
        self.shift_button.setCheckable(True)
        self.shift_button.toggled.connect(self._set_shift)
        self.accent_button = key_button("´`^", "smallkey", name="key_accent")
        self.accent_button.clicked.connect(self.next_accent)
        self.space_button = key_button("", "smallkey", name="key_space")
        self.space_button.clicked.connect(lambda: self.type_char(" "))
        self.backspace_button = key_button("⌫", "smallkey", name="key_backspace")
        self.backspace_button.clicked.connect(self.backspace)
        self.clear_button = key_button("C", "smallkey", name="key_clear")
        self.clear_button.clicked.connect(self.clear)
        self.cancel_button, self.ok_button = answer_keys(self, self.confirm)
        bottom.addWidget(self.shift_button)
        bottom.addWidget(self.accent_button)
        bottom.addWidget(self.space_button, 3)
        bottom.addWidget(self.backspace_button)
        bottom.addWidget(self.clear_button)
        bottom.addWidget(self.cancel_button, 1)
        bottom.addWidget(self.ok_button, 1)

        self.panel_layout.addWidget(self.title_label)
        self.panel_layout.addWidget(self.display)
        self.panel_layout.addWidget(self.error_label)
        self.panel_layout.addLayout(grid)
        self.panel_layout.addLayout(punctuation_row)
        self.panel_layout.addLayout(bottom)
        self.retranslate()
        self._refresh()

    def retranslate(self) -> None:
        self.space_button.setText(self.tr("Space"))
        self.cancel_button.setText(self.tr("Cancel"))
        self.ok_button.setText(self.tr("OK"))

    def _set_shift(self, on: bool) -> None:
        self.shift = on
        self._label_keys()

    def next_accent(self) -> None:
        """The next accent on the letters that take it (after the last: plain again)."""
        self.accent = self.accent + 1 if self.accent + 1 < len(ACCENTS) else -1
        self._label_keys()

    def _letter(self, char: str) -> str:
        accented = ACCENTS[self.accent].get(char, char) if self.accent >= 0 else char
        return accented.upper() if self.shift else accented

    def _label_keys(self) -> None:
        for char, button in self.letter_keys.items():
            button.setText(self._letter(char))

    def type_char(self, char: str) -> None:
        if len(self.text) >= self.max_length:
            self.error_label.setText(
                self.tr("At most %1 characters.").replace("%1", str(self.max_length))
            )
            return
        self.text += self._letter(char) if char in self.letter_keys else char
        if self.accent >= 0:
            self.accent = -1
            self._label_keys()
        if self.shift:
            self.shift_button.setChecked(False)
        self.error_label.setText("")
        self._refresh()

    def backspace(self) -> None:
        self.text = self.text[:-1]
        self.error_label.setText("")
        self._refresh()

    def clear(self) -> None:
        self.text = ""
        self._refresh()

    def keyPressEvent(self, event: QKeyEvent) -> None:
        key = event.key()
        if key == Qt.Key.Key_Backspace:
            self.backspace()
        elif key in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
            self.confirm()
        elif key == Qt.Key.Key_Escape:
            self.reject()
        elif event.text() and event.text().isprintable():
            if len(self.text) < self.max_length:
                self.text += event.text()
                self._refresh()
        else:
            super().keyPressEvent(event)

    def _refresh(self) -> None:
        self.display.setText(self.text + "▏")

    def problem(self) -> str:
        text = self.text.strip()
        if not text and not self.allow_empty:
            return self.tr("Enter a text.")
        return self._check(text) if self._check is not None else ""

    def confirm(self) -> None:
        problem = self.problem()
        if problem:
            self.error_label.setText(problem)
            return
        self.textAccepted.emit(self.text.strip())
        self.accept()
