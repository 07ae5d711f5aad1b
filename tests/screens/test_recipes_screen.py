"""Recipes screen: edit through the keypads, see bad values refused, save, new/copy/delete,
import and export, and the preview following the draft."""

from __future__ import annotations

import json

from app.geometry.width_range import cuttable_widths
from app.screens.formatting import format_number
from app.screens.widgets.dialogs import ConfirmOverlay, MessageOverlay
from app.screens.widgets.file_chooser import FileChooser
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.keypad import KeypadMode
from tests.screens.helpers import enter_pin, find_button, is_keypad, wait_for


def open_recipes(window, tap):
    tap(find_button(window, "nav_recipes"))
    screen = window.page("recipes")
    assert window.current_screen is screen
    return screen


def keys(tap, overlay, text: str) -> None:
    for key in text:
        tap(find_button(overlay, f"key_{key}"))


def test_edit_thickness_through_the_keypad_bad_value_refused(qtbot, window, database, tap) -> None:
    screen = open_recipes(window, tap)
    recipe = database.list_recipes()[0]
    screen.select_recipe(recipe.id)
    assert screen.draft == recipe and not screen.dirty
    assert screen.preview is not None and screen.preview.ok
    d_before = screen.preview.d_mm

    tap(find_button(window, "field_thickness_mm"))
    keypad = window.overlay()
    assert is_keypad(keypad, KeypadMode.NUMBER)
    assert "25" in keypad.range_label.text() and "90" in keypad.range_label.text()
    keys(tap, keypad, "120")
    tap(find_button(keypad, "okButton"))
    assert keypad.is_open, "120 mm must be refused"
    assert "outside the allowed range" in keypad.error_label.text()
    assert screen.draft.thickness_mm == recipe.thickness_mm
    tap(find_button(keypad, "key_clear"))
    keys(tap, keypad, "32")
    tap(find_button(keypad, "okButton"))
    assert window.overlay() is None
    assert screen.draft.thickness_mm == 32.0 and screen.dirty
    assert find_button(window, "field_thickness_mm").text() == "32 mm"
    assert "not saved" in screen.editor_title.text()

    # A length change moves the preview (same width, longer stave: other rise D).
    tap(find_button(window, "field_length_mm"))
    keypad = window.overlay()
    keys(tap, keypad, "1200")
    tap(find_button(keypad, "okButton"))
    assert screen.preview.ok and screen.preview.d_mm != d_before

    tap(find_button(window, "saveRecipe"))
    stored = database.get_recipe(recipe.id)
    assert stored.thickness_mm == 32.0 and stored.length_mm == 1200.0
    assert not screen.dirty


def test_a_width_ratio_that_makes_the_head_too_narrow_is_refused(qtbot, window, tap) -> None:
    screen = open_recipes(window, tap)
    original = screen.draft
    tap(find_button(window, "field_width_ratio"))
    keypad = window.overlay()
    assert is_keypad(keypad, KeypadMode.FRACTION)
    keys(tap, keypad, "1")
    tap(find_button(keypad, "key_slash"))
    keys(tap, keypad, "5")
    tap(find_button(keypad, "okButton"))
    assert keypad.is_open
    assert keypad.error_label.text() == (
        "0.2 makes the head narrower than 60 mm even on a board of 280 mm: allowed 0.214 to below 1"
    )
    tap(find_button(keypad, "cancelButton"))
    assert screen.draft == original


def test_new_recipe_named_on_the_keyboard_and_saved(qtbot, window, database, tap) -> None:
    screen = open_recipes(window, tap)
    count = len(database.list_recipes())
    tap(find_button(window, "newRecipe"))
    assert screen.draft.id is None and screen.dirty
    tap(find_button(window, "field_name"))
    keyboard = window.overlay()
    assert isinstance(keyboard, TextKeyboard)
    tap(find_button(keyboard, "key_clear"))
    tap(find_button(keyboard, "key_shift"))
    keys(tap, keyboard, "barrique")
    tap(find_button(keyboard, "okButton"))
    assert screen.draft.name == "Barrique"
    tap(find_button(window, "saveRecipe"))
    recipes = database.list_recipes()
    assert len(recipes) == count + 1
    assert any(r.name == "Barrique" for r in recipes)
    assert screen.current is not None and screen.current.name == "Barrique"


def test_a_duplicate_name_is_refused_on_the_keyboard(qtbot, window, database, tap) -> None:
    screen = open_recipes(window, tap)
    first, second = database.list_recipes()[:2]
    screen.select_recipe(second.id)
    tap(find_button(window, "field_name"))
    keyboard = window.overlay()
    tap(find_button(keyboard, "key_clear"))
    keyboard.text = first.name  # typed letter by letter in the test above
    tap(find_button(keyboard, "okButton"))
    assert keyboard.is_open
    assert first.name in keyboard.error_label.text()


def test_copy_then_delete_with_confirmation_and_technician_pin(
    qtbot, window, database, tap
) -> None:
    screen = open_recipes(window, tap)
    source = database.list_recipes()[0]
    screen.select_recipe(source.id)
    tap(find_button(window, "copyRecipe"))
    keyboard = window.overlay()
    assert isinstance(keyboard, TextKeyboard)
    assert keyboard.text.endswith("copy")
    tap(find_button(keyboard, "okButton"))
    copy = database.get_recipe_by_name(keyboard.text)
    assert copy is not None and copy.length_mm == source.length_mm
    assert screen.current.id == copy.id

    tap(find_button(window, "deleteRecipe"))
    pad = window.overlay()
    assert is_keypad(pad, KeypadMode.PIN)  # an operator may not delete: a technician PIN is asked
    enter_pin(qtbot, window, tap, "0000")
    assert "Technician" in pad.error_label.text()
    enter_pin(qtbot, window, tap, "1234")
    confirm = window.overlay()
    assert isinstance(confirm, ConfirmOverlay)
    assert copy.name in confirm.message_label.text()
    tap(confirm.confirm_button)
    assert database.get_recipe_by_name(copy.name) is None
    window.session.logout()


def test_export_then_import(qtbot, window, database, tap, tmp_path) -> None:
    screen = open_recipes(window, tap)
    screen.export_recipes(tmp_path)
    chooser = window.overlay()
    assert isinstance(chooser, FileChooser)
    tap(find_button(chooser, "okButton"))
    exported = list(tmp_path.glob("recipes-*.json"))
    assert len(exported) == 1
    document = json.loads(exported[0].read_text(encoding="utf-8"))
    assert [row["name"] for row in document["recipes"]] == [r.name for r in database.list_recipes()]

    incoming = tmp_path / "incoming.json"
    incoming.write_text(
        json.dumps(
            [
                {
                    "name": "Imported 1",
                    "length_mm": 1000,
                    "thickness_mm": 27,
                    "length_ratio": "1/4",
                    "width_ratio": "3/4",
                    "tilt_deg": 7.5,
                },
                {
                    "name": "Too short",
                    "length_mm": 500,
                    "thickness_mm": 27,
                    "length_ratio": "1/4",
                    "width_ratio": "3/4",
                    "tilt_deg": 7.5,
                },
            ]
        ),
        encoding="utf-8",
    )
    window.session.set_user(database.authenticate("1234"))
    screen.import_recipes(tmp_path)
    chooser = window.overlay()
    assert isinstance(chooser, FileChooser)
    item = next(
        chooser.entries.item(i)
        for i in range(chooser.entries.count())
        if chooser.entries.item(i).text().strip() == "incoming.json"
    )
    chooser._clicked(item)
    tap(find_button(chooser, "okButton"))
    report = window.overlay()
    assert isinstance(report, MessageOverlay)
    text = report.message_label.text()
    assert "1 accepted" in text and "1 rejected" in text
    assert "row 2 (Too short): 500 is outside the allowed range: 900 to 3500 mm" in text
    assert "length_mm" not in text  # the reason in words, not the program's field
    assert database.get_recipe_by_name("Imported 1") is not None
    window.session.logout()


def test_preview_width_follows_the_keypad(qtbot, window, tap) -> None:
    screen = open_recipes(window, tap)
    tap(find_button(window, "previewWidth"))
    keypad = window.overlay()
    keys(tap, keypad, "300")
    tap(find_button(keypad, "okButton"))
    assert keypad.is_open  # above the 280 mm the machine takes
    tap(find_button(keypad, "key_clear"))
    keys(tap, keypad, "160")
    tap(find_button(keypad, "okButton"))
    assert screen.preview.width_mm == 160.0 and screen.preview.ok
    assert screen.plan_view.outline_item.getData()[0] is not None
    # 200 mm tilts the first recipe's bevel beyond this machine's Z travel (+-15 deg).
    screen.set_preview_width(200.0)
    assert not screen.preview.ok
    assert "Outside the widths" in screen.preview_errors.text()


def test_the_recipe_on_the_machine_is_not_deleted_and_a_saved_change_asks(
    qtbot, window, machine, database, tap
) -> None:
    screen = open_recipes(window, tap)
    on_machine = machine.controller.recipe
    assert on_machine is not None and on_machine.id is not None
    screen.select_recipe(on_machine.id)

    tap(find_button(window, "deleteRecipe"))
    refused = window.overlay()
    assert isinstance(refused, MessageOverlay)  # before any PIN: nothing to authorise
    assert on_machine.name in refused.message_label.text()
    assert "selected on the machine" in refused.message_label.text()
    tap(find_button(refused, "okButton"))
    assert database.get_recipe(on_machine.id) == on_machine

    def save_thickness(text: str) -> ConfirmOverlay:
        tap(find_button(window, "field_thickness_mm"))
        keypad = window.overlay()
        tap(find_button(keypad, "key_clear"))
        keys(tap, keypad, text)
        tap(find_button(keypad, "okButton"))
        tap(find_button(window, "saveRecipe"))
        question = window.overlay()
        assert isinstance(question, ConfirmOverlay)
        assert on_machine.name in question.message_label.text()
        return question

    tap(save_thickness("33").cancel_button)  # keep the version the machine has
    machine.run_for(0.1)
    assert database.get_recipe(on_machine.id).thickness_mm == 33.0
    assert machine.controller.recipe == on_machine

    tap(save_thickness("34").confirm_button)
    wait_for(
        qtbot,
        window,
        lambda s: (
            machine.controller.recipe is not None and machine.controller.recipe.thickness_mm == 34.0
        ),
    )


def test_the_list_shows_each_recipes_widths_on_this_machine(qtbot, window, database, tap) -> None:
    screen = open_recipes(window, tap)
    items = [screen.recipe_list.item(row) for row in range(screen.recipe_list.count())]
    assert items and all("\n" in item.text() for item in items)  # at once, ranges to follow
    qtbot.waitUntil(lambda: not any(item.text().endswith("…") for item in items), timeout=20_000)
    parameters = database.get_parameters()
    for recipe, item in zip(database.list_recipes(), items, strict=True):
        widths = cuttable_widths(recipe.stave, parameters, database.limits)  # the machine's own
        assert widths is not None, recipe.name  # the shipped recipes fit the shipped machine
        expected = f"{format_number(widths.min_mm, 1)} to {format_number(widths.max_mm, 1)} mm"
        if window.poller.snapshot.recipe_id == recipe.id:  # marked
            expected = f"on the machine, {expected}"
            assert item.text() == f"▶ {recipe.id}  {recipe.name}\n{expected}"
        else:
            assert item.text() == f"{recipe.id}  {recipe.name}\n{expected}"
