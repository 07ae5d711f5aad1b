"""How far the edge a tool path would cut lies from the profile (plan view, at the table).

The cutter acts in plan view as a circle of radius rc = r/cos(alpha) about the point where its
axis meets the table. An edge point q is cut exactly when the closest tool position is rc
away: dist(q, tool path) - rc is 0 for a perfect path, negative where the cutter bites into
the stave (overcut) and positive where it leaves wood standing (undercut). Sampling the true
profile gives the error a path makes; `benchmarks/geometry_bench.py` uses it to compare the
original y-only shift with the normal offset.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from app.geometry.curved_profile import SideProfile
from app.geometry.profile import StaveProfile
from app.geometry.segments import ArcSegment, LineSegment, Point, Segment
from app.geometry.toolpath import SIDE_SIGN, ToolPath


@dataclass(frozen=True)
class EdgeDeviation:
    """Worst errors of one side's cut edge against the profile (mm, normal to the edge)."""

    side: str
    max_overcut_mm: float
    max_undercut_mm: float

    @property
    def max_abs_mm(self) -> float:
        return max(self.max_overcut_mm, self.max_undercut_mm)


def profile_edge(profile: SideProfile, side: str) -> tuple[Segment, ...]:
    """The stave's edge itself (profile frame) as segments, in cut order."""
    return profile.edge(side)


def tool_centre_path(toolpath: ToolPath, side: str) -> tuple[Segment, ...]:
    """The side's cutting moves moved back into the profile frame, pivot shift undone.

    What remains is the path of the point where the cutter's axis meets the table.
    """
    params = toolpath.params
    dx = -params.start_x_mm
    dy = -params.start_y_mm + SIDE_SIGN[side] * params.side_pivot_shift_mm(side)
    moved: list[Segment] = []
    for segment in toolpath.side_segments(side):
        start = (segment.start[0] + dx, segment.start[1] + dy)
        end = (segment.end[0] + dx, segment.end[1] + dy)
        if isinstance(segment, ArcSegment):
            centre = (segment.center[0] + dx, segment.center[1] + dy)
            moved.append(ArcSegment(start, end, centre, segment.clockwise, 0.0, 0.0, True, side))
        else:
            moved.append(LineSegment(start, end, 0.0, 0.0, True, side))
    return tuple(moved)


def distance_to_path(point: Point, path: tuple[Segment, ...]) -> float:
    """Plan-view distance from a point to the nearest segment of a path."""
    return min(segment.distance_to(point) for segment in path)


def edge_deviation(toolpath: ToolPath, side: str, samples_per_piece: int = 400) -> EdgeDeviation:
    """Sample the profile edge of `side` and measure how the path's cutter meets it."""
    if samples_per_piece < 2:
        raise ValueError(f"samples_per_piece = {samples_per_piece} is out of range: allowed >= 2")
    path = tool_centre_path(toolpath, side)
    radius = toolpath.params.side_effective_radius_mm(side)
    overcut = undercut = 0.0
    for piece in profile_edge(toolpath.profile, side):
        length = piece.length_mm
        for index in range(samples_per_piece + 1):
            point = piece.point_at(length * index / samples_per_piece)
            error = distance_to_path(point, path) - radius
            overcut = max(overcut, -error)
            undercut = max(undercut, error)
    return EdgeDeviation(side=side, max_overcut_mm=overcut, max_undercut_mm=undercut)


def tangent_point_shift_mm(original: ToolPath, ours: ToolPath) -> float:
    """How far along X the original method puts the line/arc junctions of the tool path."""
    shift = 0.0
    for side in SIDE_SIGN:
        for old, new in zip(original.side_segments(side), ours.side_segments(side), strict=True):
            shift = max(shift, abs(old.end[0] - new.end[0]))
    return shift


def slope_overcut_formula_mm(profile: StaveProfile, effective_radius_mm: float) -> float:
    """The error across the stave of the original's y-only shift: rc * (1/cos(theta) - 1).

    docs/MACHINE.md section 3 gives the formula; the benchmark sets it beside the measured error.
    """
    return effective_radius_mm * (1.0 / math.cos(profile.slope_rad) - 1.0)
