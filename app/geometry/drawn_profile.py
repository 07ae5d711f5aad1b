"""A side profile drawn in CAD: the drawing's curve found, checked and made scalable.

The data layer reads the file (DXF) and hands over plain primitives (lines, arcs, splines,
each naming the entity and layer it came from); this module does no I/O. It joins them into
chains by their end points, insists on exactly one open chain, orients it left to right and
checks what the cutter needs: a smooth curve (no corner), a single function of x, no
self-intersection, heads of equal width and the belly in the middle.

How a drawing is scaled onto a board: the drawing gives the *shape*; the board gives the
size. The drawn span in x is stretched to the recipe's length L, and the depth below the belly
is scaled so that the heads come out at the recipe's width ratio, W1 = k*W, with the belly at
the measured width W:

    x' = (x - x_left) * L / (x_right - x_left)
    y' = W1/2 + (W - W1)/2 * (y - y_head) / (y_belly - y_head)

So one drawing serves every board and every length, like the families by equation. A drawing
of the lower side (belly below the heads) is mirrored first. The scaled curve is still exact:
lines stay lines, arcs become elliptic arcs evaluated from their angle, splines stay splines
(their control points scaled).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import pairwise

from app.geometry.errors import FieldError, GeometryError
from app.geometry.nurbs import Nurbs

Point = tuple[float, float]

JOIN_TOLERANCE_MM = 1e-4
"""End points closer than this are one joint of the drawn chain."""

CORNER_TOLERANCE_RAD = math.radians(0.01)
"""A change of direction at a joint above this is a corner the cutter cannot follow exactly."""

BELLY_POSITION_TOLERANCE = 0.005
"""How far from the middle the drawn belly may lie, as a fraction of the span."""

HEAD_MISMATCH_TOLERANCE = 0.005
"""How much the two heads' depths may differ, as a fraction of the belly's rise."""

_MONOTONE_SAMPLES = 64
_INTERSECTION_SAMPLES = 24

FIELD = "drawn_profile"


@dataclass(frozen=True)
class DrawnLine:
    start: Point
    end: Point
    source: str = ""

    def point(self, t: float) -> Point:
        return (
            self.start[0] + (self.end[0] - self.start[0]) * t,
            self.start[1] + (self.end[1] - self.start[1]) * t,
        )

    def derivative(self, t: float) -> Point:
        return (self.end[0] - self.start[0], self.end[1] - self.start[1])

    def reversed(self) -> DrawnLine:
        return DrawnLine(self.end, self.start, self.source)

    def to_dict(self) -> dict[str, object]:
        return {
            "type": "line",
            "start": list(self.start),
            "end": list(self.end),
            "source": self.source,
        }


@dataclass(frozen=True)
class DrawnArc:
    """A circular arc from `start_angle_rad` turning by `sweep_rad` (> 0 counter-clockwise)."""

    center: Point
    radius: float
    start_angle_rad: float
    sweep_rad: float
    source: str = ""

    def point(self, t: float) -> Point:
        angle = self.start_angle_rad + self.sweep_rad * t
        return (
            self.center[0] + self.radius * math.cos(angle),
            self.center[1] + self.radius * math.sin(angle),
        )

    def derivative(self, t: float) -> Point:
        angle = self.start_angle_rad + self.sweep_rad * t
        factor = self.radius * self.sweep_rad
        return (-factor * math.sin(angle), factor * math.cos(angle))

    def reversed(self) -> DrawnArc:
        return DrawnArc(
            self.center,
            self.radius,
            self.start_angle_rad + self.sweep_rad,
            -self.sweep_rad,
            self.source,
        )

    def to_dict(self) -> dict[str, object]:
        return {
            "type": "arc",
            "center": list(self.center),
            "radius": self.radius,
            "start_angle_rad": self.start_angle_rad,
            "sweep_rad": self.sweep_rad,
            "source": self.source,
        }


@dataclass(frozen=True)
class DrawnSpline:
    """A NURBS curve; `reverse` runs it from its last point to its first."""

    nurbs: Nurbs
    reverse: bool = False
    source: str = ""

    def _u(self, t: float) -> float:
        low, high = self.nurbs.domain
        return high - (high - low) * t if self.reverse else low + (high - low) * t

    def point(self, t: float) -> Point:
        return self.nurbs.point_at(self._u(t))

    def derivative(self, t: float) -> Point:
        low, high = self.nurbs.domain
        dx, dy = self.nurbs.derivative_at(self._u(t))
        factor = -(high - low) if self.reverse else high - low
        return (dx * factor, dy * factor)

    def reversed(self) -> DrawnSpline:
        return DrawnSpline(self.nurbs, not self.reverse, self.source)

    def to_dict(self) -> dict[str, object]:
        return {
            "type": "spline",
            "degree": self.nurbs.degree,
            "knots": list(self.nurbs.knots),
            "control_points": [list(p) for p in self.nurbs.control_points],
            "weights": list(self.nurbs.weights),
            "reverse": self.reverse,
            "source": self.source,
        }


Primitive = DrawnLine | DrawnArc | DrawnSpline


def from_bulge(start: Point, end: Point, bulge: float, source: str = "") -> DrawnLine | DrawnArc:
    """A polyline segment with a bulge: the arc whose sweep is 4*atan(bulge) (> 0 is
    counter-clockwise), or the straight line for bulge 0 (the DXF convention)."""
    if bulge == 0.0:
        return DrawnLine(start, end, source)
    sweep = 4.0 * math.atan(bulge)
    cx, cy = end[0] - start[0], end[1] - start[1]
    chord = math.hypot(cx, cy)
    if chord == 0.0:
        raise ValueError(f"{source}: a bulged segment with coinciding ends")
    offset = (chord / 2.0) / math.tan(sweep / 2.0)
    centre = (
        (start[0] + end[0]) / 2.0 - cy / chord * offset,
        (start[1] + end[1]) / 2.0 + cx / chord * offset,
    )
    radius = chord / (2.0 * abs(math.sin(sweep / 2.0)))
    angle = math.atan2(start[1] - centre[1], start[0] - centre[0])
    return DrawnArc(centre, radius, angle, sweep, source)


def primitive_from_dict(item: dict[str, object]) -> Primitive:
    """The inverse of `to_dict` (the form a recipe stores); ValueError names what is wrong."""

    def point(value: object) -> Point:
        if not (isinstance(value, list | tuple) and len(value) == 2):
            raise ValueError(f"a point must be two numbers, got {value!r}")
        return (float(value[0]), float(value[1]))

    def number(name: str) -> float:
        value = item.get(name)
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise ValueError(f"{name} must be a number, got {value!r}")
        return float(value)

    def numbers(name: str) -> tuple[float, ...]:
        value = item.get(name)
        if not isinstance(value, list):
            raise ValueError(f"{name} must be a list of numbers, got {value!r}")
        return tuple(float(v) for v in value)

    kind, source = item.get("type"), str(item.get("source", ""))
    if kind == "line":
        return DrawnLine(point(item.get("start")), point(item.get("end")), source)
    if kind == "arc":
        return DrawnArc(
            point(item.get("center")),
            number("radius"),
            number("start_angle_rad"),
            number("sweep_rad"),
            source,
        )
    if kind == "spline":
        points = item.get("control_points")
        if not isinstance(points, list):
            raise ValueError(f"control_points must be a list of points, got {points!r}")
        degree = item.get("degree")
        if not isinstance(degree, int) or isinstance(degree, bool):
            raise ValueError(f"degree must be a whole number, got {degree!r}")
        nurbs = Nurbs(degree, numbers("knots"), tuple(point(p) for p in points), numbers("weights"))
        return DrawnSpline(nurbs, bool(item.get("reverse", False)), source)
    raise ValueError(f"type = {kind!r} is not a drawn primitive: allowed line, arc, spline")


def _start(primitive: Primitive) -> Point:
    return primitive.point(0.0)


def _end(primitive: Primitive) -> Point:
    return primitive.point(1.0)


def _close(a: Point, b: Point) -> bool:
    return math.hypot(a[0] - b[0], a[1] - b[1]) <= JOIN_TOLERANCE_MM


def _refuse(
    message: str, value: object = None, allowed: str = "one smooth open curve"
) -> GeometryError:
    return GeometryError([FieldError(FIELD, value, allowed, message)])


def _describe(primitives: list[Primitive]) -> str:
    names = [p.source or type(p).__name__ for p in primitives]
    return ", ".join(names)


def _chains(primitives: list[Primitive]) -> list[list[Primitive]]:
    """Group primitives into chains joined end to end (each reoriented to run along)."""
    remaining = list(primitives)
    chains: list[list[Primitive]] = []
    while remaining:
        chain = [remaining.pop(0)]
        grown = True
        while grown:
            grown = False
            for index, candidate in enumerate(remaining):
                head, tail = _start(chain[0]), _end(chain[-1])
                if _close(tail, _start(candidate)):
                    chain.append(candidate)
                elif _close(tail, _end(candidate)):
                    chain.append(candidate.reversed())
                elif _close(head, _end(candidate)):
                    chain.insert(0, candidate)
                elif _close(head, _start(candidate)):
                    chain.insert(0, candidate.reversed())
                else:
                    continue
                remaining.pop(index)
                grown = True
                break
        chains.append(chain)
    return chains


def _branch_points(primitives: list[Primitive]) -> list[Point]:
    ends = [e for p in primitives for e in (_start(p), _end(p))]
    return [a for i, a in enumerate(ends) if sum(_close(a, b) for b in ends) > 2 and i % 2 == 0]


def _unit(vector: Point) -> Point:
    length = math.hypot(*vector)
    return (vector[0] / length, vector[1] / length) if length > 0.0 else (0.0, 0.0)


def _turn_rad(a: Point, b: Point) -> float:
    ua, ub = _unit(a), _unit(b)
    return abs(math.atan2(ua[0] * ub[1] - ua[1] * ub[0], ua[0] * ub[0] + ua[1] * ub[1]))


def _segments_cross(p1: Point, p2: Point, q1: Point, q2: Point) -> Point | None:
    """The crossing point of two segments' interiors, if any."""
    rx, ry = p2[0] - p1[0], p2[1] - p1[1]
    sx, sy = q2[0] - q1[0], q2[1] - q1[1]
    denominator = rx * sy - ry * sx
    if abs(denominator) <= 1e-12 * math.hypot(rx, ry) * math.hypot(sx, sy):
        return None  # parallel (collinear neighbours of one line): no single crossing
    qpx, qpy = q1[0] - p1[0], q1[1] - p1[1]
    t = (qpx * sy - qpy * sx) / denominator
    u = (qpx * ry - qpy * rx) / denominator
    if -1e-12 <= t <= 1.0 + 1e-12 and -1e-12 <= u <= 1.0 + 1e-12:
        return (p1[0] + t * rx, p1[1] + t * ry)
    return None


def _self_intersection(chain: list[Primitive]) -> Point | None:
    points = [_start(chain[0])]
    for primitive in chain:
        points += [
            primitive.point(i / _INTERSECTION_SAMPLES) for i in range(1, _INTERSECTION_SAMPLES + 1)
        ]
    edges = list(pairwise(points))
    for i, (a, b) in enumerate(edges):
        for c, d in edges[i + 2 :]:
            crossing = _segments_cross(a, b, c, d)
            if crossing is not None:
                return crossing
    return None


def _turning_back(chain: list[Primitive]) -> tuple[Primitive, float] | None:
    """Where the chain stops advancing in x (the first such place), if anywhere."""
    for primitive in chain:
        for i in range(_MONOTONE_SAMPLES + 1):
            t = i / _MONOTONE_SAMPLES
            if not primitive.derivative(t)[0] > 0.0:
                return primitive, primitive.point(t)[0]
    return None


def _extreme(chain: list[Primitive], samples: int = 400) -> tuple[float, float, float]:
    """(x of the highest point, its y, the lowest y) sampled along the chain.

    A flat top counts as one belly at its middle; two separate highest places (a trough
    between them) give the first one, which the caller finds off the middle.
    """
    points = [p.point(i / samples) for p in chain for i in range(samples + 1)]
    top = max(y for _, y in points)
    low = min(y for _, y in points)
    ties = [index for index, (_, y) in enumerate(points) if y >= top - 1e-9]
    contiguous = all(b - a <= 2 for a, b in pairwise(ties))
    if not contiguous:
        return points[ties[0]][0], top, low
    return 0.5 * (points[ties[0]][0] + points[ties[-1]][0]), top, low


def _mirrored(primitive: Primitive) -> Primitive:
    if isinstance(primitive, DrawnLine):
        return DrawnLine(
            (primitive.start[0], -primitive.start[1]),
            (primitive.end[0], -primitive.end[1]),
            primitive.source,
        )
    if isinstance(primitive, DrawnArc):
        c = primitive.center
        return DrawnArc(
            (c[0], -c[1]),
            primitive.radius,
            -primitive.start_angle_rad,
            -primitive.sweep_rad,
            primitive.source,
        )
    return DrawnSpline(
        primitive.nurbs.mapped(1.0, -1.0, 0.0, 0.0), primitive.reverse, primitive.source
    )


@dataclass(frozen=True)
class DrawnShape:
    """The checked drawn curve, left to right, belly up, with the frame it is scaled from.

    `primitives` join exactly at `joints` (len = len(primitives) + 1); `x_left`..`x_right`
    is the drawn span, `y_head` the heads' level (their mean) and `y_belly` the belly's.
    """

    primitives: tuple[Primitive, ...]
    joints: tuple[Point, ...]
    x_left: float
    x_right: float
    y_head: float
    y_belly: float
    sources: tuple[str, ...] = field(default=())

    def to_dict(self) -> dict[str, object]:
        """The form a recipe stores: the primitives as drawn (after orientation)."""
        return {"primitives": [p.to_dict() for p in self.primitives]}


def shape_from_dict(data: object) -> DrawnShape:
    """A stored shape back (checked again, so a tampered record cannot cut a bad curve)."""
    if not isinstance(data, dict) or not isinstance(data.get("primitives"), list):
        raise _refuse(f"{FIELD}: the stored drawing is not readable (no primitives)")
    try:
        primitives = [primitive_from_dict(item) for item in data["primitives"]]
    except (ValueError, TypeError) as error:
        raise _refuse(f"{FIELD}: the stored drawing is not readable: {error}") from None
    return drawn_shape(primitives)


def drawn_shape(primitives: list[Primitive], found_elsewhere: tuple[str, ...] = ()) -> DrawnShape:
    """Find the one profile curve among `primitives` and check it; GeometryError says why not.

    `found_elsewhere` names the drawing's entities that are not curves (for the message when
    nothing usable is left).
    """
    if not primitives:
        found = ", ".join(found_elsewhere) or "nothing"
        raise _refuse(
            f"{FIELD}: the drawing has no usable curve (LINE, ARC, LWPOLYLINE, POLYLINE or "
            f"SPLINE); found: {found}",
            found,
        )
    branches = _branch_points(primitives)
    if branches:
        x, y = branches[0]
        raise _refuse(
            f"{FIELD}: the drawing's curves branch at ({x:.3f}, {y:.3f}) mm; draw one side only",
            branches[0],
        )
    chains = _chains(primitives)
    if len(chains) > 1:
        listed = "; ".join(f"curve {i + 1}: {_describe(c)}" for i, c in enumerate(chains))
        raise _refuse(
            f"{FIELD}: the drawing has {len(chains)} candidate curves ({listed}); keep one, or "
            f"choose its layer",
            len(chains),
        )
    chain = chains[0]
    if _close(_start(chain[0]), _end(chain[-1])):
        raise _refuse(
            f"{FIELD}: the curve is closed ({_describe(chain)}); draw one side, open, "
            "from head to head"
        )
    if _start(chain[0])[0] > _end(chain[-1])[0]:
        chain = [p.reversed() for p in reversed(chain)]
    crossing = _self_intersection(chain)
    if crossing is not None:
        raise _refuse(
            f"{FIELD}: the curve crosses itself at ({crossing[0]:.3f}, {crossing[1]:.3f}) mm",
            crossing,
        )
    back = _turning_back(chain)
    if back is not None:
        primitive, x = back
        raise _refuse(
            f"{FIELD}: the curve is not a single function of x: it stops advancing along the "
            f"stave at x = {x:.3f} mm ({primitive.source or type(primitive).__name__})",
            x,
            "a curve that advances along the stave everywhere",
        )
    for before, after in pairwise(chain):
        turn = _turn_rad(before.derivative(1.0), after.derivative(0.0))
        if turn > CORNER_TOLERANCE_RAD:
            x, y = _end(before)
            raise _refuse(
                f"{FIELD}: the curve has a corner of {math.degrees(turn):.3f} deg at "
                f"({x:.3f}, {y:.3f}) mm between {before.source} and {after.source}; the side "
                "must be smooth (draw it with arcs, bulges or a spline)",
                math.degrees(turn),
                f"corners up to {math.degrees(CORNER_TOLERANCE_RAD):.2f} deg",
            )
    joints = [_start(chain[0])]
    for before, after in pairwise(chain):
        a, b = _end(before), _start(after)
        joints.append(((a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0))
    joints.append(_end(chain[-1]))
    x_left, x_right = joints[0][0], joints[-1][0]
    heads_y = (joints[0][1] + joints[-1][1]) / 2.0
    x_top, y_top, y_low = _extreme(chain)
    if y_top - heads_y < heads_y - y_low:
        chain = [_mirrored(p) for p in chain]
        joints = [(x, -y) for x, y in joints]
        heads_y = -heads_y
        x_top, y_top, y_low = _extreme(chain)
    rise = y_top - heads_y
    span = x_right - x_left
    if not rise > JOIN_TOLERANCE_MM:
        raise _refuse(
            f"{FIELD}: the curve has no belly: its middle is not wider than its heads", rise
        )
    mismatch = abs(joints[0][1] - joints[-1][1])
    if mismatch > HEAD_MISMATCH_TOLERANCE * rise:
        raise _refuse(
            f"{FIELD}: the two heads differ by {mismatch:.3f} mm in depth (of a {rise:.3f} mm "
            f"rise); allowed {100 * HEAD_MISMATCH_TOLERANCE:.1f} %",
            mismatch,
        )
    middle = (x_left + x_right) / 2.0
    if abs(x_top - middle) > BELLY_POSITION_TOLERANCE * span:
        raise _refuse(
            f"{FIELD}: the belly is at x = {x_top:.3f} mm, not in the middle of the drawn "
            f"span ({middle:.3f} mm); allowed within {100 * BELLY_POSITION_TOLERANCE:.1f} % of "
            "the length",
            x_top,
            f"x = {middle:.3f} mm +- {BELLY_POSITION_TOLERANCE * span:.3f} mm",
        )
    return DrawnShape(
        primitives=tuple(chain),
        joints=tuple(joints),
        x_left=x_left,
        x_right=x_right,
        y_head=heads_y,
        y_belly=y_top,
        sources=tuple(p.source for p in chain),
    )
