"""A test rig for the simulated machine: a configuration built from the shipped machine.toml
with overrides, the backend activated, and the loop a machine layer would run (write the
setpoints, advance one period, read the feedback), all on the simulated clock."""

from __future__ import annotations

import math
import tomllib
from collections.abc import Callable, Mapping
from typing import Any

from app.config import MachineConfig, default_config_path, parse_config
from app.drivers.cia402 import Cia402State
from app.drivers.contracts import AxisFeedback
from app.drivers.sim.backend import SimIO, SimMotion, create_backend
from app.drivers.sim.faults import SimFaultInjector
from app.drivers.sim.world import SimWorld

# The axis values these tests are written against, pinned so that a change of the shipped
# machine.toml (travel, switch positions) does not silently change what a test checks.
PINNED_AXES: dict[str, dict[str, Any]] = {
    "X": {
        "min_position": -5.0,
        "max_position": 3900.0,
        "home_switch_position": -5.0,
        "limit_switch_margin": 5.0,
        "homing_direction": -1,
        "homing_velocity": 40.0,
        "max_velocity": 400.0,
        "max_acceleration": 2000.0,
        "jog_acceleration": 500.0,
        "following_error_limit": 2.0,
        "encoder": "incremental",
        "home_position": 0.0,
    },
    "Y": {
        "min_position": -5.0,
        "max_position": 800.0,
        "home_switch_position": -5.0,
        "limit_switch_margin": 5.0,
        "homing_direction": -1,
        "homing_velocity": 30.0,
        "max_velocity": 300.0,
        "max_acceleration": 2000.0,
        "jog_acceleration": 500.0,
        "following_error_limit": 2.0,
        "encoder": "incremental",
        "home_position": 0.0,
    },
    "Z": {
        "min_position": -15.0,
        "max_position": 15.0,
        "home_switch_position": -15.0,
        "limit_switch_margin": 2.0,
        "homing_direction": -1,
        "homing_velocity": 3.0,
        "max_velocity": 30.0,
        "max_acceleration": 150.0,
        "jog_acceleration": 40.0,
        "following_error_limit": 0.5,
        "encoder": "absolute",
        "home_position": 0.0,
    },
}


def make_config(
    sim: Mapping[str, Any] | None = None,
    gauge: Mapping[str, Any] | None = None,
    axes: Mapping[str, Mapping[str, Any]] | None = None,
    io: Mapping[str, Any] | None = None,
    period_ms: float | None = None,
) -> MachineConfig:
    """The shipped configuration, axes pinned to :data:`PINNED_AXES`, with some tables
    overridden (keys merged per table)."""
    data = tomllib.loads(default_config_path().read_text(encoding="utf-8"))
    data["backend"]["sim"] = dict(sim or {})
    data["gauge"]["sim"] = dict(gauge or {})
    for name, values in PINNED_AXES.items():
        data["axes"][name].update(values)
    for name, values in (axes or {}).items():
        data["axes"][name].update(values)
    data["io"].update(io or {})
    if period_ms is not None:
        data["backend"]["period_ms"] = period_ms
    return parse_config(data, "test")


# Start positions well inside the travel, so that a test moves freely.
CENTRE = {"X": 1000.0, "Y": 300.0, "Z": 0.0}


class Rig:
    """The simulated machine, active, driven period by period like the machine loop does."""

    def __init__(self, config: MachineConfig) -> None:
        self.config = config
        backend = create_backend(config)
        assert isinstance(backend.motion, SimMotion) and isinstance(backend.io, SimIO)
        self.backend = backend
        self.motion: SimMotion = backend.motion
        self.io: SimIO = backend.io
        world = backend.extras["world"]
        faults = backend.extras["faults"]
        assert isinstance(world, SimWorld) and isinstance(faults, SimFaultInjector)
        self.world = world
        self.faults = faults
        self.period_s = config.period_s
        self.motion.activate()
        self.io.activate()
        self.command = {name: fb.position for name, fb in self.motion.read_axes().items()}

    @classmethod
    def centred(cls, **sim: Any) -> Rig:
        """Absolute encoders on X and Y too, all axes started mid-travel."""
        settings = {"start_position": dict(CENTRE), **sim}
        return cls(
            make_config(settings, axes={"X": {"encoder": "absolute"}, "Y": {"encoder": "absolute"}})
        )

    def fb(self, axis: str) -> AxisFeedback:
        return self.motion.read_axes()[axis]

    def tick(self, periods: int = 1) -> None:
        """Periods of the machine loop: command the axes, advance, read back; an axis that
        is not enabled, or homes, is commanded where it is (as the machine layer does)."""
        for _ in range(periods):
            self.motion.write_setpoints(self.command)
            self.motion.advance(self.period_s)
            for name, fb in self.motion.read_axes().items():
                if not fb.enabled or fb.homing_active:
                    self.command[name] = fb.position

    def run(self, seconds: float) -> None:
        self.tick(round(seconds / self.period_s))

    def run_until(self, condition: Callable[[], bool], timeout_s: float) -> float:
        """Tick until ``condition()``; returns the simulated time it took."""
        start = self.world.time_s
        while not condition():
            if self.world.time_s - start > timeout_s:
                raise AssertionError(f"not reached within {timeout_s} s")
            self.tick()
        return self.world.time_s - start

    def enable(self, *axes: str) -> None:
        for axis in axes or self.motion.axis_names:
            self.motion.enable(axis)
        self.run_until(lambda: all(self.fb(a).enabled for a in axes or self.motion.axis_names), 0.2)

    def move(
        self,
        axis: str,
        distance: float,
        velocity: float,
        acceleration: float,
        record: Callable[[AxisFeedback], None] | None = None,
    ) -> None:
        """A trapezoidal move of the command by ``distance`` (sign = direction)."""
        start = self.command[axis]
        for position in trapezoid(distance, velocity, acceleration, self.period_s):
            self.command[axis] = start + position
            self.tick()
            if record is not None:
                record(self.fb(axis))

    def state(self, axis: str) -> Cia402State:
        return self.fb(axis).power_state


def trapezoid(
    distance: float, velocity: float, acceleration: float, period_s: float
) -> list[float]:
    """Positions (from 0) of a move with trapezoidal velocity, one per period."""
    sign = 1.0 if distance >= 0 else -1.0
    length = abs(distance)
    ramp = velocity * velocity / acceleration
    if ramp > length:  # triangle
        velocity = math.sqrt(length * acceleration)
        ramp = length
    t_acc = velocity / acceleration
    t_total = 2 * t_acc + (length - ramp) / velocity
    positions = []
    n = math.ceil(t_total / period_s)
    for i in range(1, n + 1):
        t = min(i * period_s, t_total)
        if t < t_acc:
            s = 0.5 * acceleration * t * t
        elif t < t_total - t_acc:
            s = 0.5 * acceleration * t_acc * t_acc + velocity * (t - t_acc)
        else:
            r = t_total - t
            s = length - 0.5 * acceleration * r * r
        positions.append(sign * s)
    return positions
