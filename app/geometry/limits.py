"""The machine's limits (docs/MACHINE.md section 1) and the checks against them.

Two levels of checks, because the inputs arrive at two different times:

* `validate_recipe_fields` when a recipe is edited: length, thickness, ratios and tilt are
  known, the board's width is not (it is measured on every board). It also rejects recipes no
  board could ever satisfy (a width ratio that makes the head narrower than 60 mm even on the
  widest board, a tilt that fits no barrel diameter within the limits).
* `validate_stave` once the width is measured: everything above plus the head width
  W1 = k*W >= 60 mm and the barrel belly diameter of this board.

The barrel belly diameter is derived, not entered: the sides are radial planes, so a stave of
width W (the face on the table, the outside of the barrel) bevelled at `alpha` belongs to a
barrel of belly diameter W / sin(alpha). It is reported on the tilt field, with the tilt range
that would fit this width, because that is what the operator can change.

All checks return *every* violation as a list of `FieldError`; an empty list means valid.
The axis travel is checked on the finished tool path, in `app.geometry.travel`.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

from app.geometry.errors import FieldError, format_value, not_a_number, out_of_range, worded
from app.geometry.rule_texts import RuleText

NOT_NUMBER = RuleText.NOT_A_NUMBER
UNIT_WORDS = {"deg": "°"}
"""Units as the screens write them."""


@dataclass(frozen=True)
class StaveLimits:
    """Limits of the machine; defaults are the table of docs/MACHINE.md section 1.

    The axis travel (x/y in mm, z in degrees, machine coordinates) is optional: None means
    "not configured, not checked". Setting a barrel diameter bound to None disables it.
    """

    max_width_mm: float = 280.0
    min_head_width_mm: float = 60.0
    min_thickness_mm: float = 25.0
    max_thickness_mm: float = 90.0
    min_length_mm: float = 900.0
    max_length_mm: float = 3500.0
    min_barrel_diameter_mm: float | None = 240.0
    max_barrel_diameter_mm: float | None = 4500.0
    min_tilt_deg: float = 0.0
    max_tilt_deg: float = 45.0
    x_min_mm: float | None = None
    x_max_mm: float | None = None
    y_min_mm: float | None = None
    y_max_mm: float | None = None
    z_min_deg: float | None = None
    z_max_deg: float | None = None


DEFAULT_LIMITS = StaveLimits()


def _finite(field: str, value: object, allowed: str, errors: list[FieldError]) -> float | None:
    """The value as a float if it is a finite real number; otherwise record an error."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        errors.append(worded(not_a_number(field, value, allowed), NOT_NUMBER, format_value(value)))
        return None
    number = float(value)
    if not math.isfinite(number):
        errors.append(worded(not_a_number(field, value, allowed), NOT_NUMBER, format_value(value)))
        return None
    return number


def _in_closed_range(
    field: str,
    value: object,
    low: float,
    high: float,
    name: str,
    unit: str,
    errors: list[FieldError],
) -> float | None:
    allowed = f"{format_value(low)} <= {name} <= {format_value(high)} {unit}".rstrip()
    number = _finite(field, value, allowed, errors)
    if number is None:
        return None
    if not low <= number <= high:
        error = out_of_range(field, value, allowed)
        errors.append(worded(error, RuleText.BETWEEN, value, low, high, UNIT_WORDS.get(unit, unit)))
        return None
    return number


def _check_length(value: object, limits: StaveLimits, errors: list[FieldError]) -> float | None:
    return _in_closed_range(
        "length_mm", value, limits.min_length_mm, limits.max_length_mm, "length", "mm", errors
    )


def _check_thickness(value: object, limits: StaveLimits, errors: list[FieldError]) -> float | None:
    return _in_closed_range(
        "thickness_mm",
        value,
        limits.min_thickness_mm,
        limits.max_thickness_mm,
        "thickness",
        "mm",
        errors,
    )


def _check_tilt(value: object, limits: StaveLimits, errors: list[FieldError]) -> float | None:
    return _in_closed_range(
        "tilt_deg", value, limits.min_tilt_deg, limits.max_tilt_deg, "tilt", "deg", errors
    )


def _check_width(value: object, limits: StaveLimits, errors: list[FieldError]) -> float | None:
    allowed = f"0 < width <= {format_value(limits.max_width_mm)} mm"
    number = _finite("width_mm", value, allowed, errors)
    if number is None:
        return None
    if not 0.0 < number <= limits.max_width_mm:
        error = out_of_range("width_mm", value, allowed)
        errors.append(worded(error, RuleText.BOARD_WIDTH, value, limits.max_width_mm))
        return None
    return number


def _check_length_ratio(value: object, errors: list[FieldError]) -> float | None:
    allowed = "0 <= length ratio < 1/2"
    number = _finite("length_ratio", value, allowed, errors)
    if number is None:
        return None
    if number < 0.0:
        error = out_of_range("length_ratio", value, allowed)
        errors.append(worded(error, RuleText.LENGTH_RATIO, value))
        return None
    if number >= 0.5:
        error = out_of_range("length_ratio", value, allowed, "no arc is left at 1/2 or more")
        errors.append(worded(error, RuleText.LENGTH_RATIO, value))
        return None
    return number


def _check_width_ratio(value: object, errors: list[FieldError]) -> float | None:
    allowed = "0 < width ratio < 1"
    number = _finite("width_ratio", value, allowed, errors)
    if number is None:
        return None
    if number == 1.0:
        message = (
            f"width_ratio = {format_value(value)} leaves nothing to cut "
            f"(head as wide as the belly): allowed {allowed}"
        )
        error = FieldError("width_ratio", value, allowed, message)
        errors.append(worded(error, RuleText.WIDTH_RATIO_ONE, value))
        return None
    if not 0.0 < number < 1.0:
        error = out_of_range("width_ratio", value, allowed)
        errors.append(worded(error, RuleText.WIDTH_RATIO_RANGE, value))
        return None
    return number


def _tilt_range_for_width(width_mm: float, limits: StaveLimits) -> tuple[float, float]:
    """The tilt interval (deg) whose barrel diameter W/sin(tilt) lies within the limits."""
    low = limits.min_tilt_deg
    high = limits.max_tilt_deg
    if limits.max_barrel_diameter_mm is not None:
        ratio = min(1.0, width_mm / limits.max_barrel_diameter_mm)
        low = max(low, math.degrees(math.asin(ratio)))
    if limits.min_barrel_diameter_mm is not None:
        ratio = min(1.0, width_mm / limits.min_barrel_diameter_mm)
        high = min(high, math.degrees(math.asin(ratio)))
    return low, high


def barrel_diameter_mm(width_mm: float, tilt_deg: float) -> float:
    """Belly diameter of the barrel a stave of this width and bevel belongs to (radial sides)."""
    sine = math.sin(math.radians(tilt_deg))
    return math.inf if sine <= 0.0 else width_mm / sine


def _check_barrel_diameter(
    width_mm: float, tilt_deg: float, limits: StaveLimits, errors: list[FieldError]
) -> None:
    diameter = barrel_diameter_mm(width_mm, tilt_deg)
    too_small = limits.min_barrel_diameter_mm is not None and (
        diameter < limits.min_barrel_diameter_mm
    )
    too_large = limits.max_barrel_diameter_mm is not None and (
        diameter > limits.max_barrel_diameter_mm
    )
    if not (too_small or too_large):
        return
    low, high = _tilt_range_for_width(width_mm, limits)
    allowed = (
        f"{low:.3f} <= tilt <= {high:.3f} deg"
        if low <= high
        else "no tilt (no barrel diameter within the limits fits this width)"
    )
    bounds = (
        f"{format_value(limits.min_barrel_diameter_mm)}.."
        f"{format_value(limits.max_barrel_diameter_mm)} mm"
    )
    note = (
        f"for width_mm = {format_value(width_mm)} the barrel belly diameter "
        f"W/sin(tilt) = {diameter:.1f} mm is outside {bounds}"
    )
    error = out_of_range("tilt_deg", tilt_deg, allowed, note)
    d_low, d_high = limits.min_barrel_diameter_mm, limits.max_barrel_diameter_mm
    if low <= high:
        rule = RuleText.BOARD_BARREL
        shown = (tilt_deg, width_mm, round(diameter, 1), d_low, d_high, round(low, 3))
        errors.append(worded(error, rule, *shown, round(high, 3)))
    else:
        errors.append(worded(error, RuleText.BOARD_NO_TILT, width_mm, d_low, d_high))


def width_ratio_minimum(limits: StaveLimits) -> float:
    """The smallest width ratio k a recipe may have: below it, even the widest board's head
    is narrower than the minimum head width (the recipe form's hint states the same bound)."""
    return limits.min_head_width_mm / limits.max_width_mm


def recipe_tilt_range(width_ratio: float, limits: StaveLimits) -> tuple[float, float]:
    """The fixed tilts (deg) a recipe of width ratio ``width_ratio`` may have: some board of
    min_head_width / k .. max_width mm then gives a barrel belly diameter W/sin(tilt) within
    the limits (some width in that span fits iff sin(tilt) lies in this range)."""
    low = _tilt_range_for_width(limits.min_head_width_mm / width_ratio, limits)[0]
    high = _tilt_range_for_width(limits.max_width_mm, limits)[1]
    return low, high


def validate_recipe_fields(
    length_mm: object,
    thickness_mm: object | None,
    length_ratio: object,
    width_ratio: object,
    tilt_deg: object | None,
    limits: StaveLimits | None = None,
) -> list[FieldError]:
    """Check a recipe before any board is measured; returns every violation found.

    `thickness_mm` and `tilt_deg` may be None (not entered yet: not checked).
    """
    limits = DEFAULT_LIMITS if limits is None else limits
    errors: list[FieldError] = []
    _check_length(length_mm, limits, errors)
    if thickness_mm is not None:
        _check_thickness(thickness_mm, limits, errors)
    _check_length_ratio(length_ratio, errors)
    k = _check_width_ratio(width_ratio, errors)
    tilt = None if tilt_deg is None else _check_tilt(tilt_deg, limits, errors)

    if k is not None:
        k_min = width_ratio_minimum(limits)
        if k < k_min:
            allowed = (
                f"{format_value(limits.min_head_width_mm)}/{format_value(limits.max_width_mm)}"
                f" = {k_min:.4f} <= width ratio < 1"
            )
            note = (
                f"the head would be narrower than {format_value(limits.min_head_width_mm)} mm "
                f"even on a board of {format_value(limits.max_width_mm)} mm"
            )
            error = out_of_range("width_ratio", width_ratio, allowed, note)
            rule = RuleText.WIDTH_RATIO_NARROW
            head, board = limits.min_head_width_mm, limits.max_width_mm
            errors.append(worded(error, rule, width_ratio, head, board, round(k_min, 3)))
            k = None

    if k is not None and tilt is not None:
        # Widths a board may have under this recipe, and those the barrel limits accept.
        width_low = limits.min_head_width_mm / k
        sine = math.sin(math.radians(tilt))
        fits_low = (
            -math.inf
            if limits.min_barrel_diameter_mm is None
            else limits.min_barrel_diameter_mm * sine
        )
        fits_high = (
            math.inf
            if limits.max_barrel_diameter_mm is None
            else limits.max_barrel_diameter_mm * sine
        )
        if max(width_low, fits_low) > min(limits.max_width_mm, fits_high):
            note = (
                f"no board of width {width_low:.1f}..{format_value(limits.max_width_mm)} mm "
                f"gives a barrel belly diameter W/sin(tilt) within "
                f"{format_value(limits.min_barrel_diameter_mm)}.."
                f"{format_value(limits.max_barrel_diameter_mm)} mm"
            )
            low, high = recipe_tilt_range(k, limits)
            allowed = f"{low:.3f} <= tilt <= {high:.3f} deg"
            error = out_of_range("tilt_deg", tilt_deg, allowed, note)
            rule = RuleText.TILT_FITS_NO_BARREL
            d_low, d_high = limits.min_barrel_diameter_mm, limits.max_barrel_diameter_mm
            bounds = (d_low, d_high, round(low, 2), round(high, 2))
            errors.append(worded(error, rule, tilt_deg, *bounds))
    return errors


def validate_stave(
    length_mm: object,
    width_mm: object,
    length_ratio: object,
    width_ratio: object,
    limits: StaveLimits | None = None,
    thickness_mm: object | None = None,
    tilt_deg: object | None = None,
) -> list[FieldError]:
    """Check one measured board against the limits; returns every violation found.

    Covers the table of docs/MACHINE.md section 1, the special cases of its section 2 (k = 1 nothing
    to cut, lambda >= 1/2 no arc, head width W1 = k*W >= 60 mm, non-finite numbers) and, when
    thickness and tilt are given, the barrel diameter and a positive top face at the heads.
    """
    limits = DEFAULT_LIMITS if limits is None else limits
    errors: list[FieldError] = []
    # lambda < 1/2 always leaves B = L/2 - lambda*L > 0 in IEEE arithmetic: lambda*L rounds
    # to at most the float just below L/2, never up to it.
    _check_length(length_mm, limits, errors)
    width = _check_width(width_mm, limits, errors)
    _check_length_ratio(length_ratio, errors)
    k = _check_width_ratio(width_ratio, errors)
    thickness = None if thickness_mm is None else _check_thickness(thickness_mm, limits, errors)
    tilt = None if tilt_deg is None else _check_tilt(tilt_deg, limits, errors)

    head_width: float | None = None
    if width is not None and k is not None:
        head_width = k * width
        if head_width < limits.min_head_width_mm:
            allowed = f"head width >= {format_value(limits.min_head_width_mm)} mm"
            note = (
                f"head width = width_ratio * width_mm = {format_value(k)} * {format_value(width)}"
            )
            error = out_of_range("head_width_mm", head_width, allowed, note)
            rule = RuleText.HEAD_NARROW
            errors.append(worded(error, rule, round(head_width, 1), limits.min_head_width_mm))
            head_width = None

    if width is not None and tilt is not None:
        _check_barrel_diameter(width, tilt, limits, errors)

    if head_width is not None and thickness is not None and tilt is not None:
        top_face_mm = head_width - 2.0 * thickness * math.tan(math.radians(tilt))
        if top_face_mm <= 0.0:
            limit_deg = math.degrees(math.atan(head_width / (2.0 * thickness)))
            allowed = f"tilt < {limit_deg:.3f} deg"
            note = (
                f"the bevels of a {format_value(thickness)} mm thick stave would meet "
                f"before the top face at the {head_width:.1f} mm wide heads"
            )
            error = out_of_range("tilt_deg", tilt_deg, allowed, note)
            rule = RuleText.TOP_FACE
            shown = (tilt_deg, thickness, round(head_width, 1), round(limit_deg, 3))
            errors.append(worded(error, rule, *shown))
    return errors
