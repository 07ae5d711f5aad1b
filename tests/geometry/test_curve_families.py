"""Curve families by equation: fitted within 0.001 mm at 10,000 points, tangent-continuous."""

from __future__ import annotations

import math

import pytest

from app.geometry.biarc import FIT_TOLERANCE_MM
from app.geometry.curved_profile import CurvedProfile, solve_side_profile
from app.geometry.errors import GeometryError
from app.geometry.profile_kinds import FAMILY_PARAMETERS, ProfileKind, default_parameters
from app.geometry.segments import ArcSegment
from tests.geometry.chain_checks import worst_deviation_mm, worst_gap_mm, worst_tangent_break_rad

L, W, K = 1000.0, 150.0, 0.75
W1 = K * W
C = (W - W1) / 2.0


def parabola(x: float) -> float:
    u = (x - L / 2) / (L / 2)
    return W1 / 2 + C * (1 - u * u)


def lame(exponent: float, ratio: float):
    """The Lame curve y = yc + b*(1 - |t|^n)^(1/n), t = (x - L/2)/a, through the heads and belly."""
    a = ratio * L / 2
    b = C / (1 - (1 - ratio**-exponent) ** (1 / exponent))
    yc = W / 2 - b

    def h(x: float) -> float:
        t = abs(x - L / 2) / a
        return yc + b * (1 - t**exponent) ** (1 / exponent)

    return h


CASES = [
    (ProfileKind.PARABOLA, {}, parabola),
    (ProfileKind.ELLIPSE, {"semi_axis_ratio": 1.05}, lame(2.0, 1.05)),
    (ProfileKind.ELLIPSE, {"semi_axis_ratio": 3.0}, lame(2.0, 3.0)),
    (ProfileKind.SUPERELLIPSE, {"exponent": 4.0, "semi_axis_ratio": 1.2}, lame(4.0, 1.2)),
    (ProfileKind.SUPERELLIPSE, {"exponent": 10.0, "semi_axis_ratio": 1.05}, lame(10.0, 1.05)),
]


def case_id(case: tuple[ProfileKind, dict[str, float], object]) -> str:
    """Stable across processes (no function addresses), so parallel workers collect alike."""
    kind, values, _ = case
    return "-".join([kind.value, *(f"{k}={v}" for k, v in values.items())])


@pytest.mark.parametrize(("kind", "values", "true_h"), CASES, ids=[case_id(c) for c in CASES])
def test_family_is_fitted_within_a_micrometre_and_tangent_continuous(kind, values, true_h):
    profile = solve_side_profile(kind, L, W, K, family_values=values)
    assert isinstance(profile, CurvedProfile)
    chain = profile.edge("A")
    assert worst_deviation_mm(chain, lambda t: (t * L, true_h(t * L))) <= FIT_TOLERANCE_MM
    assert worst_tangent_break_rad(chain) < 1e-9
    assert worst_gap_mm(chain) == 0.0
    assert chain[0].start == (0.0, pytest.approx(W1 / 2, abs=1e-12))
    assert chain[-1].end == (L, pytest.approx(W1 / 2, abs=1e-12))
    # Symmetric about the middle, belly W/2 there.
    assert abs(max(s.bounds()[3] for s in chain) - W / 2) <= FIT_TOLERANCE_MM
    mirrored = [c for s in reversed(chain) for c in (L - s.end[0], s.end[1])]
    assert [c for s in chain for c in s.start] == pytest.approx(mirrored, abs=1e-9)


@pytest.mark.parametrize("kind", [k for k in ProfileKind if k.is_family])
def test_side_b_is_the_mirror_of_side_a_cut_backwards(kind):
    profile = solve_side_profile(kind, L, W, K, family_values=default_parameters(kind))
    side_a, side_b = profile.edge("A"), profile.edge("B")
    assert len(side_a) == len(side_b)
    assert side_b[0].start == (L, -side_a[-1].end[1])
    assert side_b[-1].end == (0.0, -side_a[0].start[1])
    for a, b in zip(side_a, reversed(side_b), strict=True):
        assert type(a) is type(b)
        if isinstance(a, ArcSegment):
            assert isinstance(b, ArcSegment)
            assert b.clockwise is a.clockwise is True  # convex: both sides clockwise


def test_families_are_convex_so_no_arc_bends_the_other_way_noticeably():
    """A convex curve's biarcs turn clockwise on side A; where the curve is flat (a high
    exponent's belly) a joint arc may turn the other way, but only as a practically straight
    arc (hundreds of metres), never one the cutter could not follow."""
    for kind, values, _ in CASES:
        chain = solve_side_profile(kind, L, W, K, family_values=values).edge("A")
        assert all(s.clockwise or s.radius_mm > 1e5 for s in chain if isinstance(s, ArcSegment))


def test_a_flatter_family_is_fuller_at_the_quarter_points():
    def quarter(values, kind):
        chain = solve_side_profile(kind, L, W, K, family_values=values).edge("A")
        return max(s.end[1] for s in chain if s.end[0] <= L / 4)

    parabolic = quarter({}, ProfileKind.PARABOLA)
    full = quarter({"exponent": 6.0, "semi_axis_ratio": 1.1}, ProfileKind.SUPERELLIPSE)
    assert full > parabolic


@pytest.mark.parametrize(
    ("kind", "values", "field"),
    [
        (ProfileKind.ELLIPSE, {"semi_axis_ratio": 1.0}, "semi_axis_ratio"),
        (ProfileKind.ELLIPSE, {}, "semi_axis_ratio"),
        (ProfileKind.ELLIPSE, {"semi_axis_ratio": math.nan}, "semi_axis_ratio"),
        (ProfileKind.SUPERELLIPSE, {"exponent": 1.5, "semi_axis_ratio": 2.0}, "exponent"),
        (ProfileKind.SUPERELLIPSE, {"exponent": "3", "semi_axis_ratio": 2.0}, "exponent"),
        (ProfileKind.PARABOLA, {"exponent": 3.0}, "exponent"),
    ],
)
def test_bad_family_parameters_are_refused_naming_the_field(kind, values, field):
    with pytest.raises(GeometryError) as refused:
        solve_side_profile(kind, L, W, K, family_values=values)
    assert field in refused.value.fields
    assert field in str(refused.value)


def test_head_width_under_60_mm_is_refused_for_every_family():
    for kind in FAMILY_PARAMETERS:
        with pytest.raises(GeometryError) as refused:
            solve_side_profile(kind, L, 70.0, 0.8, family_values=default_parameters(kind))
        assert "head_width_mm" in refused.value.fields


def test_drawn_kind_without_a_drawing_is_refused():
    with pytest.raises(GeometryError) as refused:
        solve_side_profile(ProfileKind.DRAWN, L, W, K)
    assert refused.value.fields == ("drawn_profile",)


def test_unknown_kind_text_names_the_allowed_kinds():
    with pytest.raises(ValueError, match="allowed line_arc_line, single_arc, parabola"):
        ProfileKind.parse("cycloid")
    assert ProfileKind.parse("ellipse") is ProfileKind.ELLIPSE


def test_line_arc_line_and_single_arc_are_the_exact_solver_unchanged():
    lal = solve_side_profile(ProfileKind.LINE_ARC_LINE, L, W, K, length_ratio=0.25)
    assert pytest.approx(12.502603, abs=1e-6) == lal.D
    single = solve_side_profile(ProfileKind.SINGLE_ARC, L, W, K, length_ratio=0.25)
    assert single.A == 0.0
    assert [type(s).__name__ for s in single.edge("A")] == ["ArcSegment"]
