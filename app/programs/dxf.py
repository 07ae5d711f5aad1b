"""The stave as a DXF drawing for the cooperage's CAD: outline, tool path and points.

Layers: OUTLINE (the finished stave at table level: both sides and both heads), TOOLPATH_A
and TOOLPATH_B (the tool centre's cutting moves, leads included), TRAVEL (the non-cutting
moves), POINTS (P1..P8 as POINT entities with their names as TEXT; a curved side's head
corners P1, P4, P5, P8). Everything in mm, in machine coordinates (the profile moved by P0),
so the outline and the path line up as on the machine. Lines are LINE entities and arcs ARC
entities (DXF arcs run counter-clockwise, so a clockwise arc is written from its end to its
start). Written with ezdxf.
"""

from __future__ import annotations

import io
import math

from ezdxf import units
from ezdxf.document import Drawing
from ezdxf.filemanagement import new
from ezdxf.layouts.layout import Modelspace

from app.geometry.curved_profile import SideProfile
from app.geometry.profile import StaveProfile
from app.geometry.segments import ArcSegment, LineSegment, Segment
from app.geometry.toolpath import ToolPath
from app.programs.header import ProgramInfo

LAYERS = {"OUTLINE": 7, "TOOLPATH_A": 1, "TOOLPATH_B": 5, "TRAVEL": 8, "POINTS": 3}
"""Layer name -> ACI colour."""
POINT_LABEL_HEIGHT_MM = 10.0

Point = tuple[float, float]


def _angle_deg(center: Point, point: Point) -> float:
    return math.degrees(math.atan2(point[1] - center[1], point[0] - center[0]))


def _add_segment(space: Modelspace, segment: Segment, layer: str) -> None:
    attribs = {"layer": layer}
    if isinstance(segment, ArcSegment):
        start, end = (
            (segment.end, segment.start)
            if segment.clockwise
            else (
                segment.start,
                segment.end,
            )
        )
        space.add_arc(
            segment.center,
            segment.radius_mm,
            _angle_deg(segment.center, start),
            _angle_deg(segment.center, end),
            dxfattribs=attribs,
        )
    elif segment.length_mm > 0.0:
        space.add_line(segment.start, segment.end, dxfattribs=attribs)


def _moved(segment: Segment, dx: float, dy: float) -> Segment:
    start = (segment.start[0] + dx, segment.start[1] + dy)
    end = (segment.end[0] + dx, segment.end[1] + dy)
    if isinstance(segment, ArcSegment):
        centre = (segment.center[0] + dx, segment.center[1] + dy)
        return ArcSegment(start, end, centre, segment.clockwise, 0.0, 0.0, False, "")
    return LineSegment(start, end, 0.0, 0.0, False, "")


def _outline(toolpath: ToolPath) -> list[Segment]:
    """The finished stave's edges (machine coordinates) as exact lines and arcs: side A, the
    right head, side B, the left head (any profile kind: its edges are lines and arcs)."""
    profile, params = toolpath.profile, toolpath.params
    x0, y0 = params.start_x_mm, params.start_y_mm
    side_a = [_moved(s, x0, y0) for s in profile.edge("A")]
    side_b = [_moved(s, x0, y0) for s in profile.edge("B")]
    right = LineSegment(side_a[-1].end, side_b[0].start, 0.0, 0.0, False, "")
    left = LineSegment(side_b[-1].end, side_a[0].start, 0.0, 0.0, False, "")
    return [*side_a, right, *side_b, left]


def named_points(profile: SideProfile) -> dict[str, Point]:
    """P1..P8 of line-arc-line; a curved side has no tangent points (P2, P3, P6, P7), so only
    its head corners are named, as line-arc-line names them (P1, P4 on side A; P5, P8 on B)."""
    if isinstance(profile, StaveProfile):
        return dict(profile.points)
    side_a, side_b = profile.edge("A"), profile.edge("B")
    return {
        "P1": side_a[0].start,
        "P4": side_a[-1].end,
        "P5": side_b[0].start,
        "P8": side_b[-1].end,
    }


def drawing(toolpath: ToolPath, info: ProgramInfo) -> Drawing:
    """The DXF document of this tool path's stave."""
    doc = new("R2010", setup=False)
    doc.units = units.MM
    doc.header["$MEASUREMENT"] = 1  # metric
    for name, colour in LAYERS.items():
        doc.layers.add(name, color=colour)
    space = doc.modelspace()
    for segment in _outline(toolpath):
        _add_segment(space, segment, "OUTLINE")
    for segment in toolpath.segments:
        layer = f"TOOLPATH_{segment.side}" if segment.cutting else "TRAVEL"
        _add_segment(space, segment, layer)
    x0, y0 = toolpath.params.start_x_mm, toolpath.params.start_y_mm
    for name, (x, y) in named_points(toolpath.profile).items():
        space.add_point((x + x0, y + y0), dxfattribs={"layer": "POINTS"})
        label = space.add_text(name, height=POINT_LABEL_HEIGHT_MM, dxfattribs={"layer": "POINTS"})
        label.set_placement((x + x0, y + y0))
    space.add_text(
        f"recipe {info.recipe_name}, {info.describe_width()}, {info.stamp()}",
        height=POINT_LABEL_HEIGHT_MM,
        dxfattribs={"layer": "OUTLINE"},
    ).set_placement((x0, y0 - toolpath.profile.width_mm - 4 * POINT_LABEL_HEIGHT_MM))
    return doc


def drawing_text(toolpath: ToolPath, info: ProgramInfo) -> str:
    """The DXF file's content."""
    stream = io.StringIO()
    drawing(toolpath, info).write(stream)
    return stream.getvalue()
