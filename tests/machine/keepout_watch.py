"""A per-period watch of the commanded cutter against the board on the table.

Independent of the machine's own keep-out model: the tilted cutter meets the table as a circle
of radius r/cos(z) about (X, Y + Hm*tan(z)) (docs/MACHINE.md section 3); it touches the raw
board (L x W at P0) when that circle reaches the rectangle. Any such period must be on the
tool path's cutting segments; and the spindle may only be switched on with the cutter clear.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from app.geometry.toolpath import ToolPath
from app.machine.runtime import MachineRuntime

ON_PATH_MM = 1.0
"""How far from the cutting path a commanded position touching the board may be: the
setpoints are exact path points; a held position after an immediate stop is the drive's
actual position, within its following error of the path."""


@dataclass
class KeepOutWatch:
    params: dict[str, float]
    length_mm: float
    width_mm: float
    toolpath: ToolPath | None = None
    periods: int = 0
    touching_periods: int = 0
    violations: list[str] = field(default_factory=list)
    max_touching_off_path_mm: float = 0.0
    _spindle_was_on: bool = False

    def _touches(self, x: float, y: float, z: float) -> bool:
        p = self.params
        r = p["tool_radius_mm"] / math.cos(math.radians(z))
        cx = x
        cy = y + p["machine_height_mm"] * math.tan(math.radians(z))
        x0, y0 = p["start_x_mm"], p["start_y_mm"] - self.width_mm / 2.0
        x1, y1 = p["start_x_mm"] + self.length_mm, p["start_y_mm"] + self.width_mm / 2.0
        dx = max(x0 - cx, 0.0, cx - x1)
        dy = max(y0 - cy, 0.0, cy - y1)
        return math.hypot(dx, dy) < r

    def _off_path_mm(self, x: float, y: float) -> float:
        if self.toolpath is None:
            return math.inf
        return min(s.distance_to((x, y)) for s in self.toolpath.segments if s.cutting)

    def __call__(self, runtime: MachineRuntime) -> None:
        c = runtime.controller
        if self.toolpath is None and c.cycle is not None and c.cycle.planned is not None:
            self.toolpath = c.cycle.planned.toolpath
        x, y, z = (c.axes.command[n] for n in ("X", "Y", "Z"))
        self.check(runtime.time_s, c.state.value, x, y, z, c.outputs.spindle_on)

    def check(self, t_s: float, label: str, x: float, y: float, z: float, spindle: bool) -> None:
        """One period: the commanded pivot (x, y), tilt z and the spindle output."""
        self.periods += 1
        if self._touches(x, y, z):
            self.touching_periods += 1
            off = self._off_path_mm(x, y)
            self.max_touching_off_path_mm = max(self.max_touching_off_path_mm, off)
            if off > ON_PATH_MM:
                self.violations.append(
                    f"t {t_s:.3f} s {label}: X {x:.2f} Y {y:.2f} Z {z:.2f} "
                    f"touches the board {off:.2f} mm off the tool path (spindle {spindle})"
                )
        if spindle and not self._spindle_was_on and self._touches(x, y, z):
            self.violations.append(
                f"t {t_s:.3f} s: spindle switched on with the cutter on the board "
                f"at X {x:.2f} Y {y:.2f}"
            )
        self._spindle_was_on = spindle
