"""The range of board widths one recipe cuts on one machine.

Why: whether a board can be cut depends on everything at once: the head width the ratios
leave, the bevel a barrel recipe derives from the width (and whether the tilt axis reaches
it), the barrel's diameter, the tool path within the axis travel. An operator cannot see that
from a recipe; one number each way can be shown on the Recipes screen and named in the alarm
for a board outside it, before anything moves.

How: every check is :func:`app.geometry.stave_cut.cut_stave`, the machine's own composition.
The widths it accepts are scanned on a coarse grid over the table's range (0 to the widest
board the table takes); the first accepted interval is refined at both ends by bisection to
``RESOLUTION_MM``. (The accepted widths of these recipes are one interval: every limit is
monotonic in the width.)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from app.geometry.limits import StaveLimits
from app.geometry.stave_cut import StaveCutRefused, StaveSpec, cut_stave

GRID_STEPS = 56
"""Coarse grid over (0, max width]: 5 mm on the standard table."""

RESOLUTION_MM = 0.01


@dataclass(frozen=True)
class WidthRange:
    """The narrowest and widest board (mm) the recipe cuts on this machine."""

    min_mm: float
    max_mm: float

    def contains(self, width_mm: float) -> bool:
        return self.min_mm <= width_mm <= self.max_mm

    def describe(self) -> str:
        return f"{self.min_mm:.1f} to {self.max_mm:.1f} mm"

    def refusal(self, width_mm: float) -> str:
        """The operator's line for a board outside the range ("" inside it)."""
        if width_mm > self.max_mm:
            bound = f"at most {self.max_mm:.1f} mm wide"
        elif width_mm < self.min_mm:
            bound = f"at least {self.min_mm:.1f} mm wide"
        else:
            return ""
        return (
            f"board {width_mm:.1f} mm: this recipe cuts boards {bound} on this machine "
            f"({self.describe()}): take the board off or choose another recipe"
        )


def _bisect(accepts: Callable[[float], bool], good: float, bad: float) -> float:
    while abs(good - bad) > RESOLUTION_MM:
        middle = (good + bad) / 2.0
        if accepts(middle):
            good = middle
        else:
            bad = middle
    return good


def cuttable_widths(
    stave: StaveSpec, params: Mapping[str, float], limits: StaveLimits
) -> WidthRange | None:
    """The widths ``stave`` is cut from on this machine, or None if it cuts none."""

    def accepts(width_mm: float) -> bool:
        try:
            cut_stave(stave, width_mm, params, limits)
        except StaveCutRefused:
            return False
        return True

    top = limits.max_width_mm
    step = top / GRID_STEPS
    grid = [step * (i + 1) for i in range(GRID_STEPS)]
    accepted = [w for w in grid if accepts(w)]
    if not accepted:
        return None
    first, last = accepted[0], accepted[-1]
    low = first if first - step <= 0.0 else _bisect(accepts, first, first - step)
    high = last if last >= top else _bisect(accepts, last, min(last + step, top))
    if high == last and last + step > top and accepts(top):
        high = top
    return WidthRange(round(low, 2), round(high, 2))
