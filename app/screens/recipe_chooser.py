"""The main screen's recipe chooser: every recipe as a big button, with search and filter.

Why its own overlay and not the generic choice list: with dozens of recipes the operator
needs the search and the barrel-type filter, and each button must show the recipe's number
whole (a centred, clipped text read "0 ..." for recipe 10): the number comes first, the text
is left-aligned and the name ends in an ellipsis when it does not fit.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import QGridLayout, QLabel, QPushButton, QScrollArea, QWidget

from app.data.recipe import Recipe
from app.screens.recipe_filter import RecipeFilter, RecipeFilterBar
from app.screens.widgets.buttons import elided_button, touch_button
from app.screens.widgets.kinetic import kinetic_scroll
from app.screens.widgets.overlay import Overlay
from app.screens.widgets.readouts import styled_label

WIDTH_SHARE = 0.62
HEIGHT_SHARE = 0.45
"""The buttons' area as shares of the window: the same layout at 1024x768 and 1920x1080
(a size in pixels left the scaled-up buttons too little room on a big panel)."""
COLUMNS = 2


def recipe_button_text(recipe: Recipe) -> str:
    """The number first, so that an elided name never hides it."""
    return f"{recipe.id}  {recipe.name}"


class RecipeChooser(Overlay):
    """Pick the recipe for the machine. ``chosen(int)`` carries the recipe's id."""

    chosen = Signal(int)

    def __init__(
        self,
        recipes: list[Recipe],
        current_id: int | None,
        open_overlay: Callable[[Overlay], object],
        keyboard_layout: Callable[[], str],
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("recipeChooser")
        self.recipes = recipes
        self.current_id = current_id
        title = styled_label(self.tr("Choose a recipe"), "title")
        self.filter_bar = RecipeFilterBar(open_overlay, keyboard_layout)
        self.filter_bar.changed.connect(self.show_matching)
        self.count_label = styled_label("", "caption", "chooserCount")
        self.content = QWidget()
        self.grid = QGridLayout(self.content)
        self.grid.setSpacing(8)
        self.grid.setAlignment(Qt.AlignmentFlag.AlignTop)
        for column in range(COLUMNS):
            self.grid.setColumnStretch(column, 1)  # equal columns, whatever the names
        self.buttons: list[QPushButton] = []
        self.buttons_area = QScrollArea()
        self.buttons_area.setWidget(self.content)
        self.buttons_area.setWidgetResizable(True)
        self.buttons_area.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        kinetic_scroll(self.buttons_area)
        self.cancel_button = touch_button("cancelButton", text=self.tr("Cancel"))
        self.cancel_button.clicked.connect(self.reject)
        self.panel_layout.addWidget(title)
        self.panel_layout.addWidget(self.filter_bar)
        self.panel_layout.addWidget(self.count_label)
        self.panel_layout.addWidget(self.buttons_area)
        self.panel_layout.addWidget(self.cancel_button)
        self.show_matching(self.filter_bar.filter)

    def open_on(self, host: QWidget) -> None:
        self.buttons_area.setFixedSize(
            round(host.width() * WIDTH_SHARE), round(host.height() * HEIGHT_SHARE)
        )
        super().open_on(host)

    def show_matching(self, wanted: RecipeFilter) -> None:
        """Rebuild the buttons for the recipes the filter lets through."""
        for button in self.buttons:
            button.hide()  # deleted later: until then it must not be drawn or tapped
            button.deleteLater()
        self.buttons = []
        while self.grid.count():
            item = self.grid.takeAt(0)
            widget = item.widget() if item is not None else None
            if isinstance(widget, QLabel):
                widget.deleteLater()
        matching = wanted.apply(self.recipes)
        for index, recipe in enumerate(matching):
            # The middle goes: the number in front and the end of the name (often what tells
            # a recipe from its neighbours, "... 27 mm") both stay.
            button = elided_button(
                f"chooseRecipe_{recipe.id}",
                text=recipe_button_text(recipe),
                mode=Qt.TextElideMode.ElideMiddle,
            )
            button.setProperty("align", "left")
            button.setCheckable(True)
            button.setChecked(recipe.id == self.current_id)
            button.clicked.connect(lambda _=False, r=recipe.id: self._pick(r))
            self.grid.addWidget(button, index // COLUMNS, index % COLUMNS)
            button.show()  # at once, not on the layout's next pass: a tap may follow now
            self.buttons.append(button)
        if not matching:
            self.grid.addWidget(styled_label(self.tr("No recipe matches."), "caption"), 0, 0)
        self.count_label.setText(
            self.tr("%1 of %2 recipes")
            .replace("%1", str(len(matching)))
            .replace("%2", str(len(self.recipes)))
        )

    def _pick(self, recipe_id: int | None) -> None:
        if recipe_id is not None:
            self.chosen.emit(recipe_id)
            self.accept()
