"""The recipe model: what a cooper enters for one kind of stave.

A recipe fixes the stave's length and thickness, the two ratios of the side profile (length
ratio lambda = L1 : L and width ratio k = W1 : W, kept as the fractions the cooper typed, their
decimals derived), and its barrel type, the cooper's explicit choice of how the bevel is chosen:

* ``BarrelType.FIXED_TILT``: every board is bevelled at ``tilt_deg``.
* ``BarrelType.ROUND`` and ``BarrelType.OVAL``: the bevel is computed for each board from its
  measured width and the barrel's belly section, so narrow and wide boards of one barrel all
  close. Round: ``barrel_diameter_mm`` (both sides asin(W/D), ``app.geometry.barrel``). Oval:
  ``barrel_diameter_mm`` the long belly axis, ``barrel_minor_diameter_mm`` the short one; the
  two sides of a stave get different bevels, which depend on where the stave sits in the
  barrel (``app.geometry.barrel_section``). ``tilt_deg`` is then the nominal tilt (for a
  typical board); it is validated like a fixed tilt but the cut uses the computed value.

The type is stored, not guessed from which diameters are filled in: a round barrel with a
stray short axis is refused, not silently made oval. ``TiltMode`` (fixed or from the barrel)
is derived from it; files written before the type existed give ``tilt_mode`` instead, and a
``barrel`` one is read as oval when it has a short axis (what those files meant).

Validation is the geometry's (``validate_recipe_fields``: length, thickness, ratios, tilt and
the machine's limits) plus what only a stored recipe has: a name, the tilt mode, the barrel's
belly diameters and perimeter, a fixed belly width (``target_width_mm``: staves made to stock,
cut centred on a wider board), the note. Name uniqueness needs the database and is checked there.

The row format (JSON object or CSV line, also what ``stave simulate --recipe-file`` reads) is
:data:`ROW_KEYS`; :func:`recipe_from_mapping` reads it and :func:`recipe_to_mapping` writes it.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Mapping
from dataclasses import dataclass
from enum import Enum

from app.data.errors import RecipeFormatError
from app.data.recipe_profile import (
    DATA_FIELD,
    KIND_FIELD,
    LINE_ARC_LINE,
    RecipeProfile,
    parse_recipe_profile,
)
from app.geometry.barrel import RoundBarrelTilt, barrel_width_errors
from app.geometry.barrel_section import MAX_AXIS_RATIO, BarrelSection, PlacedBarrelTilt
from app.geometry.bevel import FixedTilt, TiltRule
from app.geometry.errors import (
    FieldError,
    GeometryError,
    format_value,
    not_a_number,
    out_of_range,
    worded,
)
from app.geometry.limits import DEFAULT_LIMITS, StaveLimits, validate_recipe_fields
from app.geometry.ratio import Ratio
from app.geometry.rule_texts import RuleText
from app.geometry.stave_cut import StaveSpec

NAME_MAX_CHARS = 40
NOTE_MAX_CHARS = 500


class TiltMode(Enum):
    """How the bevel of a board is chosen (derived from the recipe's barrel type)."""

    FIXED = "fixed"  # the recipe's tilt_deg for every board
    BARREL = "barrel"  # computed per board from the barrel's belly section and the width


class BarrelType(Enum):
    """What the recipe's bevel follows: the cooper's choice, stored with the recipe."""

    FIXED_TILT = "fixed"
    ROUND = "round"
    OVAL = "oval"

    @property
    def tilt_mode(self) -> TiltMode:
        return TiltMode.FIXED if self is BarrelType.FIXED_TILT else TiltMode.BARREL


BARREL_TYPE_ALLOWED = "fixed, round or oval"


@dataclass(frozen=True)
class Recipe:
    """One stored recipe. ``id`` is None until the database has stored it."""

    id: int | None
    name: str
    length_mm: float
    thickness_mm: float
    length_ratio: Ratio
    width_ratio: Ratio
    barrel_type: BarrelType
    tilt_deg: float
    barrel_diameter_mm: float | None
    barrel_perimeter_mm: float | None
    note: str = ""
    profile: RecipeProfile = LINE_ARC_LINE
    barrel_minor_diameter_mm: float | None = None
    target_width_mm: float | None = None
    """Cut every board to this belly width (staves made to stock; None: the board's width)."""

    @property
    def tilt_mode(self) -> TiltMode:
        """Fixed, or computed per board from the barrel (round or oval)."""
        if not isinstance(self.barrel_type, BarrelType):  # refused by validate()
            return TiltMode.FIXED
        return self.barrel_type.tilt_mode

    @property
    def barrel_section(self) -> BarrelSection | None:
        """The belly cross-section the staves are placed on (None: fixed tilt, or no diameter)."""
        if self.tilt_mode is not TiltMode.BARREL or self.barrel_diameter_mm is None:
            return None
        minor = self.barrel_minor_diameter_mm if self.barrel_type is BarrelType.OVAL else None
        major = self.barrel_diameter_mm
        return BarrelSection(major / 2.0, (major if minor is None else minor) / 2.0)

    @property
    def length_ratio_decimal(self) -> float:
        """lambda = L1 : L as a decimal (derived, never stored on its own)."""
        return self.length_ratio.value

    @property
    def width_ratio_decimal(self) -> float:
        """k = W1 : W as a decimal (derived, never stored on its own)."""
        return self.width_ratio.value

    def validate(self, limits: StaveLimits | None = None) -> list[FieldError]:
        """Every reason this recipe cannot be stored (empty list: valid)."""
        return validate_recipe(self, limits)

    @property
    def tilt_rule(self) -> TiltRule:
        """How this recipe bevels a board of a measured width (``app.geometry.barrel`` has the
        barrel's mathematics)."""
        section = self.barrel_section
        if self.barrel_type is BarrelType.OVAL and section is not None:
            return PlacedBarrelTilt(section)  # the first stave's place; a barrel set moves it
        if self.tilt_mode is TiltMode.BARREL:
            return RoundBarrelTilt(self.barrel_diameter_mm)
        return FixedTilt(self.tilt_deg)

    @property
    def stave(self) -> StaveSpec:
        """What the geometry cuts for this recipe (``app.geometry.stave_cut.cut_stave``)."""
        return StaveSpec(
            self.length_mm,
            self.thickness_mm,
            self.length_ratio.value,
            self.width_ratio.value,
            self.tilt_rule,
            self.profile.spec,
            self.target_width_mm,
        )


def _check_name(name: object, errors: list[FieldError]) -> None:
    allowed = f"1 to {NAME_MAX_CHARS} characters, no leading or trailing spaces"
    if not isinstance(name, str):
        errors.append(not_a_text("name", name, allowed))
    elif not name.strip():
        error = FieldError("name", name, allowed, f"name is empty: allowed {allowed}")
        errors.append(worded(error, RuleText.NAME_EMPTY, NAME_MAX_CHARS))
    elif name != name.strip() or len(name) > NAME_MAX_CHARS:
        errors.append(
            worded(out_of_range("name", name, allowed), RuleText.NAME_LENGTH, NAME_MAX_CHARS)
        )
    elif any(not ch.isprintable() for ch in name):
        message = f"name = {name!r} contains a control character: allowed {allowed}"
        errors.append(worded(FieldError("name", name, allowed, message), RuleText.NAME_CONTROL))


def not_a_text(field: str, value: object, allowed: str) -> FieldError:
    """The error for a value that should have been text."""
    message = f"{field} = {format_value(value)} is not text: allowed {allowed}"
    return worded(
        FieldError(field, value, allowed, message), RuleText.NOT_TEXT, format_value(value)
    )


def _diameter_bounds(limits: StaveLimits) -> tuple[float, float]:
    low = 0.0 if limits.min_barrel_diameter_mm is None else limits.min_barrel_diameter_mm
    high = math.inf if limits.max_barrel_diameter_mm is None else limits.max_barrel_diameter_mm
    return low, high


def _check_optional_positive(
    field: str, value: object, low: float, high: float, errors: list[FieldError]
) -> float | None:
    if value is None:
        return None
    allowed = f"empty, or {format_value(low)} <= {field} <= {format_value(high)} mm"
    shown = format_value(value)
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        errors.append(worded(not_a_number(field, value, allowed), RuleText.NOT_A_NUMBER, shown))
        return None
    number = float(value)
    if not math.isfinite(number):
        errors.append(worded(not_a_number(field, value, allowed), RuleText.NOT_A_NUMBER, shown))
        return None
    if not (low <= number <= high and number > 0):
        error = out_of_range(field, value, allowed)
        rule = RuleText.OPTIONAL_BETWEEN
        errors.append(worded(error, rule, value, round(low, 1), round(high, 1), "mm"))
        return None
    return number


def validate_recipe(recipe: Recipe, limits: StaveLimits | None = None) -> list[FieldError]:
    """Every reason ``recipe`` cannot be stored, the geometry's checks first."""
    limits = DEFAULT_LIMITS if limits is None else limits
    errors: list[FieldError] = []
    _check_name(recipe.name, errors)

    # A ratio that is not a Ratio goes to the geometry as it is: it reports it as not a number.
    ratios: dict[str, object] = {
        "length_ratio": _ratio_value(recipe.length_ratio),
        "width_ratio": _ratio_value(recipe.width_ratio),
    }
    errors.extend(
        validate_recipe_fields(
            recipe.length_mm,
            recipe.thickness_mm,
            ratios["length_ratio"],
            ratios["width_ratio"],
            recipe.tilt_deg,
            limits,
        )
    )

    d_low, d_high = _diameter_bounds(limits)
    diameter = _check_optional_positive(
        "barrel_diameter_mm", recipe.barrel_diameter_mm, d_low, d_high, errors
    )
    _check_optional_positive(
        "barrel_perimeter_mm", recipe.barrel_perimeter_mm, math.pi * d_low, math.pi * d_high, errors
    )
    minor = _check_optional_positive(
        "barrel_minor_diameter_mm", recipe.barrel_minor_diameter_mm, d_low, d_high, errors
    )
    if diameter is not None and minor is not None:
        _check_oval(diameter, minor, errors)
    _check_short_axis(recipe, errors)
    target = _check_optional_positive(
        "target_width_mm",
        recipe.target_width_mm,
        limits.min_head_width_mm,
        limits.max_width_mm,
        errors,
    )
    if target is not None and isinstance(recipe.width_ratio, Ratio):
        head = target * recipe.width_ratio.value
        if head < limits.min_head_width_mm:
            allowed = (
                f"target_width_mm >= {format_value(limits.min_head_width_mm)} / width ratio "
                f"= {limits.min_head_width_mm / recipe.width_ratio.value:.1f} mm"
            )
            error = out_of_range(
                "target_width_mm", target, allowed, f"the head would be {head:.1f} mm wide"
            )
            least = round(limits.min_head_width_mm / recipe.width_ratio.value, 1)
            errors.append(worded(error, RuleText.TARGET_HEAD, target, round(head, 1), least))

    if not isinstance(recipe.barrel_type, BarrelType):
        errors.append(unknown_barrel_type(recipe.barrel_type))
    elif recipe.tilt_mode is TiltMode.BARREL:
        if recipe.barrel_diameter_mm is None:
            allowed = f"{format_value(d_low)} <= barrel_diameter_mm <= {format_value(d_high)} mm"
            message = (
                f"barrel_diameter_mm is missing: a {recipe.barrel_type.value} barrel computes "
                f"the tilt from it (allowed {allowed})"
            )
            error = FieldError("barrel_diameter_mm", None, allowed, message)
            errors.append(worded(error, RuleText.DIAMETER_MISSING, d_low, d_high))
        elif diameter is not None and isinstance(recipe.width_ratio, Ratio):
            k = recipe.width_ratio.value
            if 0 < k <= 1:
                errors.extend(barrel_width_errors(diameter, k, limits))

    if not isinstance(recipe.note, str):
        errors.append(not_a_text("note", recipe.note, f"at most {NOTE_MAX_CHARS} characters"))
    elif len(recipe.note) > NOTE_MAX_CHARS:
        allowed = f"at most {NOTE_MAX_CHARS} characters"
        message = f"note is {len(recipe.note)} characters long: allowed {allowed}"
        error = FieldError("note", recipe.note, allowed, message)
        errors.append(worded(error, RuleText.NOTE_LONG, len(recipe.note), NOTE_MAX_CHARS))
    if isinstance(recipe.profile, RecipeProfile):
        errors.extend(recipe.profile.validate())
    else:
        message = f"{DATA_FIELD} = {format_value(recipe.profile)} is not a side profile"
        errors.append(FieldError(DATA_FIELD, recipe.profile, "a side profile", message))
    return errors


def unknown_barrel_type(value: object) -> FieldError:
    """The refusal of a barrel type that is none of the three."""
    message = f"barrel_type = {format_value(value)} is unknown: allowed {BARREL_TYPE_ALLOWED}"
    error = FieldError("barrel_type", value, BARREL_TYPE_ALLOWED, message)
    return worded(error, RuleText.BARREL_TYPE, format_value(value))


def _check_short_axis(recipe: Recipe, errors: list[FieldError]) -> None:
    """The short belly axis belongs to an oval barrel, and an oval barrel needs it."""
    minor = recipe.barrel_minor_diameter_mm
    kind = recipe.barrel_type
    if kind is BarrelType.OVAL and minor is None:
        allowed = "the oval's short belly axis in mm, at most barrel_diameter_mm"
        message = f"barrel_minor_diameter_mm is missing: an oval barrel needs it ({allowed})"
        error = FieldError("barrel_minor_diameter_mm", None, allowed, message)
        errors.append(worded(error, RuleText.SHORT_AXIS_MISSING))
    elif kind in (BarrelType.FIXED_TILT, BarrelType.ROUND) and minor is not None:
        allowed = "empty unless barrel_type is 'oval'"
        use = "a fixed tilt" if kind is BarrelType.FIXED_TILT else "a round barrel"
        message = (
            f"barrel_minor_diameter_mm = {format_value(minor)} has no use with {use}: "
            f"allowed {allowed}"
        )
        rule = (
            RuleText.SHORT_AXIS_FIXED
            if kind is BarrelType.FIXED_TILT
            else RuleText.SHORT_AXIS_ROUND
        )
        error = FieldError("barrel_minor_diameter_mm", minor, allowed, message)
        errors.append(worded(error, rule, minor))


def _check_oval(major_mm: float, minor_mm: float, errors: list[FieldError]) -> None:
    """An oval's short belly axis: no longer than the long one, at least half of it."""
    low = major_mm / MAX_AXIS_RATIO
    if not low <= minor_mm <= major_mm:
        allowed = (
            f"{format_value(low)} <= barrel_minor_diameter_mm <= barrel_diameter_mm = "
            f"{format_value(major_mm)} mm"
        )
        note = "the oval's short belly axis; the long one is barrel_diameter_mm"
        error = out_of_range("barrel_minor_diameter_mm", minor_mm, allowed, note)
        rule = RuleText.SHORT_AXIS_BETWEEN
        errors.append(worded(error, rule, minor_mm, round(low, 1), major_mm))


def _ratio_value(ratio: object) -> object:
    return ratio.value if isinstance(ratio, Ratio) else ratio


# ----------------------------------------------------------------------------- row format

REQUIRED_KEYS: tuple[str, ...] = (
    "name",
    "length_mm",
    "thickness_mm",
    "length_ratio",
    "width_ratio",
    "tilt_deg",
)
OPTIONAL_KEYS: tuple[str, ...] = (
    "barrel_type",
    "barrel_diameter_mm",
    "barrel_minor_diameter_mm",
    "barrel_perimeter_mm",
    "target_width_mm",
    "note",
    KIND_FIELD,
    DATA_FIELD,
)
ROW_KEYS: tuple[str, ...] = (*REQUIRED_KEYS[:5], "barrel_type", "tilt_deg", *OPTIONAL_KEYS[1:])
# An exported database id means nothing in another database: accepted and ignored.
IGNORED_KEYS: frozenset[str] = frozenset({"id"})
LEGACY_KEYS: tuple[str, ...] = ("tilt_mode",)
"""Read from files written before the barrel type existed (``_read_barrel_type``)."""

_NUMBER_ALLOWED = "a number"
_RATIO_ALLOWED = "a fraction like '1/4' or a decimal like '0.25'"


def _is_blank(value: object) -> bool:
    return value is None or (isinstance(value, str) and not value.strip())


def _read_number(key: str, value: object, errors: list[FieldError]) -> float | None:
    unit = " mm" if key.endswith("_mm") else " deg" if key.endswith("_deg") else ""
    allowed = f"{_NUMBER_ALLOWED}{unit}"
    if isinstance(value, bool):
        errors.append(not_a_number(key, value, allowed))
        return None
    if isinstance(value, numbers.Real):
        try:
            number = float(value)
        except OverflowError:  # an integer like 10**400
            number = math.inf
    elif isinstance(value, str):
        try:
            number = float(value.strip())
        except ValueError:
            errors.append(not_a_number(key, value, allowed))
            return None
    else:
        errors.append(not_a_number(key, value, allowed))
        return None
    if not math.isfinite(number):
        errors.append(not_a_number(key, value, allowed))
        return None
    return number


def _read_ratio(key: str, value: object, errors: list[FieldError]) -> Ratio | None:
    try:
        if isinstance(value, bool):
            raise ValueError("a boolean is not a ratio")
        if isinstance(value, numbers.Real):
            return Ratio.from_float(float(value))
        if isinstance(value, str):
            return Ratio.parse(value)
        raise ValueError("not text or a number")
    except (ValueError, OverflowError) as exc:
        message = f"{key} = {format_value(value)} is not a ratio ({exc}): allowed {_RATIO_ALLOWED}"
        errors.append(FieldError(key, value, _RATIO_ALLOWED, message))
        return None


def _missing(key: str, allowed: str) -> FieldError:
    return FieldError(key, None, allowed, f"{key} is missing: expected {allowed}")


def recipe_from_mapping(row: Mapping[str, object]) -> Recipe:
    """Read one recipe row (JSON object or CSV line as a dict); the result has ``id`` None.

    Numbers may be numbers or text ("950", "27.5"); ratios "N/D" or a decimal; ``barrel_type``
    "fixed" (default), "round" or "oval" (older files: ``tilt_mode``); empty optional fields
    are None. Raises RecipeFormatError naming every missing, unknown or unreadable key. The
    values are only read here, not checked against the machine's limits: that is
    :meth:`Recipe.validate`.
    """
    if not isinstance(row, Mapping):
        allowed = f"an object with the keys {', '.join(ROW_KEYS)}"
        message = f"recipe row = {format_value(row)} is not an object: expected {allowed}"
        raise RecipeFormatError([FieldError("row", row, allowed, message)])
    errors: list[FieldError] = []
    known = set(ROW_KEYS) | IGNORED_KEYS | set(LEGACY_KEYS)
    for key in row:
        if key not in known:
            allowed = ", ".join(ROW_KEYS)
            message = f"key {key!r} is unknown: allowed keys {allowed}"
            errors.append(FieldError(str(key), row[key], allowed, message))

    name: str = ""
    raw_name = row.get("name")
    if _is_blank(raw_name):
        errors.append(_missing("name", f"a name of 1 to {NAME_MAX_CHARS} characters"))
    elif not isinstance(raw_name, str):
        errors.append(not_a_text("name", raw_name, f"1 to {NAME_MAX_CHARS} characters"))
    else:
        name = raw_name.strip()

    numbers_read: dict[str, float | None] = {}
    for key in ("length_mm", "thickness_mm", "tilt_deg"):
        value = row.get(key)
        if _is_blank(value):
            errors.append(_missing(key, f"{_NUMBER_ALLOWED} in {key.rsplit('_', 1)[1]}"))
            numbers_read[key] = None
        else:
            numbers_read[key] = _read_number(key, value, errors)
    for key in (
        "barrel_diameter_mm",
        "barrel_minor_diameter_mm",
        "barrel_perimeter_mm",
        "target_width_mm",
    ):
        value = row.get(key)
        numbers_read[key] = None if _is_blank(value) else _read_number(key, value, errors)

    ratios: dict[str, Ratio | None] = {}
    for key in ("length_ratio", "width_ratio"):
        value = row.get(key)
        if _is_blank(value):
            errors.append(_missing(key, _RATIO_ALLOWED))
            ratios[key] = None
        else:
            ratios[key] = _read_ratio(key, value, errors)

    barrel_type = _read_barrel_type(row, numbers_read["barrel_minor_diameter_mm"], errors)

    note = ""
    raw_note = row.get("note")
    if not _is_blank(raw_note):
        if isinstance(raw_note, str):
            note = raw_note.strip()
        else:
            errors.append(not_a_text("note", raw_note, f"at most {NOTE_MAX_CHARS} characters"))

    profile = LINE_ARC_LINE
    try:
        profile = parse_recipe_profile(row.get(KIND_FIELD), row.get(DATA_FIELD))
    except GeometryError as error:
        errors.extend(error.errors)

    length_ratio, width_ratio = ratios["length_ratio"], ratios["width_ratio"]
    length_mm, thickness_mm = numbers_read["length_mm"], numbers_read["thickness_mm"]
    tilt_deg = numbers_read["tilt_deg"]
    if errors or None in (length_ratio, width_ratio, length_mm, thickness_mm, tilt_deg):
        raise RecipeFormatError(errors)
    assert length_ratio is not None and width_ratio is not None  # narrowed above
    assert length_mm is not None and thickness_mm is not None and tilt_deg is not None
    return Recipe(
        id=None,
        name=name,
        length_mm=length_mm,
        thickness_mm=thickness_mm,
        length_ratio=length_ratio,
        width_ratio=width_ratio,
        barrel_type=barrel_type,
        tilt_deg=tilt_deg,
        barrel_diameter_mm=numbers_read["barrel_diameter_mm"],
        barrel_perimeter_mm=numbers_read["barrel_perimeter_mm"],
        note=note,
        profile=profile,
        barrel_minor_diameter_mm=numbers_read["barrel_minor_diameter_mm"],
        target_width_mm=numbers_read["target_width_mm"],
    )


def _read_barrel_type(
    row: Mapping[str, object], minor_mm: float | None, errors: list[FieldError]
) -> BarrelType:
    """``barrel_type`` (fixed, round or oval; default fixed), or an older file's ``tilt_mode``:
    "barrel" was a round barrel, or an oval one when the short axis was filled in."""
    raw_type, raw_mode = row.get("barrel_type"), row.get("tilt_mode")
    barrel_type = BarrelType.FIXED_TILT
    if not _is_blank(raw_type):
        try:
            if not isinstance(raw_type, str):
                raise ValueError
            barrel_type = BarrelType(raw_type.strip().lower())
        except ValueError:
            errors.append(unknown_barrel_type(raw_type))
            return barrel_type
    if _is_blank(raw_mode):
        return barrel_type
    allowed = " or ".join(repr(mode.value) for mode in TiltMode)
    try:
        if not isinstance(raw_mode, str):
            raise ValueError
        tilt_mode = TiltMode(raw_mode.strip().lower())
    except ValueError:
        message = f"tilt_mode = {format_value(raw_mode)} is unknown: allowed {allowed}"
        errors.append(FieldError("tilt_mode", raw_mode, allowed, message))
        return barrel_type
    if _is_blank(raw_type):
        if tilt_mode is TiltMode.FIXED:
            return BarrelType.FIXED_TILT
        return BarrelType.ROUND if minor_mm is None else BarrelType.OVAL
    if barrel_type.tilt_mode is not tilt_mode:
        message = (
            f"tilt_mode = {format_value(raw_mode)} contradicts barrel_type = "
            f"{format_value(raw_type)}: allowed tilt_mode {barrel_type.tilt_mode.value!r} "
            "or no tilt_mode"
        )
        errors.append(FieldError("tilt_mode", raw_mode, barrel_type.tilt_mode.value, message))
    return barrel_type


def recipe_to_mapping(recipe: Recipe) -> dict[str, object]:
    """The row format of ``recipe`` (no id: it belongs to one database), keys in ROW_KEYS order."""
    return {
        "name": recipe.name,
        "length_mm": recipe.length_mm,
        "thickness_mm": recipe.thickness_mm,
        "length_ratio": str(recipe.length_ratio),
        "width_ratio": str(recipe.width_ratio),
        "barrel_type": recipe.barrel_type.value,
        "tilt_deg": recipe.tilt_deg,
        "barrel_diameter_mm": recipe.barrel_diameter_mm,
        "barrel_minor_diameter_mm": recipe.barrel_minor_diameter_mm,
        "barrel_perimeter_mm": recipe.barrel_perimeter_mm,
        "target_width_mm": recipe.target_width_mm,
        "note": recipe.note,
        KIND_FIELD: recipe.profile.kind.value,
        DATA_FIELD: recipe.profile.data(),
    }
