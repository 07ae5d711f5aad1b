"""Biarc fitting: any smooth plane curve as a tangent-continuous chain of lines and arcs.

Why biarcs: the drives, the planner, the executor and the program export all work on exact
lines and circular arcs, and a pair of arcs can match a curve's two end points *and* its two
end tangents. Fitting every stretch of a curve with one biarc and splitting the stretch in
two until the biarc lies within the tolerance gives a chain whose joints are tangent by
construction (each biarc starts and ends on the curve's own tangent), which the classic
point-by-point polygon of the parametric lathe programs does not.

The joint of each biarc is chosen with equal tangent lengths (the symmetric biarc), which is
well defined for the gently curved stretches a stave's side has. The deviation of a biarc is
measured from the true curve at interior sample points to the two arcs; the fit keeps it to a
fraction of the tolerance, so that a much denser check (10,000 points) still holds.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

from app.geometry.segments import ArcSegment, LineSegment, Point, Segment

FIT_TOLERANCE_MM = 0.001
"""How close the fitted chain stays to the true curve."""

_SAFETY = 0.25
"""The fit aims at this fraction of the tolerance at its sample points."""

_SAMPLES_PER_STRETCH = 16
_MIN_STRETCH = 1e-7
"""Shortest parameter interval split further; reaching it means the curve is not smooth."""

_STRAIGHT_SAGITTA_MM = 1e-9
"""An arc whose sagitta is below this is emitted as a line (a radius of many kilometres)."""


class Curve(Protocol):
    """A plane curve on the parameter interval [0, 1]: point and derivative d(point)/dt."""

    def point(self, t: float) -> Point: ...

    def derivative(self, t: float) -> Point: ...


class FitError(ValueError):
    """The curve could not be fitted (it is not smooth at `t`)."""

    def __init__(self, t: float) -> None:
        super().__init__(f"the curve is not smooth near parameter {t:.6g}")
        self.t = t


@dataclass(frozen=True)
class _Stretch:
    t0: float
    t1: float
    p0: Point
    p1: Point
    tangent0: Point
    tangent1: Point


def _unit(vector: Point) -> Point:
    length = math.hypot(vector[0], vector[1])
    if length == 0.0 or not math.isfinite(length):
        raise ValueError("the curve has no direction here (zero or non-finite derivative)")
    return (vector[0] / length, vector[1] / length)


def _arc_or_line(start: Point, tangent: Point, end: Point) -> Segment:
    """The arc that leaves `start` along `tangent` and ends at `end` (a line if straight)."""
    wx, wy = end[0] - start[0], end[1] - start[1]
    chord_sq = wx * wx + wy * wy
    normal = (-tangent[1], tangent[0])
    curvature = 2.0 * (normal[0] * wx + normal[1] * wy) / chord_sq  # > 0: turning left
    if abs(curvature) * chord_sq / 8.0 < _STRAIGHT_SAGITTA_MM:
        return LineSegment(start, end, 0.0, 0.0, False, "")
    radius = 1.0 / curvature
    centre = (start[0] + normal[0] * radius, start[1] + normal[1] * radius)
    return ArcSegment(start, end, centre, curvature < 0.0, 0.0, 0.0, False, "")


def _reversed(segment: Segment) -> Segment:
    if isinstance(segment, LineSegment):
        return LineSegment(segment.end, segment.start, 0.0, 0.0, False, "")
    return ArcSegment(
        segment.end, segment.start, segment.center, not segment.clockwise, 0.0, 0.0, False, ""
    )


def biarc(p0: Point, tangent0: Point, p1: Point, tangent1: Point) -> tuple[Segment, ...]:
    """The symmetric biarc from p0 (unit tangent0) to p1 (unit tangent1).

    Returns one line when the stretch is straight, else two pieces meeting tangentially at
    the joint. Raises ValueError when no forward-going biarc exists (tangents opposing the
    chord), which a finer split cures for a smooth curve.
    """
    vx, vy = p1[0] - p0[0], p1[1] - p0[1]
    chord_sq = vx * vx + vy * vy
    if chord_sq == 0.0:
        raise ValueError("a biarc needs two distinct end points")
    tx, ty = tangent0[0] + tangent1[0], tangent0[1] + tangent1[1]
    v_dot_t = vx * tx + vy * ty
    denominator = 2.0 * (1.0 - (tangent0[0] * tangent1[0] + tangent0[1] * tangent1[1]))
    if denominator < 1e-14:
        along = vx * tangent1[0] + vy * tangent1[1]
        if along <= 0.0:
            raise ValueError("the tangents point away from the chord")
        cross = tangent0[0] * vy - tangent0[1] * vx
        if abs(cross) * math.sqrt(chord_sq) < 8.0 * _STRAIGHT_SAGITTA_MM:
            return (LineSegment(p0, p1, 0.0, 0.0, False, ""),)
        d = chord_sq / (4.0 * along)
    else:
        d = (-v_dot_t + math.sqrt(v_dot_t * v_dot_t + denominator * chord_sq)) / denominator
    if not d > 0.0:
        raise ValueError("no forward-going biarc for these tangents")
    joint = (
        (p0[0] + p1[0] + d * (tangent0[0] - tangent1[0])) / 2.0,
        (p0[1] + p1[1] + d * (tangent0[1] - tangent1[1])) / 2.0,
    )
    first = _arc_or_line(p0, tangent0, joint)
    second = _reversed(_arc_or_line(p1, (-tangent1[0], -tangent1[1]), joint))
    return (first, second)


def _sweep_ok(pieces: tuple[Segment, ...]) -> bool:
    """A biarc piece turning by a quarter turn or more means the split was too coarse."""
    return all(isinstance(p, LineSegment) or p.sweep_rad < math.pi / 2.0 for p in pieces)


def _deviation_mm(curve: Curve, stretch: _Stretch, pieces: tuple[Segment, ...]) -> float:
    worst = 0.0
    for i in range(1, _SAMPLES_PER_STRETCH):
        t = stretch.t0 + (stretch.t1 - stretch.t0) * i / _SAMPLES_PER_STRETCH
        point = curve.point(t)
        worst = max(worst, min(piece.distance_to(point) for piece in pieces))
    return worst


def fit_biarcs(
    curve: Curve,
    tolerance_mm: float = FIT_TOLERANCE_MM,
    start_tangent: Point | None = None,
    end_tangent: Point | None = None,
    splits: tuple[float, ...] = (),
) -> tuple[Segment, ...]:
    """The chain of lines and arcs within `tolerance_mm` of `curve` over t in [0, 1].

    `start_tangent` / `end_tangent` replace the curve's own end tangents (to join the next
    curve of a chain with one common tangent); `splits` are parameters where the fit must
    have a joint (e.g. the belly). The chain's pieces carry no tilt and no side; raises
    FitError where the curve is not smooth enough to fit.
    """
    budget = _SAFETY * tolerance_mm

    def stretch(t0: float, t1: float, tangent0: Point | None, tangent1: Point | None) -> _Stretch:
        return _Stretch(
            t0,
            t1,
            curve.point(t0),
            curve.point(t1),
            tangent0 or _unit(curve.derivative(t0)),
            tangent1 or _unit(curve.derivative(t1)),
        )

    bounds = [0.0, *sorted(t for t in splits if 0.0 < t < 1.0), 1.0]
    pending: list[_Stretch] = []
    for index in range(len(bounds) - 2, -1, -1):
        first, last = index == 0, index == len(bounds) - 2
        pending.append(
            stretch(
                bounds[index],
                bounds[index + 1],
                start_tangent if first else None,
                end_tangent if last else None,
            )
        )
    chain: list[Segment] = []
    while pending:
        current = pending.pop()
        try:
            pieces = biarc(current.p0, current.tangent0, current.p1, current.tangent1)
            good = _sweep_ok(pieces) and _deviation_mm(curve, current, pieces) <= budget
        except ValueError:
            good = False
        if good:
            # Join exactly: the next piece starts where this one ended (no gap, not 1 ulp).
            chain.extend(pieces)
            continue
        if current.t1 - current.t0 < _MIN_STRETCH:
            raise FitError(current.t0)
        middle = 0.5 * (current.t0 + current.t1)
        middle_point = curve.point(middle)
        middle_tangent = _unit(curve.derivative(middle))
        pending.append(
            _Stretch(middle, current.t1, middle_point, current.p1, middle_tangent, current.tangent1)
        )
        pending.append(
            _Stretch(current.t0, middle, current.p0, middle_point, current.tangent0, middle_tangent)
        )
    return tuple(chain)
