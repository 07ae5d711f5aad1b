"""Recipes screen: an oval barrel's short axis and a belly width to cut, entered on the
keypads and checked by the recipe's own rules; the preview shows both sides' tilts."""

from __future__ import annotations

import pytest

from app.data.recipe import BarrelType
from app.geometry.limits import width_ratio_minimum
from app.geometry.ratio import Ratio
from app.screens.formatting import format_number
from app.screens.widgets.keypad import Keypad, KeypadMode
from tests.screens.helpers import find_button, is_keypad
from tests.screens.test_recipes_screen import keys, open_recipes


def tap_choice(window, tap, name: str) -> None:
    """Tap a button of the recipe form, scrolled into view first (as a finger would)."""
    button = find_button(window, name)
    window.page("recipes").form_scroll.ensureWidgetVisible(button)
    tap(button)


def enter(window, tap, field: str, text: str) -> Keypad:
    window.page("recipes").edit_field(field)  # the row's tap (it may be scrolled out of view)
    keypad = window.overlay()
    assert is_keypad(keypad, KeypadMode.NUMBER)
    tap(find_button(keypad, "key_clear"))
    keys(tap, keypad, text)
    tap(find_button(keypad, "okButton"))
    return keypad


def test_an_oval_recipe_on_the_keypads(qtbot, window, database, tap) -> None:
    screen = open_recipes(window, tap)
    # A round barrel of 760 mm that is not the machine's recipe (that one is edited on a copy).
    barrique = database.get_recipe_by_name("Hogshead 300 l")
    screen.select_recipe(barrique.id)
    assert screen.preview.tilt_deg == screen.preview.tilt_b_deg  # round: one bevel
    assert find_button(window, "barrelType_round").isChecked()
    assert not find_button(window, "field_barrel_minor_diameter_mm").isVisible()
    # The tilt comes from the barrel: shown, not entered; the diameter is not optional.
    tilt_row = find_button(window, "field_tilt_deg")
    assert not tilt_row.isEnabled()
    assert tilt_row.text() == f"{format_number(screen.preview.tilt_deg, 2)} °"
    assert screen.range_labels["tilt_deg"].text() == "from the barrel, for a 150 mm board"
    assert screen.range_labels["barrel_diameter_mm"].text().endswith("mm")
    tap_choice(window, tap, "barrelType_oval")
    assert screen.draft.barrel_type is BarrelType.OVAL
    assert find_button(window, "field_barrel_minor_diameter_mm").isVisible()
    assert screen.error_labels["barrel_minor_diameter_mm"].text() == (
        "An oval barrel needs its short axis"
    )
    refused = enter(window, tap, "barrel_minor_diameter_mm", "800")  # longer than 760
    assert refused.is_open and refused.error_label.text() == (
        "800 mm is not allowed: the short axis is 380 mm up to the long axis, 760 mm"
    )
    tap(find_button(refused, "cancelButton"))
    assert enter(window, tap, "barrel_minor_diameter_mm", "740").is_open is False
    assert screen.draft.barrel_type is BarrelType.OVAL
    assert find_button(window, "field_barrel_minor_diameter_mm").text() == "740.0 mm"
    preview = screen.preview
    assert preview.ok and preview.tilt_deg != preview.tilt_b_deg
    tilt_text = screen.result_labels["tilt"].text()
    assert tilt_text.startswith("A ") and " / B " in tilt_text
    both = f"{format_number(preview.tilt_deg, 2)} / {format_number(preview.tilt_b_deg, 2)} °"
    assert find_button(window, "field_tilt_deg").text() == both

    assert enter(window, tap, "target_width_mm", "300").is_open  # wider than any board
    tap(find_button(window.overlay(), "cancelButton"))
    assert enter(window, tap, "target_width_mm", "120").is_open is False
    tap(find_button(window, "saveRecipe"))
    stored = database.get_recipe(barrique.id)
    assert (stored.barrel_minor_diameter_mm, stored.target_width_mm) == (740.0, 120.0)


def test_a_fixed_tilt_is_entered_and_the_barrel_is_then_optional(qtbot, window, tap) -> None:
    screen = open_recipes(window, tap)
    tap_choice(window, tap, "barrelType_fixed")
    assert screen.draft is not None and screen.draft.barrel_type is BarrelType.FIXED_TILT
    assert find_button(window, "field_tilt_deg").isEnabled()
    assert find_button(window, "field_tilt_deg").text().endswith("°")
    assert screen.range_labels["barrel_diameter_mm"].text().endswith("(optional)")
    tap_choice(window, tap, "barrelType_round")
    assert not screen.range_labels["barrel_diameter_mm"].text().endswith("(optional)")


def test_the_hints_state_the_bounds_the_validation_applies(qtbot, window, tap) -> None:
    """The width ratio's hint names the smallest ratio the validation accepts (it used to say
    "above 0" while 1/10 was refused), and a fixed tilt's the tilts that fit a barrel."""
    screen = open_recipes(window, tap)
    tap_choice(window, tap, "barrelType_fixed")
    limits = screen.limits
    k_min = width_ratio_minimum(limits)
    assert screen.range_labels["width_ratio"].text() == f"{format_number(k_min, 3)} to below 1"
    below = Ratio(1, 10)
    assert below.value < k_min and screen._check("width_ratio", below)  # refused, as hinted
    assert screen._check("width_ratio", Ratio(1, 4)) == ""
    low, high, unit = screen.field_range("tilt_deg")
    assert unit == "°" and limits.min_tilt_deg < low < high <= limits.max_tilt_deg
    assert screen.range_labels["tilt_deg"].text() == (
        f"{format_number(low)} … {format_number(high)} °"
    )
    assert screen._check("tilt_deg", low) == "" and screen._check("tilt_deg", high) == ""
    assert screen._check("tilt_deg", low - 0.02) and screen._check("tilt_deg", high + 0.02)
    # A belly width to cut keeps the head at its minimum: 60 mm / k.
    low, high, _ = screen.field_range("target_width_mm")
    k = screen.draft.width_ratio.value
    assert low == pytest.approx(limits.min_head_width_mm / k, abs=0.1) and low > 60.0
    assert screen.range_labels["target_width_mm"].text().startswith(f"{format_number(low)} … ")
    assert screen._check("target_width_mm", low) == ""
    assert screen._check("target_width_mm", low - 0.2)
