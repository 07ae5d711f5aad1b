"""Homing with a board on the table: first move clear of it, or refuse.

Why: homing drives Y and then X to their switches in straight lines; with a board clamped
(or lying) on the table those lines may run through it. When the axes know where they are
(homed, or absolute encoders), the machine first tilts upright in place (a smaller tilt only
shrinks the cutter's reach) and travels around the board to the side of it where Y's home
switch lies; from there Y and X home without crossing it. When they do not know where they
are, or the switches lie across the board, homing is refused: the operator takes the board
off first.
"""

from __future__ import annotations

from collections.abc import Mapping

from app.config import AxisConfig
from app.machine.planner.chunked import ChunkedTrajectory
from app.machine.planner.keepout import KeepOutRefused, TableKeepOut, routed_chunks
from app.machine.planner.limits import MotionLimits
from app.machine.planner.trajectory import Phase

XYZ = tuple[float, float, float]


def homing_clearance(
    xyz: XYZ,
    keep_out: TableKeepOut,
    axes: Mapping[str, AxisConfig],
    limits: MotionLimits,
    homing: tuple[str, ...],
) -> ChunkedTrajectory | None:
    """The move (spindle off) that takes the cutter clear of the board before ``homing``
    (axis names in homing order), or None if it already is. Raises KeepOutRefused."""
    upright = (xyz[0], xyz[1], 0.0 if "Z" in homing else xyz[2])
    if keep_out.inside(xyz):
        raise KeepOutRefused(
            f"the cutter stands over the board at X {xyz[0]:.1f} Y {xyz[1]:.1f} mm: "
            "take the board off (or jog clear in Manual) before homing"
        )
    # Homing Z swings the tilt to its switch where the cutter then stands: clear of that too.
    swing = abs(axes["Z"].home_switch_position) if "Z" in homing else 0.0
    box = keep_out.extent(max(abs(upright[2]), swing))
    y = axes["Y"]
    below = y.homing_direction < 0
    clear_y = box.y_min - keep_out.clearance_mm if below else box.y_max + keep_out.clearance_mm
    if not y.min_position <= clear_y <= y.max_position:
        raise KeepOutRefused(
            f"Y cannot reach {clear_y:.1f} mm beside the board (travel {y.min_position:g} to "
            f"{y.max_position:g} mm): take the board off before homing"
        )
    target = upright
    if "Y" in homing and (upright[1] > clear_y if below else upright[1] < clear_y):
        target = (upright[0], clear_y, upright[2])
    # The homing moves from there: Y to its switch, then X to its switch at that Y.
    y_end = y.home_switch_position if "Y" in homing else target[1]
    x_end = axes["X"].home_switch_position if "X" in homing else target[0]
    z = max(abs(target[2]), swing)
    homing_path = [(target[0], target[1], z), (target[0], y_end, z), (x_end, y_end, z)]
    if keep_out.crossing(homing_path) is not None:
        raise KeepOutRefused(
            "homing would run the cutter through the board (the home switches lie across "
            "it): take the board off before homing"
        )
    chunks = []
    if upright[2] != xyz[2]:
        chunks += routed_chunks(keep_out, xyz, upright, limits, Phase.POINT_TO_POINT)
    chunks += routed_chunks(keep_out, upright, target, limits, Phase.POINT_TO_POINT)
    return ChunkedTrajectory(chunks) if chunks else None
