"""The ``stave simulate`` options that jog by hand: what is allowed, and the one-line
message naming the option, the value and what is allowed."""

from __future__ import annotations

import pytest

from app.cli.simulate_jog import JogOptionError, StickPush, WheelTurn, parse_stick, parse_wheel


def test_a_wheel_turn_is_axis_counts_and_an_optional_multiplier() -> None:
    assert parse_wheel("x:1000") == WheelTurn("X", 1000, 1)
    assert parse_wheel("Z:-25:100") == WheelTurn("Z", -25, 100)


def test_a_stick_push_is_axis_fraction_and_seconds() -> None:
    assert parse_stick("y:-0.25:2", ("X", "Y")) == StickPush("Y", -0.25, 2.0)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("W:10", "--handwheel 'W:10': axis 'W' is not allowed: AXIS:COUNTS[:MULT]"),
        ("X:10:5", "multiplier '5' is not allowed: 1, 10 or 100"),
        ("X:0", "counts '0' is not allowed: a whole number, not 0"),
        ("X:1.5", "counts '1.5' is not allowed"),
        ("X:200000", "from -100000 to 100000"),
        ("X", "--handwheel 'X' is not allowed: AXIS:COUNTS[:MULT]"),
    ],
)
def test_a_bad_wheel_turn_says_what_is_allowed(text: str, message: str) -> None:
    with pytest.raises(JogOptionError) as raised:
        parse_wheel(text)
    assert message in str(raised.value)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("X:1.5:1", "fraction '1.5' is not allowed: -1 to 1, not 0"),
        ("X:0:1", "fraction '0' is not allowed"),
        ("X:nan:1", "fraction 'nan' is not allowed"),
        ("Y:0.5:0", "seconds '0' is not allowed: more than 0, at most 60"),
        ("Y:0.5:inf", "seconds 'inf' is not allowed"),
        ("Z:0.5:1", "axis 'Z' is not allowed: AXIS:FRACTION:SECONDS, AXIS one of X, Y"),
        ("X:0.5", "--joystick 'X:0.5' is not allowed: AXIS:FRACTION:SECONDS"),
    ],
)
def test_a_bad_stick_push_says_what_is_allowed(text: str, message: str) -> None:
    with pytest.raises(JogOptionError) as raised:
        parse_stick(text, ("X", "Y"))
    assert message in str(raised.value)
