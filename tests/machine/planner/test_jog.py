"""Manual jog: stops at the soft limits (never beyond), stops on release, exact steps,
limits kept, only motion back into range after a trip, dead-man release."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.machine.planner.jog import Jogger, JogMode

from .support import CONFIG, PERIOD_S

X = CONFIG.axes["X"]
LOW, HIGH = 0.0, 500.0
V, A, J = 100.0, 500.0, 20000.0


def jogger(position: float = 250.0, **kwargs) -> Jogger:
    return Jogger("X", position, LOW, HIGH, V, A, J, max_acceleration=2000.0, **kwargs)


def run(jog: Jogger, periods: int) -> list[float]:
    return [jog.next_position(PERIOD_S) for _ in range(periods)]


def fd_peaks(positions: list[float]) -> tuple[float, float, float]:
    p = np.array(positions)
    v = np.diff(p) / PERIOD_S
    a = np.diff(v) / PERIOD_S
    j = np.diff(a) / PERIOD_S
    return float(np.abs(v).max()), float(np.abs(a).max()), float(np.abs(j).max())


@settings(max_examples=40, deadline=None)
@given(
    start=st.floats(LOW, HIGH),
    direction=st.sampled_from([1, -1]),
    velocity=st.floats(20.0, 400.0),
    acceleration=st.floats(10.0, 2000.0),
)
def test_continuous_jog_stops_exactly_at_the_soft_limit(
    start, direction, velocity, acceleration
) -> None:
    jog = jogger(start)
    jog.set_limits(velocity, acceleration)
    result = jog.press(direction)
    limit = HIGH if direction > 0 else LOW
    if abs(start - limit) < 1e-9:
        assert not result.accepted and "soft limit" in str(result.reason)
        return
    assert result.accepted
    trace = [start]
    while jog.moving:
        trace.append(jog.next_position(PERIOD_S))
        assert len(trace) < 20_000
    assert min(trace) >= LOW and max(trace) <= HIGH
    assert jog.position == limit and jog.velocity == 0.0
    if len(trace) > 3:
        v, a, j = fd_peaks(trace)
        assert v <= velocity * 1.001 and a <= acceleration * 1.01 and j <= J * 1.01


def test_release_decelerates_to_standstill_within_the_braking_distance() -> None:
    jog = jogger(100.0)
    jog.press(1)
    run(jog, 200)  # cruising at V by now
    assert jog.velocity == pytest.approx(V)
    at_release = jog.position
    jog.release()
    assert jog.mode is JogMode.STOPPING
    trace = run(jog, 200)
    assert not jog.moving and jog.velocity == 0.0
    assert trace[-1] == trace[-2]
    # V = 100 < A^2/J = 12.5? no: A^2/J = 12.5 < V, so a trapezoidal stop:
    braking = V / 2 * (V / A + A / J)
    assert jog.position - at_release == pytest.approx(braking, rel=1e-6)


def test_step_jog_is_exact_and_steps_add_up() -> None:
    jog = jogger(100.0)
    assert jog.step(0.1).accepted
    run(jog, 100)
    assert jog.position == 100.1 and not jog.moving
    jog.step(10.0)
    run(jog, 5)
    jog.step(-2.5)  # while the first step runs: targets add up
    run(jog, 400)
    assert jog.position == pytest.approx(107.6, abs=1e-12)


@settings(max_examples=40, deadline=None)
@given(start=st.floats(LOW, HIGH), distance=st.floats(-600.0, 600.0))
def test_a_step_ends_exactly_on_target_or_clipped_at_the_limit(start, distance) -> None:
    jog = jogger(start)
    result = jog.step(distance)
    expected = min(max(start + distance, LOW), HIGH)
    if not result.accepted:
        assert distance == 0.0 or abs(expected - start) < 1e-9
        assert result.reason
        return
    assert result.target == pytest.approx(expected, abs=1e-9)
    assert ("clipped" in str(result.reason)) == (expected != start + distance)
    trace = [start]
    while jog.moving:
        trace.append(jog.next_position(PERIOD_S))
    assert jog.position == result.target
    assert min(trace) >= LOW - 1e-9 and max(trace) <= HIGH + 1e-9


def test_after_a_trip_only_motion_back_into_range_is_accepted() -> None:
    jog = jogger(HIGH + 3.0)
    assert jog.tripped
    refused = jog.press(1)
    assert not refused.accepted and "only motion back" in str(refused.reason)
    assert not jog.step(1.0).accepted
    assert jog.step(-1.0).accepted
    run(jog, 200)
    assert jog.position == HIGH + 2.0
    assert jog.press(-1).accepted
    run(jog, 100)
    jog.release()
    run(jog, 100)
    assert not jog.tripped


def test_lowering_the_acceleration_while_fast_never_passes_the_limit() -> None:
    jog = jogger(HIGH - 60.0)
    jog.set_limits(400.0, 2000.0)
    jog.press(1)
    trace = run(jog, 40)
    jog.set_limits(400.0, 20.0)  # would need metres to stop
    trace += run(jog, 500)
    assert max(trace) <= HIGH
    assert jog.position == HIGH


def test_the_dead_man_releases_a_jog_that_is_not_renewed() -> None:
    jog = jogger(100.0, deadman_s=0.2)
    jog.press(1)
    for _ in range(100):  # renewed every 0.1 s: keeps running
        if _ % 25 == 0:
            jog.press(1)
        jog.next_position(PERIOD_S)
    assert jog.mode is JogMode.CONTINUOUS
    run(jog, 51)  # 0.204 s without renewal
    assert jog.mode is JogMode.STOPPING
    run(jog, 200)
    assert not jog.moving


def test_from_config_and_bad_input() -> None:
    jog = Jogger.from_axis_config(X, 0.0)
    assert jog.limits == (X.min_position, X.max_position)
    with pytest.raises(ValueError, match="direction = 0"):
        jog.press(0)
    with pytest.raises(ValueError, match="velocity = -1"):
        jog.set_limits(-1.0, 10.0)
    with pytest.raises(ValueError, match="distance = nan"):
        jog.step(math.nan)
    with pytest.raises(ValueError, match="max_position"):
        Jogger("X", 0.0, 10.0, 10.0, V, A, J)
    jog.press(1)
    with pytest.raises(ValueError, match="set_position while jogging"):
        jog.set_position(1.0)
    assert not jog.step(1.0).accepted
