"""Kinematic limits the planner, the executor and the jogger must never exceed.

Why a value object of its own: the same limits are read from the configuration (what the
mechanics allow), tightened by the technician's parameters (what the shop wants), and then
used by three consumers that must agree exactly (planner, executor re-planning on an
override change, jogger). Every number is checked once, here, with a message that names it.

Units: X and Y in mm, mm/s, mm/s^2, mm/s^3; Z (the tilt) in deg, deg/s, deg/s^2, deg/s^3.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from app.config import AxisConfig

MAX_OVERRIDE_PCT = 120.0
"""The highest feed override the executor accepts; the planner budgets centripetal
acceleration for a cut run at this override."""


def _check_positive(field: str, value: float) -> None:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise ValueError(f"{field} = {value!r} is not allowed: a number > 0")
    if not math.isfinite(value) or value <= 0.0:
        raise ValueError(f"{field} = {value!r} is not allowed: a finite number > 0")


@dataclass(frozen=True)
class AxisLimits:
    """Symmetric limits of one axis: |v| <= velocity, |a| <= acceleration, |j| <= jerk."""

    velocity: float
    acceleration: float
    jerk: float

    def __post_init__(self) -> None:
        _check_positive("velocity", self.velocity)
        _check_positive("acceleration", self.acceleration)
        _check_positive("jerk", self.jerk)

    @classmethod
    def from_axis_config(cls, axis: AxisConfig) -> AxisLimits:
        return cls(axis.max_velocity, axis.max_acceleration, axis.max_jerk)


@dataclass(frozen=True)
class MotionLimits:
    """The three axes' limits and the cutting feed (mm/s along the tool path)."""

    x: AxisLimits
    y: AxisLimits
    z: AxisLimits
    feed_mm_s: float

    def __post_init__(self) -> None:
        _check_positive("feed_mm_s", self.feed_mm_s)

    @classmethod
    def from_axes(cls, axes: Mapping[str, AxisConfig], feed_mm_s: float) -> MotionLimits:
        """From ``MachineConfig.axes`` (keys "X", "Y", "Z") and a cutting feed."""
        missing = [name for name in ("X", "Y", "Z") if name not in axes]
        if missing:
            raise ValueError(
                f"axes = {sorted(axes)!r} is not allowed: X, Y and Z are required "
                f"(missing {', '.join(missing)})"
            )
        return cls(
            x=AxisLimits.from_axis_config(axes["X"]),
            y=AxisLimits.from_axis_config(axes["Y"]),
            z=AxisLimits.from_axis_config(axes["Z"]),
            feed_mm_s=feed_mm_s,
        )

    def axis(self, index: int) -> AxisLimits:
        """Limits of axis 0 (X), 1 (Y) or 2 (Z)."""
        return (self.x, self.y, self.z)[index]

    @property
    def axes(self) -> tuple[AxisLimits, AxisLimits, AxisLimits]:
        return (self.x, self.y, self.z)
