"""The kinds of side profile a recipe can ask for, and the curve families' equations.

Why families by equation: coopers shape barrels with a fuller or a flatter bilge, and the
parametric lathe programs this product learns from (docs/MACHINE.md section 6) cut contours
given by equations. Every family gives the half-width along the stave as

    h(x) = W1/2 + C * shape(x),   C = (W - W1)/2,   shape(0) = shape(L) = 0,  shape(L/2) = 1

so each runs from the head width W1 = k*W at both ends to W/2 at the belly, symmetric about
the middle, exactly like line-arc-line. The shapes:

* parabola: shape = 1 - u^2 with u = (x - L/2)/(L/2);
* ellipse arc: the arc of an ellipse centred below the belly whose semi-axis along the stave
  is a = s*L/2 (s = `semi_axis_ratio` > 1: the ellipse is longer than the stave, so its ends
  are not vertical); as s grows it tends to the parabola;
* superellipse (Lame curve) |t|^n + |v|^n = 1 with the exponent n: n = 2 is the ellipse, a
  larger n a flatter, fuller belly with quicker shoulders. Its shape is
  (g(t) - g_e)/(1 - g_e) with g(t) = (1 - |t|^n)^(1/n), t = (x - L/2)/a and g_e = g(1/s).

Exponents below 2 are not offered: there the curvature at the belly is infinite (a kink in
all but name).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from enum import Enum

from app.geometry.errors import FieldError, format_value, not_a_number, out_of_range, worded
from app.geometry.rule_texts import RuleText


class ProfileKind(Enum):
    """What the side of the stave looks like (stored by value in recipes)."""

    LINE_ARC_LINE = "line_arc_line"
    SINGLE_ARC = "single_arc"
    PARABOLA = "parabola"
    ELLIPSE = "ellipse"
    SUPERELLIPSE = "superellipse"
    DRAWN = "drawn"

    @classmethod
    def parse(cls, text: str) -> ProfileKind:
        """From its stored value; a clear error naming the allowed values otherwise."""
        try:
            return cls(text)
        except ValueError:
            allowed = ", ".join(kind.value for kind in cls)
            raise ValueError(f"profile_kind = {text!r} is not known: allowed {allowed}") from None

    @property
    def is_family(self) -> bool:
        """Given by an equation of the half-width (fitted with biarcs per board)."""
        return self in FAMILY_PARAMETERS


@dataclass(frozen=True)
class FamilyParameter:
    """One parameter of a curve family, with its allowed closed range."""

    name: str
    minimum: float
    maximum: float
    default: float
    unit: str = ""

    @property
    def allowed(self) -> str:
        return f"{format_value(self.minimum)} <= {self.name} <= {format_value(self.maximum)}"


SEMI_AXIS_RATIO = FamilyParameter("semi_axis_ratio", 1.05, 10.0, 1.5)
EXPONENT = FamilyParameter("exponent", 2.0, 10.0, 3.0)

FAMILY_PARAMETERS: Mapping[ProfileKind, tuple[FamilyParameter, ...]] = {
    ProfileKind.PARABOLA: (),
    ProfileKind.ELLIPSE: (SEMI_AXIS_RATIO,),
    ProfileKind.SUPERELLIPSE: (EXPONENT, SEMI_AXIS_RATIO),
}


def default_parameters(kind: ProfileKind) -> dict[str, float]:
    """The family's parameters at their defaults (empty for the kinds without any)."""
    return {p.name: p.default for p in FAMILY_PARAMETERS.get(kind, ())}


def validate_family_parameters(kind: ProfileKind, values: Mapping[str, object]) -> list[FieldError]:
    """Every problem with a family's parameters: missing, unknown, not finite, out of range."""
    errors: list[FieldError] = []
    specs = {p.name: p for p in FAMILY_PARAMETERS.get(kind, ())}
    for name in values:
        if name not in specs:
            allowed = ", ".join(specs) or "none"
            message = f"{name} is not a parameter of the {kind.value} profile: allowed {allowed}"
            error = FieldError(name, values[name], allowed, message)
            errors.append(worded(error, RuleText.PROFILE_UNKNOWN_PARAMETER))
    for name, spec in specs.items():
        value = values.get(name)
        if (
            isinstance(value, bool)
            or not isinstance(value, int | float)
            or not math.isfinite(value)
        ):
            error = not_a_number(name, value, spec.allowed)
            errors.append(worded(error, RuleText.NOT_A_NUMBER, format_value(value)))
        elif not spec.minimum <= value <= spec.maximum:
            error = out_of_range(name, value, spec.allowed)
            bounds = (spec.minimum, spec.maximum, spec.unit)
            errors.append(worded(error, RuleText.BETWEEN, value, *bounds))
    return errors


@dataclass(frozen=True)
class FamilyShape:
    """shape(x) in [0, 1] of one family on a stave of length L, and its derivative in x.

    A frozen value (not a closure) so that a profile carrying it crosses process boundaries.
    """

    kind: ProfileKind
    length_mm: float
    exponent: float = 2.0
    semi_axis_ratio: float = 1.0

    def _lame(self, t: float) -> float:
        return float((1.0 - abs(t) ** self.exponent) ** (1.0 / self.exponent))

    def value(self, x_mm: float) -> float:
        half = self.length_mm / 2.0
        if self.kind is ProfileKind.PARABOLA:
            u = (x_mm - half) / half
            return 1.0 - u * u
        a = self.semi_axis_ratio * half
        end = self._lame(1.0 / self.semi_axis_ratio)
        return (self._lame((x_mm - half) / a) - end) / (1.0 - end)

    def slope(self, x_mm: float) -> float:
        """d shape / dx (1/mm)."""
        half = self.length_mm / 2.0
        if self.kind is ProfileKind.PARABOLA:
            return -2.0 * (x_mm - half) / (half * half)
        a = self.semi_axis_ratio * half
        t = (x_mm - half) / a
        if t == 0.0:
            return 0.0
        n = self.exponent
        end = self._lame(1.0 / self.semi_axis_ratio)
        g_t = (
            -((1.0 - abs(t) ** n) ** (1.0 / n - 1.0)) * abs(t) ** (n - 1.0) * math.copysign(1.0, t)
        )
        return float(g_t / a / (1.0 - end))


def family_shape(kind: ProfileKind, length_mm: float, values: Mapping[str, float]) -> FamilyShape:
    """The shape of a family with already validated parameters."""
    if kind is ProfileKind.PARABOLA:
        return FamilyShape(kind, length_mm)
    if kind is ProfileKind.ELLIPSE:
        return FamilyShape(kind, length_mm, 2.0, float(values[SEMI_AXIS_RATIO.name]))
    if kind is ProfileKind.SUPERELLIPSE:
        return FamilyShape(
            kind, length_mm, float(values[EXPONENT.name]), float(values[SEMI_AXIS_RATIO.name])
        )
    raise ValueError(f"{kind.value} is not a curve family")
