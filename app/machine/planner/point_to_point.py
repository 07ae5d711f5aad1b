"""A single synchronised move between two positions, at rest at both ends.

Used to bring the cutter to the stave plan's start, and by the machine for moves outside
the cycle (to home, to a service position). X-Y moves along the straight line between the
two points (the only path known to be clear is the one the caller chose), Z moves on its
own profile, and both arrive together (ruckig "Time" synchronisation): as fast as the
slowest of them allows, with the others slowed to match.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from app.machine.planner.chunk import Chunk, make_chunk
from app.machine.planner.chunked import ChunkedTrajectory
from app.machine.planner.limits import MotionLimits
from app.machine.planner.path import LinePiece, Path
from app.machine.planner.trajectory import Phase, PlannerError

XYZ = tuple[float, float, float]

SAME_POSITION_MM = 1e-9
"""Two positions closer than this (mm or deg per axis) are the same: no move is planned."""


def _check_xyz(name: str, value: Sequence[float]) -> XYZ:
    if len(value) != 3 or not all(isinstance(v, int | float) and math.isfinite(v) for v in value):
        raise PlannerError(f"{name} = {value!r} is not allowed: three finite numbers (x, y, z)")
    return (float(value[0]), float(value[1]), float(value[2]))


def point_to_point_chunk(
    start_xyz: Sequence[float], target_xyz: Sequence[float], limits: MotionLimits, phase: Phase
) -> Chunk | None:
    """The chunk of a straight move, or None if start and target are the same."""
    start = _check_xyz("start_xyz", start_xyz)
    target = _check_xyz("target_xyz", target_xyz)
    path = None
    if max(abs(target[0] - start[0]), abs(target[1] - start[1])) > SAME_POSITION_MM:
        path = Path((LinePiece(start[:2], target[:2]),))
    z_end = target[2] if abs(target[2] - start[2]) > SAME_POSITION_MM else start[2]
    if path is None and z_end == start[2]:
        return None
    return make_chunk(phase, path, start[:2], start[2], z_end, limits.x, limits.y, limits.z, None)


def plan_point_to_point(
    start_xyz: Sequence[float], target_xyz: Sequence[float], limits: MotionLimits
) -> ChunkedTrajectory:
    """Time-optimal jerk-limited move from rest at ``start_xyz`` to rest at ``target_xyz``.

    Raises PlannerError if start and target are the same position (nothing to move)."""
    chunk = point_to_point_chunk(start_xyz, target_xyz, limits, Phase.POINT_TO_POINT)
    if chunk is None:
        raise PlannerError(
            f"target_xyz = {tuple(target_xyz)!r} is the start position: nothing to move"
        )
    return ChunkedTrajectory([chunk])
