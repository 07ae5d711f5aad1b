"""The stave side profile: two straight end sections joined by a tangent circular arc.

docs/MACHINE.md section 2: with A = lambda*L, B = L/2 - A, C = (W - W1)/2 the rise D of the straight
section is the root in (0, C) of

    f(D) = D^3 - 2*C*D^2 + (C^2 - B^2 - 2*A*B)*D + 2*A*B*C

and R = A*B/D + C - D.

How the root is found, and why not by bisection or Newton on f itself: near lambda -> 1/2
(B -> 0) f approaches D*(D - C)^2, whose double root at C makes f ill-conditioned (its
rounding noise divided by its slope reaches millimetres). The same root is well-conditioned in
the half-angle t = tan(theta/2) of the straight section's slope theta: the arc rises C - D over
B with tangent angle theta, so D = A*tan(theta) and C - D = B*tan(theta/2), which gives

    h(t) = 2*A*t / (1 - t^2) + B*t - C = 0,   D = 2*A*t / (1 - t^2)

h is increasing and convex on (0, 1), h(0) = -C and h(C / (2A + B)) >= 0, so Newton's method
started at that upper bound converges monotonically (quadratically) without ever leaving the
bracket; a bisection step guards it anyway. Multiplying h by -(1 - t^2) gives a cubic in t
equivalent to f, so the root is the D of relation (3). Finally the root is *certified* in exact
rational arithmetic: f is evaluated exactly at D -/+ 1e-10 mm and must change sign there, so the
error in D is provably below 1e-10 mm whatever the floating-point rounding did. Should that ever
fail, an exact-sign bisection on [0, C] takes over (it cannot fail: f(0) > 0 > f(C)).

The radius comes from relation (1), R = A*B/D + (C - D), which stays accurate both when D is
tiny (k -> 1) and when D -> C (lambda -> 1/2); relation (2) would lose digits in C - D.
"""

# docs/MACHINE.md names the quantities A, B, C, D, R, L, W, W1; the code keeps those names.
# ruff: noqa: N803, N806

from __future__ import annotations

import math
from dataclasses import dataclass

from app.geometry.errors import GeometryError
from app.geometry.limits import StaveLimits, validate_stave
from app.geometry.segments import ArcSegment, LineSegment, Segment

ROOT_TOLERANCE_MM = 1e-10
"""Certified bound on |D - exact root| (the product promises below 1e-9 mm)."""

_MAX_NEWTON_STEPS = 200

Point = tuple[float, float]


@dataclass(frozen=True)
class StaveProfile:
    """The solved side profile in the profile frame of docs/MACHINE.md section 2 (all mm).

    x runs along the stave from its left end (x = 0) to its right end (x = L); y across it,
    0 on the centre line, +y towards side A (cut first). `points` holds P1..P8; the arcs run
    P2 -> P3 about `arc_center_a` and P6 -> P7 about `arc_center_b`, both of radius R.
    """

    length_mm: float
    width_mm: float
    length_ratio: float
    width_ratio: float
    A: float
    B: float
    C: float
    D: float
    R: float
    W1: float
    points: dict[str, Point]
    arc_center_a: Point
    arc_center_b: Point

    @property
    def slope_rad(self) -> float:
        """Angle theta of the straight sections against the x axis (the tangent at P1).

        With no straight section (lambda = 0) it is the arc's tangent angle at P1.
        """
        if self.A > 0.0:
            return math.atan2(self.D, self.A)
        return 2.0 * math.atan2(self.C, self.B)

    @property
    def head_width_mm(self) -> float:
        """W1, the width at both heads."""
        return self.W1

    def edge(self, side: str) -> tuple[Segment, ...]:
        """The stave's edge itself (profile frame) as segments, in cut order.

        Side A runs P1 -> P4 (left to right), side B P5 -> P8 (right to left); a straight
        section of zero length (lambda = 0) is left out.
        """
        if side not in ("A", "B"):
            raise ValueError(f"side must be 'A' or 'B', got {side!r}")
        p = self.points
        names = ("P1", "P2", "P3", "P4") if side == "A" else ("P5", "P6", "P7", "P8")
        first, second, third, fourth = (p[name] for name in names)
        centre = self.arc_center_a if side == "A" else self.arc_center_b
        pieces: list[Segment] = []
        if first != second:
            pieces.append(LineSegment(first, second, 0.0, 0.0, False, side))
        pieces.append(ArcSegment(second, third, centre, True, 0.0, 0.0, False, side))
        if third != fourth:
            pieces.append(LineSegment(third, fourth, 0.0, 0.0, False, side))
        return tuple(pieces)


def cubic_f(A: float, B: float, C: float, D: float) -> float:
    """f(D) of relation (3), in floating point (for display and diagnostics)."""
    return D**3 - 2.0 * C * D**2 + (C * C - B * B - 2.0 * A * B) * D + 2.0 * A * B * C


def _cubic_sign_exact(A: float, B: float, C: float, D: float) -> int:
    """Sign of f(D) computed without rounding: -1, 0 or +1.

    Every float is an integer times a power of two; scaling A, B, C, D to a common power
    makes them integers, and f is homogeneous of degree 3, so the sign of f equals the sign
    of the same polynomial over those integers (Python integers never round). This is the
    exact rational evaluation without Fraction's gcd overhead.
    """
    ratios = [value.as_integer_ratio() for value in (A, B, C, D)]
    common = max(denominator for _, denominator in ratios)
    a, b, c, d = (numerator * (common // denominator) for numerator, denominator in ratios)
    value = ((d - 2 * c) * d + (c * c - b * b - 2 * a * b)) * d + 2 * a * b * c
    return (value > 0) - (value < 0)


def certify_root(A: float, B: float, C: float, D: float, tolerance_mm: float) -> bool:
    """True if f changes sign (decided exactly) between D - tolerance_mm and D + tolerance_mm.

    Since f(0) > 0 > f(C) and the root in (0, C) is unique, a sign change proves that the
    root lies within `tolerance_mm` of D (plus one rounding of D -/+ tolerance_mm).
    """
    low = max(0.0, D - tolerance_mm)
    high = min(C, D + tolerance_mm)
    return _cubic_sign_exact(A, B, C, low) >= 0 >= _cubic_sign_exact(A, B, C, high)


def _bisect_exact(A: float, B: float, C: float, tolerance_mm: float) -> float:
    """Bisection on [0, C] deciding each sign exactly: slow, but it cannot fail."""
    low, high = 0.0, C
    while high - low > tolerance_mm:
        middle = 0.5 * (low + high)
        if middle in (low, high):
            break
        if _cubic_sign_exact(A, B, C, middle) > 0:
            low = middle
        else:
            high = middle
    return 0.5 * (low + high)


def _solve_half_angle(A: float, B: float, C: float) -> float:
    """Root t in (0, 1) of h(t) = 2At/(1 - t^2) + Bt - C (see the module docstring)."""
    low = 0.0
    high = min(1.0, C / (2.0 * A + B))  # 1.0 only for inputs far outside the machine's range
    t = high if high < 1.0 else 0.5
    for _ in range(_MAX_NEWTON_STEPS):
        one_minus = (1.0 - t) * (1.0 + t)
        value = 2.0 * A * t / one_minus + B * t - C
        if value == 0.0:
            return t
        if value > 0.0:
            high = t
        else:
            low = t
        slope = 2.0 * A * (1.0 + t * t) / (one_minus * one_minus) + B
        step = value / slope
        candidate = t - step
        if not low < candidate < high:
            candidate = 0.5 * (low + high)
        if candidate == t or abs(candidate - t) <= 2.0 * math.ulp(t):
            return candidate
        t = candidate
    return t


def solve_cubic_d(A: float, B: float, C: float) -> float:
    """The physical root D in (0, C) of the cubic (3), certified to within 1e-10 mm.

    A >= 0, B > 0, C > 0 (mm). A = 0 (lambda = 0, no straight section) gives D = 0 as
    docs/MACHINE.md section 2 says (f(0) = 0 there). Raises ValueError for non-finite or
    out-of-domain arguments.
    """
    for name, value in (("A", A), ("B", B), ("C", C)):
        if not math.isfinite(value):
            raise ValueError(f"{name} = {value} is not a finite number")
    if A < 0.0 or B <= 0.0 or C <= 0.0:
        raise ValueError(f"solve_cubic_d needs A >= 0, B > 0, C > 0; got A={A}, B={B}, C={C}")
    if A == 0.0:
        return 0.0
    t = _solve_half_angle(A, B, C)
    D = 2.0 * A * t / ((1.0 - t) * (1.0 + t))
    if 0.0 < D < C and certify_root(A, B, C, D, ROOT_TOLERANCE_MM):
        return D
    return _bisect_exact(A, B, C, ROOT_TOLERANCE_MM)


def solve_profile(
    length_mm: float,
    width_mm: float,
    length_ratio: float,
    width_ratio: float,
    limits: StaveLimits | None = None,
) -> StaveProfile:
    """Solve the side profile of one board; raises GeometryError listing every violation."""
    errors = validate_stave(length_mm, width_mm, length_ratio, width_ratio, limits)
    if errors:
        raise GeometryError(errors)
    L = float(length_mm)
    W = float(width_mm)
    lam = float(length_ratio)
    k = float(width_ratio)

    A = lam * L
    B = L / 2.0 - A
    W1 = k * W
    C = (W - W1) / 2.0
    D = solve_cubic_d(A, B, C)
    R = A * B / D + (C - D) if A > 0.0 else (B * B + C * C) / (2.0 * C)

    half_head = W1 / 2.0
    rise = half_head + D
    points: dict[str, Point] = {
        "P1": (0.0, half_head),
        "P2": (A, rise),
        "P3": (L - A, rise),
        "P4": (L, half_head),
        "P5": (L, -half_head),
        "P6": (L - A, -rise),
        "P7": (A, -rise),
        "P8": (0.0, -half_head),
    }
    centre_y = W / 2.0 - R
    return StaveProfile(
        length_mm=L,
        width_mm=W,
        length_ratio=lam,
        width_ratio=k,
        A=A,
        B=B,
        C=C,
        D=D,
        R=R,
        W1=W1,
        points=points,
        arc_center_a=(L / 2.0, centre_y),
        arc_center_b=(L / 2.0, -centre_y),
    )
