"""How far a manual jog may take the cutter before it touches the board on the table.

Why the jog is checked too: the keep-out model (:mod:`app.machine.planner.keepout`) keeps every
move the machine makes on its own clear of the clamped board; a jog is the operator's move,
but a button held a moment too long drives the turning cutter (or a travel) into the board
just the same. So with a board on the table a continuous jog stops at the edge of the nearest
keep-out box (the board's, a closed clamp's, the centering device's while it is out), and a
step that would end in one or cross it is refused. A pivot already inside
the box (a cut stopped on the board) may be jogged anywhere: the operator has to get it out.
"""

from __future__ import annotations

from collections.abc import Sequence

from app.geometry.toolpath import KeepOutBox
from app.machine.planner.keepout import TableKeepOut

_TILT_BISECTIONS = 40  # 2^-40 of the tilt range: far below a micro-degree


def jog_reach(keep_out: TableKeepOut, xyz: Sequence[float], axis: str, target: float) -> float:
    """The position of ``axis`` nearest ``target`` (along the jog from ``xyz``) that keeps
    the pivot out of the keep-out box: ``target`` itself when the way is clear."""
    x, y, z = (float(v) for v in xyz)
    if keep_out.inside((x, y, z)):
        return target
    if axis == "Z":
        return _tilt_reach(keep_out, x, y, z, target)
    reach = target
    for _, box in keep_out.boxes(z):
        reach = _linear_reach(box, axis, x, y, reach)
    return reach


def _linear_reach(box: KeepOutBox, axis: str, x: float, y: float, target: float) -> float:
    """How far an X or Y jog from (x, y) toward ``target`` goes before ``box``."""
    here, across, low, high, band_low, band_high = (
        (x, y, box.x_min, box.x_max, box.y_min, box.y_max)
        if axis == "X"
        else (y, x, box.y_min, box.y_max, box.x_min, box.x_max)
    )
    if not band_low < across < band_high:
        return target  # the line of the jog passes beside the box
    if target > here and here <= low < target:
        return low
    if target < here and here >= high > target:
        return high
    return target


def _tilt_reach(keep_out: TableKeepOut, x: float, y: float, z: float, target: float) -> float:
    """The box grows with the tilt: the last tilt toward ``target`` with the pivot outside."""
    if not keep_out.inside((x, y, target)):
        return target
    clear, touching = z, target  # outside at ``clear``, inside at ``touching``
    for _ in range(_TILT_BISECTIONS):
        middle = (clear + touching) / 2.0
        if keep_out.inside((x, y, middle)):
            touching = middle
        else:
            clear = middle
    return clear
