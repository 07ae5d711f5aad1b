"""The finished tool path against the configured axis travel.

Why beside the tool path and not in `limits`: the check reads a `ToolPath`, and the tool path
is built from a profile that `limits` validates; keeping it here keeps the imports one way
(limits <- profile <- toolpath <- travel).
"""

from __future__ import annotations

import math

from app.geometry.errors import FieldError, format_value, worded
from app.geometry.limits import UNIT_WORDS, StaveLimits
from app.geometry.rule_texts import RuleText
from app.geometry.toolpath import ToolPath


def check_toolpath_travel(toolpath: ToolPath, limits: StaveLimits) -> list[FieldError]:
    """Check every point of the path (arcs included, not only their ends) against the travel.

    One error per violated bound, naming the axis, the furthest value reached and the range.
    """
    x_low = y_low = z_low = math.inf
    x_high = y_high = z_high = -math.inf
    for segment in toolpath.segments:
        sx_low, sy_low, sx_high, sy_high = segment.bounds()
        x_low, y_low = min(x_low, sx_low), min(y_low, sy_low)
        x_high, y_high = max(x_high, sx_high), max(y_high, sy_high)
        z_low = min(z_low, segment.z_start_deg, segment.z_end_deg)
        z_high = max(z_high, segment.z_start_deg, segment.z_end_deg)
    errors: list[FieldError] = []
    axes = (
        ("x_mm", "X", "mm", x_low, x_high, limits.x_min_mm, limits.x_max_mm),
        ("y_mm", "Y", "mm", y_low, y_high, limits.y_min_mm, limits.y_max_mm),
        ("z_deg", "Z", "deg", z_low, z_high, limits.z_min_deg, limits.z_max_deg),
    )
    for field, axis, unit, low, high, travel_min, travel_max in axes:
        allowed = (
            f"{'-inf' if travel_min is None else format_value(travel_min)} <= {axis} <= "
            f"{'inf' if travel_max is None else format_value(travel_max)} {unit}"
        )
        bounds = (UNIT_WORDS.get(unit, unit), travel_min, travel_max)
        if travel_min is not None and low < travel_min:
            message = (
                f"{field} = {low:.3f} is out of range: allowed {allowed} "
                f"(the tool path goes beyond the {axis} axis travel)"
            )
            error = FieldError(field, low, allowed, message)
            errors.append(worded(error, RuleText.TRAVEL, axis, round(low, 3), *bounds))
        if travel_max is not None and high > travel_max:
            message = (
                f"{field} = {high:.3f} is out of range: allowed {allowed} "
                f"(the tool path goes beyond the {axis} axis travel)"
            )
            error = FieldError(field, high, allowed, message)
            errors.append(worded(error, RuleText.TRAVEL, axis, round(high, 3), *bounds))
    return errors
