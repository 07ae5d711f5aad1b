"""The plan view's data: the stave outline and the tool path, in machine X/Y.

Computed once per planned board in the machine process and sent to the screens with its id,
so the GUI draws without computing any geometry of the cut itself."""

from __future__ import annotations

import math

from app.geometry.profile import StaveProfile
from app.machine.cycle_plan import PlannedStave
from app.machine.snapshot import PlanPreview

PREVIEW_CHORD_MM = 0.2  # plenty for a drawing a few hundred pixels wide


def _arc(
    center: tuple[float, float],
    radius: float,
    start: tuple[float, float],
    end: tuple[float, float],
    points: int,
) -> list[tuple[float, float]]:
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


def stave_outline(
    profile: StaveProfile, origin: tuple[float, float], arc_points: int = 60
) -> list[tuple[float, float]]:
    """The closed outline of the finished stave at table level, in machine coordinates."""
    p = profile.points
    side_a = [
        p["P1"],
        *_arc(profile.arc_center_a, profile.R, p["P2"], p["P3"], arc_points),
        p["P4"],
    ]
    side_b = [
        p["P5"],
        *_arc(profile.arc_center_b, profile.R, p["P6"], p["P7"], arc_points),
        p["P8"],
    ]
    closed = [*side_a, *side_b, p["P1"]]
    return [(origin[0] + x, origin[1] + y) for x, y in closed]


def build_preview(plan_id: int, planned: PlannedStave) -> PlanPreview:
    params = planned.toolpath.params
    outline = stave_outline(planned.profile, (params.start_x_mm, params.start_y_mm))
    polyline = planned.toolpath.to_polyline(PREVIEW_CHORD_MM)
    return PlanPreview(
        plan_id=plan_id,
        outline_xy=tuple(outline),
        toolpath_xy=tuple((p[0], p[1]) for p in polyline),
        cutting_mask=tuple(bool(p[3]) for p in polyline),
    )
