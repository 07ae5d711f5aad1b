"""Reading a drawn side profile from a DXF file (with ezdxf) into the geometry's primitives.

Why here and not in app.geometry: geometry does no I/O and knows no file format. This module
turns the bytes of a file (read by the caller: the recipe screen's file chooser, the command
line) into plain lines, arcs and splines that name their entity and layer, and lets
`app.geometry.drawn_profile` find and check the one curve. The file's name and SHA-256 travel
with the result: a recipe keeps both beside the geometry, so it cuts the same after the file
is gone, and shows which file it came from.

Units: only the drawing's shape matters (it is scaled to the recipe's length and the board's
width), so $INSUNITS is not needed; the entities are taken in the model space, flat in the
drawing plane (an entity tilted out of it is refused by name).
"""

from __future__ import annotations

import hashlib
import io
import math
from collections import Counter
from dataclasses import dataclass
from itertools import pairwise

from ezdxf import recover
from ezdxf.entities.arc import Arc
from ezdxf.entities.dxfgfx import DXFGraphic
from ezdxf.entities.line import Line
from ezdxf.entities.lwpolyline import LWPolyline
from ezdxf.entities.polyline import Polyline
from ezdxf.entities.spline import Spline
from ezdxf.lldxf.const import DXFError

from app.data.errors import DataError
from app.geometry.drawn_profile import (
    DrawnArc,
    DrawnLine,
    DrawnShape,
    DrawnSpline,
    Primitive,
    drawn_shape,
    from_bulge,
)
from app.geometry.errors import GeometryError
from app.geometry.nurbs import Nurbs

MAX_FILE_BYTES = 20 * 1024 * 1024
"""A side profile is a few kilobytes; anything this large is not one."""


class DxfProfileError(DataError, ValueError):
    """The file gives no usable profile; the message names the file, the entity, the problem.

    ``curve_layers`` names the layers holding curves when the whole drawing (no layer chosen)
    was refused and there are several: a frame or a second view on its own layer is the usual
    cause, and choosing the profile's layer is the cure (``stave solve --dxf-layer``, the
    Recipes screen's layer choice)."""

    def __init__(self, message: str, curve_layers: tuple[str, ...] = ()) -> None:
        super().__init__(message)
        self.curve_layers = curve_layers


@dataclass(frozen=True)
class DxfProfile:
    """The checked curve of a drawing, with where it came from."""

    file_name: str
    sha256: str
    shape: DrawnShape


def _source(entity: DXFGraphic) -> str:
    return f"{entity.dxftype()} #{entity.dxf.handle} on layer {entity.dxf.layer}"


def _flat(entity: DXFGraphic) -> bool:
    extrusion = entity.dxf.get("extrusion")
    return extrusion is None or (
        abs(extrusion[0]) < 1e-12 and abs(extrusion[1]) < 1e-12 and extrusion[2] > 0
    )


def _arc(entity: Arc, source: str) -> DrawnArc:
    start = math.radians(entity.dxf.start_angle)
    sweep = math.radians(entity.dxf.end_angle) - start
    while sweep <= 0.0:
        sweep += 2.0 * math.pi  # a DXF arc runs counter-clockwise from start to end angle
    centre = entity.dxf.center
    return DrawnArc((centre[0], centre[1]), float(entity.dxf.radius), start, sweep, source)


def _polyline(
    vertices: list[tuple[float, float, float]], closed: bool, source: str
) -> list[Primitive]:
    """(x, y, bulge) vertices as lines and arcs; the bulge belongs to the segment after it."""
    pairs = list(pairwise(vertices))
    if closed and len(vertices) > 1:
        pairs.append((vertices[-1], vertices[0]))
    result: list[Primitive] = []
    for index, ((x0, y0, bulge), (x1, y1, _)) in enumerate(pairs):
        if (x0, y0) == (x1, y1):
            continue
        result.append(from_bulge((x0, y0), (x1, y1), bulge, f"{source}, segment {index + 1}"))
    return result


def _spline(entity: Spline, source: str) -> DrawnSpline:
    tool = entity.construction_tool()
    points = [(float(p[0]), float(p[1])) for p in tool.control_points]
    if any(abs(p[2]) > 1e-9 for p in tool.control_points):
        raise DxfProfileError(f"{source} is not flat in the drawing plane")
    weights = tuple(float(w) for w in tool.weights()) or tuple(1.0 for _ in points)
    nurbs = Nurbs(tool.degree, tuple(float(k) for k in tool.knots()), tuple(points), weights)
    return DrawnSpline(nurbs, False, source)


def _primitives(entity: DXFGraphic) -> list[Primitive]:
    source = _source(entity)
    if not _flat(entity):
        raise DxfProfileError(f"{source} is not flat in the drawing plane (tilted extrusion)")
    if isinstance(entity, Line):
        start, end = entity.dxf.start, entity.dxf.end
        if abs(start[2]) > 1e-9 or abs(end[2]) > 1e-9:
            raise DxfProfileError(f"{source} is not flat in the drawing plane")
        return [DrawnLine((start[0], start[1]), (end[0], end[1]), source)]
    if isinstance(entity, Arc):
        return [_arc(entity, source)]
    if isinstance(entity, LWPolyline):
        points = [(float(x), float(y), float(b)) for x, y, b in entity.get_points(format="xyb")]
        return _polyline(points, bool(entity.closed), source)
    if isinstance(entity, Polyline):
        if not entity.is_2d_polyline:
            raise DxfProfileError(f"{source} is a 3D polyline or mesh; draw the side in 2D")
        points = [
            (float(v.dxf.location[0]), float(v.dxf.location[1]), float(v.dxf.get("bulge", 0.0)))
            for v in entity.vertices
        ]
        return _polyline(points, bool(entity.is_closed), source)
    if isinstance(entity, Spline):
        return [_spline(entity, source)]
    raise DxfProfileError(f"{source} is not a curve this product reads")


def _is_curve(entity: DXFGraphic) -> bool:
    return isinstance(entity, Line | Arc | LWPolyline | Polyline | Spline)


def _ends_with_eof(data: bytes) -> bool:
    """A complete text DXF ends with the group "0" / "EOF" (a binary one is not checked)."""
    if data.startswith(b"AutoCAD Binary DXF"):
        return True
    return data.rstrip().split()[-1:] == [b"EOF"]


def read_dxf_profile(file_name: str, data: bytes, layer: str | None = None) -> DxfProfile:
    """The one side curve of a DXF drawing (of the layer `layer`, if given).

    Raises DxfProfileError with one line: the file, then what is wrong (an unreadable file,
    no usable curve with the entities and layers found, several candidates named one by one,
    a corner, a curve that turns back, ...).
    """
    if len(data) > MAX_FILE_BYTES:
        raise DxfProfileError(
            f"{file_name}: {len(data)} bytes is too large for a profile drawing "
            f"(allowed up to {MAX_FILE_BYTES} bytes)"
        )
    if not data.strip():
        raise DxfProfileError(f"{file_name}: the file is empty: not a DXF drawing")
    try:
        document, auditor = recover.read(io.BytesIO(data))
    except (DXFError, UnicodeError, ValueError, TypeError, IndexError) as error:
        raise DxfProfileError(f"{file_name}: not a readable DXF file ({error})") from None
    if auditor.has_errors:
        first = auditor.errors[0].message if auditor.errors else "unknown error"
        raise DxfProfileError(f"{file_name}: the DXF file is damaged ({first})")
    primitives: list[Primitive] = []
    other: Counter[str] = Counter()
    curve_layers = tuple(  # in drawing order, all of them before any entity is refused
        dict.fromkeys(str(e.dxf.layer) for e in document.modelspace() if _is_curve(e))
    )
    try:
        for entity in document.modelspace():
            where = f"{entity.dxftype()} on layer {entity.dxf.layer}"
            if layer is not None and entity.dxf.layer != layer:
                other[where] += 1
            elif _is_curve(entity):
                primitives += _primitives(entity)
            else:
                other[where] += 1
        if not primitives and not other and not _ends_with_eof(data):
            raise DxfProfileError(
                "no entity could be read and the file ends without the DXF end marker (EOF): "
                "it is cut short or damaged"
            )
        found = tuple(
            f"{count} x {where}" if count > 1 else where for where, count in other.items()
        )
        shape = drawn_shape(primitives, found)
    except (DxfProfileError, GeometryError, ValueError, DXFError) as error:
        layers = curve_layers if layer is None and len(curve_layers) > 1 else ()
        raise DxfProfileError(f"{file_name}: {error}", layers) from None
    return DxfProfile(file_name, hashlib.sha256(data).hexdigest(), shape)
