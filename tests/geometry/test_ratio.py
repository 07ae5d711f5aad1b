import pickle
from fractions import Fraction

import pytest

from app.geometry.ratio import Ratio


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("3/4", Ratio(3, 4)),
        ("1/4", Ratio(1, 4)),
        (" 6 / 8 ", Ratio(6, 8)),  # kept as entered, not reduced
        ("0.75", Ratio(3, 4)),
        ("0.25", Ratio(1, 4)),
        (".5", Ratio(1, 2)),
        ("1", Ratio(1, 1)),
        ("0", Ratio(0, 1)),
        ("0.33333", Ratio(1, 3)),  # nearest fraction with a denominator <= 10000
        ("0.12345", Ratio(448, 3629)),
        ("2.5e-1", Ratio(1, 4)),
    ],
)
def test_parse_accepts_fractions_and_decimals(text, expected):
    ratio = Ratio.parse(text)
    assert ratio == expected
    assert ratio.denominator <= 10_000


def test_decimal_conversion_is_the_nearest_fraction():
    ratio = Ratio.parse("0.12345")
    assert ratio.fraction == Fraction("0.12345").limit_denominator(10_000)
    assert abs(ratio.value - 0.12345) < 1e-6


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        ("", "expected a fraction"),
        ("abc", "expected a fraction"),
        ("3/0", "denominator must not be 0"),
        ("1/2/3", "expected a fraction"),
        ("-1/4", "expected a fraction"),
        ("-0.25", "expected a fraction"),
        ("1.5/2", "expected a fraction"),
        ("nan", "expected a fraction"),
        ("inf", "expected a fraction"),
        ("3/4x", "expected a fraction"),
    ],
)
def test_parse_rejects_bad_text_naming_it(text, fragment):
    with pytest.raises(ValueError, match=fragment) as info:
        Ratio.parse(text)
    assert repr(text) in str(info.value)


def test_parse_rejects_non_text():
    with pytest.raises(ValueError, match="invalid ratio"):
        Ratio.parse(0.75)  # type: ignore[arg-type]


def test_str_value_and_fraction():
    ratio = Ratio(6, 8)
    assert str(ratio) == "6/8"
    assert ratio.value == 0.75
    assert ratio.fraction == Fraction(3, 4)


def test_str_round_trips_through_parse():
    for ratio in (Ratio(1, 4), Ratio(3, 4), Ratio(2, 3), Ratio(0, 5), Ratio(4999, 10000)):
        assert Ratio.parse(str(ratio)) == ratio


def test_from_float():
    assert Ratio.from_float(0.75) == Ratio(3, 4)
    assert Ratio.from_float(1 / 3) == Ratio(1, 3)
    assert Ratio.from_float(0.3333, max_denominator=10) == Ratio(1, 3)
    assert Ratio.from_float(0) == Ratio(0, 1)


@pytest.mark.parametrize("value", [float("nan"), float("inf"), -0.5, True, "0.5"])
def test_from_float_rejects(value):
    with pytest.raises(ValueError, match="invalid ratio"):
        Ratio.from_float(value)


def test_from_float_rejects_bad_max_denominator():
    with pytest.raises(ValueError, match="max_denominator"):
        Ratio.from_float(0.5, max_denominator=0)


@pytest.mark.parametrize(
    ("numerator", "denominator", "fragment"),
    [
        (1, 0, "denominator must be a positive integer"),
        (1, -4, "denominator must be a positive integer"),
        (-1, 4, "numerator must not be negative"),
        (1.5, 4, "numerator must be an integer"),
        (1, True, "denominator must be an integer"),
    ],
)
def test_constructor_validates(numerator, denominator, fragment):
    with pytest.raises(ValueError, match=fragment):
        Ratio(numerator, denominator)


def test_ratio_is_a_frozen_hashable_value():
    ratio = Ratio(3, 4)
    assert {ratio: 1}[Ratio(3, 4)] == 1
    assert pickle.loads(pickle.dumps(ratio)) == ratio
    with pytest.raises(AttributeError):
        ratio.numerator = 2  # type: ignore[misc]
