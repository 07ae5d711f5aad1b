"""How an interrupted board goes on: clear of the board first, then resume or abandon.

Why: after a stop, an E-stop, a fault or a restart in the middle of a board the cutter may
stand on the stave's edge, inside the board's keep-out box. A fresh cycle would start the
spindle there and drive straight through the board. Instead, with the spindle off:

* the cutter retracts *backwards along the path it has just cut* (the wood there is gone) to
  that side's lead-in start, outside the board, at the cutting feed;
* from there (or from wherever it stood outside the box) it travels around the board
  (``keepout.py``) to the lead-in start of the first side not cut completely (resume) or to
  the home position (abandon, or nothing left to cut);
* on resume, the spindle comes up to speed at the lead-in and the remaining tool path from
  that side's lead-in start is run at the cutting feed (the part of the side cut before the
  stop is run again, in air).

A side counts as cut once the cutter has reached its lead-out (past the board's end).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

from app.geometry.segments import ArcSegment, LineSegment, Point, Segment
from app.geometry.toolpath import ToolPath
from app.machine.planner.chunk import Chunk, make_chunk
from app.machine.planner.chunked import ChunkedTrajectory
from app.machine.planner.keepout import KeepOutRefused, TableKeepOut, routed_chunks
from app.machine.planner.limits import MotionLimits
from app.machine.planner.path import ArcPiece, LinePiece, Path, Piece
from app.machine.planner.point_to_point import point_to_point_chunk
from app.machine.planner.stave_plan import StavePlan, plan_stave
from app.machine.planner.trajectory import Phase
from app.table_outlines import TableOutline

XYZ = tuple[float, float, float]

OFF_PATH_TOLERANCE_MM = 3.0
"""How far from the side's path (plan view) a stopped cutter may stand and still retract along
it: the following error limit plus the deviation of a quick stop on an arc."""

SIDE_OF_PHASE = {Phase.CUT_A: "A", Phase.CUT_B: "B"}


@dataclass(frozen=True)
class Continuation:
    """The moves that take an interrupted board on: ``clear`` with the spindle off, then
    (resume) ``cut`` from a lead-in start with the spindle on."""

    clear: ChunkedTrajectory | None
    cut: StavePlan | None
    next_side: str | None  # the side the cut starts with; None: nothing left to cut


def _arc_length_to(segment: Segment, point: Point) -> float:
    """Arc length from the segment's start to the point of it nearest ``point``."""
    if isinstance(segment, LineSegment):
        dx, dy = segment.end[0] - segment.start[0], segment.end[1] - segment.start[1]
        squared = dx * dx + dy * dy
        if squared == 0.0:
            return 0.0
        t = ((point[0] - segment.start[0]) * dx + (point[1] - segment.start[1]) * dy) / squared
        return min(max(t, 0.0), 1.0) * math.sqrt(squared)
    cx, cy = segment.center
    direction = math.atan2(point[1] - cy, point[0] - cx)
    if not segment.contains_direction(direction):
        to_start = math.dist(point, segment.start)
        return 0.0 if to_start <= math.dist(point, segment.end) else segment.length_mm
    ux, uy = segment.start[0] - cx, segment.start[1] - cy
    offset = direction - math.atan2(uy, ux)
    if segment.clockwise:
        offset = -offset
    return (offset % (2.0 * math.pi)) * segment.radius_mm


@dataclass(frozen=True)
class PathPosition:
    """Where on one side's cutting segments a point lies."""

    index: int  # segment index within the side
    s_mm: float  # along that segment
    distance_mm: float  # plan-view distance of the point from the path


def locate_on_side(side_segments: Sequence[Segment], point: Point) -> PathPosition:
    """The nearest point of a side's path (lead-in .. lead-out) to ``point``."""
    distances = [segment.distance_to(point) for segment in side_segments]
    index = min(range(len(distances)), key=distances.__getitem__)
    return PathPosition(index, _arc_length_to(side_segments[index], point), distances[index])


def side_complete(side_segments: Sequence[Segment], point: Point) -> bool:
    """True once the cutter has reached the side's lead-out: the whole edge is cut."""
    where = locate_on_side(side_segments, point)
    return where.index == len(side_segments) - 1 and where.s_mm > 0.0


def _reversed_piece(segment: Segment, s_mm: float) -> Piece | None:
    """From the point at ``s_mm`` back to the segment's start (None if there is nothing)."""
    if s_mm <= 1e-9:
        return None
    here = segment.point_at(min(s_mm, segment.length_mm))
    if isinstance(segment, ArcSegment):
        return ArcPiece.through(here, segment.start, segment.center, not segment.clockwise)
    return LinePiece(here, segment.start)


def retract_chunks(
    side_segments: Sequence[Segment], xyz: XYZ, limits: MotionLimits
) -> tuple[list[Chunk], XYZ]:
    """Moves (spindle off, cutting feed) from ``xyz`` back along the side's path to its
    lead-in start, and that point. Raises KeepOutRefused if the cutter is off the path."""
    where = locate_on_side(side_segments, xyz[:2])
    side = side_segments[0].side
    if where.distance_mm > OFF_PATH_TOLERANCE_MM:
        raise KeepOutRefused(
            f"the cutter stands {where.distance_mm:.1f} mm off the path of side {side} "
            f"(allowed {OFF_PATH_TOLERANCE_MM:g} mm): it cannot retract along the cut"
        )
    tilt = side_segments[0].z_start_deg
    chunks: list[Chunk] = []
    on_path = side_segments[where.index].point_at(where.s_mm)
    onto = point_to_point_chunk(xyz, (*on_path, tilt), limits, Phase.RETRACT)
    if onto is not None:
        chunks.append(onto)
    pieces = [_reversed_piece(side_segments[where.index], where.s_mm)]
    pieces += [_reversed_piece(s, s.length_mm) for s in reversed(side_segments[: where.index])]
    back = [p for p in pieces if p is not None]
    if back:
        path = Path(tuple(back))
        chunks.append(
            make_chunk(
                Phase.RETRACT,
                path,
                path.start,
                tilt,
                tilt,
                limits.x,
                limits.y,
                limits.z,
                limits.feed_mm_s,
            )
        )
    start = side_segments[0].start
    return chunks, (start[0], start[1], tilt)


def next_side(toolpath: ToolPath, phase: Phase, xyz: XYZ) -> str | None:
    """The first side not cut completely, given the phase the cut was in when it stopped."""
    if phase in (Phase.APPROACH, Phase.POINT_TO_POINT):
        return "A"
    if phase is Phase.REPOSITION:
        return "B"
    if phase is Phase.RETURN:
        return None
    side = SIDE_OF_PHASE.get(phase)
    if side is None:
        raise ValueError(f"phase = {phase!r} is not a phase of the cut")
    if not side_complete(toolpath.side_segments(side), xyz[:2]):
        return side
    return "B" if side == "A" else None


def _remaining_toolpath(toolpath: ToolPath, side: str) -> ToolPath:
    first = next(i for i, s in enumerate(toolpath.segments) if s.cutting and s.side == side)
    return replace(toolpath, segments=toolpath.segments[first:])


def _clear_chunks(
    toolpath: ToolPath,
    phase: Phase,
    xyz: XYZ,
    target: XYZ,
    limits: MotionLimits,
    devices: Sequence[TableOutline],
) -> list[Chunk]:
    keep_out = TableKeepOut.around_toolpath(toolpath, devices)
    chunks: list[Chunk] = []
    here = xyz
    if keep_out.inside(xyz):
        side = SIDE_OF_PHASE.get(phase)
        if side is None:
            raise KeepOutRefused(
                f"the cutter stands over the board at X {xyz[0]:.1f} Y {xyz[1]:.1f} mm "
                f"while {phase.value}: it cannot be moved clear automatically"
            )
        chunks, here = retract_chunks(toolpath.side_segments(side), xyz, limits)
    chunks += routed_chunks(keep_out, here, target, limits, Phase.RETRACT)
    return chunks


def plan_continuation(
    toolpath: ToolPath,
    phase: Phase,
    xyz: XYZ,
    limits: MotionLimits,
    *,
    resume: bool,
    devices: Sequence[TableOutline] = (),
) -> Continuation:
    """Resume (``resume`` True) or abandon the board whose cut stopped in ``phase`` with the
    cutter at ``xyz``. Raises KeepOutRefused (a PlannerError) if no safe way exists."""
    side = next_side(toolpath, phase, xyz) if resume else None
    params = toolpath.params
    home: XYZ = (params.home_x_mm, params.home_y_mm, params.home_z_deg)
    if side is None:
        target = home
        cut = None
    else:
        remaining = _remaining_toolpath(toolpath, side)
        first = remaining.segments[0]
        target = (first.start[0], first.start[1], first.z_start_deg)
        cut = plan_stave(remaining, target, limits, devices=devices)
    chunks = _clear_chunks(toolpath, phase, xyz, target, limits, devices)
    clear = ChunkedTrajectory(chunks) if chunks else None
    return Continuation(clear, cut, side)
