"""The touch keypads and keyboard, operated by tapping their keys."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.keypad import Keypad, parse_number
from app.screens.widgets.overlay import top_overlay
from tests.screens.helpers import find_button


def type_keys(tap, keypad, keys: str) -> None:
    names = {".": "key_.", "±": "key_±"}
    for key in keys:
        tap(find_button(keypad, names.get(key, f"key_{key}")))


def test_number_keypad_accepts_a_value_in_range(host, qtbot, tap) -> None:
    keypad = Keypad.for_number("Thickness", 27.0, 25.0, 90.0, "mm")
    keypad.open_on(host)
    assert top_overlay(host) is keypad
    assert "25" in keypad.range_label.text() and "90" in keypad.range_label.text()
    assert keypad.display.text() == "27"
    type_keys(tap, keypad, "32.5")  # the first key replaces the shown value
    assert keypad.display.text() == "32.5"
    with qtbot.waitSignal(keypad.valueAccepted) as accepted:
        tap(find_button(keypad, "okButton"))
    assert accepted.args == [32.5]
    assert top_overlay(host) is None


def test_number_keypad_refuses_a_value_out_of_range_and_stays_open(host, qtbot, tap) -> None:
    keypad = Keypad.for_number("Thickness", 27.0, 25.0, 90.0, "mm")
    keypad.open_on(host)
    values: list[float] = []
    keypad.valueAccepted.connect(values.append)
    type_keys(tap, keypad, "120")
    assert keypad.display.property("invalid") == "true"  # red while typing
    tap(find_button(keypad, "okButton"))
    assert values == []
    assert keypad.is_open
    message = keypad.error_label.text()
    assert "120 mm is outside the allowed range" in message
    assert "25" in message and "90" in message
    tap(find_button(keypad, "key_clear"))
    type_keys(tap, keypad, "30")
    tap(find_button(keypad, "okButton"))
    assert values == [30.0]


def test_number_keypad_sign_point_backspace_and_custom_check(host, tap) -> None:
    keypad = Keypad.for_number(
        "Home X",
        0.0,
        -500.0,
        6000.0,
        "mm",
        decimals=2,
        check=lambda v: "not 13" if v == -13 else "",
    )
    keypad.open_on(host)
    assert find_button(keypad, "key_±").isEnabled()
    type_keys(tap, keypad, "13.456")  # third decimal refused
    assert keypad.text == "13.45"
    tap(find_button(keypad, "key_backspace"))
    tap(find_button(keypad, "key_backspace"))
    tap(find_button(keypad, "key_backspace"))
    assert keypad.text == "13"
    type_keys(tap, keypad, "±")
    assert keypad.text == "-13"
    tap(find_button(keypad, "okButton"))
    assert keypad.error_label.text() == "not 13"
    assert keypad.is_open


def test_integer_keypad_has_no_point_and_positive_range_has_no_sign(host) -> None:
    keypad = Keypad.for_number("Shifts", 3, 1, 6, integer=True)
    keypad.open_on(host)
    assert not find_button(keypad, "key_.").isEnabled()
    assert not find_button(keypad, "key_±").isEnabled()
    assert "whole number" in keypad.range_label.text()


def test_number_keypad_takes_a_usb_keyboard(host, qtbot) -> None:
    keypad = Keypad.for_number("Length", 950.0, 900.0, 3500.0, "mm")
    keypad.open_on(host)
    qtbot.keyClicks(keypad, "1234,5")
    assert keypad.text == "1234.5"
    with qtbot.waitSignal(keypad.valueAccepted) as accepted:
        qtbot.keyClick(keypad, Qt.Key.Key_Return)
    assert accepted.args == [1234.5]


def test_optional_keypad_can_be_emptied(host, qtbot, tap) -> None:
    keypad = Keypad.for_number("Barrel diameter", 600.0, 240.0, 4500.0, "mm", optional=True)
    keypad.open_on(host)
    tap(find_button(keypad, "key_clear"))
    with qtbot.waitSignal(keypad.cleared):
        tap(find_button(keypad, "okButton"))


def test_cancel_closes_without_a_value(host, qtbot, tap) -> None:
    keypad = Keypad.for_number("Length", 950.0, 900.0, 3500.0, "mm")
    keypad.open_on(host)
    with qtbot.waitSignal(keypad.finished) as finished:
        tap(find_button(keypad, "cancelButton"))
    assert finished.args == [False]
    assert top_overlay(host) is None


@pytest.mark.parametrize(
    ("text", "value"),
    [("12", 12.0), ("-0.5", -0.5), ("", None), ("-", None), (".", None), ("1e999", None)],
)
def test_parse_number(text: str, value: float | None) -> None:
    assert parse_number(text) == value


def test_fraction_keypad(host, qtbot, tap) -> None:
    def check(numerator: int, denominator: int) -> str:
        return "" if numerator / denominator < 0.5 else "no arc is left at 1/2 or more"

    keypad = Keypad.for_fraction("Length ratio", 1, 4, "0 to below 1/2", check)
    keypad.open_on(host)
    assert keypad.decimal_label.text() == "= 0.2500"
    type_keys(tap, keypad, "2")
    tap(find_button(keypad, "key_slash"))
    type_keys(tap, keypad, "3")
    assert keypad.values() == (2, 3)
    tap(find_button(keypad, "okButton"))
    assert "no arc" in keypad.error_label.text()
    assert keypad.is_open
    keypad.select(1)
    tap(find_button(keypad, "key_clear"))
    tap(find_button(keypad, "okButton"))
    assert "numerator and the denominator" in keypad.error_label.text()
    type_keys(tap, keypad, "0")
    tap(find_button(keypad, "okButton"))
    assert "must not be 0" in keypad.error_label.text()
    tap(find_button(keypad, "key_backspace"))
    type_keys(tap, keypad, "7")
    assert keypad.decimal_label.text() == "= 0.2857"
    with qtbot.waitSignal(keypad.fractionAccepted) as accepted:
        tap(find_button(keypad, "okButton"))
    assert accepted.args == [2, 7]


def test_pin_pad_masks_digits_and_reports_them(host, qtbot, tap) -> None:
    pad = Keypad.for_pin("Log in")
    pad.open_on(host)
    tap(find_button(pad, "okButton"))
    assert pad.error_label.text()  # empty PIN refused
    for key in "1234":
        tap(find_button(pad, f"key_{key}"))
    assert pad.display.text() == "●●●●"
    with qtbot.waitSignal(pad.pinEntered) as entered:
        tap(find_button(pad, "okButton"))
    assert entered.args == ["1234"]
    pad.show_error("Wrong PIN.")
    assert pad.is_open and pad.pin == "" and pad.error_label.text() == "Wrong PIN."


def test_text_keyboard(host, qtbot, tap) -> None:
    keyboard = TextKeyboard(
        "Name",
        "",
        max_length=6,
        layout="qwertz",
        check=lambda text: "taken" if text == "Taken" else "",
    )
    keyboard.open_on(host)
    tap(find_button(keyboard, "key_shift"))
    for key in "hrast":
        tap(find_button(keyboard, f"key_{key}"))
    assert keyboard.text == "Hrast"  # shift applies to one letter
    tap(find_button(keyboard, "key_š"))
    tap(find_button(keyboard, "key_ž"))  # seventh character refused
    assert keyboard.text == "Hrastš"
    assert "6" in keyboard.error_label.text()
    tap(find_button(keyboard, "key_backspace"))
    with qtbot.waitSignal(keyboard.textAccepted) as accepted:
        tap(find_button(keyboard, "okButton"))
    assert accepted.args == ["Hrast"]


def test_text_keyboard_refuses_empty_and_checked_text(host, tap) -> None:
    keyboard = TextKeyboard("Name", "Taken", check=lambda text: "taken" if text == "Taken" else "")
    keyboard.open_on(host)
    tap(find_button(keyboard, "okButton"))
    assert keyboard.error_label.text() == "taken"
    tap(find_button(keyboard, "key_clear"))
    tap(find_button(keyboard, "okButton"))
    assert keyboard.error_label.text()
    assert keyboard.is_open
