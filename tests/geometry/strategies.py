"""Shared hypothesis strategies and helpers for the geometry tests.

The strategies cover the whole valid range of docs/MACHINE.md section 1: L in [900, 3500], lambda in
[0, 1/2), k with a head width W1 = k*W >= 60 mm on a board of W <= 280 mm. Ratios are drawn as
fractions with denominators up to 10000, the resolution `Ratio.parse` keeps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

from hypothesis import assume, settings
from hypothesis import strategies as st

from app.cli.solve import PROCESS_DEFAULTS
from app.geometry.profile import StaveProfile, solve_profile
from app.geometry.toolpath import ToolPathParams

PROPERTY = settings(max_examples=120, deadline=None)
"""Enough examples to sweep the range; keeps tests/geometry well under 30 s."""

DEFAULT_PARAMS = ToolPathParams.from_parameters(PROCESS_DEFAULTS, tilt_deg=3.5)


@dataclass(frozen=True)
class StaveInput:
    length_mm: float
    width_mm: float
    length_ratio: Fraction
    width_ratio: Fraction

    def solve(self) -> StaveProfile:
        return solve_profile(
            self.length_mm, self.width_mm, float(self.length_ratio), float(self.width_ratio)
        )


@st.composite
def length_ratios(draw: st.DrawFn) -> Fraction:
    denominator = draw(st.integers(1, 10_000))
    numerator = draw(st.integers(0, (denominator - 1) // 2))
    return Fraction(numerator, denominator)


@st.composite
def stave_inputs(draw: st.DrawFn) -> StaveInput:
    length = draw(st.floats(900.0, 3500.0))
    lam = draw(length_ratios())
    denominator = draw(st.integers(2, 10_000))
    numerator = draw(st.integers(math.ceil(3 * denominator / 14), denominator - 1))
    k = Fraction(numerator, denominator)
    width = draw(st.floats(min(280.0, 60.0 / float(k)), 280.0))
    assume(float(k) * width >= 60.0)
    return StaveInput(length, width, lam, k)


@st.composite
def toolpath_params(draw: st.DrawFn) -> ToolPathParams:
    """Tool radius, machine height, tilt, lead and start over a wide range.

    Home stays at the origin, which these start positions keep below and left of the board
    (the routing around the board has its own test with homes all around it).
    """
    radius = draw(st.floats(5.0, 60.0))
    tilt = draw(st.floats(0.0, 45.0))
    effective = radius / math.cos(math.radians(tilt))
    return ToolPathParams(
        tool_radius_mm=radius,
        machine_height_mm=draw(st.floats(0.0, 400.0)),
        tilt_deg=tilt,
        start_x_mm=draw(st.floats(70.0, 300.0)),
        start_y_mm=draw(st.floats(700.0, 900.0)),
        lead_mm=effective + draw(st.floats(0.01, 100.0)),
        home_x_mm=0.0,
        home_y_mm=0.0,
        home_z_deg=0.0,
        tilt_clearance_mm=draw(st.floats(0.0, 100.0)),
    )


def mirror_y(point: tuple[float, float], axis_y: float) -> tuple[float, float]:
    return (point[0], 2.0 * axis_y - point[1])


def close(a: tuple[float, float], b: tuple[float, float], tolerance: float) -> bool:
    return math.hypot(a[0] - b[0], a[1] - b[1]) <= tolerance
