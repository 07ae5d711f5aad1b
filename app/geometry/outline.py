"""The outline of the finished stave at table level, as points for drawing.

Shared by the machine's plan preview and the recipe screen's preview, so both draw the same
stave; each arc is sampled at a fixed number of points, plenty for a few hundred pixels (a
fitted curve's arcs are short, so its outline is finer still)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from app.geometry.curved_profile import SideProfile
from app.geometry.segments import ArcSegment, Segment
from app.geometry.toolpath import ToolPath

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


def _edge_points(edge: tuple[Segment, ...]) -> list[Point]:
    points = [edge[0].start]
    for segment in edge:
        if isinstance(segment, ArcSegment):
            points += arc_points(segment.center, segment.radius_mm, segment.start, segment.end)[1:]
        else:
            points.append(segment.end)
    return points


def stave_outline(profile: SideProfile, origin: Point) -> list[Point]:
    """The closed outline of the finished stave, in machine coordinates (origin = P0)."""
    side_a = _edge_points(profile.edge("A"))
    side_b = _edge_points(profile.edge("B"))
    return [(origin[0] + x, origin[1] + y) for x, y in (*side_a, *side_b, side_a[0])]


DRAWING_CHORD_MM = 0.2  # plenty for a drawing a few hundred pixels wide


@dataclass(frozen=True)
class StaveDrawing:
    """What a plan view draws, in machine X/Y: the finished stave's outline and the tool
    path, with whether the move ending at each tool path point cuts."""

    outline_xy: tuple[Point, ...]
    toolpath_xy: tuple[Point, ...]
    cutting_mask: tuple[bool, ...]


def stave_drawing(toolpath: ToolPath) -> StaveDrawing:
    """The drawing of a planned cut; the machine's plan view and the recipe screen's preview
    both draw from this one function, so they show the same stave."""
    params = toolpath.params
    outline = stave_outline(toolpath.profile, (params.start_x_mm, params.start_y_mm))
    polyline = toolpath.to_polyline(DRAWING_CHORD_MM)
    return StaveDrawing(
        outline_xy=tuple(outline),
        toolpath_xy=tuple((p[0], p[1]) for p in polyline),
        cutting_mask=tuple(bool(p[3]) for p in polyline),
    )
