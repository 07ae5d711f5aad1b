"""Recipes screen: the list, the editor with a keypad for every value, and a live preview.

Why edit a draft and save explicitly: a recipe may be the one the machine is cutting; half an
edit must never reach it. Every keypad shows the allowed range and refuses a value the
recipe's validation refuses for that field (the same validation the database applies); what
depends on other fields is shown under the field at once, so nothing surprises at Save.
The preview solves the draft for a chosen board width with the machine's own geometry.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from datetime import datetime
from pathlib import Path
from typing import Any

from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import (
    QButtonGroup,
    QFrame,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QListWidget,
    QListWidgetItem,
    QPushButton,
    QScrollArea,
    QSizePolicy,
    QVBoxLayout,
    QWidget,
)

from app.data.dxf_profile import DxfProfileError, read_dxf_profile
from app.data.errors import DataError, FieldValidationError
from app.data.exchange import ImportReport, export_recipes, import_recipes
from app.data.recipe import NAME_MAX_CHARS, NOTE_MAX_CHARS, BarrelType, Recipe
from app.data.recipe_profile import RecipeProfile
from app.data.users import Role
from app.geometry.errors import FieldError
from app.geometry.limits import StaveLimits, recipe_tilt_range, width_ratio_minimum
from app.geometry.profile_kinds import (
    EXPONENT,
    SEMI_AXIS_RATIO,
    FamilyParameter,
    ProfileKind,
    default_parameters,
)
from app.geometry.ratio import Ratio
from app.geometry.width_range import WidthRange
from app.machine.commands import SelectRecipe
from app.machine.program_export import ExportFormat, export_file_name, export_text
from app.machine.snapshot import MachineSnapshot
from app.screens.base import Screen, ScreenContext, refusal
from app.screens.formatting import format_number, format_optional
from app.screens.recipe_filter import RecipeFilterBar
from app.screens.recipe_preview import RecipePreview, preview_recipe
from app.screens.texts import rule_message
from app.screens.theme import set_style_property
from app.screens.widgets.buttons import elided_button, touch_button
from app.screens.widgets.dialogs import ChoiceOverlay, ConfirmOverlay, MessageOverlay
from app.screens.widgets.file_chooser import FileChooser, default_exchange_dir
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.keypad import Keypad
from app.screens.widgets.kinetic import kinetic_scroll
from app.screens.widgets.plan_view import PlanView
from app.screens.widgets.readouts import set_text, styled_label
from app.screens.width_ranges import PENDING, WidthRanges

DEFAULT_PREVIEW_WIDTH_MM = 150.0
RANGE_POLL_MS = 50  # how often the list looks for width ranges the worker has finished
LABEL_WIDTH_PX = 165
LIST_WIDTH_PX = 250
TEXT_ROWS = ("name", "note", "drawing")
"""Rows whose value is text: under their label, across the form (a name is read whole)."""
MACHINE_MARK = "▶"
"""Marks the recipe on the machine in the list."""
NUMBER_FIELDS = (
    "length_mm",
    "thickness_mm",
    "tilt_deg",
    "barrel_diameter_mm",
    "barrel_minor_diameter_mm",
    "barrel_perimeter_mm",
    "target_width_mm",
)
OPTIONAL_NUMBERS = (
    "barrel_diameter_mm",
    "barrel_minor_diameter_mm",
    "barrel_perimeter_mm",
    "target_width_mm",
)
"""Number rows the keypad can also clear (an oval's short axis: empty for a round barrel)."""
FIELDS = (
    "name",
    "length_mm",
    "thickness_mm",
    "length_ratio",
    "width_ratio",
    "profile_kind",
    "exponent",
    "semi_axis_ratio",
    "drawing",
    "barrel_type",
    "tilt_deg",
    "barrel_diameter_mm",
    "barrel_minor_diameter_mm",
    "barrel_perimeter_mm",
    "target_width_mm",
    "note",
)
PROFILE_FIELDS = ("profile_kind", "exponent", "semi_axis_ratio", "drawing")
"""The side profile's rows: the kind, a family's parameters, a drawing's file."""
FAMILY_FIELDS: dict[str, FamilyParameter] = {
    EXPONENT.name: EXPONENT,
    SEMI_AXIS_RATIO.name: SEMI_AXIS_RATIO,
}
# Validation names a drawing's problems on these fields; the screen shows them on its row.
ERROR_FIELD_ROWS = {"profile": "drawing", "drawn_profile": "drawing"}


def field_value(recipe: Recipe, name: str) -> object:
    """A row's value: a recipe attribute, or a part of its side profile."""
    profile = recipe.profile
    if name == "profile_kind":
        return profile.kind
    if name in FAMILY_FIELDS:
        return dict(profile.params).get(name)
    if name == "drawing":
        return (profile.file_name, profile.file_sha256)
    return getattr(recipe, name)


def with_profile_kind(profile: RecipeProfile, kind: ProfileKind) -> RecipeProfile:
    """The profile switched to ``kind``: a family starts from its defaults (keeping values
    the two families share), a drawing is kept only while the kind stays drawn."""
    if kind is profile.kind:
        return profile
    if kind.is_family:
        known = dict(profile.params)
        params = {name: known.get(name, value) for name, value in default_parameters(kind).items()}
        return RecipeProfile(kind, tuple(sorted(params.items())))
    return RecipeProfile(kind)


def with_family_value(profile: RecipeProfile, name: str, value: float) -> RecipeProfile:
    params = {**dict(profile.params), name: value}
    return replace(profile, params=tuple(sorted(params.items())))


def new_recipe_template(name: str) -> Recipe:
    """The values a new recipe starts from (a common 950 mm wine-barrel stave)."""
    return Recipe(
        id=None,
        name=name,
        length_mm=950.0,
        thickness_mm=27.0,
        length_ratio=Ratio(1, 4),
        width_ratio=Ratio(3, 4),
        barrel_type=BarrelType.FIXED_TILT,
        tilt_deg=7.5,
        barrel_diameter_mm=None,
        barrel_perimeter_mm=None,
    )


def field_errors(recipe: Recipe, limits: StaveLimits) -> dict[str, list[FieldError]]:
    """The recipe's validation errors grouped by the row that shows them."""
    grouped: dict[str, list[FieldError]] = {}
    for error in recipe.validate(limits):
        grouped.setdefault(ERROR_FIELD_ROWS.get(error.field, error.field), []).append(error)
    return grouped


class RecipesScreen(Screen):
    key = "recipes"

    def __init__(self, context: ScreenContext, parent: QWidget | None = None) -> None:
        super().__init__(context, parent)
        self.limits = context.database.limits
        self.recipes: list[Recipe] = []
        self.current: Recipe | None = None
        self.draft: Recipe | None = None
        self.preview_width_mm = DEFAULT_PREVIEW_WIDTH_MM
        self.preview: RecipePreview | None = None
        self.parameters: dict[str, float] = context.database.get_parameters()
        self.errors: dict[str, list[FieldError]] = {}

        # -- list ---------------------------------------------------------------------------
        self.list_title = styled_label("", "title")
        self.recipe_list = QListWidget()
        self.recipe_list.setObjectName("recipeList")
        self.recipe_list.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.recipe_list.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.recipe_list.setTextElideMode(Qt.TextElideMode.ElideRight)
        self.recipe_list.setWordWrap(True)  # a long name takes two lines: read whole
        self.recipe_list.itemClicked.connect(self._list_clicked)
        self.filter_bar = RecipeFilterBar(context.open, context.keyboard_layout, compact=True)
        self.filter_bar.changed.connect(lambda _filter: self.reload())
        self.list_count = styled_label("", "caption", "recipeCount")
        kinetic_scroll(self.recipe_list)
        self.new_button = touch_button("newRecipe")
        self.copy_button = touch_button("copyRecipe")
        self.delete_button = touch_button("deleteRecipe", "danger")
        self.import_button = touch_button("importRecipes")
        self.export_button = touch_button("exportRecipes")
        self.new_button.clicked.connect(self.new_recipe)
        self.copy_button.clicked.connect(self.copy_recipe)
        self.delete_button.clicked.connect(self.delete_recipe)
        self.import_button.clicked.connect(self.import_recipes)
        self.export_button.clicked.connect(self.export_recipes)
        list_buttons = QGridLayout()
        list_buttons.setSpacing(6)
        list_buttons.addWidget(self.new_button, 0, 0)
        list_buttons.addWidget(self.copy_button, 0, 1)
        list_buttons.addWidget(self.delete_button, 1, 0, 1, 2)
        list_buttons.addWidget(self.import_button, 2, 0)
        list_buttons.addWidget(self.export_button, 2, 1)
        list_layout = QVBoxLayout()
        list_layout.setContentsMargins(0, 4, 0, 4)  # the panels beside it have their own frames
        title_row = QHBoxLayout()
        title_row.addWidget(self.list_title, 1)
        assert self.filter_bar.type_button is not None  # a compact bar
        title_row.addWidget(self.filter_bar.type_button)  # beside the title: room for a name
        list_layout.addLayout(title_row)
        list_layout.addWidget(self.filter_bar)
        list_layout.addWidget(self.list_count)
        list_layout.addWidget(self.recipe_list, 1)
        list_layout.addLayout(list_buttons)
        self.list_widget = QWidget()
        self.list_widget.setLayout(list_layout)
        self.list_widget.setFixedWidth(LIST_WIDTH_PX)

        # -- editor ----------------------------------------------------------------------------
        editor = QFrame()
        editor.setObjectName("panel")
        self.editor_title = styled_label("", "title", "editorTitle")
        rows = QVBoxLayout()
        rows.setSpacing(6)
        self.field_labels: dict[str, QLabel] = {}
        self.range_labels: dict[str, QLabel] = {}
        self.field_buttons: dict[str, QPushButton] = {}
        self.error_labels: dict[str, QLabel] = {}
        self.row_widgets: dict[str, list[QWidget]] = {}
        for name in FIELDS:
            # One row per field: name and allowed range on the left, the value (a button
            # that opens the keypad) on the right, the error (if any) across below.
            label = styled_label("", "field", f"label_{name}")
            label.setWordWrap(True)
            caption = styled_label("", "caption", f"range_{name}")
            caption.setWordWrap(True)
            row = QGridLayout()
            row.setHorizontalSpacing(8)
            row.setVerticalSpacing(0)
            row.addWidget(label, 0, 0)
            row.addWidget(caption, 1, 0)
            for text_label in (label, caption):
                text_label.setFixedWidth(LABEL_WIDTH_PX)  # the values line up
            row.setColumnStretch(1, 1)
            if name == "barrel_type":
                self.type_buttons: dict[BarrelType, QPushButton] = {}
                group = QButtonGroup(self)
                mode_row = QHBoxLayout()
                for kind in BarrelType:
                    button = touch_button(f"barrelType_{kind.value}", "tab")
                    button.setCheckable(True)
                    group.addButton(button)
                    button.clicked.connect(lambda _=False, k=kind: self.set_barrel_type(k))
                    mode_row.addWidget(button)
                    self.type_buttons[kind] = button
                row.addLayout(mode_row, 2, 0, 1, 2)  # three choices need the full width
            else:
                button = elided_button(f"field_{name}", "field")
                if name in TEXT_ROWS:
                    button.setProperty("align", "left")  # show where a long text begins
                button.clicked.connect(lambda _=False, n=name: self.edit_field(n))
                # Long names and notes must not widen the form: the text is cut instead.
                button.setMinimumWidth(150)
                button.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Fixed)
                if name in TEXT_ROWS:
                    row.addWidget(button, 2, 0, 1, 2)  # the text gets the row's full width
                else:
                    row.addWidget(button, 0, 1, 2, 1)
                self.field_buttons[name] = button
            error = styled_label("", "error", f"error_{name}")
            error.setWordWrap(True)
            error.setVisible(False)
            row.addWidget(error, 3, 0, 1, 2)
            rows.addLayout(row)
            self.row_widgets[name] = [label, caption, error]
            if name in self.field_buttons:
                self.row_widgets[name].append(self.field_buttons[name])
            self.field_labels[name] = label
            self.range_labels[name] = caption
            self.error_labels[name] = error
        self.save_button = touch_button("saveRecipe", "primary")
        self.discard_button = touch_button("discardRecipe")
        self.use_button = touch_button("useRecipe")
        self.save_button.clicked.connect(self.save)
        self.discard_button.clicked.connect(self.discard)
        self.use_button.clicked.connect(self.use_on_machine)
        actions = QHBoxLayout()
        actions.addWidget(self.save_button)
        actions.addWidget(self.discard_button)
        actions.addWidget(self.use_button)
        form = QWidget()
        form_layout = QVBoxLayout(form)
        form_layout.setContentsMargins(0, 0, 6, 0)
        form_layout.addLayout(rows)
        form_layout.addStretch(1)
        self.form_scroll = QScrollArea()
        self.form_scroll.setObjectName("recipeForm")
        self.form_scroll.setWidget(form)
        self.form_scroll.setWidgetResizable(True)
        self.form_scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        kinetic_scroll(self.form_scroll)
        editor_layout = QVBoxLayout(editor)
        editor_layout.setContentsMargins(10, 6, 10, 8)
        editor_layout.addWidget(self.editor_title)
        editor_layout.addWidget(self.form_scroll, 1)
        editor_layout.addLayout(actions)

        # -- preview ---------------------------------------------------------------------------
        preview_panel = QFrame()
        preview_panel.setObjectName("panel")
        self.preview_title = styled_label("", "title")
        self.width_button = touch_button("previewWidth", "field")
        self.width_button.clicked.connect(self.edit_preview_width)
        self.width_caption = styled_label("", "caption")
        self.range_label = styled_label("", "caption", "previewWidthRange")
        self.range_label.setWordWrap(True)
        self.width_ranges = WidthRanges(self.limits)
        self._range_timer = QTimer(self)
        self._range_timer.setInterval(RANGE_POLL_MS)
        self._range_timer.timeout.connect(self._ranges_arrived)
        self.destroyed.connect(self.width_ranges.close)
        self.program_button = touch_button("exportProgram")
        self.program_button.clicked.connect(self.export_program)
        self.plan_view = PlanView(show_cutter=False)
        self.plan_view.setMinimumSize(220, 150)
        self.plan_view.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Expanding)
        self.result_labels: dict[str, QLabel] = {}
        results = QGridLayout()
        results.setVerticalSpacing(0)
        for index, key in enumerate(("head", "d", "r", "tilt")):
            caption = styled_label("", "caption")
            value = styled_label("—", "value", f"preview_{key}")
            grid_row, grid_column = 2 * (index // 2), index % 2
            results.addWidget(caption, grid_row, grid_column)
            results.addWidget(value, grid_row + 1, grid_column)
            self.result_labels[key] = value
            self.result_labels[key + "_caption"] = caption
        self.preview_errors = styled_label("", "error", "previewErrors")
        self.preview_errors.setWordWrap(True)
        preview_layout = QVBoxLayout(preview_panel)
        preview_layout.setContentsMargins(10, 6, 10, 8)
        preview_layout.addWidget(self.preview_title)
        preview_layout.addWidget(self.width_caption)
        preview_layout.addWidget(self.width_button)
        preview_layout.addWidget(self.range_label)
        preview_layout.addWidget(self.plan_view, 1)
        preview_layout.addLayout(results)
        preview_layout.addWidget(self.preview_errors)
        preview_layout.addWidget(self.program_button)

        layout = QHBoxLayout(self)
        layout.setContentsMargins(8, 8, 8, 8)
        layout.setSpacing(8)
        layout.addWidget(self.list_widget)
        layout.addWidget(editor, 3)
        layout.addWidget(preview_panel, 2)
        self.retranslate()
        self.reload()

    # -- texts ----------------------------------------------------------------------------------

    def title(self) -> str:
        return self.tr("Recipes")

    def field_title(self, name: str) -> str:
        titles = {
            "name": self.tr("Name"),
            "length_mm": self.tr("Length L"),
            "thickness_mm": self.tr("Thickness H"),
            "length_ratio": self.tr("Length ratio L1 : L"),
            "width_ratio": self.tr("Width ratio W1 : W"),
            "profile_kind": self.tr("Side profile"),
            "exponent": self.tr("Exponent n"),
            "semi_axis_ratio": self.tr("Semi-axis a : L/2"),
            "drawing": self.tr("Drawing (DXF)"),
            "barrel_type": self.tr("Barrel type"),
            "tilt_deg": self.tr("Tilt α"),
            "barrel_diameter_mm": self.tr("Barrel diameter"),
            "barrel_minor_diameter_mm": self.tr("Oval: short axis"),
            "barrel_perimeter_mm": self.tr("Barrel perimeter"),
            "target_width_mm": self.tr("Belly width to cut"),
            "note": self.tr("Note"),
        }
        return titles[name]

    def field_range(self, name: str) -> tuple[float, float, str]:
        """(minimum, maximum, unit) of a number field, from the machine's limits; a fixed
        tilt's from the draft's width ratio too (the recipe's validation refuses a tilt for
        which no board of the recipe fits a barrel within the limits)."""
        limits = self.limits
        if name == "tilt_deg" and self.draft is not None:
            k = self.draft.width_ratio.value
            if 0.0 < k < 1.0:
                low, high = recipe_tilt_range(k, limits)
                if low <= high:
                    # Rounded inwards: the keypad never offers a bound the rule refuses.
                    return (math.ceil(low * 100) / 100, math.floor(high * 100) / 100, "°")
        if name == "target_width_mm" and self.draft is not None:
            k = self.draft.width_ratio.value
            if 0.0 < k < 1.0:  # the head of the stave to stock must keep its minimum width
                low = max(limits.min_head_width_mm, limits.min_head_width_mm / k)
                return (math.ceil(low * 10) / 10, limits.max_width_mm, "mm")
        d_low = limits.min_barrel_diameter_mm or 1.0
        d_high = limits.max_barrel_diameter_mm or 100_000.0
        ranges = {
            "length_mm": (limits.min_length_mm, limits.max_length_mm, "mm"),
            "thickness_mm": (limits.min_thickness_mm, limits.max_thickness_mm, "mm"),
            "tilt_deg": (limits.min_tilt_deg, limits.max_tilt_deg, "°"),
            "barrel_diameter_mm": (d_low, d_high, "mm"),
            "barrel_minor_diameter_mm": (d_low, d_high, "mm"),
            "barrel_perimeter_mm": (round(math.pi * d_low, 1), round(math.pi * d_high, 1), "mm"),
            "target_width_mm": (limits.min_head_width_mm, limits.max_width_mm, "mm"),
        }
        return ranges[name]

    def range_text(self, name: str) -> str:
        """The hint under a field: the bounds the recipe's validation applies, computed by
        the same functions (a hint must never promise what Save then refuses)."""
        if name in NUMBER_FIELDS:
            low, high, unit = self.field_range(name)
            text = f"{format_number(low)} … {format_number(high)} {unit}"
            if name in OPTIONAL_NUMBERS and not self._required(name):
                text += " " + self.tr("(optional)")
            return text
        if name == "length_ratio":
            return self.tr("0 to below 1/2")
        if name == "width_ratio":
            return self.tr("%1 to below 1").replace(
                "%1", format_number(width_ratio_minimum(self.limits), 3)
            )
        if name == "name":
            return self.tr("1 to %1 characters").replace("%1", str(NAME_MAX_CHARS))
        if name == "note":
            return self.tr("optional")
        if name == "barrel_type":
            return self.tr("the tilt: fixed, or from the barrel")
        if name in FAMILY_FIELDS:
            spec = FAMILY_FIELDS[name]
            return f"{format_number(spec.minimum)} … {format_number(spec.maximum)}"
        if name == "profile_kind":
            return self.tr("the shape of both sides")
        if name == "drawing":
            return self.tr("one side, head to head; scaled to L and W")
        return ""

    def barrel_type_titles(self) -> dict[BarrelType, str]:
        return {
            BarrelType.FIXED_TILT: self.tr("Fixed tilt"),
            BarrelType.ROUND: self.tr("Round"),
            BarrelType.OVAL: self.tr("Oval"),
        }

    def _required(self, name: str) -> bool:
        """A barrel's belly diameter is needed once the tilt comes from the barrel, its short
        axis once the barrel is oval (the recipe's validation refuses them missing)."""
        kind = self.draft.barrel_type if self.draft is not None else BarrelType.FIXED_TILT
        if name == "barrel_diameter_mm":
            return kind is not BarrelType.FIXED_TILT
        return name == "barrel_minor_diameter_mm" and kind is BarrelType.OVAL

    def kind_title(self, kind: ProfileKind) -> str:
        titles = {
            ProfileKind.LINE_ARC_LINE: self.tr("Line–arc–line"),
            ProfileKind.SINGLE_ARC: self.tr("Single arc"),
            ProfileKind.PARABOLA: self.tr("Parabola"),
            ProfileKind.ELLIPSE: self.tr("Ellipse arc"),
            ProfileKind.SUPERELLIPSE: self.tr("Superellipse"),
            ProfileKind.DRAWN: self.tr("Drawn (DXF)"),
        }
        return titles[kind]

    def retranslate(self) -> None:
        self.list_title.setText(self.tr("Recipes"))
        self.filter_bar.retranslate()
        self.new_button.setText(self.tr("New"))
        self.copy_button.setText(self.tr("Copy"))
        self.delete_button.setText(self.tr("Delete"))
        self.import_button.setText(self.tr("Import"))
        self.export_button.setText(self.tr("Export"))
        self.save_button.setText(self.tr("Save"))
        self.discard_button.setText(self.tr("Discard"))
        self.use_button.setText(self.tr("Use on machine"))
        for kind, text in self.barrel_type_titles().items():
            self.type_buttons[kind].setText(text)
        self.preview_title.setText(self.tr("Preview"))
        self.width_caption.setText(self.tr("Board width for the preview"))
        self.program_button.setText(self.tr("G-code, DXF…"))
        captions = {
            "head": self.tr("Head W1"),
            "d": self.tr("Rise D"),
            "r": self.tr("Radius R"),
            "tilt": self.tr("Tilt"),
        }
        for key, text in captions.items():
            self.result_labels[key + "_caption"].setText(text)
        for name in FIELDS:
            self.field_labels[name].setText(self.field_title(name))
            self.range_labels[name].setText(self.range_text(name))
        self.show_draft()

    # -- list ------------------------------------------------------------------------------------

    def reload(self, select_id: int | None = None) -> None:
        """Read the recipes again and select ``select_id`` (or keep the current one)."""
        self.recipes = self.context.database.list_recipes()
        wanted = self.filter_bar.filter
        shown = wanted.apply(self.recipes)
        set_text(
            self.list_count,
            self.tr("%1 of %2 recipes")
            .replace("%1", str(len(shown)))
            .replace("%2", str(len(self.recipes))),
        )
        keep = (
            select_id
            if select_id is not None
            else (self.current.id if self.current is not None else None)
        )
        self.recipe_list.clear()
        for recipe in shown:
            item = QListWidgetItem(self._list_text(recipe))
            item.setData(Qt.ItemDataRole.UserRole, recipe.id)
            self.recipe_list.addItem(item)
        if self.width_ranges.pending:
            self._range_timer.start()
        target = next((r for r in self.recipes if r.id == keep), None)
        if target is None and self.recipes and self.draft is None:
            loaded = self.snapshot.recipe_id if self.snapshot is not None else None
            target = next((r for r in self.recipes if r.id == loaded), self.recipes[0])
        if target is not None:
            self.load(target)
        elif self.current is not None and self.current.id is not None:
            # The recipe being shown was deleted.
            self.current = None
            self.draft = None
            self.show_draft()

    def _list_text(self, recipe: Recipe) -> str:
        """The list's line: number, name and the widths the recipe cuts on this machine (filled
        in by the worker; the list does not wait for it)."""
        widths = self.width_ranges.get(recipe, self.parameters)
        if widths == PENDING:
            range_text = "…"
        elif isinstance(widths, WidthRange):
            range_text = (
                self.tr("%1 to %2 mm")
                .replace("%1", format_number(widths.min_mm, 1))
                .replace("%2", format_number(widths.max_mm, 1))
            )
        else:
            range_text = self.tr("cuts no board here")
        if self.snapshot is not None and self.snapshot.recipe_id == recipe.id:
            return f"{MACHINE_MARK} {recipe.id}  {recipe.name}\n" + self.tr(
                "on the machine, %1"
            ).replace("%1", range_text)
        return f"{recipe.id}  {recipe.name}\n{range_text}"

    def fill_width_ranges(self) -> None:
        """Wait for every recipe's range now (the screenshots: a picture with all of them)."""
        for recipe in self.recipes:
            self.width_ranges.now(recipe, self.parameters)
        self._relabel()

    def _relabel(self) -> None:
        for row in range(self.recipe_list.count()):
            item = self.recipe_list.item(row)
            recipe_id = item.data(Qt.ItemDataRole.UserRole)
            recipe = next((r for r in self.recipes if r.id == recipe_id), None)
            if recipe is not None:
                item.setText(self._list_text(recipe))

    def _ranges_arrived(self) -> None:
        if self.width_ranges.collect():
            self._relabel()
        if not self.width_ranges.pending:
            self._range_timer.stop()

    def _row_of(self, recipe_id: int | None) -> int:
        for row in range(self.recipe_list.count()):
            if self.recipe_list.item(row).data(Qt.ItemDataRole.UserRole) == recipe_id:
                return row
        return -1

    def _list_clicked(self, item: QListWidgetItem) -> None:
        recipe_id = item.data(Qt.ItemDataRole.UserRole)
        recipe = next((r for r in self.recipes if r.id == recipe_id), None)
        if recipe is None or (self.current is not None and recipe.id == self.current.id):
            return
        self.after_discard_confirmed(lambda: self.load(recipe))

    def select_recipe(self, recipe_id: int) -> None:
        """Show the recipe with this id in the editor (as a tap on the list does)."""
        row = self._row_of(recipe_id)
        if row < 0:
            raise ValueError(f"recipe id {recipe_id} is not in the list")
        self._list_clicked(self.recipe_list.item(row))

    def load(self, recipe: Recipe) -> None:
        self.current = recipe
        self.draft = recipe
        row = self._row_of(recipe.id)
        if row >= 0:
            self.recipe_list.setCurrentRow(row)
        self.update_preview()
        self.show_draft()

    @property
    def dirty(self) -> bool:
        return self.draft is not None and self.draft != self.current

    def after_discard_confirmed(self, action: Callable[[], None]) -> None:
        """Run ``action`` now, or after the user agreed to lose unsaved changes."""
        if not self.dirty:
            action()
            return
        overlay = ConfirmOverlay(
            self.tr("Unsaved changes"),
            self.tr("Discard the changes to %1?").replace(
                "%1", self.draft.name if self.draft else ""
            ),
            self.tr("Discard"),
            danger=True,
        )
        overlay.finished.connect(lambda ok: action() if ok else self._reselect_current())
        self.context.open(overlay)

    def _reselect_current(self) -> None:
        if self.current is not None:
            row = self._row_of(self.current.id)
            if row >= 0:
                self.recipe_list.setCurrentRow(row)

    # -- editing ----------------------------------------------------------------------------

    def edit_field(self, name: str) -> None:
        """Open the keypad (or keyboard) for one field of the draft."""
        draft = self.draft
        if draft is None:
            return
        title = self.field_title(name)
        if name in ("name", "note"):
            keyboard = TextKeyboard(
                title,
                str(getattr(draft, name)),
                max_length=NAME_MAX_CHARS if name == "name" else NOTE_MAX_CHARS,
                layout=self.context.keyboard_layout(),
                check=lambda text: self._check(name, text),
            )
            keyboard.textAccepted.connect(lambda text: self.set_field(name, text))
            self.context.open(keyboard)
        elif name in ("length_ratio", "width_ratio"):
            ratio: Ratio = getattr(draft, name)
            keypad = Keypad.for_fraction(
                title,
                ratio.numerator,
                ratio.denominator,
                self.range_text(name),
                check=lambda num, den: self._check(name, Ratio(num, den)),
            )
            keypad.fractionAccepted.connect(lambda num, den: self.set_field(name, Ratio(num, den)))
            self.context.open(keypad)
        elif name == "profile_kind":
            chooser = ChoiceOverlay(
                title,
                [(self.kind_title(kind), kind) for kind in ProfileKind],
                current=draft.profile.kind,
                columns=2,
            )
            chooser.chosen.connect(lambda kind: self.set_field("profile_kind", kind))
            self.context.open(chooser)
        elif name == "drawing":
            self.choose_drawing()
        elif name in FAMILY_FIELDS:
            spec = FAMILY_FIELDS[name]
            current = dict(draft.profile.params).get(name, spec.default)
            keypad_family = Keypad.for_number(
                title,
                current,
                spec.minimum,
                spec.maximum,
                spec.unit,
                decimals=3,
                check=lambda value: self._check(name, value),
            )
            keypad_family.valueAccepted.connect(lambda value: self.set_field(name, value))
            self.context.open(keypad_family)
        elif name in NUMBER_FIELDS:
            low, high, unit = self.field_range(name)
            optional = name in OPTIONAL_NUMBERS
            keypad_number = Keypad.for_number(
                title,
                getattr(draft, name),
                low,
                high,
                unit,
                decimals=3,
                optional=optional,
                check=lambda value: self._check(name, value),
            )
            keypad_number.valueAccepted.connect(lambda value: self.set_field(name, value))
            keypad_number.cleared.connect(lambda: self.set_field(name, None))
            self.context.open(keypad_number)

    def _check(self, name: str, value: object) -> str:
        """The message refusing ``value`` for field ``name`` ("" when it is acceptable): the
        recipe's validation run on the draft with that value, errors of that field only."""
        if self.draft is None:
            return ""
        candidate = self._with(self.draft, name, value)
        problems = field_errors(candidate, self.limits).get(name, [])
        if name == "name" and isinstance(value, str):
            clash = self.context.database.get_recipe_by_name(value)
            if clash is not None and clash.id != self.draft.id:
                return (
                    self.tr("The name %1 is already used by recipe %2.")
                    .replace("%1", value)
                    .replace("%2", str(clash.id))
                )
        return "\n".join(rule_message(p) for p in problems)

    @staticmethod
    def _with(recipe: Recipe, name: str, value: object) -> Recipe:
        """The recipe with one row changed (the profile's rows change its profile)."""
        if name == "profile_kind" and isinstance(value, ProfileKind):
            return replace(recipe, profile=with_profile_kind(recipe.profile, value))
        if name in FAMILY_FIELDS and isinstance(value, int | float):
            return replace(recipe, profile=with_family_value(recipe.profile, name, float(value)))
        if name == "drawing" and isinstance(value, RecipeProfile):
            return replace(recipe, profile=value)
        # The field is chosen by name at run time; the recipe's own validation judges the value.
        change: dict[str, Any] = {name: value}
        return replace(recipe, **change)

    def set_field(self, name: str, value: object) -> None:
        if self.draft is None:
            return
        self.draft = self._with(self.draft, name, value)
        self.update_preview()
        self.show_draft()

    def choose_drawing(self, directory: Path | None = None) -> None:
        """The touch file chooser for a DXF drawing of one side."""
        chooser = FileChooser(
            self.tr("Import a side profile (DXF)"),
            directory or default_exchange_dir(),
            keyboard_layout=self.context.keyboard_layout(),
            suffixes=(".dxf",),
        )
        chooser.fileChosen.connect(lambda path: self.import_drawing(Path(path)))
        self.context.open(chooser)

    def import_drawing(self, path: Path, layer: str | None = None) -> None:
        """Read the drawing into the draft (drawn profile) or say why it cannot be used; a
        drawing refused as a whole with curves on several layers (a frame, a second view)
        asks which layer holds the side."""
        try:
            drawing = read_dxf_profile(path.name, path.read_bytes(), layer)
        except OSError as exc:
            self._message(self.tr("Drawing not imported"), f"{path}: {exc.strerror or exc}")
            return
        except DxfProfileError as exc:
            if exc.curve_layers:
                chooser = ChoiceOverlay(
                    self.tr("Layer of the side profile"),
                    [(name, name) for name in exc.curve_layers],
                )
                chooser.chosen.connect(lambda chosen: self.import_drawing(path, str(chosen)))
                self.context.open(chooser)
                return
            self._message(self.tr("Drawing not imported"), str(exc))
            return
        profile = RecipeProfile(
            ProfileKind.DRAWN,
            drawing=drawing.shape,
            file_name=drawing.file_name,
            file_sha256=drawing.sha256,
        )
        self.set_field("drawing", profile)

    def show_draft(self) -> None:
        """Put the draft's values, the inline errors and the button states on screen."""
        draft = self.draft
        editing = draft is not None
        for button in self.field_buttons.values():
            button.setEnabled(editing)
        for type_button in self.type_buttons.values():
            type_button.setEnabled(editing)
        if draft is None:
            set_text(self.editor_title, self.tr("No recipe"))
            for button in self.field_buttons.values():
                button.setText("")
            for label in self.error_labels.values():
                label.setVisible(False)
            self._update_buttons()
            return
        title = (
            self.tr("New recipe")
            if draft.id is None
            else self.tr("Recipe %1").replace("%1", str(draft.id))
        )
        if self.dirty:
            title += "  " + self.tr("(changed, not saved)")
        set_text(self.editor_title, title)
        values = {
            "name": draft.name,
            "length_mm": f"{format_number(draft.length_mm)} mm",
            "thickness_mm": f"{format_number(draft.thickness_mm)} mm",
            "length_ratio": f"{draft.length_ratio} = {draft.length_ratio.value:.2f}",
            "width_ratio": f"{draft.width_ratio} = {draft.width_ratio.value:.2f}",
            "profile_kind": self.kind_title(draft.profile.kind),
            "exponent": format_optional(dict(draft.profile.params).get("exponent"), 3, ""),
            "semi_axis_ratio": format_optional(
                dict(draft.profile.params).get("semi_axis_ratio"), 3, ""
            ),
            "drawing": draft.profile.file_name or self.tr("Import a DXF file…"),
            "tilt_deg": f"{format_number(draft.tilt_deg)} °",
            "barrel_diameter_mm": format_optional(draft.barrel_diameter_mm, 1, "mm"),
            "barrel_minor_diameter_mm": format_optional(draft.barrel_minor_diameter_mm, 1, "mm"),
            "barrel_perimeter_mm": format_optional(draft.barrel_perimeter_mm, 1, "mm"),
            "target_width_mm": format_optional(draft.target_width_mm, 1, "mm"),
            "note": draft.note or "—",  # elided on the button, whole on the keyboard
        }
        for name, text in values.items():
            set_text(self.field_buttons[name], text)
        for kind, type_button in self.type_buttons.items():
            type_button.setChecked(draft.barrel_type is kind)
        self._show_profile_rows(draft.profile.kind)
        self._show_barrel_rows(draft.barrel_type)
        self.errors = field_errors(draft, self.limits)
        for name in FIELDS:
            problems = self.errors.get(name, [])
            label = self.error_labels[name]
            set_text(label, "\n".join(rule_message(p) for p in problems))
            label.setVisible(bool(problems))
            field_button = self.field_buttons.get(name)
            if field_button is not None:
                set_style_property(field_button, "invalid", "true" if problems else "false")
                changed = self.current is not None and field_value(draft, name) != field_value(
                    self.current, name
                )
                set_style_property(
                    field_button, "changed", "true" if changed and not problems else "false"
                )
        self._update_buttons()

    def set_barrel_type(self, kind: BarrelType) -> None:
        """The touch choice of fixed tilt, round or oval. A short axis belongs only to an oval:
        leaving oval clears it (saving would refuse it), coming back restores the saved one."""
        draft = self.draft
        if draft is None:
            return
        changed = replace(draft, barrel_type=kind)
        if kind is not BarrelType.OVAL:
            changed = replace(changed, barrel_minor_diameter_mm=None)
        elif changed.barrel_minor_diameter_mm is None and self.current is not None:
            changed = replace(
                changed, barrel_minor_diameter_mm=self.current.barrel_minor_diameter_mm
            )
        self.draft = changed
        self.update_preview()
        self.show_draft()

    def _show_barrel_rows(self, kind: BarrelType) -> None:
        """The barrel's rows only for a barrel, the short axis only for an oval; with a barrel
        the tilt is computed for each board, so its row shows the value and is not a field."""
        barrel = kind is not BarrelType.FIXED_TILT
        name = "barrel_minor_diameter_mm"
        shown = kind is BarrelType.OVAL
        for widget in self.row_widgets[name]:
            if widget is self.error_labels[name] and shown:
                continue
            widget.setVisible(shown)
        for row in ("barrel_diameter_mm", name, "target_width_mm"):  # depend on the draft
            set_text(self.range_labels[row], self.range_text(row))
        self.field_buttons["tilt_deg"].setEnabled(not barrel)
        self._show_computed_tilt()

    def _show_computed_tilt(self) -> None:
        """With a barrel, the tilt row shows the tilt the barrel gives the preview's board,
        read-only (the machine computes it for each measured board); its caption says so."""
        draft = self.draft
        if draft is None or draft.barrel_type is BarrelType.FIXED_TILT:
            set_text(self.range_labels["tilt_deg"], self.range_text("tilt_deg"))
            return
        set_text(
            self.range_labels["tilt_deg"],
            self.tr("from the barrel, for a %1 mm board").replace(
                "%1", format_number(self.preview_width_mm, 1)
            ),
        )
        preview = self.preview
        if preview is None or preview.tilt_deg is None:
            set_text(self.field_buttons["tilt_deg"], "—")
            return
        text = f"{format_number(preview.tilt_deg, 2)} °"
        if preview.tilt_b_deg is not None and preview.tilt_b_deg != preview.tilt_deg:
            text = (
                f"{format_number(preview.tilt_deg, 2)} / {format_number(preview.tilt_b_deg, 2)} °"
            )
        set_text(self.field_buttons["tilt_deg"], text)

    def _show_profile_rows(self, kind: ProfileKind) -> None:
        """Only the rows the kind uses: a family's parameters, a drawing's file, lambda only
        for line-arc-line."""
        used = {name for name, _ in default_parameters(kind).items()}
        visible = {
            "exponent": "exponent" in used,
            "semi_axis_ratio": "semi_axis_ratio" in used,
            "drawing": kind is ProfileKind.DRAWN,
            "length_ratio": kind is ProfileKind.LINE_ARC_LINE,
        }
        for name, shown in visible.items():
            for widget in self.row_widgets[name]:
                if widget is self.error_labels[name] and shown:
                    continue  # the error label shows itself when there is an error
                widget.setVisible(shown)

    def _update_buttons(self) -> None:
        has_current = self.current is not None and self.current.id is not None
        self.copy_button.setEnabled(has_current)
        self.delete_button.setEnabled(has_current)
        self.save_button.setEnabled(self.dirty)
        self.discard_button.setEnabled(self.dirty)
        reason = refusal(self.snapshot, "SelectRecipe") if self.snapshot is not None else ""
        can_use = has_current and not self.dirty and not reason
        self.use_button.setEnabled(can_use)
        self.use_button.setToolTip(reason)

    # -- preview ---------------------------------------------------------------------------

    def edit_preview_width(self) -> None:
        keypad = Keypad.for_number(
            self.tr("Board width for the preview"),
            self.preview_width_mm,
            1.0,
            self.limits.max_width_mm,
            "mm",
            decimals=1,
        )
        keypad.valueAccepted.connect(self.set_preview_width)
        self.context.open(keypad)

    def set_preview_width(self, width_mm: float) -> None:
        self.preview_width_mm = width_mm
        self.update_preview()

    def update_preview(self) -> None:
        set_text(self.width_button, f"{format_number(self.preview_width_mm, 1)} mm")
        if self.draft is None:
            self.preview = None
            self.plan_view.set_paths((), (), ())
            return
        preview = preview_recipe(self.draft, self.preview_width_mm, self.parameters, self.limits)
        self.preview = preview
        widths = self._width_range(self.draft)
        errors = list(preview.errors)
        if widths is None:
            set_text(self.range_label, self.tr("This recipe cuts no board on this machine"))
        else:
            set_text(
                self.range_label,
                self.tr("Boards it cuts on this machine: %1 to %2 mm")
                .replace("%1", format_number(widths.min_mm, 1))
                .replace("%2", format_number(widths.max_mm, 1)),
            )
            if not widths.contains(self.preview_width_mm):
                errors.insert(0, self.tr("Outside the widths this recipe cuts on this machine"))
        self.plan_view.set_paths(preview.outline, preview.toolpath, preview.cutting)
        set_text(self.result_labels["head"], format_optional(preview.head_width_mm, 1, "mm"))
        set_text(self.result_labels["d"], format_optional(preview.d_mm, 2, "mm"))
        set_text(self.result_labels["r"], format_optional(preview.r_mm, 0, "mm"))
        tilt_text = format_optional(preview.tilt_deg, 2, "°")
        if preview.tilt_b_deg is not None and preview.tilt_b_deg != preview.tilt_deg:
            tilt_text = f"A {tilt_text} / B {format_optional(preview.tilt_b_deg, 2, '°')}"
        set_text(self.result_labels["tilt"], tilt_text)
        set_text(self.preview_errors, "\n".join(errors))
        self._show_computed_tilt()

    def _width_range(self, recipe: Recipe) -> WidthRange | None:
        """The recipe's range of board widths on this machine (cached: a scan of the
        machine's own composition, some 0.1 s, done again only when the stave changes)."""
        return self.width_ranges.now(recipe, self.parameters)

    # -- actions -----------------------------------------------------------------------------

    def _message(self, title: str, text: str) -> None:
        self.context.open(MessageOverlay(title, text))

    def save(self) -> None:
        draft = self.draft
        user = self.context.session.acting_user()
        if draft is None:
            return
        if user is None:
            self._message(self.tr("Not saved"), self.tr("No user account to save as."))
            return
        try:
            saved = self.context.database.save_recipe(draft, user)
        except FieldValidationError as exc:
            self.errors = {}
            lines = [rule_message(e) for e in exc.errors]
            self.show_draft()
            self._message(self.tr("Recipe not saved"), "\n".join(lines))
            return
        except DataError as exc:
            self._message(self.tr("Recipe not saved"), str(exc))
            return
        self.current = saved
        self.draft = saved
        self.reload(saved.id)
        self.context.notify(self.tr("Recipe %1 saved.").replace("%1", saved.name))
        if self.snapshot is not None and self.snapshot.recipe_id == saved.id:
            self._ask_to_use_new_version(saved)

    def _ask_to_use_new_version(self, saved: Recipe) -> None:
        """The machine cuts the version it was given: a saved change reaches it only when
        the operator says so."""
        overlay = ConfirmOverlay(
            self.tr("Use the new version?"),
            self.tr(
                "Recipe %1 is selected on the machine. Cut the saved version from the next "
                "board on? Cancel: the machine keeps the version it has."
            ).replace("%1", saved.name),
            self.tr("Use the new version"),
        )
        overlay.finished.connect(lambda ok: self._use_new_version(saved) if ok else None)
        self.context.open(overlay)

    def _use_new_version(self, saved: Recipe) -> None:
        reason = refusal(self.snapshot, "SelectRecipe") if self.snapshot is not None else ""
        if reason:
            self._message(self.tr("Not changed on the machine"), reason)
            return
        assert saved.id is not None  # stored recipes have an id
        self.context.send(SelectRecipe(saved.id))
        self.context.notify(self.tr("Recipe %1 selected.").replace("%1", saved.name))

    def discard(self) -> None:
        if self.current is not None:
            self.load(self.current)
        else:
            self.draft = None
            self.reload()

    def use_on_machine(self) -> None:
        if self.current is not None and self.current.id is not None:
            self.context.send(SelectRecipe(self.current.id))
            self.context.notify(self.tr("Recipe %1 selected.").replace("%1", self.current.name))

    def new_recipe(self) -> None:
        def start() -> None:
            names = {r.name.casefold() for r in self.recipes}
            name = self.tr("New recipe")
            number = 2
            while name.casefold() in names:
                name = self.tr("New recipe %1").replace("%1", str(number))
                number += 1
            self.current = None
            self.draft = new_recipe_template(name)
            self.recipe_list.clearSelection()
            self.update_preview()
            self.show_draft()

        self.after_discard_confirmed(start)

    def copy_recipe(self) -> None:
        source = self.current
        if source is None or source.id is None:
            return
        keyboard = TextKeyboard(
            self.tr("Name of the copy"),
            self.tr("%1 copy").replace("%1", source.name)[:NAME_MAX_CHARS],
            max_length=NAME_MAX_CHARS,
            layout=self.context.keyboard_layout(),
            check=lambda text: (
                self._check("name", text)
                if self.draft is None or self.draft.name != text
                else self.tr("Choose a new name.")
            ),
        )

        def copy(name: str) -> None:
            user = self.context.session.acting_user()
            if user is None or source.id is None:
                return
            try:
                copied = self.context.database.copy_recipe(source.id, name, user)
            except DataError as exc:
                self._message(self.tr("Not copied"), str(exc))
                return
            self.current = copied
            self.draft = copied
            self.reload(copied.id)
            self.context.notify(self.tr("Recipe %1 created.").replace("%1", copied.name))

        keyboard.textAccepted.connect(lambda name: self.after_discard_confirmed(lambda: copy(name)))
        self.context.open(keyboard)

    def delete_recipe(self) -> None:
        recipe = self.current
        if recipe is None or recipe.id is None:
            return
        if self.snapshot is not None and self.snapshot.recipe_id == recipe.id:
            self._message(
                self.tr("Not deleted"),
                self.tr(
                    "Recipe %1 is selected on the machine: select another recipe there first."
                ).replace("%1", recipe.name),
            )
            return

        def confirm() -> None:
            overlay = ConfirmOverlay(
                self.tr("Delete recipe"),
                self.tr("Delete recipe %1 (%2)? Its last version stays in the recipe history.")
                .replace("%1", str(recipe.id))
                .replace("%2", recipe.name),
                self.tr("Delete"),
                danger=True,
            )
            overlay.finished.connect(lambda ok: self._do_delete(recipe) if ok else None)
            self.context.open(overlay)

        self.context.require(Role.TECHNICIAN, confirm)

    def _do_delete(self, recipe: Recipe) -> None:
        user = self.context.session.acting_user()
        if user is None or recipe.id is None:
            return
        try:
            self.context.database.delete_recipe(recipe.id, user)
        except DataError as exc:
            self._message(self.tr("Not deleted"), str(exc))
            return
        self.current = None
        self.draft = None
        self.reload()
        self.context.notify(self.tr("Recipe %1 deleted.").replace("%1", recipe.name))

    def import_recipes(self, directory: Path | None = None) -> None:
        def choose() -> None:
            chooser = FileChooser(
                self.tr("Import recipes"),
                directory or default_exchange_dir(),
                keyboard_layout=self.context.keyboard_layout(),
            )
            chooser.fileChosen.connect(lambda path: self.import_file(Path(path)))
            self.context.open(chooser)

        self.context.require(Role.TECHNICIAN, choose)

    def import_file(self, path: Path) -> None:
        user = self.context.session.acting_user()
        if user is None:
            return
        try:
            report = import_recipes(self.context.database, path, user)
        except (DataError, OSError, ValueError) as exc:
            self._message(self.tr("Import failed"), str(exc))
            return
        self.reload()
        lines = self.import_lines(report)
        shown = lines[:12] + (
            [self.tr("… and %1 more lines").replace("%1", str(len(lines) - 12))]
            if len(lines) > 12
            else []
        )
        self._message(self.tr("Import"), "\n".join(shown))

    def import_lines(self, report: ImportReport) -> list[str]:
        """The import's report in the user's language: the counts, then each rejected row's
        reasons in words (a reason about the file's own columns, an unknown or missing one,
        names that column as the file spells it)."""
        lines = [
            self.tr("%1: %2 accepted (%3 new, %4 updated, %5 unchanged), %6 rejected")
            .replace("%1", report.path.name)
            .replace("%2", str(report.accepted))
            .replace("%3", str(len(report.created)))
            .replace("%4", str(len(report.updated)))
            .replace("%5", str(len(report.unchanged)))
            .replace("%6", str(len(report.rejected)))
        ]
        for row in report.rejected:
            label = (
                self.tr("row %1 (%2)").replace("%1", str(row.row)).replace("%2", row.name)
                if row.name
                else self.tr("row %1").replace("%1", str(row.row))
            )
            for error in row.errors:
                reason = rule_message(error) if error.rule else error.message
                lines.append(f"{label}: {reason}")
        return lines

    def export_recipes(self, directory: Path | None = None) -> None:
        name = f"recipes-{datetime.now().strftime('%Y%m%d-%H%M')}.json"
        chooser = FileChooser(
            self.tr("Export recipes"),
            directory or default_exchange_dir(),
            save_name=name,
            keyboard_layout=self.context.keyboard_layout(),
        )
        chooser.fileChosen.connect(lambda path: self.export_file(Path(path)))
        self.context.open(chooser)

    def export_file(self, path: Path) -> None:
        try:
            count = export_recipes(self.context.database, path)
        except (DataError, OSError, ValueError) as exc:
            self._message(self.tr("Export failed"), str(exc))
            return
        self.context.notify(
            self.tr("%1 recipes written to %2.").replace("%1", str(count)).replace("%2", str(path))
        )

    def export_program(self, directory: Path | None = None) -> None:
        """The saved recipe's program (for the preview's width, or parametric) or drawing,
        written where the operator chooses (a USB stick, a folder)."""
        recipe = self.current
        if recipe is None or self.dirty:
            self._message(
                self.tr("Nothing to export"),
                self.tr("Select a saved recipe (save the changes first)."),
            )
            return
        width = self.preview_width_mm
        width_text = f"{format_number(width, 1)} mm"
        choices = [
            (self.tr("LinuxCNC program, %1").replace("%1", width_text), ExportFormat.LINUXCNC),
            (self.tr("LinuxCNC, parametric (every width)"), ExportFormat.LINUXCNC_PARAMETRIC),
            (self.tr("SINUMERIK program, %1").replace("%1", width_text), ExportFormat.SINUMERIK),
            (self.tr("DXF drawing, %1").replace("%1", width_text), ExportFormat.DXF),
        ]
        overlay = ChoiceOverlay(self.tr("Program for another control"), choices)
        overlay.chosen.connect(lambda chosen: self._export_as(recipe, chosen, width, directory))
        self.context.open(overlay)

    def _export_as(
        self, recipe: Recipe, export_format: ExportFormat, width_mm: float, directory: Path | None
    ) -> None:
        try:
            text = export_text(recipe, export_format, width_mm, self.parameters, self.limits)
        except ValueError as exc:  # the machine would refuse this board: say why
            self._message(self.tr("Not exported"), str(exc))
            return
        chooser = FileChooser(
            self.tr("Write the program"),
            directory or default_exchange_dir(),
            save_name=export_file_name(recipe, export_format, width_mm),
            keyboard_layout=self.context.keyboard_layout(),
            suffixes=(export_format.suffix,),
        )
        chooser.fileChosen.connect(lambda path: self._write_program(Path(path), text))
        self.context.open(chooser)

    def _write_program(self, path: Path, text: str) -> None:
        try:
            path.write_text(text, encoding="utf-8")
        except OSError as exc:
            self._message(self.tr("Export failed"), f"{path}: {exc.strerror}")
            return
        self.context.notify(self.tr("Written to %1.").replace("%1", str(path)))

    # -- machine ------------------------------------------------------------------------------

    def activated(self) -> None:
        self.parameters = self.context.database.get_parameters()
        if not self.dirty:
            self.reload()
        if (
            self.snapshot is not None
            and self.snapshot.last_width_mm
            and self.preview_width_mm == DEFAULT_PREVIEW_WIDTH_MM
        ):
            self.preview_width_mm = round(self.snapshot.last_width_mm, 1)
        self.update_preview()

    def update_snapshot(self, snapshot: MachineSnapshot, force: bool = False) -> None:
        previous = self.snapshot
        self.snapshot = snapshot
        if (
            force
            or previous is None
            or previous.allowed.get("SelectRecipe") != snapshot.allowed.get("SelectRecipe")
        ):
            self._update_buttons()
        if previous is None or previous.recipe_id != snapshot.recipe_id:
            self._relabel()  # the mark moves to the recipe now on the machine

    def apply_scale(self, scale: float) -> None:
        self.list_widget.setFixedWidth(round(LIST_WIDTH_PX * scale))
        for name in FIELDS:
            for label in (self.field_labels[name], self.range_labels[name]):
                label.setFixedWidth(round(LABEL_WIDTH_PX * scale))
        self.plan_view.set_scale(scale)
