"""Exact path segments (straight lines and circular arcs in the X-Y plane, with a tilt).

A segment is a value: it knows its length, the point and the unit tangent at any arc length
from its start, its bounding box (arcs included, for the axis travel check) and its distance
to a point. The drives take lines and arcs as they are; `polyline.py` splits arcs into chords
for drives without circular interpolation.

Orientation: "clockwise" is seen from above with +X to the right and +Y up (the usual right-handed
X-Y plane); in the profile frame of docs/MACHINE.md section 2 both sides of a stave are cut
clockwise around the board (side A left to right along +y, side B right to left along -y).

Tilt: a cutting segment keeps one tilt (Z stays constant while a side is cut); a non-cutting
segment may change it, linearly with the distance travelled (a zero-length non-cutting line
is a pure tilt move).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

Point = tuple[float, float]

SIDES = ("A", "B", "")

_RADIUS_TOLERANCE = 1e-9
"""Relative mismatch allowed between an arc's start and end radius."""


def _check_common(
    start: Point, end: Point, z_start_deg: float, z_end_deg: float, cutting: bool, side: str
) -> None:
    for name, point in (("start", start), ("end", end)):
        if len(point) != 2 or not all(math.isfinite(c) for c in point):
            raise ValueError(f"segment {name} must be two finite numbers, got {point!r}")
    if not (math.isfinite(z_start_deg) and math.isfinite(z_end_deg)):
        raise ValueError(f"segment tilt must be finite, got {z_start_deg}, {z_end_deg}")
    if side not in SIDES:
        raise ValueError(f"segment side must be one of {SIDES}, got {side!r}")
    if cutting and z_start_deg != z_end_deg:
        raise ValueError(
            f"a cutting segment keeps its tilt: z_start_deg = {z_start_deg} "
            f"but z_end_deg = {z_end_deg}"
        )


def _interpolate_tilt(z_start_deg: float, z_end_deg: float, fraction: float) -> float:
    if z_start_deg == z_end_deg:
        return z_start_deg
    return z_start_deg + (z_end_deg - z_start_deg) * fraction


@dataclass(frozen=True)
class LineSegment:
    """A straight move from `start` to `end` (mm) with the tilt going z_start -> z_end."""

    start: Point
    end: Point
    z_start_deg: float
    z_end_deg: float
    cutting: bool
    side: str

    def __post_init__(self) -> None:
        _check_common(
            self.start, self.end, self.z_start_deg, self.z_end_deg, self.cutting, self.side
        )

    @property
    def length_mm(self) -> float:
        return math.hypot(self.end[0] - self.start[0], self.end[1] - self.start[1])

    def _check_s(self, s_mm: float) -> float:
        length = self.length_mm
        if not -1e-9 <= s_mm <= length + 1e-9:
            raise ValueError(f"s_mm = {s_mm} is outside the segment (0 .. {length} mm)")
        return min(max(s_mm, 0.0), length)

    def point_at(self, s_mm: float) -> Point:
        """The point at arc length `s_mm` from the start (0 <= s_mm <= length_mm)."""
        s = self._check_s(s_mm)
        length = self.length_mm
        if s == length:
            return self.end
        if s == 0.0:
            return self.start
        fraction = s / length
        return (
            self.start[0] + (self.end[0] - self.start[0]) * fraction,
            self.start[1] + (self.end[1] - self.start[1]) * fraction,
        )

    def tangent_at(self, s_mm: float) -> Point:
        """Unit direction of motion (the same everywhere on a line)."""
        self._check_s(s_mm)
        length = self.length_mm
        if length == 0.0:
            raise ValueError("a zero-length segment (a pure tilt move) has no tangent")
        return ((self.end[0] - self.start[0]) / length, (self.end[1] - self.start[1]) / length)

    def z_at(self, s_mm: float) -> float:
        """Tilt (deg) at arc length `s_mm`, linear in the distance travelled."""
        s = self._check_s(s_mm)
        length = self.length_mm
        fraction = 1.0 if length == 0.0 else s / length
        return _interpolate_tilt(self.z_start_deg, self.z_end_deg, fraction)

    def bounds(self) -> tuple[float, float, float, float]:
        """(x_min, y_min, x_max, y_max) of the segment."""
        return (
            min(self.start[0], self.end[0]),
            min(self.start[1], self.end[1]),
            max(self.start[0], self.end[0]),
            max(self.start[1], self.end[1]),
        )

    def distance_to(self, point: Point) -> float:
        """Plan-view distance from `point` to the nearest point of the segment."""
        dx, dy = self.end[0] - self.start[0], self.end[1] - self.start[1]
        px, py = point[0] - self.start[0], point[1] - self.start[1]
        squared = dx * dx + dy * dy
        fraction = 0.0 if squared == 0.0 else min(1.0, max(0.0, (px * dx + py * dy) / squared))
        return math.hypot(px - fraction * dx, py - fraction * dy)


@dataclass(frozen=True)
class ArcSegment:
    """A circular move from `start` to `end` about `center` (mm), clockwise or not.

    The sweep is taken in the given direction and lies in (0, 2*pi); start and end must be
    at the same distance from the centre (relative 1e-9).
    """

    start: Point
    end: Point
    center: Point
    clockwise: bool
    z_start_deg: float
    z_end_deg: float
    cutting: bool
    side: str

    def __post_init__(self) -> None:
        _check_common(
            self.start, self.end, self.z_start_deg, self.z_end_deg, self.cutting, self.side
        )
        if len(self.center) != 2 or not all(math.isfinite(c) for c in self.center):
            raise ValueError(f"arc center must be two finite numbers, got {self.center!r}")
        radius = self.radius_mm
        end_radius = math.hypot(self.end[0] - self.center[0], self.end[1] - self.center[1])
        if radius == 0.0:
            raise ValueError("an arc needs a radius > 0 (start coincides with the center)")
        if abs(end_radius - radius) > _RADIUS_TOLERANCE * radius + 1e-12:
            raise ValueError(
                f"arc start and end are not on one circle: radii {radius} and {end_radius} mm"
            )
        if self.start == self.end:
            raise ValueError("an arc's start and end coincide (zero sweep)")

    @property
    def radius_mm(self) -> float:
        return math.hypot(self.start[0] - self.center[0], self.start[1] - self.center[1])

    @property
    def sweep_rad(self) -> float:
        """Angle travelled, in (0, 2*pi), in the arc's own direction."""
        ux, uy = self.start[0] - self.center[0], self.start[1] - self.center[1]
        vx, vy = self.end[0] - self.center[0], self.end[1] - self.center[1]
        # atan2 of cross and dot: accurate even for tiny sweeps on huge radii.
        angle = math.atan2(ux * vy - uy * vx, ux * vx + uy * vy)  # ccw, in (-pi, pi]
        if self.clockwise:
            angle = -angle
        return angle if angle > 0.0 else angle + 2.0 * math.pi

    @property
    def length_mm(self) -> float:
        return self.radius_mm * self.sweep_rad

    def _check_s(self, s_mm: float) -> float:
        length = self.length_mm
        if not -1e-9 <= s_mm <= length + 1e-9:
            raise ValueError(f"s_mm = {s_mm} is outside the segment (0 .. {length} mm)")
        return min(max(s_mm, 0.0), length)

    def _radial_at(self, s: float) -> Point:
        """Radius vector (centre -> point) after travelling `s` along the arc."""
        angle = s / self.radius_mm
        if self.clockwise:
            angle = -angle
        ux, uy = self.start[0] - self.center[0], self.start[1] - self.center[1]
        cos_a, sin_a = math.cos(angle), math.sin(angle)
        return (ux * cos_a - uy * sin_a, ux * sin_a + uy * cos_a)

    def point_at(self, s_mm: float) -> Point:
        """The point at arc length `s_mm` from the start (0 <= s_mm <= length_mm)."""
        s = self._check_s(s_mm)
        if s == 0.0:
            return self.start
        if s == self.length_mm:
            return self.end
        rx, ry = self._radial_at(s)
        return (self.center[0] + rx, self.center[1] + ry)

    def tangent_at(self, s_mm: float) -> Point:
        """Unit direction of motion at arc length `s_mm`."""
        rx, ry = self._radial_at(self._check_s(s_mm))
        radius = math.hypot(rx, ry)
        ux, uy = rx / radius, ry / radius
        return (uy, -ux) if self.clockwise else (-uy, ux)

    def z_at(self, s_mm: float) -> float:
        """Tilt (deg) at arc length `s_mm`, linear in the distance travelled."""
        s = self._check_s(s_mm)
        length = self.length_mm
        return _interpolate_tilt(self.z_start_deg, self.z_end_deg, s / length)

    def contains_direction(self, direction_rad: float) -> bool:
        """True if the ray from the centre at `direction_rad` crosses the arc."""
        ux, uy = self.start[0] - self.center[0], self.start[1] - self.center[1]
        offset = direction_rad - math.atan2(uy, ux)
        if self.clockwise:
            offset = -offset
        offset %= 2.0 * math.pi
        return offset <= self.sweep_rad

    def bounds(self) -> tuple[float, float, float, float]:
        """(x_min, y_min, x_max, y_max), including the extremes inside the sweep."""
        xs = [self.start[0], self.end[0]]
        ys = [self.start[1], self.end[1]]
        radius = self.radius_mm
        cx, cy = self.center
        for quarter, (dx, dy) in enumerate(((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))):
            if self.contains_direction(quarter * math.pi / 2.0):
                xs.append(cx + dx * radius)
                ys.append(cy + dy * radius)
        return (min(xs), min(ys), max(xs), max(ys))

    def distance_to(self, point: Point) -> float:
        """Plan-view distance from `point` to the nearest point of the arc."""
        px, py = point[0] - self.center[0], point[1] - self.center[1]
        if self.contains_direction(math.atan2(py, px)):
            return abs(math.hypot(px, py) - self.radius_mm)
        return min(
            math.hypot(point[0] - self.start[0], point[1] - self.start[1]),
            math.hypot(point[0] - self.end[0], point[1] - self.end[1]),
        )


Segment = LineSegment | ArcSegment
