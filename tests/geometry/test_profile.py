# docs/MACHINE.md names the quantities A, B, C, D; pytest.approx on the right reads naturally.
# ruff: noqa: N803, SIM300
import math
from fractions import Fraction

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from app.geometry.errors import GeometryError
from app.geometry.limits import StaveLimits
from app.geometry.profile import (
    ROOT_TOLERANCE_MM,
    _bisect_exact,
    certify_root,
    cubic_f,
    solve_cubic_d,
    solve_profile,
)
from tests.geometry.strategies import PROPERTY, StaveInput, stave_inputs


def exact_f(A: float, B: float, C: float, D: float) -> Fraction:
    """f(D) of spec relation (3) in rational arithmetic (independent of the solver's code)."""
    a, b, c, d = (Fraction(v) for v in (A, B, C, D))
    return d**3 - 2 * c * d**2 + (c**2 - b**2 - 2 * a * b) * d + 2 * a * b * c


def assert_root_within(A: float, B: float, C: float, D: float, tolerance: float) -> None:
    """The exact cubic changes sign within D -/+ tolerance: |D - root| <= tolerance."""
    low = max(Fraction(0), Fraction(D) - Fraction(tolerance))
    high = min(Fraction(C), Fraction(D) + Fraction(tolerance))
    a, b, c = (Fraction(v) for v in (A, B, C))
    f = lambda d: d**3 - 2 * c * d**2 + (c**2 - b**2 - 2 * a * b) * d + 2 * a * b * c  # noqa: E731
    assert f(low) >= 0 >= f(high)


def test_worked_example_of_the_spec():
    p = solve_profile(1000.0, 150.0, 0.25, 0.75)
    assert (p.A, p.B, p.C, p.W1) == (250.0, 250.0, 18.75, 112.5)
    assert round(p.D, 6) == 12.502603
    assert round(p.R, 4) == 5005.2066
    assert_root_within(p.A, p.B, p.C, p.D, 1e-9)


def test_worked_example_points_and_centres():
    p = solve_profile(1000.0, 150.0, 0.25, 0.75)
    top = 56.25 + p.D
    assert p.points == {
        "P1": (0.0, 56.25),
        "P2": (250.0, top),
        "P3": (750.0, top),
        "P4": (1000.0, 56.25),
        "P5": (1000.0, -56.25),
        "P6": (750.0, -top),
        "P7": (250.0, -top),
        "P8": (0.0, -56.25),
    }
    assert p.arc_center_a == (500.0, 75.0 - p.R)
    assert p.arc_center_b == (500.0, -(75.0 - p.R))
    assert p.slope_rad == pytest.approx(math.atan(p.D / 250.0), abs=1e-15)


def test_length_ratio_zero_is_one_arc():
    p = solve_profile(1000.0, 150.0, 0.0, 0.75)
    assert p.A == 0.0 and p.D == 0.0
    assert p.R == (500.0**2 + 18.75**2) / (2 * 18.75)
    assert p.points["P1"] == p.points["P2"] and p.points["P3"] == p.points["P4"]
    # The single arc still runs through the heads and the belly.
    cx, cy = p.arc_center_a
    assert math.hypot(0.0 - cx, 56.25 - cy) == pytest.approx(p.R, rel=1e-15)
    assert cy + p.R == pytest.approx(75.0, abs=1e-9)
    assert p.slope_rad == pytest.approx(2 * math.atan(18.75 / 500.0), rel=1e-15)


def test_solve_cubic_d_zero_length_ratio():
    assert solve_cubic_d(0.0, 500.0, 18.75) == 0.0


@pytest.mark.parametrize(
    ("args", "fragment"),
    [
        ((math.nan, 1.0, 1.0), "A = nan is not a finite number"),
        ((1.0, math.inf, 1.0), "B = inf is not a finite number"),
        ((-1.0, 1.0, 1.0), "needs A >= 0, B > 0, C > 0"),
        ((1.0, 0.0, 1.0), "needs A >= 0, B > 0, C > 0"),
        ((1.0, 1.0, 0.0), "needs A >= 0, B > 0, C > 0"),
    ],
)
def test_solve_cubic_d_rejects_bad_arguments(args, fragment):
    with pytest.raises(ValueError, match=fragment):
        solve_cubic_d(*args)


@PROPERTY
@given(
    A=st.floats(1e-6, 2000.0),
    B=st.floats(1e-9, 2000.0),
    C=st.floats(1e-6, 200.0),
)
@example(A=250.0, B=250.0, C=18.75)
@example(A=1749.9999, B=1e-4, C=110.0)  # lambda -> 1/2: f nearly has a double root at C
@example(A=449.99999991, B=9e-8, C=50.0)
@example(A=1e-6, B=1750.0, C=110.0)  # lambda -> 0
@example(A=1750.0, B=1750.0, C=1e-6)  # k -> 1
@example(A=1.0, B=1.0, C=200.0)  # far outside the machine's range, still solved
def test_cubic_root_is_exact_everywhere(A, B, C):
    D = solve_cubic_d(A, B, C)
    assert 0.0 < D < C
    assert_root_within(A, B, C, D, 1e-9)
    assert exact_f(A, B, C, 0.0) > 0 > exact_f(A, B, C, C)


def test_cubic_in_float_is_ill_conditioned_where_the_solver_is_not():
    # Why the solver works in the half angle and certifies exactly: near lambda = 1/2 the
    # float residual of f around the root is rounding noise that, divided by the slope,
    # would claim an uncertainty far above 1e-9 mm; the exact sign test still pins D.
    A, B, C = 1749.9999999, 1e-7, 110.0
    D = solve_cubic_d(A, B, C)
    assert_root_within(A, B, C, D, 1e-12)
    slope = 3 * D**2 - 4 * C * D + C**2 - B**2 - 2 * A * B
    noise = max(abs(cubic_f(A, B, C, D + k * math.ulp(D))) for k in range(-3, 4))
    assert noise / abs(slope) > 1e-7


def test_certify_root_accepts_the_root_and_rejects_a_wrong_one():
    D = solve_cubic_d(250.0, 250.0, 18.75)
    assert certify_root(250.0, 250.0, 18.75, D, ROOT_TOLERANCE_MM)
    assert not certify_root(250.0, 250.0, 18.75, D + 1e-8, ROOT_TOLERANCE_MM)
    assert not certify_root(250.0, 250.0, 18.75, D - 1e-8, ROOT_TOLERANCE_MM)


@pytest.mark.parametrize(
    ("A", "B", "C"), [(250.0, 250.0, 18.75), (1749.9999, 1e-4, 110.0), (1.0, 1750.0, 0.01)]
)
def test_exact_bisection_fallback_finds_the_same_root(A, B, C):
    root = _bisect_exact(A, B, C, ROOT_TOLERANCE_MM)
    assert_root_within(A, B, C, root, 2 * ROOT_TOLERANCE_MM)
    assert root == pytest.approx(solve_cubic_d(A, B, C), abs=2 * ROOT_TOLERANCE_MM)


def test_cubic_f_in_float_matches_exact():
    assert cubic_f(250.0, 250.0, 18.75, 10.0) == float(exact_f(250.0, 250.0, 18.75, 10.0))


@PROPERTY
@given(stave_inputs())
@example(StaveInput(1000.0, 150.0, Fraction(1, 4), Fraction(3, 4)))
@example(StaveInput(900.0, 280.0, Fraction(4999, 10000), Fraction(3, 14)))
@example(StaveInput(3500.0, 60.0 / 0.9999, Fraction(0), Fraction(9999, 10000)))
@example(StaveInput(3500.0, 280.0, Fraction(0), Fraction(3, 14)))
def test_profile_properties_over_the_whole_range(stave):
    p = stave.solve()
    L, W = stave.length_mm, stave.width_mm
    assert p.W1 >= 60.0 and p.W1 == pytest.approx(float(stave.width_ratio) * W)
    assert p.A + p.B == pytest.approx(L / 2, abs=1e-12)
    assert p.C == pytest.approx((W - p.W1) / 2, abs=1e-12)
    assert_root_within(p.A, p.B, p.C, p.D, 1e-9)
    if p.A > 0:
        assert 0.0 < p.D < p.C
    # Relations (1) and (2) of docs/MACHINE.md section 2 give the same radius.
    if p.A > 0:
        assert p.R == pytest.approx(p.A * p.B / p.D + p.C - p.D, rel=1e-12)
    u = p.C - p.D
    assert p.R == pytest.approx((p.B**2 + u**2) / (2 * u), rel=1e-6)

    # Float resolution of distances from a centre R away: a few ulp of R.
    tolerance = 1e-9 + 8 * math.ulp(p.R)
    for centre, outward, (first, second, third, fourth) in (
        (p.arc_center_a, 1.0, ("P1", "P2", "P3", "P4")),
        (p.arc_center_b, -1.0, ("P8", "P7", "P6", "P5")),
    ):
        for name in (second, third):
            x, y = p.points[name]
            assert abs(math.hypot(x - centre[0], y - centre[1]) - p.R) <= tolerance
        # The arc's outermost point is the belly: half-width W/2 at x = L/2.
        assert centre[0] == L / 2
        assert abs(centre[1] + outward * p.R - outward * W / 2) <= tolerance
        if p.A > 0:
            # Tangent continuity: the radius at P2 (P3) is perpendicular to the line.
            for line_from, line_to, junction in ((first, second, second), (fourth, third, third)):
                (x0, y0), (x1, y1) = p.points[line_from], p.points[line_to]
                jx, jy = p.points[junction]
                dx, dy = x1 - x0, y1 - y0
                rx, ry = jx - centre[0], jy - centre[1]
                cosine = (dx * rx + dy * ry) / (math.hypot(dx, dy) * math.hypot(rx, ry))
                assert abs(cosine) < 1e-9


@PROPERTY
@given(st.floats(900.0, 3500.0))
def test_largest_length_ratio_below_one_half_still_leaves_an_arc(length):
    lam = math.nextafter(0.5, 0.0)
    p = solve_profile(length, 150.0, lam, 0.75)
    assert p.B > 0.0
    assert_root_within(p.A, p.B, p.C, p.D, 1e-9)


@pytest.mark.parametrize(
    ("args", "fields"),
    [
        ((1000.0, 150.0, 0.25, 1.0), ("width_ratio",)),
        ((1000.0, 150.0, 0.5, 0.75), ("length_ratio",)),
        ((1000.0, 150.0, 0.6, 0.75), ("length_ratio",)),
        ((1000.0, math.nan, 0.25, 0.75), ("width_mm",)),
        ((1000.0, math.inf, 0.25, 0.75), ("width_mm",)),
        ((1000.0, 300.0, 0.25, 0.75), ("width_mm",)),
        ((1000.0, 70.0, 0.25, 0.75), ("head_width_mm",)),
        ((800.0, 150.0, 0.25, 0.75), ("length_mm",)),
        ((math.nan, 150.0, -1.0, 2.0), ("length_mm", "length_ratio", "width_ratio")),
    ],
)
def test_solve_profile_raises_geometry_error(args, fields):
    with pytest.raises(GeometryError) as info:
        solve_profile(*args)
    assert info.value.fields == fields


def test_solve_profile_uses_the_given_limits():
    narrow = StaveLimits(max_width_mm=140.0)
    with pytest.raises(GeometryError, match="allowed 0 < width <= 140 mm"):
        solve_profile(1000.0, 150.0, 0.25, 0.75, narrow)
