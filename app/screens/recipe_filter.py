"""Finding a recipe among many: a search by name and a filter by barrel type.

Why one module for the Recipes screen and the main screen's chooser: an operator who found a
recipe with a search on one screen expects the same search, the same words and the same
result on the other. The search is typed on the on-screen keyboard (a touch panel has no
other), matches any part of the name regardless of case and accents, or the recipe's number.
"""

from __future__ import annotations

import unicodedata
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from PySide6.QtCore import Signal
from PySide6.QtWidgets import QButtonGroup, QHBoxLayout, QPushButton, QSizePolicy, QWidget

from app.data.recipe import NAME_MAX_CHARS, BarrelType, Recipe
from app.screens.widgets.buttons import elided_button, touch_button
from app.screens.widgets.dialogs import ChoiceOverlay
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.overlay import Overlay

SEARCH_MIN_WIDTH_PX = 100
ALL_TYPES = "all"
"""The choice "every barrel type" (ChoiceOverlay needs a value that is not None)."""


def _folded(text: str) -> str:
    """Lower case without accents: "pièce" is found by "piece", "Č" by "c"."""
    decomposed = unicodedata.normalize("NFKD", text.casefold())
    return "".join(ch for ch in decomposed if not unicodedata.combining(ch))


@dataclass(frozen=True)
class RecipeFilter:
    """What the operator asked for: a part of the name (or the number), a barrel type."""

    text: str = ""
    barrel_type: BarrelType | None = None  # None: every type

    def matches(self, recipe: Recipe) -> bool:
        if self.barrel_type is not None and recipe.barrel_type is not self.barrel_type:
            return False
        wanted = _folded(self.text.strip())
        if not wanted:
            return True
        return wanted in _folded(recipe.name) or wanted == str(recipe.id)

    def apply(self, recipes: Iterable[Recipe]) -> list[Recipe]:
        return [recipe for recipe in recipes if self.matches(recipe)]

    @property
    def active(self) -> bool:
        return bool(self.text.strip()) or self.barrel_type is not None


class RecipeFilterBar(QWidget):
    """One row: the search button (opens the keyboard; its C key and OK clear the search)
    and the barrel-type choice, either four toggles and a clear button (``compact`` False:
    the chooser, which has the width) or one button that opens the four choices
    (``type_button``, which a narrow list places itself, beside its title).

    ``changed(RecipeFilter)`` is emitted whenever the filter changes. ``open_overlay`` opens
    the keyboard or the choice over the panel."""

    changed = Signal(object)

    def __init__(
        self,
        open_overlay: Callable[[Overlay], object],
        keyboard_layout: Callable[[], str],
        *,
        compact: bool = False,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self._open = open_overlay
        self._layout_name = keyboard_layout
        self.filter = RecipeFilter()
        self.search_button = elided_button("recipeSearch", "field")
        self.search_button.setProperty("align", "left")
        self.search_button.clicked.connect(self.edit_search)
        self.search_button.setMinimumWidth(SEARCH_MIN_WIDTH_PX)
        self.search_button.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Fixed)
        row = QHBoxLayout(self)
        row.setContentsMargins(0, 0, 0, 0)
        row.setSpacing(6)
        row.addWidget(self.search_button, 1)
        self.type_buttons: dict[BarrelType | None, QPushButton] = {}
        self.clear_button: QPushButton | None = None
        self.type_button: QPushButton | None = None
        if compact:
            self.type_button = touch_button("filterType", "tab")
            self.type_button.setCheckable(True)
            self.type_button.clicked.connect(self.choose_barrel_type)
        else:
            self.clear_button = touch_button("clearSearch", text="✕")
            self.clear_button.clicked.connect(lambda: self.set_filter(RecipeFilter()))
            row.addWidget(self.clear_button)
            group = QButtonGroup(self)
            for kind in (None, *BarrelType):
                button = touch_button(f"filter_{kind.value if kind else 'all'}", "tab")
                button.setCheckable(True)
                group.addButton(button)
                button.clicked.connect(lambda _=False, k=kind: self.set_barrel_type(k))
                row.addWidget(button)
                self.type_buttons[kind] = button
        self.retranslate()
        self._show()

    def type_titles(self) -> dict[BarrelType | None, str]:
        return {
            None: self.tr("All"),
            BarrelType.FIXED_TILT: self.tr("Fixed"),
            BarrelType.ROUND: self.tr("Round"),
            BarrelType.OVAL: self.tr("Oval"),
        }

    def retranslate(self) -> None:
        for kind, button in self.type_buttons.items():
            button.setText(self.type_titles()[kind])
        self._show()

    def choose_barrel_type(self) -> None:
        """The compact bar's type button: the four choices over the panel."""
        titles = self.type_titles()
        chooser = ChoiceOverlay(
            self.tr("Show recipes of barrel type"),
            [(text, ALL_TYPES if kind is None else kind) for kind, text in titles.items()],
            current=self.filter.barrel_type or ALL_TYPES,
            columns=2,
        )
        chooser.chosen.connect(
            lambda kind: self.set_barrel_type(None if kind is ALL_TYPES else kind)
        )
        chooser.finished.connect(lambda _ok: self._show())
        self._open(chooser)

    def edit_search(self) -> None:
        keyboard = TextKeyboard(
            self.tr("Search recipes by name or number"),
            self.filter.text,
            max_length=NAME_MAX_CHARS,
            layout=self._layout_name(),
            allow_empty=True,
        )
        keyboard.textAccepted.connect(self.set_text)
        self._open(keyboard)

    def set_text(self, text: str) -> None:
        self.set_filter(RecipeFilter(text.strip(), self.filter.barrel_type))

    def set_barrel_type(self, kind: BarrelType | None) -> None:
        self.set_filter(RecipeFilter(self.filter.text, kind))

    def set_filter(self, wanted: RecipeFilter) -> None:
        if wanted == self.filter:
            self._show()
            return
        self.filter = wanted
        self._show()
        self.changed.emit(wanted)

    def _show(self) -> None:
        text = self.filter.text
        self.search_button.setText(f"“{text}”" if text else self.tr("Search…"))
        if self.clear_button is not None:
            self.clear_button.setEnabled(self.filter.active)
        for kind, button in self.type_buttons.items():
            button.setChecked(kind is self.filter.barrel_type)
        if self.type_button is not None:
            self.type_button.setText(self.type_titles()[self.filter.barrel_type])
            self.type_button.setChecked(self.filter.barrel_type is not None)
