"""The exact X-Y geometry the planner moves along: lines and circular arcs by arc length.

Why the planner keeps its own copy of the geometry instead of calling the tool path's
``point_at``: it needs more than points. The time-scaling needs the first, second and third
derivatives of the curve with respect to arc length (tangent, curvature vector, its rate) and
their largest absolute value per axis over each piece, to turn axis limits into limits along
the path; the benchmark needs the same evaluations vectorised over thousands of samples.
These formulas are short, exact, and tested against ``app.geometry`` segment by segment.

Conventions: s is the arc length in mm from the start of a piece (or of a path). For an arc
the angle phi of the radius vector (centre -> point) is phi(s) = phi0 + sign * s / R with
sign = -1 for clockwise, so

    c(s)    = centre + R (cos phi, sin phi)
    c'(s)   = sign (-sin phi, cos phi)               unit tangent
    c''(s)  = -(1/R) (cos phi, sin phi)              curvature vector, |c''| = 1/R
    c'''(s) = -(1/R^2) c'(s)
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
Point = tuple[float, float]

_TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class DerivativeBounds:
    """Largest |d^k x_axis / ds^k| over a piece, for k = 1, 2, 3 and the axes X, Y.

    ``step`` is the largest jump of |d^2 x_axis / ds^2| where two pieces join (a change of
    curvature at a tangent joint: line to arc, or between the arcs of a fitted curve); zero
    inside one piece."""

    first: tuple[float, float]
    second: tuple[float, float]
    third: tuple[float, float]
    step: tuple[float, float] = (0.0, 0.0)

    def merge(self, other: DerivativeBounds) -> DerivativeBounds:
        def mx(a: tuple[float, float], b: tuple[float, float]) -> tuple[float, float]:
            return (max(a[0], b[0]), max(a[1], b[1]))

        return DerivativeBounds(
            mx(self.first, other.first),
            mx(self.second, other.second),
            mx(self.third, other.third),
            mx(self.step, other.step),
        )


@dataclass(frozen=True)
class LinePiece:
    """A straight piece from ``start`` to ``end`` (mm); ``cutting``/``side`` as the tool path."""

    start: Point
    end: Point
    cutting: bool = False
    side: str = ""

    def __post_init__(self) -> None:
        if self.length_mm <= 0.0:
            raise ValueError(f"line piece start = end = {self.start!r}: a piece needs length > 0")

    @property
    def length_mm(self) -> float:
        return math.hypot(self.end[0] - self.start[0], self.end[1] - self.start[1])

    @property
    def direction(self) -> Point:
        length = self.length_mm
        return ((self.end[0] - self.start[0]) / length, (self.end[1] - self.start[1]) / length)

    @property
    def curvature(self) -> float:
        """Signed curvature (1/mm, + to the left): 0 on a line."""
        return 0.0

    def start_tangent(self) -> Point:
        return self.direction

    def end_tangent(self) -> Point:
        return self.direction

    def bounds(self) -> DerivativeBounds:
        ux, uy = self.direction
        return DerivativeBounds((abs(ux), abs(uy)), (0.0, 0.0), (0.0, 0.0))

    def point(self, s: float) -> Point:
        if s >= self.length_mm:
            return self.end
        ux, uy = self.direction
        return (self.start[0] + ux * s, self.start[1] + uy * s)

    def points(self, s: FloatArray) -> tuple[FloatArray, FloatArray]:
        ux, uy = self.direction
        x = self.start[0] + ux * s
        y = self.start[1] + uy * s
        at_end = s >= self.length_mm
        return np.where(at_end, self.end[0], x), np.where(at_end, self.end[1], y)

    def derivatives(self, s: float) -> tuple[Point, Point, Point]:
        """(c', c'', c''') at s."""
        return self.direction, (0.0, 0.0), (0.0, 0.0)

    def distances(self, x: FloatArray, y: FloatArray) -> FloatArray:
        dx, dy = self.end[0] - self.start[0], self.end[1] - self.start[1]
        px, py = x - self.start[0], y - self.start[1]
        fraction = np.clip((px * dx + py * dy) / (dx * dx + dy * dy), 0.0, 1.0)
        result: FloatArray = np.hypot(px - fraction * dx, py - fraction * dy)
        return result


@dataclass(frozen=True)
class ArcPiece:
    """A circular piece about ``center``, from ``start`` through ``sweep_rad`` (> 0) in the
    given direction."""

    center: Point
    radius_mm: float
    start_angle_rad: float
    sweep_rad: float
    clockwise: bool
    cutting: bool = False
    side: str = ""

    def __post_init__(self) -> None:
        if not (self.radius_mm > 0.0 and math.isfinite(self.radius_mm)):
            raise ValueError(f"arc radius_mm = {self.radius_mm!r}: a finite number > 0")
        if not 0.0 < self.sweep_rad < _TWO_PI + 1e-12:
            raise ValueError(f"arc sweep_rad = {self.sweep_rad!r}: allowed 0 < sweep <= 2*pi")

    @classmethod
    def through(
        cls,
        start: Point,
        end: Point,
        center: Point,
        clockwise: bool,
        cutting: bool = False,
        side: str = "",
    ) -> ArcPiece:
        """The arc from ``start`` to ``end`` about ``center`` (the tool path's description)."""
        ux, uy = start[0] - center[0], start[1] - center[1]
        vx, vy = end[0] - center[0], end[1] - center[1]
        angle = math.atan2(ux * vy - uy * vx, ux * vx + uy * vy)
        if clockwise:
            angle = -angle
        sweep = angle if angle > 0.0 else angle + _TWO_PI
        radius = math.hypot(ux, uy)
        return cls(center, radius, math.atan2(uy, ux), sweep, clockwise, cutting, side)

    @property
    def sign(self) -> float:
        return -1.0 if self.clockwise else 1.0

    @property
    def length_mm(self) -> float:
        return self.radius_mm * self.sweep_rad

    @property
    def curvature(self) -> float:
        """Signed curvature (1/mm): + turning left (counter-clockwise), - turning right."""
        return self.sign / self.radius_mm

    def _angle(self, s: float) -> float:
        return self.start_angle_rad + self.sign * s / self.radius_mm

    def start_tangent(self) -> Point:
        phi = self.start_angle_rad
        return (-self.sign * math.sin(phi), self.sign * math.cos(phi))

    def end_tangent(self) -> Point:
        phi = self._angle(self.length_mm)
        return (-self.sign * math.sin(phi), self.sign * math.cos(phi))

    def _angle_range(self) -> tuple[float, float]:
        a = self.start_angle_rad
        b = a + self.sign * self.sweep_rad
        return (min(a, b), max(a, b))

    @staticmethod
    def _max_abs_cos(lo: float, hi: float) -> float:
        """max |cos phi| for phi in [lo, hi]: 1 if a multiple of pi lies inside."""
        if math.floor(hi / math.pi) >= math.ceil(lo / math.pi):
            return 1.0
        return max(abs(math.cos(lo)), abs(math.cos(hi)))

    def bounds(self) -> DerivativeBounds:
        lo, hi = self._angle_range()
        max_cos = self._max_abs_cos(lo, hi)
        max_sin = self._max_abs_cos(lo - math.pi / 2.0, hi - math.pi / 2.0)
        r = self.radius_mm
        # c' = sign(-sin, cos); c'' = -(cos, sin)/R; c''' = -c'/R^2
        return DerivativeBounds(
            (max_sin, max_cos), (max_cos / r, max_sin / r), (max_sin / r**2, max_cos / r**2)
        )

    def point(self, s: float) -> Point:
        phi = self._angle(s)
        return (
            self.center[0] + self.radius_mm * math.cos(phi),
            self.center[1] + self.radius_mm * math.sin(phi),
        )

    def points(self, s: FloatArray) -> tuple[FloatArray, FloatArray]:
        phi = self.start_angle_rad + self.sign * s / self.radius_mm
        return (
            self.center[0] + self.radius_mm * np.cos(phi),
            self.center[1] + self.radius_mm * np.sin(phi),
        )

    def derivatives(self, s: float) -> tuple[Point, Point, Point]:
        phi = self._angle(s)
        c, si = math.cos(phi), math.sin(phi)
        r = self.radius_mm
        first = (-self.sign * si, self.sign * c)
        return first, (-c / r, -si / r), (-first[0] / r**2, -first[1] / r**2)

    def distances(self, x: FloatArray, y: FloatArray) -> FloatArray:
        px, py = x - self.center[0], y - self.center[1]
        offset = (np.arctan2(py, px) - self.start_angle_rad) * self.sign
        offset = np.mod(offset, _TWO_PI)
        inside = offset <= self.sweep_rad
        end_phi = self._angle(self.length_mm)
        sx = self.center[0] + self.radius_mm * math.cos(self.start_angle_rad)
        sy = self.center[1] + self.radius_mm * math.sin(self.start_angle_rad)
        ex = self.center[0] + self.radius_mm * math.cos(end_phi)
        ey = self.center[1] + self.radius_mm * math.sin(end_phi)
        ends = np.minimum(np.hypot(x - sx, y - sy), np.hypot(x - ex, y - ey))
        result: FloatArray = np.where(inside, np.abs(np.hypot(px, py) - self.radius_mm), ends)
        return result


Piece = LinePiece | ArcPiece


def _tangent_angle_between(a: Point, b: Point) -> float:
    return abs(math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]))


@dataclass(frozen=True)
class Path:
    """Consecutive pieces joined with a continuous tangent (G1), parameterised by arc length.

    Why G1 is required: the planner runs a path without stopping, so a corner would demand
    an infinite acceleration; corners are where one path ends (at rest) and the next begins.
    """

    pieces: tuple[Piece, ...]
    offsets: tuple[float, ...] = field(init=False)

    POSITION_TOLERANCE_MM = 1e-6
    TANGENT_TOLERANCE_RAD = 1e-6

    def __post_init__(self) -> None:
        if not self.pieces:
            raise ValueError("a path needs at least one piece")
        offsets = [0.0]
        for index, piece in enumerate(self.pieces):
            if index:
                previous = self.pieces[index - 1]
                gap = math.dist(_end_point(previous), _start_point(piece))
                if gap > self.POSITION_TOLERANCE_MM:
                    raise ValueError(
                        f"path piece {index} starts {gap:.3g} mm away from the end "
                        "of the previous one"
                    )
                turn = _tangent_angle_between(previous.end_tangent(), piece.start_tangent())
                if turn > self.TANGENT_TOLERANCE_RAD:
                    raise ValueError(
                        f"path piece {index} turns by {math.degrees(turn):.4g} deg "
                        "at its start: pieces of one path must join tangentially"
                    )
            offsets.append(offsets[-1] + piece.length_mm)
        object.__setattr__(self, "offsets", tuple(offsets))

    @property
    def length_mm(self) -> float:
        return self.offsets[-1]

    @property
    def start(self) -> Point:
        return _start_point(self.pieces[0])

    @property
    def end(self) -> Point:
        return _end_point(self.pieces[-1])

    def bounds(self) -> DerivativeBounds:
        result = self.pieces[0].bounds()
        for previous, piece in zip(self.pieces, self.pieces[1:], strict=False):
            result = result.merge(piece.bounds()).merge(_joint_step(previous, piece))
        return result

    def locate(self, s: float) -> tuple[int, float]:
        """(piece index, s within that piece) for a path arc length, clamped to the path."""
        s = min(max(s, 0.0), self.length_mm)
        index = min(bisect.bisect_right(self.offsets, s) - 1, len(self.pieces) - 1)
        return index, s - self.offsets[index]

    def point(self, s: float) -> Point:
        index, local = self.locate(s)
        return self.pieces[index].point(local)

    def derivatives(self, s: float) -> tuple[Point, Point, Point]:
        index, local = self.locate(s)
        return self.pieces[index].derivatives(local)

    def points(self, s: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Vectorised :meth:`point` (s clamped to the path)."""
        s = np.clip(np.asarray(s, dtype=np.float64), 0.0, self.length_mm)
        index = np.clip(np.searchsorted(self.offsets, s, side="right") - 1, 0, len(self.pieces) - 1)
        x = np.empty_like(s)
        y = np.empty_like(s)
        for i, piece in enumerate(self.pieces):
            mask = index == i
            if np.any(mask):
                x[mask], y[mask] = piece.points(s[mask] - self.offsets[i])
        return x, y

    def distances(self, x: FloatArray, y: FloatArray) -> FloatArray:
        """Plan-view distance of each point to the nearest point of the path."""
        result = self.pieces[0].distances(x, y)
        for piece in self.pieces[1:]:
            result = np.minimum(result, piece.distances(x, y))
        return result

    def curvature_steps(self) -> tuple[float, ...]:
        """Arc lengths where a line meets an arc (P2/P3/P6/P7 of line-arc-line).

        At such a point the normal acceleration v^2 * kappa steps, so the jerk is unbounded
        for an instant whatever the speed: the only places the jerk limit is not kept. The
        smaller steps between the arcs of a fitted curve are kept within it by the path box."""
        steps = []
        for index in range(1, len(self.pieces)):
            if _is_declared_step(self.pieces[index - 1], self.pieces[index]):
                steps.append(self.offsets[index])
        return tuple(steps)

    def cutting_ranges(self) -> tuple[tuple[float, float, str], ...]:
        """(s_start, s_end, side) of each cutting piece."""
        return tuple(
            (self.offsets[i], self.offsets[i + 1], p.side)
            for i, p in enumerate(self.pieces)
            if p.cutting
        )


def _is_declared_step(before: Piece, after: Piece) -> bool:
    """A line meeting an arc: a curvature step of the profile itself (line-arc-line's P2, P3,
    P6, P7, or a drawn line meeting a drawn arc), the declared exception to the jerk limit.
    Between two arcs the step comes from fitting a smooth curve, and the planner keeps the
    jerk there (see `planner.chunk`)."""
    kinds = (isinstance(before, LinePiece), isinstance(after, LinePiece))
    return kinds[0] != kinds[1] and before.curvature != after.curvature


def _joint_step(before: Piece, after: Piece) -> DerivativeBounds:
    """The jump of c'' at a tangent joint between two arcs: (k_after - k_before) times the
    common normal (zero at a declared step and between lines)."""
    zero = (0.0, 0.0)
    if isinstance(before, LinePiece) or isinstance(after, LinePiece):
        return DerivativeBounds(zero, zero, zero)
    jump = abs(after.curvature - before.curvature)
    tx, ty = after.start_tangent()
    return DerivativeBounds(zero, zero, zero, (jump * abs(ty), jump * abs(tx)))


def _start_point(piece: Piece) -> Point:
    return piece.start if isinstance(piece, LinePiece) else piece.point(0.0)


def _end_point(piece: Piece) -> Point:
    return piece.end if isinstance(piece, LinePiece) else piece.point(piece.length_mm)


def join_tolerance_ok(a: Sequence[float], b: Sequence[float]) -> bool:
    """True if two tangents are parallel and same-sense within the path's tolerance."""
    return _tangent_angle_between((a[0], a[1]), (b[0], b[1])) <= Path.TANGENT_TOLERANCE_RAD
