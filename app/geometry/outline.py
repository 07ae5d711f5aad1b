"""The outline of the finished stave at table level, as points for drawing.

Shared by the machine's plan preview and the recipe screen's preview, so both draw the same
stave; the arcs are sampled at a fixed number of points, plenty for a few hundred pixels."""

from __future__ import annotations

import math

from app.geometry.profile import StaveProfile

Point = tuple[float, float]
ARC_POINTS = 60


def arc_points(
    center: Point, radius: float, start: Point, end: Point, points: int = ARC_POINTS
) -> list[Point]:
    """Points along the shorter arc from ``start`` to ``end`` about ``center``."""
    a0 = math.atan2(start[1] - center[1], start[0] - center[0])
    a1 = math.atan2(end[1] - center[1], end[0] - center[0])
    if a1 - a0 > math.pi:
        a1 -= 2 * math.pi
    elif a0 - a1 > math.pi:
        a1 += 2 * math.pi
    return [
        (
            center[0] + radius * math.cos(a0 + (a1 - a0) * i / points),
            center[1] + radius * math.sin(a0 + (a1 - a0) * i / points),
        )
        for i in range(points + 1)
    ]


def stave_outline(profile: StaveProfile, origin: Point) -> list[Point]:
    """The closed outline of the finished stave, in machine coordinates (origin = P0)."""
    p = profile.points
    side_a = [p["P1"], *arc_points(profile.arc_center_a, profile.R, p["P2"], p["P3"]), p["P4"]]
    side_b = [p["P5"], *arc_points(profile.arc_center_b, profile.R, p["P6"], p["P7"]), p["P8"]]
    return [(origin[0] + x, origin[1] + y) for x, y in (*side_a, *side_b, p["P1"])]
