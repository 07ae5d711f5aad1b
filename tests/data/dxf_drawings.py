"""DXF drawings of side profiles, made with ezdxf for the tests (no files shipped)."""

from __future__ import annotations

import io
import math
from collections.abc import Callable, Sequence

import ezdxf
from ezdxf.document import Drawing

from app.geometry.limits import StaveLimits
from app.geometry.profile import solve_profile

Point = tuple[float, float]

# The drawn stave: a line-arc-line of half the recipe's length and another width, so that the
# scaling onto a board is uneven and arcs become elliptic (the general case).
DRAWN_L, DRAWN_W, DRAWN_LAMBDA, DRAWN_K = 500.0, 80.0, 0.25, 0.75
# A drawing is not a board: the machine's limits do not apply to its size.
DRAWN = solve_profile(
    DRAWN_L, DRAWN_W, DRAWN_LAMBDA, DRAWN_K, StaveLimits(min_length_mm=100.0, min_head_width_mm=1.0)
)
DRAWN_HEAD_Y = DRAWN.W1 / 2
DRAWN_BELLY_Y = DRAWN_W / 2


def drawn_half_width(x: float) -> float:
    """The drawn line-arc-line's y at x, from its own A, D, R (independent of the fitting)."""
    a, d, r = DRAWN.A, DRAWN.D, DRAWN.R
    if x <= a:
        return DRAWN_HEAD_Y + d * x / a
    if x >= DRAWN_L - a:
        return DRAWN_HEAD_Y + d * (DRAWN_L - x) / a
    centre_y = DRAWN_BELLY_Y - r
    return centre_y + math.sqrt(r * r - (x - DRAWN_L / 2) ** 2)


def to_bytes(document: Drawing) -> bytes:
    stream = io.StringIO()
    document.write(stream)
    return stream.getvalue().encode("utf-8")


def new_drawing() -> Drawing:
    return ezdxf.new("R2010")


def _arc_angles_deg(centre: Point, start: Point, end: Point) -> tuple[float, float]:
    a0 = math.degrees(math.atan2(start[1] - centre[1], start[0] - centre[0]))
    a1 = math.degrees(math.atan2(end[1] - centre[1], end[0] - centre[0]))
    return a0, a1


def lines_and_arc(offset: Point = (300.0, 200.0), layer: str = "SIDE") -> bytes:
    """LINE, ARC, LINE, drawn away from the origin, with a TEXT and a CIRCLE on other layers."""
    document = new_drawing()
    space = document.modelspace()
    p = {name: (x + offset[0], y + offset[1]) for name, (x, y) in DRAWN.points.items()}
    centre = (DRAWN.arc_center_a[0] + offset[0], DRAWN.arc_center_a[1] + offset[1])
    space.add_line(p["P3"], p["P4"], dxfattribs={"layer": layer})
    # A DXF arc runs counter-clockwise: from P3 round to P2.
    start, end = _arc_angles_deg(centre, p["P3"], p["P2"])
    space.add_arc(centre, DRAWN.R, start, end, dxfattribs={"layer": layer})
    space.add_line(p["P2"], p["P1"], dxfattribs={"layer": layer})
    space.add_text("stave 500", dxfattribs={"layer": "NOTES"})
    space.add_circle((0.0, 0.0), 5.0, dxfattribs={"layer": "HOLES"})
    return to_bytes(document)


def _bulge(centre: Point, start: Point, end: Point) -> float:
    """tan(sweep/4) of the shorter arc from start to end about centre (> 0 counter-clockwise)."""
    ux, uy = start[0] - centre[0], start[1] - centre[1]
    vx, vy = end[0] - centre[0], end[1] - centre[1]
    sweep = math.atan2(ux * vy - uy * vx, ux * vx + uy * vy)
    return math.tan(sweep / 4.0)


def bulged_polyline_belly_down() -> bytes:
    """One LWPOLYLINE with a bulge, drawn right to left as the lower side (belly down)."""
    document = new_drawing()
    mirrored = {name: (x, -y) for name, (x, y) in DRAWN.points.items()}
    centre = (DRAWN.arc_center_a[0], -DRAWN.arc_center_a[1])
    bulge = _bulge(centre, mirrored["P3"], mirrored["P2"])
    vertices = [
        (*mirrored["P4"], 0.0, 0.0, 0.0),
        (*mirrored["P3"], 0.0, 0.0, bulge),
        (*mirrored["P2"], 0.0, 0.0, 0.0),
        (*mirrored["P1"], 0.0, 0.0, 0.0),
    ]
    document.modelspace().add_lwpolyline(vertices, format="xyseb", dxfattribs={"layer": "0"})
    return to_bytes(document)


def bulged_old_polyline() -> bytes:
    """The same side as one 2D POLYLINE (the older entity, vertices with bulges), left to
    right, belly up, on layer SIDE."""
    document = new_drawing()
    points = DRAWN.points
    bulge = _bulge(DRAWN.arc_center_a, points["P2"], points["P3"])
    vertices = [
        (*points["P1"], 0.0),
        (*points["P2"], bulge),
        (*points["P3"], 0.0),
        (*points["P4"], 0.0),
    ]
    document.modelspace().add_polyline2d(vertices, format="xyb", dxfattribs={"layer": "SIDE"})
    return to_bytes(document)


SPLINE_POINTS: Sequence[Point] = (
    (0.0, 0.0),
    (120.0, 14.0),
    (250.0, 22.0),
    (380.0, 14.0),
    (500.0, 0.0),
)


DIPS_POINTS: Sequence[Point] = (
    (0.0, 0.0),
    (200.0, 12.0),
    (230.0, 2.0),
    (260.0, 12.0),
    (500.0, 20.0),
    (740.0, 12.0),
    (770.0, 2.0),
    (800.0, 12.0),
    (1000.0, 0.0),
)
"""A spline with two narrow concave dips between heads and belly (radius about 53 mm on a
1000 x 150 mm board, k 3/4): its side turns both ways."""


def spline(points: Sequence[Point] = SPLINE_POINTS, layer: str = "0") -> bytes:
    document = new_drawing()
    document.modelspace().add_open_spline(points, degree=3, dxfattribs={"layer": layer})
    return to_bytes(document)


def with_entities(build: Callable[[ezdxf.layouts.Modelspace], object]) -> bytes:
    document = new_drawing()
    build(document.modelspace())
    return to_bytes(document)
