"""Limits are checked once with clear messages, and the path box keeps every axis in its
limits for every state inside it (the property the executor's re-planning relies on)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.machine.planner.chunk import path_box
from app.machine.planner.limits import AxisLimits, MotionLimits
from app.machine.planner.path import ArcPiece, LinePiece

from .support import CONFIG, LIMITS


def test_limits_from_the_configuration() -> None:
    limits = MotionLimits.from_axes(CONFIG.axes, 150.0)
    assert limits.x == AxisLimits(400.0, 2000.0, 20000.0)
    assert limits.z.velocity == CONFIG.axes["Z"].max_velocity
    assert limits.feed_mm_s == 150.0


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"velocity": 0.0, "acceleration": 1.0, "jerk": 1.0}, "velocity = 0.0"),
        ({"velocity": 1.0, "acceleration": math.nan, "jerk": 1.0}, "acceleration = nan"),
        ({"velocity": 1.0, "acceleration": 1.0, "jerk": -5.0}, "jerk = -5.0"),
    ],
)
def test_bad_axis_limits_name_the_field(kwargs: dict[str, float], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        AxisLimits(**kwargs)


def test_bad_feed_and_missing_axis_are_named() -> None:
    with pytest.raises(ValueError, match="feed_mm_s = 0"):
        MotionLimits(LIMITS.x, LIMITS.y, LIMITS.z, 0)
    axes = dict(CONFIG.axes)
    del axes["Z"]
    with pytest.raises(ValueError, match="missing Z"):
        MotionLimits.from_axes(axes, 100.0)


@settings(max_examples=150, deadline=None)
@given(
    radius=st.floats(2.0, 20000.0),
    start_angle=st.floats(-math.pi, math.pi),
    sweep=st.floats(0.01, 6.0),
    feed=st.floats(5.0, 1000.0),
    state=st.tuples(
        st.floats(0.0, 1.0), st.floats(-1.0, 1.0), st.floats(-1.0, 1.0), st.floats(-1.0, 1.0)
    ),
)
def test_every_state_in_the_path_box_keeps_the_axes_in_their_limits(
    radius: float,
    start_angle: float,
    sweep: float,
    feed: float,
    state: tuple[float, float, float, float],
) -> None:
    piece = ArcPiece((0.0, 0.0), radius, start_angle, sweep, True)
    box = path_box(piece.bounds(), LIMITS.x, LIMITS.y, feed, feed * 1.2)
    assert box.nominal_velocity <= feed
    s = state[0] * piece.length_mm
    v, a, j = state[1] * box.velocity_cap, state[2] * box.acceleration, state[3] * box.jerk
    c1, c2, c3 = piece.derivatives(s)
    for axis, limits in enumerate((LIMITS.x, LIMITS.y)):
        velocity = c1[axis] * v
        acceleration = c1[axis] * a + c2[axis] * v * v
        jerk = c1[axis] * j + 3 * c2[axis] * v * a + c3[axis] * v**3
        assert abs(velocity) <= limits.velocity * (1 + 1e-9)
        assert abs(acceleration) <= limits.acceleration * (1 + 1e-9)
        assert abs(jerk) <= limits.jerk * (1 + 1e-9)


def test_a_line_box_is_exactly_the_projected_axis_limits() -> None:
    line = LinePiece((0.0, 0.0), (3.0, 4.0))  # direction (0.6, 0.8)
    box = path_box(line.bounds(), LIMITS.x, LIMITS.y, math.inf, math.inf)
    assert box.velocity_cap == pytest.approx(min(400 / 0.6, 300 / 0.8))
    assert box.acceleration == pytest.approx(2000 / 0.8)
    assert box.jerk == pytest.approx(20000 / 0.8)


def test_a_tight_arc_slows_the_feed_to_its_centripetal_limit() -> None:
    arc = ArcPiece((0.0, 0.0), 5.0, 0.0, math.pi, True)  # 5 mm radius, half a turn
    box = path_box(arc.bounds(), LIMITS.x, LIMITS.y, 120.0, 144.0)
    assert box.nominal_velocity < 120.0
    assert box.nominal_velocity**2 / 5.0 <= LIMITS.x.acceleration / 2 * (1 + 1e-12)
