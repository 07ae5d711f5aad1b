"""Side profiles of any shape for one measured board: the true curve and its fitted chain.

Every kind ends as the same thing the tool path already knows, a tangent-continuous chain of
lines and arcs for side A in the profile frame (docs/MACHINE.md section 2), side B being its
mirror image. Line-arc-line and the single arc are solved exactly by `profile.solve_profile`;
the curve families and drawn profiles are fitted with biarcs within 0.001 mm of the true
curve, which this module also keeps (as exact curve pieces) so that the fit can be checked.

The chain is fitted per board because the board's width scales the curve unevenly (the depth
changes, the length does not), and an arc scaled unevenly is no longer an arc.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from itertools import pairwise

from app.geometry.biarc import FIT_TOLERANCE_MM, Curve, FitError, fit_biarcs
from app.geometry.drawn_profile import DrawnLine, DrawnShape, Primitive
from app.geometry.errors import FieldError, GeometryError
from app.geometry.limits import StaveLimits, validate_stave
from app.geometry.profile import StaveProfile, solve_profile
from app.geometry.profile_kinds import (
    FamilyShape,
    ProfileKind,
    family_shape,
    validate_family_parameters,
)
from app.geometry.segments import ArcSegment, LineSegment, Point, Segment


@dataclass(frozen=True)
class _FamilyCurve:
    """h(x) = W1/2 + C*shape(x) for x from x0 to x1, as a curve over t in [0, 1]."""

    shape: FamilyShape
    half_head_mm: float
    depth_mm: float
    x0: float
    x1: float

    def point(self, t: float) -> Point:
        x = self.x1 if t == 1.0 else self.x0 + (self.x1 - self.x0) * t
        return (x, self.half_head_mm + self.depth_mm * self.shape.value(x))

    def derivative(self, t: float) -> Point:
        x = self.x0 + (self.x1 - self.x0) * t
        span = self.x1 - self.x0
        return (span, span * self.depth_mm * self.shape.slope(x))


@dataclass(frozen=True)
class _ScaledPrimitive:
    """A drawn primitive under the drawing-to-board map, its ends pinned to the joints."""

    primitive: Primitive
    scale_x: float
    scale_y: float
    x_left: float
    y_head: float
    half_head_mm: float
    start: Point
    end: Point

    def _map(self, point: Point) -> Point:
        return (
            self.scale_x * (point[0] - self.x_left),
            self.half_head_mm + self.scale_y * (point[1] - self.y_head),
        )

    def point(self, t: float) -> Point:
        if t == 0.0:
            return self.start
        if t == 1.0:
            return self.end
        return self._map(self.primitive.point(t))

    def derivative(self, t: float) -> Point:
        dx, dy = self.primitive.derivative(t)
        return (self.scale_x * dx, self.scale_y * dy)


def mirrored_side(edge_a: tuple[Segment, ...], side: str = "B") -> tuple[Segment, ...]:
    """Side B from side A: mirrored in y and run backwards (right to left).

    Mirroring flips an arc's sense and running it backwards flips it again, so a clockwise arc
    on side A stays clockwise on side B (both sides are cut clockwise around the board).
    """
    result: list[Segment] = []
    for segment in reversed(edge_a):
        start = (segment.end[0], -segment.end[1])
        end = (segment.start[0], -segment.start[1])
        if isinstance(segment, LineSegment):
            result.append(LineSegment(start, end, 0.0, 0.0, False, side))
        else:
            centre = (segment.center[0], -segment.center[1])
            result.append(ArcSegment(start, end, centre, segment.clockwise, 0.0, 0.0, False, side))
    return tuple(result)


def _mirrored_in_x(chain: tuple[Segment, ...], length_mm: float) -> tuple[Segment, ...]:
    """The right half of a symmetric side from its left half (x -> L - x, run forwards)."""
    result: list[Segment] = []
    for segment in reversed(chain):
        start = (length_mm - segment.end[0], segment.end[1])
        end = (length_mm - segment.start[0], segment.start[1])
        if isinstance(segment, LineSegment):
            result.append(LineSegment(start, end, 0.0, 0.0, False, "A"))
        else:
            centre = (length_mm - segment.center[0], segment.center[1])
            result.append(ArcSegment(start, end, centre, segment.clockwise, 0.0, 0.0, False, "A"))
    return tuple(result)


def _on_side_a(chain: tuple[Segment, ...]) -> tuple[Segment, ...]:
    return tuple(
        LineSegment(s.start, s.end, 0.0, 0.0, False, "A")
        if isinstance(s, LineSegment)
        else ArcSegment(s.start, s.end, s.center, s.clockwise, 0.0, 0.0, False, "A")
        for s in chain
    )


@dataclass(frozen=True)
class CurvedProfile:
    """A side profile fitted with lines and arcs (profile frame, all mm).

    `edge_a` runs along side A from (0, W1/2) to (L, W1/2); `curve_a` is the true curve it
    was fitted to, in pieces over t in [0, 1].
    """

    kind: ProfileKind
    length_mm: float
    width_mm: float
    width_ratio: float
    W1: float
    edge_a: tuple[Segment, ...]
    curve_a: tuple[Curve, ...]

    @property
    def head_width_mm(self) -> float:
        return self.W1

    @property
    def D(self) -> float | None:
        """Line-arc-line's rise of the straight section: none on a curve."""
        return None

    @property
    def R(self) -> float | None:
        """Line-arc-line's arc radius: none on a curve (its radius varies)."""
        return None

    def edge(self, side: str) -> tuple[Segment, ...]:
        """The stave's edge in cut order: side A left to right, side B right to left."""
        if side == "A":
            return self.edge_a
        if side == "B":
            return mirrored_side(self.edge_a)
        raise ValueError(f"side must be 'A' or 'B', got {side!r}")


SideProfile = StaveProfile | CurvedProfile
"""Every solved profile: both know their length, width, head width and `edge(side)`."""


def _family_chain(
    shape: FamilyShape, length_mm: float, half_head: float, depth: float
) -> tuple[tuple[Segment, ...], tuple[Curve, ...]]:
    half = length_mm / 2.0
    left = _FamilyCurve(shape, half_head, depth, 0.0, half)
    right = _FamilyCurve(shape, half_head, depth, half, length_mm)
    fitted = fit_biarcs(left, end_tangent=(1.0, 0.0))
    return _on_side_a(fitted) + _mirrored_in_x(fitted, length_mm), (left, right)


def _joint_tangent(before: Curve, after: Curve) -> Point:
    ax, ay = before.derivative(1.0)
    bx, by = after.derivative(0.0)
    la, lb = math.hypot(ax, ay), math.hypot(bx, by)
    x, y = ax / la + bx / lb, ay / la + by / lb
    length = math.hypot(x, y)
    return (x / length, y / length)


def _drawn_chain(
    shape: DrawnShape, length_mm: float, half_head: float, depth: float
) -> tuple[tuple[Segment, ...], tuple[Curve, ...]]:
    scale_x = length_mm / (shape.x_right - shape.x_left)
    scale_y = depth / (shape.y_belly - shape.y_head)

    def mapped(point: Point) -> Point:
        return (
            scale_x * (point[0] - shape.x_left),
            half_head + scale_y * (point[1] - shape.y_head),
        )

    joints = [mapped(p) for p in shape.joints]
    joints[0] = (0.0, joints[0][1])
    joints[-1] = (length_mm, joints[-1][1])
    curves: list[Curve] = [
        _ScaledPrimitive(p, scale_x, scale_y, shape.x_left, shape.y_head, half_head, a, b)
        for p, (a, b) in zip(shape.primitives, pairwise(joints), strict=True)
    ]
    tangents = [_joint_tangent(a, b) for a, b in pairwise(curves)]
    chain: list[Segment] = []
    for index, (primitive, curve) in enumerate(zip(shape.primitives, curves, strict=True)):
        start_tangent = tangents[index - 1] if index > 0 else None
        end_tangent = tangents[index] if index < len(tangents) else None
        start, end = joints[index], joints[index + 1]
        if isinstance(primitive, DrawnLine):
            direction = (end[0] - start[0], end[1] - start[1])
            length = math.hypot(*direction)
            own = (direction[0] / length, direction[1] / length)
            if all(
                t is None or math.hypot(t[0] - own[0], t[1] - own[1]) < 1e-12
                for t in (start_tangent, end_tangent)
            ):
                chain.append(LineSegment(start, end, 0.0, 0.0, False, "A"))
                continue
        try:
            chain.extend(fit_biarcs(curve, start_tangent=start_tangent, end_tangent=end_tangent))
        except FitError:
            raise GeometryError(
                [
                    FieldError(
                        "drawn_profile",
                        primitive.source,
                        "a smooth curve",
                        f"drawn_profile: {primitive.source} is not smooth enough to follow",
                    )
                ]
            ) from None
    return _on_side_a(tuple(chain)), tuple(curves)


def _sides_apart(chain: tuple[Segment, ...]) -> list[FieldError]:
    """The two sides meet where side A reaches the centre line (y <= 0)."""
    for segment in chain:
        x_min, y_min, _, _ = segment.bounds()
        if y_min <= 0.0:
            message = (
                f"drawn_profile: the two sides of the stave meet or cross near x = {x_min:.3f} mm "
                "(the drawn curve dips below the centre line when scaled to this board)"
            )
            return [FieldError("drawn_profile", x_min, "a half-width > 0 everywhere", message)]
    return []


def solve_side_profile(
    kind: ProfileKind,
    length_mm: float,
    width_mm: float,
    width_ratio: float,
    length_ratio: float = 0.0,
    family_values: Mapping[str, object] | None = None,
    drawn: DrawnShape | None = None,
    limits: StaveLimits | None = None,
) -> SideProfile:
    """The side profile of one board of width `width_mm`, of any kind.

    `length_ratio` is used by line-arc-line only (the single arc is line-arc-line at 0);
    `family_values` holds a family's parameters, `drawn` the checked drawing. Raises
    GeometryError with every violation (board and recipe limits, family parameters, a drawing
    that this board cannot take).
    """
    if kind is ProfileKind.LINE_ARC_LINE:
        return solve_profile(length_mm, width_mm, length_ratio, width_ratio, limits)
    if kind is ProfileKind.SINGLE_ARC:
        return solve_profile(length_mm, width_mm, 0.0, width_ratio, limits)
    errors = validate_stave(length_mm, width_mm, 0.0, width_ratio, limits)
    if kind.is_family:
        errors += validate_family_parameters(kind, family_values or {})
    elif drawn is None:
        allowed = "a drawing imported from a DXF file"
        message = "drawn_profile: the recipe has no drawing: import one from a DXF file"
        errors.append(FieldError("drawn_profile", None, allowed, message))
    if errors:
        raise GeometryError(errors)
    length, width, k = float(length_mm), float(width_mm), float(width_ratio)
    head = k * width
    half_head, depth = head / 2.0, (width - head) / 2.0
    if kind.is_family:
        values = {
            name: float(value)
            for name, value in (family_values or {}).items()
            if isinstance(value, int | float)
        }
        chain, curves = _family_chain(family_shape(kind, length, values), length, half_head, depth)
    else:
        assert drawn is not None
        chain, curves = _drawn_chain(drawn, length, half_head, depth)
        problems = _sides_apart(chain)
        if problems:
            raise GeometryError(problems)
    return CurvedProfile(kind, length, width, k, head, chain, curves)


@dataclass(frozen=True)
class ProfileSpec:
    """What a recipe says about the side's shape: the kind, a family's parameters (name,
    value pairs), and for a drawn profile the checked drawing."""

    kind: ProfileKind = ProfileKind.LINE_ARC_LINE
    values: tuple[tuple[str, float], ...] = ()
    drawn: DrawnShape | None = None

    def uses_length_ratio(self) -> bool:
        """Only line-arc-line has straight end sections; the other kinds ignore lambda."""
        return self.kind is ProfileKind.LINE_ARC_LINE

    def solve(
        self,
        length_mm: float,
        width_mm: float,
        width_ratio: float,
        length_ratio: float,
        limits: StaveLimits | None = None,
    ) -> SideProfile:
        return solve_side_profile(
            self.kind,
            length_mm,
            width_mm,
            width_ratio,
            length_ratio,
            dict(self.values),
            self.drawn,
            limits,
        )


def tangent_breaks_rad(chain: tuple[Segment, ...]) -> list[float]:
    """The change of direction at every joint of a chain (0 for a tangent-continuous one)."""
    breaks = []
    for before, after in pairwise(chain):
        a = before.tangent_at(before.length_mm)
        b = after.tangent_at(0.0)
        breaks.append(abs(math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1])))
    return breaks


__all__ = [
    "FIT_TOLERANCE_MM",
    "CurvedProfile",
    "ProfileSpec",
    "SideProfile",
    "mirrored_side",
    "solve_side_profile",
    "tangent_breaks_rad",
]
