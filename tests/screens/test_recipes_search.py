"""Recipes at scale: search by name and filter by barrel type on the Recipes screen and in the
main screen's chooser (typed on the on-screen keyboard), the recipe on the machine marked, and
recipe numbers never cut off."""

from __future__ import annotations

from dataclasses import replace

import pytest

from app.data.recipe import BarrelType, Recipe
from app.data.users import Role
from app.machine.commands import SelectRecipe
from app.screens.recipe_chooser import RecipeChooser
from app.screens.recipe_filter import RecipeFilter
from app.screens.widgets.buttons import ElidedButton
from app.screens.widgets.dialogs import ChoiceOverlay
from app.screens.widgets.keyboard import TextKeyboard
from tests.data.test_recipe import make_recipe
from tests.screens.helpers import find_button, wait_for
from tests.screens.test_recipes_screen import keys, open_recipes

RECIPES_ON_THE_PANEL = 70


@pytest.fixture
def many(database) -> list[Recipe]:
    """The samples and copies of them up to 70 recipes, one of them an oval barrel."""
    service = {u.role: u for u in database.list_users()}[Role.SERVICE]
    samples = database.list_recipes()
    count = len(samples)
    while count < RECIPES_ON_THE_PANEL:
        source = samples[count % len(samples)]
        database.save_recipe(replace(source, id=None, name=f"{source.name} no. {count}"), service)
        count += 1
    oval = [r for r in database.list_recipes() if r.barrel_type is BarrelType.ROUND][-1]
    assert oval.barrel_diameter_mm is not None
    database.save_recipe(
        replace(
            oval,
            barrel_type=BarrelType.OVAL,
            barrel_minor_diameter_mm=round(oval.barrel_diameter_mm * 0.8),
        ),
        service,
    )
    return database.list_recipes()


def listed_ids(screen) -> list[int]:
    return [screen.recipe_list.item(row).data(256) for row in range(screen.recipe_list.count())]


def search(window, tap, button_parent, text: str) -> None:
    tap(find_button(button_parent, "recipeSearch"))
    keyboard = window.overlay()
    assert isinstance(keyboard, TextKeyboard)
    tap(find_button(keyboard, "key_clear"))
    for word_index, word in enumerate(text.split(" ")):
        if word_index:
            tap(find_button(keyboard, "key_space"))
        keys(tap, keyboard, word)
    tap(find_button(keyboard, "okButton"))


def test_the_filter_finds_names_without_case_or_accents_and_numbers() -> None:
    piece = make_recipe(name="Pièce 228 l Bourgogne")
    piece = replace(piece, id=12)
    assert RecipeFilter("PIECE").matches(piece)
    assert RecipeFilter("bourg").matches(piece)
    assert RecipeFilter("12").matches(piece)
    assert not RecipeFilter("1").matches(piece)  # a number is matched whole
    assert not RecipeFilter("bordeaux").matches(piece)
    assert not RecipeFilter(barrel_type=BarrelType.ROUND).matches(piece)  # a fixed tilt
    assert RecipeFilter(barrel_type=BarrelType.FIXED_TILT).matches(piece)


def test_search_and_filter_on_the_recipes_screen(qtbot, window, many, tap) -> None:
    screen = open_recipes(window, tap)
    assert len(listed_ids(screen)) == RECIPES_ON_THE_PANEL
    search(window, tap, window, "bordeaux")
    expected = [r.id for r in many if "bordeaux" in r.name.casefold()]
    assert 1 < len(expected) < RECIPES_ON_THE_PANEL
    assert listed_ids(screen) == expected
    assert screen.list_count.text() == f"{len(expected)} of {RECIPES_ON_THE_PANEL} recipes"
    assert find_button(window, "recipeSearch").text() == "“bordeaux”"

    tap(find_button(window, "filterType"))
    choice = window.overlay()
    assert isinstance(choice, ChoiceOverlay)
    tap(choice.buttons[2])  # Round
    round_ones = [
        r.id for r in many if "bordeaux" in r.name.casefold() and r.barrel_type is BarrelType.ROUND
    ]
    assert listed_ids(screen) == round_ones
    assert find_button(window, "filterType").text() == "Round"

    search(window, tap, window, "")  # the keyboard's C and OK: every name again
    assert listed_ids(screen) == [r.id for r in many if r.barrel_type is BarrelType.ROUND]
    tap(find_button(window, "filterType"))
    tap(window.overlay().buttons[3])  # Oval
    [oval] = [r for r in many if r.barrel_type is BarrelType.OVAL]
    assert listed_ids(screen) == [oval.id]
    tap(find_button(window, "filterType"))
    tap(window.overlay().buttons[0])  # All
    assert len(listed_ids(screen)) == RECIPES_ON_THE_PANEL


def test_the_recipe_on_the_machine_is_marked_in_the_list(qtbot, window, many, tap) -> None:
    screen = open_recipes(window, tap)
    target = many[9]
    window.link.send(SelectRecipe(target.id))
    wait_for(qtbot, window, lambda s: s.recipe_id == target.id)
    qtbot.waitUntil(lambda: screen.recipe_list.item(9).text().startswith("▶"))
    marked = [
        screen.recipe_list.item(row).text()
        for row in range(screen.recipe_list.count())
        if "on the machine" in screen.recipe_list.item(row).text()
    ]
    assert marked == [screen.recipe_list.item(9).text()]
    assert marked[0].startswith(f"▶ {target.id}  {target.name}\n")
    other = many[10]
    window.link.send(SelectRecipe(other.id))
    qtbot.waitUntil(lambda: screen.recipe_list.item(10).text().startswith("▶"))
    assert not screen.recipe_list.item(9).text().startswith("▶")


def test_the_chooser_shows_every_number_whole_and_searches(qtbot, window, many, tap) -> None:
    tap(find_button(window, "recipeList"))
    chooser = window.overlay()
    assert isinstance(chooser, RecipeChooser)
    assert len(chooser.buttons) == RECIPES_ON_THE_PANEL
    for recipe, button in zip(many, chooser.buttons, strict=True):
        assert isinstance(button, ElidedButton)
        shown = button.shown_text()
        assert shown.startswith(f"{recipe.id}  "), shown  # never "0 ..." for recipe 10
        # The middle goes, the end stays: names of one barrel differ at their ends.
        head, ellipsis, tail = shown.partition("…")
        assert shown == button.text() or (
            ellipsis and button.text().startswith(head) and button.text().endswith(tail)
        )
        assert not ellipsis or len(tail) >= 4, shown
    assert any("…" in button.shown_text() for button in chooser.buttons)

    tap(find_button(chooser, "filter_oval"))
    [oval] = [r for r in many if r.barrel_type is BarrelType.OVAL]
    assert [b.objectName() for b in chooser.buttons] == [f"chooseRecipe_{oval.id}"]
    shown = [b for b in chooser.content.findChildren(ElidedButton) if b.isVisible()]
    assert shown == chooser.buttons  # the buttons filtered out are not drawn any more
    tap(find_button(chooser, "filter_all"))
    search(window, tap, chooser, "no. 6")
    expected = [r for r in many if "no. 6" in r.name]
    assert len(chooser.buttons) == len(expected) and chooser.count_label.text() == (
        f"{len(expected)} of {RECIPES_ON_THE_PANEL} recipes"
    )
    tap(find_button(chooser, "clearSearch"))
    assert len(chooser.buttons) == RECIPES_ON_THE_PANEL
    tap(chooser.buttons[9])
    wait_for(qtbot, window, lambda s: s.recipe_id == many[9].id)
    assert window.overlay() is None


def test_the_ratios_are_shown_whole_at_1024x768(qtbot, window, tap) -> None:
    """A field that does not fit ends in an ellipsis; the ratios, fraction and decimal, fit."""
    screen = open_recipes(window, tap)
    for recipe in screen.recipes:
        screen.select_recipe(recipe.id)
        for name in ("length_ratio", "width_ratio", "length_mm", "thickness_mm"):
            button = find_button(window, f"field_{name}")
            assert isinstance(button, ElidedButton)
            assert button.shown_text() == button.text(), (recipe.name, button.text())
