"""The spline evaluation against ezdxf (an independent implementation) and biarc basics."""

from __future__ import annotations

import math
import random

import pytest
from ezdxf.math import BSpline

from app.geometry.biarc import biarc, fit_biarcs
from app.geometry.nurbs import Nurbs
from app.geometry.segments import ArcSegment, LineSegment
from tests.geometry.chain_checks import worst_deviation_mm, worst_tangent_break_rad


@pytest.mark.parametrize("degree", [1, 2, 3, 5])
@pytest.mark.parametrize("rational", [False, True])
def test_spline_point_and_derivative_match_ezdxf(degree, rational):
    rng = random.Random(degree * 10 + rational)
    points = [(i * 100.0 + rng.uniform(-20, 20), rng.uniform(0, 30)) for i in range(8)]
    weights = [rng.uniform(0.5, 2.0) if rational else 1.0 for _ in points]
    reference = BSpline(points, order=degree + 1, weights=weights if rational else None)
    ours = Nurbs(degree, tuple(reference.knots()), tuple(points), tuple(weights))
    low, high = ours.domain
    for i in range(201):
        u = low + (high - low) * i / 200
        expected = reference.point(u)
        assert ours.point_at(u) == pytest.approx((expected.x, expected.y), abs=1e-9)
        if not rational:
            derivative = reference.derivative(u, 1)[1]
            assert ours.derivative_at(u) == pytest.approx((derivative.x, derivative.y), rel=1e-9)
        else:  # ezdxf has no rational derivative: compare with a central difference
            h = 1e-6 * (high - low)
            v = min(max(u, low + h), high - h)
            a, b = ours.point_at(v + h), ours.point_at(v - h)
            difference = ((a[0] - b[0]) / (2 * h), (a[1] - b[1]) / (2 * h))
            assert ours.derivative_at(v) == pytest.approx(difference, rel=1e-5, abs=1e-5)


def test_spline_refuses_inconsistent_data_by_name():
    with pytest.raises(ValueError, match="needs 6 knots"):
        Nurbs(2, (0.0, 0.0, 1.0), ((0.0, 0.0), (1.0, 1.0), (2.0, 0.0)), (1.0, 1.0, 1.0))
    with pytest.raises(ValueError, match="weights must be finite and > 0"):
        Nurbs(1, (0.0, 0.0, 1.0, 1.0), ((0.0, 0.0), (1.0, 1.0)), (1.0, 0.0))


def test_biarc_of_a_straight_stretch_is_one_line():
    pieces = biarc((0.0, 0.0), (1.0, 0.0), (10.0, 0.0), (1.0, 0.0))
    assert pieces == (LineSegment((0.0, 0.0), (10.0, 0.0), 0.0, 0.0, False, ""),)


def test_biarc_reproduces_a_circle_and_keeps_its_end_tangents():
    radius = 50.0
    p0, p1 = (radius, 0.0), (0.0, radius)
    pieces = biarc(p0, (0.0, 1.0), p1, (-1.0, 0.0))
    assert all(isinstance(p, ArcSegment) for p in pieces)
    assert [p.radius_mm for p in pieces] == pytest.approx([radius, radius])
    assert pieces[0].tangent_at(0.0) == pytest.approx((0.0, 1.0))
    assert pieces[-1].tangent_at(pieces[-1].length_mm) == pytest.approx((-1.0, 0.0))
    assert worst_tangent_break_rad(pieces) < 1e-12


class _Sine:
    """y = 5 sin(2 pi x / 200) over x in [0, 400]: S-bends with inflections."""

    def point(self, t):
        x = 400.0 * t
        return (x, 5.0 * math.sin(2 * math.pi * x / 200.0))

    def derivative(self, t):
        x = 400.0 * t
        return (400.0, 400.0 * 5.0 * 2 * math.pi / 200.0 * math.cos(2 * math.pi * x / 200.0))


def test_fit_follows_inflections_within_the_tolerance():
    curve = _Sine()
    chain = fit_biarcs(curve, tolerance_mm=0.001)
    assert worst_deviation_mm(chain, curve.point) <= 0.001
    assert worst_tangent_break_rad(chain) < 1e-9
    assert chain[0].start == curve.point(0.0)
    assert chain[-1].end == curve.point(1.0)
    # A coarser tolerance needs fewer pieces: the subdivision adapts.
    assert len(fit_biarcs(curve, tolerance_mm=0.1)) < len(chain)
