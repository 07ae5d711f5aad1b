"""The planner's own geometry agrees with app.geometry, and its derivative bounds hold."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.geometry.segments import ArcSegment, LineSegment
from app.machine.planner.path import ArcPiece, LinePiece, Path

from .support import toolpath

PROPERTY = settings(max_examples=60, deadline=None)

coordinates = st.floats(-2000.0, 2000.0)


@st.composite
def arcs(draw: st.DrawFn) -> ArcSegment:
    cx, cy = draw(coordinates), draw(coordinates)
    radius = draw(st.floats(1.0, 6000.0))
    a0 = draw(st.floats(-math.pi, math.pi))
    sweep = draw(st.floats(0.01, 2.0 * math.pi - 0.01))
    clockwise = draw(st.booleans())
    a1 = a0 - sweep if clockwise else a0 + sweep
    start = (cx + radius * math.cos(a0), cy + radius * math.sin(a0))
    end = (cx + radius * math.cos(a1), cy + radius * math.sin(a1))
    return ArcSegment(start, end, (cx, cy), clockwise, 0.0, 0.0, True, "A")


@PROPERTY
@given(arcs(), st.floats(0.0, 1.0))
def test_arc_piece_matches_the_geometry_segment(segment: ArcSegment, fraction: float) -> None:
    piece = ArcPiece.through(segment.start, segment.end, segment.center, segment.clockwise)
    assert piece.length_mm == pytest.approx(segment.length_mm, rel=1e-9, abs=1e-9)
    s = fraction * min(piece.length_mm, segment.length_mm)
    assert math.dist(piece.point(s), segment.point_at(s)) < 1e-6
    tangent = piece.derivatives(s)[0]
    assert math.dist(tangent, segment.tangent_at(s)) < 1e-9
    assert math.dist(piece.point(piece.length_mm), segment.end) < 1e-6


@PROPERTY
@given(arcs())
def test_arc_derivative_bounds_hold_everywhere_and_are_reached(segment: ArcSegment) -> None:
    piece = ArcPiece.through(segment.start, segment.end, segment.center, segment.clockwise)
    bounds = piece.bounds()
    found = np.zeros((3, 2))
    for s in np.linspace(0.0, piece.length_mm, 2001):
        for k, vector in enumerate(piece.derivatives(float(s))):
            found[k] = np.maximum(found[k], np.abs(vector))
    for k, bound in enumerate((bounds.first, bounds.second, bounds.third)):
        assert np.all(found[k] <= np.array(bound) * (1 + 1e-12) + 1e-15)
        # and it is not needlessly loose (the sampling misses at most a sliver of the peak)
        assert np.all(found[k] >= np.array(bound) * (1 - 1e-4) - 1e-15)


@PROPERTY
@given(arcs())
def test_second_derivative_is_the_finite_difference_of_the_tangent(segment: ArcSegment) -> None:
    piece = ArcPiece.through(segment.start, segment.end, segment.center, segment.clockwise)
    s, h = piece.length_mm / 2.0, min(piece.length_mm, piece.radius_mm) * 1e-4
    (t0, c2, c3), (t1, c2b, _) = piece.derivatives(s), piece.derivatives(s + h)
    for axis in range(2):
        assert (t1[axis] - t0[axis]) / h == pytest.approx(c2[axis], abs=1e-3 / piece.radius_mm)
        assert (c2b[axis] - c2[axis]) / h == pytest.approx(c3[axis], abs=1e-3 / piece.radius_mm**2)


def test_distances_match_the_geometry_package() -> None:
    path = toolpath()
    rng = np.random.default_rng(1)
    xs = rng.uniform(0.0, 1300.0, 200)
    ys = rng.uniform(300.0, 500.0, 200)
    for segment in path.segments:
        if segment.length_mm == 0.0:
            continue
        if isinstance(segment, ArcSegment):
            piece = ArcPiece.through(segment.start, segment.end, segment.center, segment.clockwise)
        else:
            piece = LinePiece(segment.start, segment.end)
        mine = piece.distances(xs, ys)
        theirs = np.array([segment.distance_to((x, y)) for x, y in zip(xs, ys, strict=True)])
        assert np.allclose(mine, theirs, atol=1e-9)


def test_a_path_refuses_a_corner_and_a_gap() -> None:
    with pytest.raises(ValueError, match="turns by 90 deg"):
        Path((LinePiece((0.0, 0.0), (1.0, 0.0)), LinePiece((1.0, 0.0), (1.0, 1.0))))
    with pytest.raises(ValueError, match=r"starts 0\.5 mm away"):
        Path((LinePiece((0.0, 0.0), (1.0, 0.0)), LinePiece((1.5, 0.0), (2.0, 0.0))))
    with pytest.raises(ValueError, match="length > 0"):
        LinePiece((1.0, 1.0), (1.0, 1.0))


def test_side_path_declares_its_curvature_steps_at_the_tangent_points() -> None:
    path = toolpath()
    side = [s for s in path.segments if s.cutting and s.side == "A"]
    pieces = []
    for s in side:
        if isinstance(s, ArcSegment):
            pieces.append(ArcPiece.through(s.start, s.end, s.center, s.clockwise, True, "A"))
        else:
            assert isinstance(s, LineSegment)
            pieces.append(LinePiece(s.start, s.end, True, "A"))
    joined = Path(tuple(pieces))
    steps = joined.curvature_steps()
    assert len(steps) == 2  # P2 and P3
    p2 = joined.point(steps[0])
    p3 = joined.point(steps[1])
    assert math.dist(p2, side[2].start) < 1e-9
    assert math.dist(p3, side[2].end) < 1e-6
