"""The time-parameterised motion of one whole stave, from the tool path.

What it does. The tool path (``app.geometry.toolpath``) is a chain of exact lines and arcs
with a tilt. This module cuts the chain into rest-to-rest chunks wherever a move cannot be
run through without stopping (a corner, a change between cutting and travel), and plans
each chunk time-optimally (see ``chunk.py``):

* a side (lead-in, P1..P4 or P5..P8, lead-out) is one tangent-continuous path, run from rest
  to rest at the feed with jerk-limited ramps, without stopping at P2/P3/P6/P7; the
  setpoints are exact points of the path, so the path is never left;
* the arc's centripetal acceleration (and its jerk) is budgeted in the path limits, for the
  feed at the highest override;
* travel moves run as fast as the axis limits allow along their straight lines; where the
  tool path changes the tilt on a travel move, Z is a second coordinate moving on its own
  jerk-limited profile during the X-Y travel and arriving with it (overlap). The tool path
  keeps travel moves out of its keep-out box, which is sized for the largest tilt of the
  cycle, so every tilt in between is safe anywhere along those moves;
* if the machine is not at the tool path's first point, a move there is prepended (phase
  APPROACH), routed around the board's keep-out box (``keepout.py``), or refused
  (:class:`KeepOutRefused`) when the machine stands over the board;
* before each side the axes dwell ``settle_s`` at rest at the lead-in start (in the phase
  before the cut), so the servo has settled from the travel's last corner when the cut
  begins.

Phases: APPROACH until the first cutting piece, CUT_A, REPOSITION, CUT_B, RETURN.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from app.geometry.segments import ArcSegment, Segment
from app.geometry.toolpath import ToolPath
from app.machine.planner.chunk import Chunk, make_chunk, make_dwell
from app.machine.planner.chunked import ChunkedTrajectory
from app.machine.planner.keepout import KeepOutRefused, TableKeepOut, routed_chunks
from app.machine.planner.limits import MotionLimits
from app.machine.planner.path import ArcPiece, FloatArray, LinePiece, Path, Piece
from app.machine.planner.trajectory import Phase, PlannerError
from app.table_outlines import TableOutline

DEFAULT_SETTLE_S = 0.1
"""Dwell at rest at each lead-in start before a side is cut, so that the drives settle
after the corner that ends the travel (on the simulated drives the lead-in's contour error
falls from 0.016 to 0.007 mm with it; on the board it is 0.002 mm either way)."""

JOIN_TOLERANCE_MM = 1e-6
"""Largest gap between one segment's end and the next one's start that is not an error."""

_CUT_PHASES = {"A": Phase.CUT_A, "B": Phase.CUT_B}


def _piece(segment: Segment) -> Piece:
    if isinstance(segment, ArcSegment):
        piece: Piece = ArcPiece.through(
            segment.start,
            segment.end,
            segment.center,
            segment.clockwise,
            segment.cutting,
            segment.side,
        )
        miss = math.dist(piece.point(piece.length_mm), segment.end)
        if miss > JOIN_TOLERANCE_MM:
            raise PlannerError(f"arc ending at {segment.end} does not close ({miss:.3g} mm)")
        return piece
    return LinePiece(segment.start, segment.end, segment.cutting, segment.side)


def _tangents(segment: Segment) -> tuple[tuple[float, float], tuple[float, float]]:
    if segment.length_mm == 0.0:
        return (0.0, 0.0), (0.0, 0.0)
    return segment.tangent_at(0.0), segment.tangent_at(segment.length_mm)


def _joins(previous: Segment, segment: Segment) -> bool:
    """True if ``segment`` continues ``previous`` without a stop between them."""
    if previous.length_mm == 0.0 or segment.length_mm == 0.0:
        return False
    if previous.cutting != segment.cutting or previous.side != segment.side:
        return False
    if previous.cutting and previous.z_end_deg != segment.z_start_deg:
        return False
    if not previous.cutting and (
        previous.z_start_deg != previous.z_end_deg or segment.z_start_deg != segment.z_end_deg
    ):
        return False  # a tilting travel move is a chunk of its own (Z is its second DOF)
    a = _tangents(previous)[1]
    b = _tangents(segment)[0]
    turn = abs(math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]))
    return turn <= Path.TANGENT_TOLERANCE_RAD


class _PhaseTracker:
    def __init__(self) -> None:
        self.sides: list[str] = []

    def phase(self, segment: Segment) -> Phase:
        if segment.cutting:
            if segment.side not in _CUT_PHASES:
                raise PlannerError(
                    f"a cutting segment has side = {segment.side!r}: allowed 'A' or 'B'"
                )
            if not self.sides or self.sides[-1] != segment.side:
                if segment.side in self.sides:
                    raise PlannerError(f"side {segment.side} is cut twice in one tool path")
                self.sides.append(segment.side)
            return _CUT_PHASES[segment.side]
        if segment.side in _CUT_PHASES:  # back round the board between two passes of a side
            return _CUT_PHASES[segment.side]
        if not self.sides:
            return Phase.APPROACH
        # A resumed cut may begin with side B: after B comes the return, whatever came before.
        return Phase.REPOSITION if self.sides[-1] == "A" else Phase.RETURN


def _chunk(run: Sequence[Segment], phase: Phase, limits: MotionLimits) -> Chunk:
    moving = [s for s in run if s.length_mm > 0.0]
    path = Path(tuple(_piece(s) for s in moving)) if moving else None
    z_start, z_end = run[0].z_start_deg, run[-1].z_end_deg
    feed = limits.feed_mm_s if run[0].cutting else None
    return make_chunk(phase, path, run[0].start, z_start, z_end, limits.x, limits.y, limits.z, feed)


_TRAVEL_SAMPLES = 16  # points per travel segment checked against the devices' boxes


def _check_travel_clear_of(devices: Sequence[TableOutline], toolpath: ToolPath) -> None:
    """The tool path's own travel (from home, the repositioning, the return) goes around the
    board by construction; a clamp configured beyond it is checked here, and the board is
    refused (KeepOutRefused) rather than driven into it."""
    if not devices:
        return
    keep_out = replace(TableKeepOut.around_toolpath(toolpath, devices), board_on_table=False)
    for segment in toolpath.segments:
        if segment.cutting or segment.length_mm == 0.0:
            continue
        points = [
            (
                *segment.point_at(segment.length_mm * k / _TRAVEL_SAMPLES),
                segment.z_at(segment.length_mm * k / _TRAVEL_SAMPLES),
            )
            for k in range(_TRAVEL_SAMPLES + 1)
        ]
        if keep_out.crossing(points) is not None:
            x, y = segment.start
            raise KeepOutRefused(
                f"the travel from X {x:.1f} Y {y:.1f} mm runs through "
                f"{keep_out.obstacle_names(max(abs(p[2]) for p in points))}: "
                "move the clamps' outline in [keep_out] or the start position"
            )


def _chunks(
    toolpath: ToolPath,
    start_xyz: Sequence[float],
    limits: MotionLimits,
    settle_s: float,
    devices: Sequence[TableOutline],
) -> list[Chunk]:
    segments = toolpath.segments
    if not segments:
        raise PlannerError("the tool path has no segments")
    first = segments[0]
    _check_travel_clear_of(devices, toolpath)
    chunks: list[Chunk] = routed_chunks(
        TableKeepOut.around_toolpath(toolpath, devices),
        start_xyz,
        (*first.start, first.z_start_deg),
        limits,
        Phase.APPROACH,
    )
    tracker = _PhaseTracker()
    run: list[Segment] = []
    run_phase = Phase.APPROACH
    for index, segment in enumerate(segments):
        if index:
            previous = segments[index - 1]
            gap = math.dist(previous.end, segment.start)
            if gap > JOIN_TOLERANCE_MM or abs(previous.z_end_deg - segment.z_start_deg) > 1e-9:
                raise PlannerError(
                    f"tool path segment {index} does not start where segment "
                    f"{index - 1} ends (gap {gap:.3g} mm)"
                )
        phase = tracker.phase(segment)
        same_kind = bool(run) and run[-1].cutting == segment.cutting  # feed or rapid
        if run and same_kind and _joins(run[-1], segment) and phase is run_phase:
            run.append(segment)
            continue
        if run and (run[-1].length_mm > 0.0 or run[-1].z_start_deg != run[-1].z_end_deg):
            chunks.append(_chunk(run, run_phase, limits))
        run, run_phase = [segment], phase
    if run[-1].length_mm > 0.0 or run[-1].z_start_deg != run[-1].z_end_deg:
        chunks.append(_chunk(run, run_phase, limits))
    if settle_s <= 0.0:
        return chunks
    settled: list[Chunk] = []
    for chunk in chunks:
        if chunk.phase in (Phase.CUT_A, Phase.CUT_B):
            before = settled[-1].phase if settled else Phase.APPROACH
            settled.append(make_dwell(before, chunk.start_xyz(), limits.z, settle_s))
        settled.append(chunk)
    return settled


class StavePlan(ChunkedTrajectory):
    """The planned motion of one stave (a :class:`Trajectory`), with the exact tool path for
    error measurement and the figures the cycle records."""

    def __init__(
        self,
        toolpath: ToolPath,
        start_xyz: Sequence[float],
        limits: MotionLimits,
        settle_s: float = DEFAULT_SETTLE_S,
        devices: Sequence[TableOutline] = (),
    ) -> None:
        if not (isinstance(settle_s, int | float) and math.isfinite(settle_s) and settle_s >= 0):
            raise PlannerError(f"settle_s = {settle_s!r} is not allowed: a finite number >= 0")
        self.toolpath = toolpath
        self.limits = limits
        self.settle_s = float(settle_s)
        super().__init__(_chunks(toolpath, start_xyz, limits, self.settle_s, devices))

    def _side_chunks(self, side: str) -> list[Chunk]:
        if side not in _CUT_PHASES:
            raise ValueError(f"side = {side!r} is not allowed: 'A' or 'B'")
        return [c.chunk for c in self.chunks if c.chunk.phase is _CUT_PHASES[side]]

    def cut_time_s(self, side: str) -> float:
        """Planned time (at 100 %) of one side, lead-in start to lead-out end, at rest at both
        ends."""
        self._side_chunks(side)
        interval = self.phase_interval(_CUT_PHASES[side])
        return 0.0 if interval is None else interval[1] - interval[0]

    def cut_length_mm(self, side: str) -> float:
        """Path length of one side, leads included."""
        return sum(c.path.length_mm for c in self._side_chunks(side) if c.path is not None)

    def cut_path(self, side: str) -> Path:
        """The exact path of one side (lead-in to lead-out)."""
        paths = [c.path for c in self._side_chunks(side) if c.path is not None]
        if not paths:
            raise PlannerError(f"the tool path has no side {side}")
        return Path(tuple(p for path in paths for p in path.pieces))

    def board_path(self, side: str) -> Path:
        """The part of a side where the cutter is on the board: P1..P4 (or P5..P8), without
        the lead-in and lead-out."""
        pieces = self.cut_path(side).pieces
        if len(pieces) < 3:
            raise PlannerError(f"side {side} has no lead-in and lead-out around its cut")
        return Path(pieces[1:-1])

    def distance_to_path(self, x: float, y: float) -> float:
        """Plan-view distance (mm) of a point to the nearest point of the whole tool path."""
        return float(self.distances_to_path(np.array([x]), np.array([y]))[0])

    def distances_to_path(self, x: FloatArray, y: FloatArray) -> FloatArray:
        """Vectorised :meth:`distance_to_path`."""
        result = np.full(np.shape(x), math.inf)
        for segment in self.toolpath.segments:
            if segment.length_mm > 0.0:
                result = np.minimum(result, _piece(segment).distances(x, y))
        return result

    def curvature_step_times(self) -> tuple[float, ...]:
        """Times (s, at 100 %) at which the path's curvature steps while moving (the line/arc
        junctions P2, P3, P6, P7): the declared exceptions to the jerk limit."""
        times = []
        for planned in self.chunks:
            chunk = planned.chunk
            if chunk.path is None or chunk.s_dof is None:
                continue
            for s in chunk.path.curvature_steps():
                t = planned.trajectory.get_first_time_at_position(0, s)
                if t is not None:
                    times.append(planned.t_start_s + float(t))
        return tuple(sorted(times))


def from_first_cut(toolpath: ToolPath) -> ToolPath:
    """The tool path from its first cutting segment on, the travel from home before it left
    out. Why: a stave planned from anywhere but home (the previous board's side B end) then
    approaches the lead-in directly, around the keep-out, instead of through home."""
    first = next((i for i, s in enumerate(toolpath.segments) if s.cutting), 0)
    return replace(toolpath, segments=toolpath.segments[first:])


def plan_stave(
    toolpath: ToolPath,
    start_xyz: tuple[float, float, float],
    limits: MotionLimits,
    *,
    settle_s: float = DEFAULT_SETTLE_S,
    devices: Sequence[TableOutline] = (),
) -> StavePlan:
    """Plan the whole stave from rest at ``start_xyz`` to rest at the tool path's end (home),
    dwelling ``settle_s`` at each lead-in start; the approach goes around the board and
    ``devices`` (the clamps' outlines: closed while the cutter moves).

    Raises PlannerError (a ValueError) naming what is wrong if it cannot be planned."""
    return StavePlan(toolpath, start_xyz, limits, settle_s, devices)
