"""Shared helpers for the planner and executor tests: reference staves, limits, and the
finite-difference checks every test applies to a setpoint stream."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.config import parse_config
from app.geometry.profile import solve_profile
from app.geometry.toolpath import ToolPath, ToolPathParams, build_toolpath
from app.machine.planner.limits import MotionLimits
from app.machine.planner.stave_plan import StavePlan, plan_stave

PERIOD_S = 0.004
CONFIG = parse_config({})
LIMITS = MotionLimits.from_axes(CONFIG.axes, CONFIG.process.feed_mm_s)
HOME = (0.0, 0.0, 0.0)
TOLERANCE = 1.01  # finite differences of the stream may reach the limit times this


def params(tilt_deg: float = 10.0, lead_mm: float = 60.0) -> ToolPathParams:
    p = CONFIG.process
    return ToolPathParams(
        tool_radius_mm=p.tool_radius_mm,
        machine_height_mm=p.machine_height_mm,
        tilt_deg=tilt_deg,
        start_x_mm=p.start_x_mm,
        start_y_mm=p.start_y_mm,
        lead_mm=lead_mm,
        home_x_mm=HOME[0],
        home_y_mm=HOME[1],
        home_z_deg=HOME[2],
        tilt_clearance_mm=p.tilt_clearance_mm,
    )


def toolpath(
    length_mm: float = 1000.0,
    width_mm: float = 150.0,
    lam: float = 0.25,
    k: float = 0.75,
    tilt_deg: float = 10.0,
) -> ToolPath:
    return build_toolpath(solve_profile(length_mm, width_mm, lam, k), params(tilt_deg))


def plan(
    length_mm: float = 1000.0,
    width_mm: float = 150.0,
    lam: float = 0.25,
    k: float = 0.75,
    tilt_deg: float = 10.0,
    limits: MotionLimits = LIMITS,
    start=HOME,
) -> StavePlan:
    return plan_stave(toolpath(length_mm, width_mm, lam, k, tilt_deg), start, limits)


@dataclass(frozen=True)
class Peaks:
    """Largest |v|, |a|, |j| per axis of a finite-differenced stream, as limit ratios."""

    velocity: np.ndarray
    acceleration: np.ndarray
    jerk: np.ndarray


def differences(xyz: np.ndarray, period_s: float = PERIOD_S):
    v = np.diff(xyz, axis=0) / period_s
    a = np.diff(v, axis=0) / period_s
    j = np.diff(a, axis=0) / period_s
    return v, a, j


def peaks(
    xyz: np.ndarray,
    limits: MotionLimits = LIMITS,
    period_s: float = PERIOD_S,
    jerk_mask: np.ndarray | None = None,
) -> Peaks:
    """Ratios to the limits; ``jerk_mask`` (len = len(xyz) - 3) excludes jerk samples."""
    v, a, j = differences(xyz, period_s)
    lim = np.array([[ax.velocity, ax.acceleration, ax.jerk] for ax in limits.axes])
    if jerk_mask is not None:
        j = j[jerk_mask]

    def peak(values: np.ndarray) -> np.ndarray:
        return np.abs(values).max(axis=0) if len(values) else np.zeros(3)

    return Peaks(peak(v) / lim[:, 0], peak(a) / lim[:, 1], peak(j) / lim[:, 2])


def jerk_mask(count: int, step_times: tuple[float, ...], period_s: float = PERIOD_S) -> np.ndarray:
    """True for jerk samples (third differences of ``count`` setpoints) whose window of four
    setpoints does not contain one of the declared curvature steps."""
    mask = np.ones(max(count - 3, 0), dtype=bool)
    for t in step_times:
        k = int(np.floor(t / period_s))
        mask[max(k - 3, 0) : k + 2] = False
    return mask


def assert_within_limits(
    xyz: np.ndarray,
    limits: MotionLimits = LIMITS,
    step_times: tuple[float, ...] = (),
    period_s: float = PERIOD_S,
) -> Peaks:
    result = peaks(xyz, limits, period_s, jerk_mask(len(xyz), step_times, period_s))
    assert np.all(result.velocity <= TOLERANCE), result
    assert np.all(result.acceleration <= TOLERANCE), result
    assert np.all(result.jerk <= TOLERANCE), result
    return result
