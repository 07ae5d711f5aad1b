"""Recipes screen: the side profile kind, a family's parameters on the keypad, a DXF drawing
through the touch file chooser, and the preview drawing the curve."""

from __future__ import annotations

from app.data.recipe_profile import RecipeProfile
from app.geometry.profile_kinds import ProfileKind
from app.screens.widgets.dialogs import ChoiceOverlay, MessageOverlay
from app.screens.widgets.file_chooser import FileChooser
from app.screens.widgets.keypad import KeypadMode
from tests.data import dxf_drawings as drawings
from tests.screens.helpers import find_button, is_keypad
from tests.screens.test_recipes_screen import keys, open_recipes


def choose_kind(window, tap, screen, title: str) -> None:
    tap(find_button(screen, "field_profile_kind"))
    chooser = window.overlay()
    assert isinstance(chooser, ChoiceOverlay)
    button = next(b for b in chooser.buttons if b.text() == title)
    tap(button)


def test_superellipse_chosen_with_its_exponent_on_the_keypad_and_saved(
    qtbot, window, database, tap
) -> None:
    screen = open_recipes(window, tap)
    recipe = database.list_recipes()[0]
    screen.select_recipe(recipe.id)
    line_arc_line_path = screen.preview.toolpath
    assert screen.field_buttons["length_ratio"].isVisible()
    assert not screen.field_buttons["exponent"].isVisible()
    choose_kind(window, tap, screen, "Superellipse")
    assert screen.draft.profile.kind is ProfileKind.SUPERELLIPSE
    assert screen.field_buttons["exponent"].isVisible()
    assert screen.field_buttons["semi_axis_ratio"].isVisible()
    assert not screen.field_buttons["length_ratio"].isVisible()
    assert "2 … 10" in screen.range_labels["exponent"].text()
    screen.form_scroll.ensureWidgetVisible(screen.field_buttons["exponent"])  # as a finger
    tap(screen.field_buttons["exponent"])
    keypad = window.overlay()
    assert is_keypad(keypad, KeypadMode.NUMBER)
    tap(find_button(keypad, "key_clear"))
    keys(tap, keypad, "12")
    tap(find_button(keypad, "okButton"))
    assert keypad.is_open, "an exponent of 12 is out of range"
    assert "Allowed: 2 to 10" in keypad.error_label.text()
    tap(find_button(keypad, "key_clear"))
    keys(tap, keypad, "6")
    tap(find_button(keypad, "okButton"))
    assert dict(screen.draft.profile.params)["exponent"] == 6.0
    assert screen.preview.toolpath != line_arc_line_path  # the preview draws the new curve
    assert screen.preview.errors == ()
    tap(find_button(screen, "saveRecipe"))
    stored = database.get_recipe(recipe.id).profile
    assert stored.kind is ProfileKind.SUPERELLIPSE and dict(stored.params)["exponent"] == 6.0


def test_a_drawing_imported_through_the_file_chooser(qtbot, window, database, tap, tmp_path):
    (tmp_path / "house style.dxf").write_bytes(drawings.spline())
    (tmp_path / "two curves.dxf").write_bytes(
        drawings.with_entities(
            lambda space: (
                space.add_open_spline(drawings.SPLINE_POINTS, degree=3),
                space.add_line((0, 100), (500, 100), dxfattribs={"layer": "FRAME"}),
            )
        )
    )
    screen = open_recipes(window, tap)
    recipe = database.list_recipes()[0]
    screen.select_recipe(recipe.id)
    choose_kind(window, tap, screen, "Drawn (DXF)")
    assert screen.field_buttons["drawing"].isVisible()
    assert screen.error_labels["drawing"].isVisible()  # no drawing yet: cannot be saved
    screen.choose_drawing(tmp_path)
    chooser = window.overlay()
    assert isinstance(chooser, FileChooser)
    names = [chooser.entries.item(i).text().strip() for i in range(chooser.entries.count())]
    assert "house style.dxf" in names and "two curves.dxf" in names

    def pick(name: str) -> None:
        item = next(
            chooser.entries.item(i)
            for i in range(chooser.entries.count())
            if chooser.entries.item(i).text().strip() == name
        )
        chooser._clicked(item)
        tap(find_button(chooser, "okButton"))

    pick("two curves.dxf")
    layers = window.overlay()  # a spline on layer 0 and a frame line on FRAME: which one?
    assert isinstance(layers, ChoiceOverlay)
    assert [b.text() for b in layers.buttons] == ["0", "FRAME"]
    tap(layers.buttons[1])
    message = window.overlay()
    assert isinstance(message, MessageOverlay)
    assert "two curves.dxf: drawn_profile: the curve has no belly" in (message.message_label.text())
    tap(find_button(message, "okButton"))
    screen.choose_drawing(tmp_path)
    chooser = window.overlay()
    pick("two curves.dxf")
    tap(window.overlay().buttons[0])
    assert window.overlay() is None
    assert screen.draft.profile.file_name == "two curves.dxf"
    assert [p.source.split(" #")[0] for p in screen.draft.profile.drawing.primitives] == ["SPLINE"]
    screen.choose_drawing(tmp_path)
    chooser = window.overlay()
    pick("house style.dxf")
    profile = screen.draft.profile
    assert isinstance(profile, RecipeProfile) and profile.file_name == "house style.dxf"
    assert "house style.dxf" in screen.field_buttons["drawing"].text()
    assert screen.preview.errors == () and len(screen.preview.outline) > 100
    tap(find_button(screen, "saveRecipe"))
    assert database.get_recipe(recipe.id).profile == profile
