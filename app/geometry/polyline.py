"""Arcs split into chords with a bounded chord error, for drives without circular interpolation.

A chord spanning the angle phi of an arc of radius R deviates from the arc by its sagitta
R * (1 - cos(phi/2)) = 2R * sin^2(phi/4); keeping that below the bound e gives the largest
step phi = 4 * asin(sqrt(e / (2R))). Written this way it stays accurate for arcs of hundreds of
metres where 1 - e/R would round away. Lines are exact already and only split when a maximum
segment length is asked for (some controls, like the polystyrene saw of docs/MACHINE.md
section 6, want segments no longer than 1 mm).
"""

from __future__ import annotations

import math
from collections.abc import Iterable

from app.geometry.segments import ArcSegment, Segment

PolylinePoint = tuple[float, float, float, bool]
"""(x_mm, y_mm, z_deg, cutting): `cutting` describes the move that ends at this point."""

MAX_STEP_RAD = math.pi / 4.0
"""Upper bound on the angle of one chord, whatever the tolerance (keeps chords short)."""


def arc_step_rad(radius_mm: float, max_chord_error_mm: float) -> float:
    """Largest angle whose chord deviates from an arc of this radius by at most the bound."""
    ratio = max_chord_error_mm / (2.0 * radius_mm)
    if ratio >= 0.5:
        return MAX_STEP_RAD
    return min(MAX_STEP_RAD, 4.0 * math.asin(math.sqrt(ratio)))


def sagitta_mm(radius_mm: float, angle_rad: float) -> float:
    """Largest distance between an arc of `angle_rad` and its chord."""
    return 2.0 * radius_mm * math.sin(angle_rad / 4.0) ** 2


def _pieces(length_mm: float, max_segment_mm: float | None) -> int:
    if max_segment_mm is None or length_mm <= max_segment_mm:
        return 1
    return math.ceil(length_mm / max_segment_mm)


def segment_points(
    segment: Segment, max_chord_error_mm: float, max_segment_mm: float | None = None
) -> list[PolylinePoint]:
    """The points after the segment's start, up to and including its end."""
    length = segment.length_mm
    if isinstance(segment, ArcSegment):
        step = arc_step_rad(segment.radius_mm, max_chord_error_mm)
        count = max(1, math.ceil(segment.sweep_rad / step))
        count = max(count, _pieces(length, max_segment_mm))
    else:
        count = _pieces(length, max_segment_mm)
    points: list[PolylinePoint] = []
    for index in range(1, count + 1):
        s = length * index / count if index < count else length
        x, y = segment.point_at(s)
        points.append((x, y, segment.z_at(s), segment.cutting))
    return points


def to_polyline(
    segments: Iterable[Segment],
    max_chord_error_mm: float = 0.001,
    max_segment_mm: float | None = None,
) -> list[PolylinePoint]:
    """The whole path as points; the first is the start of the first segment."""
    if not (math.isfinite(max_chord_error_mm) and max_chord_error_mm > 0.0):
        raise ValueError(
            f"max_chord_error_mm = {max_chord_error_mm} is out of range: allowed > 0 mm"
        )
    if max_segment_mm is not None and not (math.isfinite(max_segment_mm) and max_segment_mm > 0.0):
        raise ValueError(f"max_segment_mm = {max_segment_mm} is out of range: allowed > 0 mm")
    points: list[PolylinePoint] = []
    for segment in segments:
        if not points:
            x, y = segment.start
            points.append((x, y, segment.z_start_deg, segment.cutting))
        points.extend(segment_points(segment, max_chord_error_mm, max_segment_mm))
    return points
