import math

import pytest

from app.geometry.errors import FieldError
from app.geometry.limits import (
    StaveLimits,
    barrel_diameter_mm,
    validate_recipe_fields,
    validate_stave,
)

VALID = {"length_mm": 1000.0, "width_mm": 150.0, "length_ratio": 0.25, "width_ratio": 0.75}
LIMITS = StaveLimits()


def stave_errors(**changes: object) -> list[FieldError]:
    fields = {**VALID, **changes}
    return validate_stave(
        fields.pop("length_mm"),
        fields.pop("width_mm"),
        fields.pop("length_ratio"),
        fields.pop("width_ratio"),
        LIMITS,
        **fields,
    )


def test_defaults_are_the_spec_table():
    assert (LIMITS.max_width_mm, LIMITS.min_head_width_mm) == (280.0, 60.0)
    assert (LIMITS.min_thickness_mm, LIMITS.max_thickness_mm) == (25.0, 90.0)
    assert (LIMITS.min_length_mm, LIMITS.max_length_mm) == (900.0, 3500.0)
    assert (LIMITS.min_barrel_diameter_mm, LIMITS.max_barrel_diameter_mm) == (240.0, 4500.0)
    assert (LIMITS.min_tilt_deg, LIMITS.max_tilt_deg) == (0.0, 45.0)
    assert LIMITS.x_min_mm is LIMITS.z_max_deg is None


def test_valid_stave_has_no_errors():
    assert stave_errors() == []
    assert stave_errors(thickness_mm=40.0, tilt_deg=3.5) == []
    assert stave_errors(length_ratio=0.0) == []
    assert stave_errors(length_mm=900.0, width_mm=280.0) == []
    assert stave_errors(length_mm=3500.0, width_mm=80.0, width_ratio=0.75) == []


@pytest.mark.parametrize(
    ("changes", "field", "message"),
    [
        (
            {"length_mm": 899.9},
            "length_mm",
            "length_mm = 899.9 is out of range: allowed 900 <= length <= 3500 mm",
        ),
        (
            {"length_mm": 3500.5},
            "length_mm",
            "length_mm = 3500.5 is out of range: allowed 900 <= length <= 3500 mm",
        ),
        (
            {"width_mm": 300.0},
            "width_mm",
            "width_mm = 300 is out of range: allowed 0 < width <= 280 mm",
        ),
        (
            {"width_mm": 0.0},
            "width_mm",
            "width_mm = 0 is out of range: allowed 0 < width <= 280 mm",
        ),
        (
            {"width_mm": -5.0},
            "width_mm",
            "width_mm = -5 is out of range: allowed 0 < width <= 280 mm",
        ),
        (
            {"length_ratio": 0.5},
            "length_ratio",
            "length_ratio = 0.5 is out of range: allowed 0 <= length ratio < 1/2 "
            "(no arc is left at 1/2 or more)",
        ),
        (
            {"length_ratio": 0.75},
            "length_ratio",
            "length_ratio = 0.75 is out of range: allowed 0 <= length ratio < 1/2 "
            "(no arc is left at 1/2 or more)",
        ),
        (
            {"length_ratio": -0.1},
            "length_ratio",
            "length_ratio = -0.1 is out of range: allowed 0 <= length ratio < 1/2",
        ),
        (
            {"width_ratio": 1.0},
            "width_ratio",
            "width_ratio = 1 leaves nothing to cut (head as wide as the belly): "
            "allowed 0 < width ratio < 1",
        ),
        (
            {"width_ratio": 1.25},
            "width_ratio",
            "width_ratio = 1.25 is out of range: allowed 0 < width ratio < 1",
        ),
        (
            {"width_ratio": 0.0},
            "width_ratio",
            "width_ratio = 0 is out of range: allowed 0 < width ratio < 1",
        ),
        (
            {"width_mm": 100.0, "width_ratio": 0.5},
            "head_width_mm",
            "head_width_mm = 50 is out of range: allowed head width >= 60 mm "
            "(head width = width_ratio * width_mm = 0.5 * 100)",
        ),
        (
            {"thickness_mm": 24.0},
            "thickness_mm",
            "thickness_mm = 24 is out of range: allowed 25 <= thickness <= 90 mm",
        ),
        (
            {"thickness_mm": 91.0},
            "thickness_mm",
            "thickness_mm = 91 is out of range: allowed 25 <= thickness <= 90 mm",
        ),
        (
            {"tilt_deg": 46.0},
            "tilt_deg",
            "tilt_deg = 46 is out of range: allowed 0 <= tilt <= 45 deg",
        ),
        (
            {"tilt_deg": -1.0},
            "tilt_deg",
            "tilt_deg = -1 is out of range: allowed 0 <= tilt <= 45 deg",
        ),
    ],
)
def test_each_invalid_case_names_field_value_and_range(changes, field, message):
    errors = stave_errors(**changes)
    assert [e.message for e in errors] == [message]
    (error,) = errors
    assert error.field == field
    assert error.allowed in message


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, "150", None, True])
@pytest.mark.parametrize(
    "field", ["length_mm", "width_mm", "length_ratio", "width_ratio", "thickness_mm"]
)
def test_non_finite_or_non_numbers_are_rejected(field, bad):
    if field == "thickness_mm" and bad is None:
        assert stave_errors(thickness_mm=None) == []  # None: not entered, not checked
        return
    errors = stave_errors(**{field: bad})
    assert [e.field for e in errors] == [field]
    assert "is not a finite number: allowed" in errors[0].message


def test_every_violation_is_reported_at_once():
    errors = stave_errors(
        length_mm=5000.0, width_mm=math.nan, length_ratio=0.5, width_ratio=1.0, thickness_mm=10.0
    )
    assert [e.field for e in errors] == [
        "length_mm",
        "width_mm",
        "length_ratio",
        "width_ratio",
        "thickness_mm",
    ]


def test_barrel_diameter_too_large_is_reported_on_the_tilt_with_the_fitting_range():
    # 280 / sin(3.5 deg) = 4586.5 mm > 4500 mm.
    (error,) = stave_errors(width_mm=280.0, tilt_deg=3.5)
    assert error.field == "tilt_deg"
    low = math.degrees(math.asin(280.0 / 4500.0))
    assert error.allowed == f"{low:.3f} <= tilt <= 45.000 deg"
    assert "barrel belly diameter W/sin(tilt) = 4586.5 mm is outside 240..4500 mm" in (
        error.message
    )
    assert stave_errors(width_mm=280.0, tilt_deg=low + 1e-6) == []


def test_barrel_diameter_too_small():
    # 70 / sin(17 deg) = 239.4 mm < 240 mm.
    (error,) = stave_errors(width_mm=70.0, width_ratio=6 / 7, tilt_deg=17.0)
    high = math.degrees(math.asin(70.0 / 240.0))
    assert error.field == "tilt_deg"
    assert error.allowed.endswith(f"<= tilt <= {high:.3f} deg")


def test_zero_tilt_is_an_infinite_barrel():
    assert barrel_diameter_mm(150.0, 0.0) == math.inf
    (error,) = stave_errors(tilt_deg=0.0)
    assert error.field == "tilt_deg"


def test_barrel_limits_can_be_disabled():
    limits = StaveLimits(min_barrel_diameter_mm=None, max_barrel_diameter_mm=None)
    assert validate_stave(1000.0, 280.0, 0.25, 0.75, limits, tilt_deg=0.0) == []


def test_bevels_meeting_before_the_top_face_are_rejected():
    # Head 60 mm, thickness 90 mm: the bevels meet at tilt atan(60 / 180) = 18.43 deg.
    (error,) = stave_errors(width_mm=200.0, width_ratio=0.3, thickness_mm=90.0, tilt_deg=20.0)
    assert error.field == "tilt_deg"
    assert error.allowed == "tilt < 18.435 deg"
    assert stave_errors(width_mm=200.0, width_ratio=0.3, thickness_mm=90.0, tilt_deg=18.0) == []


def test_recipe_fields_valid():
    assert validate_recipe_fields(1000.0, 40.0, 0.25, 0.75, 3.5, LIMITS) == []
    assert validate_recipe_fields(1000.0, None, 0.0, 0.75, None) == []


def test_recipe_fields_each_invalid():
    errors = validate_recipe_fields(800.0, 100.0, 0.5, 1.0, 50.0, LIMITS)
    assert [e.field for e in errors] == [
        "length_mm",
        "thickness_mm",
        "length_ratio",
        "width_ratio",
        "tilt_deg",
    ]


def test_recipe_width_ratio_no_board_can_satisfy():
    (error,) = validate_recipe_fields(1000.0, 40.0, 0.25, 0.2, 3.5, LIMITS)
    assert error.field == "width_ratio"
    assert error.allowed == "60/280 = 0.2143 <= width ratio < 1"
    assert validate_recipe_fields(1000.0, 40.0, 0.25, 60 / 280, 4.0, LIMITS) == []


def test_recipe_tilt_that_fits_no_barrel():
    # k = 3/4: boards of 80..280 mm; at 1 deg even 80 mm gives a 4584 mm barrel.
    (error,) = validate_recipe_fields(1000.0, 40.0, 0.25, 0.75, 1.0, LIMITS)
    assert error.field == "tilt_deg"
    low = math.degrees(math.asin(80.0 / 4500.0))
    assert error.allowed == f"{low:.3f} <= tilt <= 45.000 deg"
    assert validate_recipe_fields(1000.0, 40.0, 0.25, 0.75, low + 0.01, LIMITS) == []
