"""From the system parameters (database) and the configuration to what geometry and the
planner take: one place that knows which parameter feeds which argument."""

from __future__ import annotations

from collections.abc import Mapping

from app.config import MachineConfig
from app.geometry.limits import StaveLimits
from app.machine.planner.limits import AxisLimits, MotionLimits


def config_parameters(config: MachineConfig) -> dict[str, float]:
    """The configuration's factory process values, under the database's parameter names."""
    p = config.process
    return {
        "tool_radius_mm": p.tool_radius_mm,
        "machine_height_mm": p.machine_height_mm,
        "start_x_mm": p.start_x_mm,
        "start_y_mm": p.start_y_mm,
        "xy_speed_mm_s": p.feed_mm_s,
        "lead_mm": p.lead_mm,
        "tilt_clearance_mm": p.tilt_clearance_mm,
        "home_x_mm": config.axes["X"].home_position,
        "home_y_mm": config.axes["Y"].home_position,
        "home_z_deg": config.axes["Z"].home_position,
    }


def stave_limits(config: MachineConfig) -> StaveLimits:
    """The stave limits of docs/MACHINE.md section 1 plus this machine's axis travel."""
    x, y, z = config.axes["X"], config.axes["Y"], config.axes["Z"]
    return StaveLimits(
        x_min_mm=x.min_position,
        x_max_mm=x.max_position,
        y_min_mm=y.min_position,
        y_max_mm=y.max_position,
        z_min_deg=z.min_position,
        z_max_deg=z.max_position,
    )


def motion_limits(config: MachineConfig, params: Mapping[str, float]) -> MotionLimits:
    """Axis limits from the configuration, tightened by the technician's parameters where
    those are lower: the configuration is what the mechanics allow, the parameters what the
    shop wants."""

    def axis(name: str, velocity_key: str, accel_key: str, jerk_key: str) -> AxisLimits:
        a = config.axes[name]
        return AxisLimits(
            velocity=min(a.max_velocity, params.get(velocity_key, a.max_velocity)),
            acceleration=min(a.max_acceleration, params.get(accel_key, a.max_acceleration)),
            jerk=min(a.max_jerk, params.get(jerk_key, a.max_jerk)),
        )

    return MotionLimits(
        x=axis("X", "xy_rapid_speed_mm_s", "xy_accel_mm_s2", "xy_jerk_mm_s3"),
        y=axis("Y", "xy_rapid_speed_mm_s", "xy_accel_mm_s2", "xy_jerk_mm_s3"),
        z=axis("Z", "z_speed_deg_s", "z_accel_deg_s2", "z_jerk_deg_s3"),
        feed_mm_s=params.get("xy_speed_mm_s", config.process.feed_mm_s),
    )


def jog_speeds(
    config: MachineConfig, params: Mapping[str, float]
) -> dict[str, tuple[float, float]]:
    """Manual jog speed and acceleration per group ("XY", "Z") from the Jogging parameters,
    never above what every axis of the group allows (the configuration's jog values stand in
    for a parameter the database does not have)."""

    def group(axes: tuple[str, ...], speed_key: str, accel_key: str) -> tuple[float, float]:
        first = config.axes[axes[0]]
        speed = params.get(speed_key, first.jog_velocity)
        accel = params.get(accel_key, first.jog_acceleration)
        return (
            min(speed, *(config.axes[a].max_velocity for a in axes)),
            min(accel, *(config.axes[a].max_acceleration for a in axes)),
        )

    return {
        "XY": group(("X", "Y"), "jog_xy_speed_mm_s", "jog_xy_accel_mm_s2"),
        "Z": group(("Z",), "jog_z_speed_deg_s", "jog_z_accel_deg_s2"),
    }
