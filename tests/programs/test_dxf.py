"""The DXF drawing read back with ezdxf: layers, entities and coordinates in mm."""

from __future__ import annotations

import io
import math

import ezdxf
import pytest

from app.data.recipe import Recipe
from app.geometry.segments import ArcSegment
from app.machine.program_export import export_drawing, stave_toolpath
from tests.programs.conftest import LIMITS, PARAMS, curved_recipes


def _arc_ends(arc) -> tuple[tuple[float, float], tuple[float, float]]:
    (cx, cy), r = (arc.dxf.center.x, arc.dxf.center.y), arc.dxf.radius
    start, end = math.radians(arc.dxf.start_angle), math.radians(arc.dxf.end_angle)
    return (
        (cx + r * math.cos(start), cy + r * math.sin(start)),
        (cx + r * math.cos(end), cy + r * math.sin(end)),
    )


def test_drawing_has_outline_toolpath_and_points(recipe: Recipe) -> None:
    width = 170.0
    toolpath = stave_toolpath(recipe, width, PARAMS, LIMITS)
    doc = ezdxf.read(io.StringIO(export_drawing(recipe, width, PARAMS, LIMITS)))
    assert doc.header["$INSUNITS"] == 4  # millimetres
    assert {"OUTLINE", "TOOLPATH_A", "TOOLPATH_B", "TRAVEL", "POINTS"} <= {
        layer.dxf.name for layer in doc.layers
    }
    space = doc.modelspace()
    x0, y0 = PARAMS["start_x_mm"], PARAMS["start_y_mm"]
    profile = toolpath.profile

    def machine(name: str) -> tuple[float, float]:
        x, y = profile.points[name]
        return (x + x0, y + y0)

    outline_arcs = space.query('ARC[layer=="OUTLINE"]')
    assert len(outline_arcs) == 2
    straights = 4 if profile.A > 0 else 0
    assert len(space.query('LINE[layer=="OUTLINE"]')) == straights + 2  # and the two heads
    for arc, (a, b) in zip(outline_arcs, (("P3", "P2"), ("P7", "P6")), strict=True):
        assert arc.dxf.radius == pytest.approx(profile.R, abs=1e-9)
        start, end = _arc_ends(arc)  # counter-clockwise: the clockwise cut's end first
        assert math.dist(start, machine(a)) < 1e-6 and math.dist(end, machine(b)) < 1e-6

    for side in ("A", "B"):
        cut = toolpath.side_segments(side)
        entities = list(space.query(f'LINE ARC[layer=="TOOLPATH_{side}"]'))
        assert len(entities) == len(cut)
        for entity, segment in zip(entities, cut, strict=True):
            if isinstance(segment, ArcSegment):
                assert entity.dxftype() == "ARC"
                assert entity.dxf.radius == pytest.approx(segment.radius_mm, abs=1e-9)
                end, start = _arc_ends(entity)
                assert math.dist(start, segment.start) < 1e-6
                assert math.dist(end, segment.end) < 1e-6
            else:
                assert entity.dxftype() == "LINE"
                assert math.dist(entity.dxf.start.vec2, segment.start) < 1e-9
                assert math.dist(entity.dxf.end.vec2, segment.end) < 1e-9

    points = space.query('POINT[layer=="POINTS"]')
    labels = {t.dxf.text: t for t in space.query('TEXT[layer=="POINTS"]')}
    assert set(labels) == {f"P{n}" for n in range(1, 9)}
    for point, name in zip(points, [f"P{n}" for n in range(1, 9)], strict=True):
        assert math.dist(point.dxf.location.vec2, machine(name)) < 1e-9
        assert math.dist(labels[name].dxf.insert.vec2, machine(name)) < 1e-9


def _same_segment(entity, segment) -> None:
    """A LINE or ARC entity is the segment (an arc drawn counter-clockwise in DXF)."""
    if isinstance(segment, ArcSegment):
        assert entity.dxftype() == "ARC"
        assert entity.dxf.radius == pytest.approx(segment.radius_mm, abs=1e-9)
        first, second = _arc_ends(entity)
        start, end = (second, first) if segment.clockwise else (first, second)
        assert math.dist(start, segment.start) < 1e-6 and math.dist(end, segment.end) < 1e-6
    else:
        assert entity.dxftype() == "LINE"
        assert math.dist(entity.dxf.start.vec2, segment.start) < 1e-9
        assert math.dist(entity.dxf.end.vec2, segment.end) < 1e-9


@pytest.mark.parametrize("index", [0, 1], ids=["parabola", "drawn"])
def test_curved_profile_drawing_has_its_fitted_outline_path_and_head_corners(index: int) -> None:
    recipe = curved_recipes()[index]
    toolpath = stave_toolpath(recipe, 150.0, PARAMS, LIMITS)
    doc = ezdxf.read(io.StringIO(export_drawing(recipe, 150.0, PARAMS, LIMITS)))
    space = doc.modelspace()
    x0, y0 = PARAMS["start_x_mm"], PARAMS["start_y_mm"]
    profile = toolpath.profile

    def machine(point: tuple[float, float]) -> tuple[float, float]:
        return (point[0] + x0, point[1] + y0)

    outline = list(space.query('LINE ARC[layer=="OUTLINE"]'))
    edge_a, edge_b = profile.edge("A"), profile.edge("B")
    assert len(outline) == len(edge_a) + len(edge_b) + 2  # both sides and the two heads
    moved = [
        type(s)(machine(s.start), machine(s.end), machine(s.center), s.clockwise, 0, 0, False, "")
        if isinstance(s, ArcSegment)
        else type(s)(machine(s.start), machine(s.end), 0, 0, False, "")
        for s in (*edge_a, *edge_b)
    ]
    sides = [e for e in outline if not (e.dxftype() == "LINE" and e.dxf.start.x == e.dxf.end.x)]
    for entity, segment in zip(sides, moved, strict=True):
        _same_segment(entity, segment)
    if index == 1:  # the drawing's dips: side A turns both ways
        assert {s.clockwise for s in edge_a if isinstance(s, ArcSegment)} == {True, False}
    for side in ("A", "B"):
        cut = toolpath.side_segments(side)
        entities = list(space.query(f'LINE ARC[layer=="TOOLPATH_{side}"]'))
        assert len(entities) == len(cut)
        for entity, segment in zip(entities, cut, strict=True):
            _same_segment(entity, segment)
    labels = {t.dxf.text: t.dxf.insert.vec2 for t in space.query('TEXT[layer=="POINTS"]')}
    corners = {
        "P1": edge_a[0].start,
        "P4": edge_a[-1].end,
        "P5": edge_b[0].start,
        "P8": edge_b[-1].end,
    }
    assert set(labels) == set(corners)
    for name, point in corners.items():
        assert math.dist(labels[name], machine(point)) < 1e-9
    assert corners["P1"] == (0.0, pytest.approx(profile.head_width_mm / 2, abs=1e-9))
