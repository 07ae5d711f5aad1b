import pickle

import pytest

from app.geometry.errors import (
    FieldError,
    GeometryError,
    format_value,
    not_a_number,
    out_of_range,
)


def test_out_of_range_message_is_the_documented_line():
    error = out_of_range("width_mm", 300.0, "0 < width <= 280 mm")
    assert error.message == "width_mm = 300 is out of range: allowed 0 < width <= 280 mm"
    assert (error.field, error.value, error.allowed) == ("width_mm", 300.0, "0 < width <= 280 mm")
    assert str(error) == error.message


def test_out_of_range_with_note():
    error = out_of_range("length_ratio", 0.5, "0 <= length ratio < 1/2", "no arc is left")
    assert error.message.endswith("allowed 0 <= length ratio < 1/2 (no arc is left)")


def test_not_a_number_message():
    error = not_a_number("width_mm", float("nan"), "0 < width <= 280 mm")
    assert error.message == "width_mm = nan is not a finite number: allowed 0 < width <= 280 mm"


def test_geometry_error_holds_all_errors_one_line_each():
    errors = [
        out_of_range("width_mm", 300.0, "0 < width <= 280 mm"),
        out_of_range("length_mm", 100.0, "900 <= length <= 3500 mm"),
    ]
    exc = GeometryError(errors)
    assert isinstance(exc, ValueError)
    assert exc.errors == tuple(errors)
    assert exc.fields == ("width_mm", "length_mm")
    assert str(exc).splitlines() == [e.message for e in errors]


def test_geometry_error_needs_an_error():
    with pytest.raises(ValueError, match="at least one"):
        GeometryError([])


def test_geometry_error_survives_pickling():
    # The machine layer may run in another process than the screens.
    exc = GeometryError([FieldError("tilt_deg", 50.0, "0 <= tilt <= 45 deg", "tilt bad")])
    copy = pickle.loads(pickle.dumps(exc))
    assert copy.errors == exc.errors
    assert str(copy) == "tilt bad"


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (300.0, "300"),
        (0.1, "0.1"),
        (1 / 3, "0.3333333333"),
        (float("inf"), "inf"),
        (7, "7"),
        ("abc", "'abc'"),
        (True, "True"),
        (None, "None"),
    ],
)
def test_format_value(value, text):
    assert format_value(value) == text
