"""Manual jog of one axis: continuous jog while a button is held, step jog, soft limits.

Why a continuous jog is planned as a move *to the soft limit*: the operator holds the
button and the axis runs at the jog velocity; if the button is still held as the limit
nears, the axis must decelerate and stop exactly at the limit, never beyond. A time-optimal
jerk-limited position move (ruckig) with the soft limit as its target does precisely that:
it cruises at the jog velocity and brakes just in time. Releasing the button replaces it
by the shortest jerk-limited deceleration to rest (ruckig, velocity interface). A step jog
is a position move to the current position plus the step (clipped to the limits), and ends
exactly on it.

After a limit trip (the axis stands outside its soft limits, e.g. after a setup change or
a move under another controller) only motion back toward the allowed range is accepted.

Optional dead-man: with ``deadman_s`` set, a continuous jog must be renewed by calling
``press`` again (same direction) at least every ``deadman_s`` seconds of ``next_position``
time, or it is released: a lost link or a stuck screen cannot keep an axis running.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ruckig import ControlInterface, InputParameter
from ruckig import Trajectory as RuckigTrajectory

from app.machine.planner.otg import calculate
from app.machine.planner.trajectory import PlannerError
from app.machine.refusals import Reason, Refusal, refusal

if TYPE_CHECKING:
    from app.config import AxisConfig

_LIMIT_TOLERANCE = 1e-9
"""Positions this close to a soft limit count as at the limit (axis units)."""


def ramp_distance(velocity: float, acceleration: float, jerk: float) -> float:
    """How far a jerk-limited ramp runs from ``velocity`` to rest (or from rest up to it):
    the velocity times half the ramp's time, the acceleration phases included."""
    if velocity * jerk >= acceleration * acceleration:
        return velocity / 2.0 * (velocity / acceleration + acceleration / jerk)
    return velocity * math.sqrt(velocity / jerk)  # the ramp never reaches the acceleration


class JogMode(enum.Enum):
    IDLE = "idle"
    CONTINUOUS = "continuous"
    STEP = "step"
    STOPPING = "stopping"


@dataclass(frozen=True)
class JogResult:
    """The answer to a jog request: accepted or not, the target, and why (for the screen)."""

    accepted: bool
    target: float | None
    reason: Refusal | None = None


def _finite(name: str, value: float, *, positive: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise ValueError(
            f"{name} = {value!r} is not allowed: a finite number" + (" > 0" if positive else "")
        )
    if positive and value <= 0.0:
        raise ValueError(f"{name} = {value!r} is not allowed: a finite number > 0")
    return float(value)


class Jogger:
    """Jog generator for one axis; ``next_position`` is called once per period."""

    def __init__(
        self,
        axis: str,
        position: float,
        min_position: float,
        max_position: float,
        velocity: float,
        acceleration: float,
        jerk: float,
        *,
        max_acceleration: float | None = None,
        deadman_s: float | None = None,
    ) -> None:
        self.axis = axis
        self._min = _finite("min_position", min_position)
        self._max = _finite("max_position", max_position)
        if self._max <= self._min:
            raise ValueError(
                f"max_position = {max_position!r} is not allowed: greater than "
                f"min_position ({min_position!r})"
            )
        self._jerk = _finite("jerk", jerk, positive=True)
        self._velocity = _finite("velocity", velocity, positive=True)
        self._acceleration = _finite("acceleration", acceleration, positive=True)
        self._max_acceleration = _finite(
            "max_acceleration",
            acceleration if max_acceleration is None else max_acceleration,
            positive=True,
        )
        self._deadman_s = (
            None if deadman_s is None else _finite("deadman_s", deadman_s, positive=True)
        )
        self._state = (_finite("position", position), 0.0, 0.0)
        self._trajectory: RuckigTrajectory | None = None
        self._t_s = 0.0
        self._mode = JogMode.IDLE
        self._direction = 0
        self._target: float | None = None
        self._since_press_s = 0.0

    @classmethod
    def from_axis_config(
        cls, config: AxisConfig, position: float, *, deadman_s: float | None = None
    ) -> Jogger:
        """A jogger at the configured jog velocity/acceleration, the axis jerk and soft
        limits; the axis' max acceleration is the reserve for braking after a lowered
        jog acceleration."""
        return cls(
            config.name,
            position,
            config.min_position,
            config.max_position,
            config.jog_velocity,
            config.jog_acceleration,
            config.max_jerk,
            max_acceleration=config.max_acceleration,
            deadman_s=deadman_s,
        )

    # -- state -----------------------------------------------------------------------------
    @property
    def position(self) -> float:
        return self._state[0]

    @property
    def velocity(self) -> float:
        return self._state[1]

    @property
    def acceleration(self) -> float:
        return self._state[2]

    @property
    def mode(self) -> JogMode:
        return self._mode

    @property
    def moving(self) -> bool:
        return self._mode is not JogMode.IDLE

    @property
    def velocity_limit(self) -> float:
        """The jog velocity now in force."""
        return self._velocity

    @property
    def limits(self) -> tuple[float, float]:
        return (self._min, self._max)

    @property
    def tripped(self) -> bool:
        """True while the axis stands outside its soft limits."""
        p = self.position
        return p < self._min - _LIMIT_TOLERANCE or p > self._max + _LIMIT_TOLERANCE

    # -- commands --------------------------------------------------------------------------
    def set_limits(self, velocity: float, acceleration: float) -> None:
        """Jog velocity and acceleration (the Manual screen's values); a move in progress
        continues with them at once."""
        self._velocity = _finite("velocity", velocity, positive=True)
        self._acceleration = _finite("acceleration", acceleration, positive=True)
        if self._mode in (JogMode.CONTINUOUS, JogMode.STEP) and self._target is not None:
            self._plan_to(self._target)

    def set_position(self, position: float) -> None:
        """Take over the measured position (at rest only: entering manual mode)."""
        if self.moving:
            raise ValueError(f"axis {self.axis}: set_position while jogging is not allowed")
        self._state = (_finite("position", position), 0.0, 0.0)

    def press(self, direction: int, stop_at: float | None = None) -> JogResult:
        """Start (or keep alive) a continuous jog in ``direction`` (+1 or -1); it runs to the
        soft limit, or to ``stop_at`` if that comes first (the board's keep-out)."""
        if direction not in (1, -1):
            raise ValueError(f"direction = {direction!r} is not allowed: +1 or -1")
        if self._mode is JogMode.CONTINUOUS and self._direction == direction:
            self._since_press_s = 0.0
            return JogResult(True, self._target)
        refused = self._refuse_outward(direction)
        if refused:
            return JogResult(False, None, refused)
        target = self._max if direction > 0 else self._min
        if stop_at is not None:
            target = min(target, stop_at) if direction > 0 else max(target, stop_at)
        self._mode = JogMode.CONTINUOUS
        self._direction = direction
        self._since_press_s = 0.0
        self._plan_to(target)
        return JogResult(True, target)

    def release(self) -> None:
        """End a continuous jog: decelerate to standstill (a step jog runs to its end)."""
        if self._mode is JogMode.CONTINUOUS:
            self.stop()

    def stop(self) -> None:
        """Decelerate any jog to standstill at once."""
        if self._mode in (JogMode.IDLE, JogMode.STOPPING):
            return
        inp = self._input()
        inp.control_interface = ControlInterface.Velocity
        inp.max_velocity = [max(self._velocity, abs(self.velocity))]
        inp.target_velocity = [0.0]
        self._start(inp)
        self._mode = JogMode.STOPPING
        self._target = None

    def step(self, distance: float) -> JogResult:
        """Step jog by ``distance`` (axis units) from where the axis is (or, while a step is
        running, from that step's target). Clipped at the soft limits, with the reason."""
        distance = _finite("distance", distance)
        if distance == 0.0:
            return JogResult(False, None, Refusal(Reason.STEP_OF_ZERO))
        if self._mode in (JogMode.CONTINUOUS, JogMode.STOPPING):
            return JogResult(False, None, refusal(Reason.RELEASE_JOG_FIRST, self.axis))
        base = self.step_base
        return self._step_to(base, base + distance, 1 if distance > 0.0 else -1)

    @property
    def step_base(self) -> float:
        """Where a step starts from: the running step's target, else the position."""
        if self._mode is JogMode.STEP and self._target is not None:
            return self._target
        return self.position

    def move_to(self, target: float) -> JogResult:
        """A step jog to ``target`` itself (the handwheel: its position is a whole number of
        increments from where it started, never a sum of rounded steps). Clipped at the soft
        limits like a step, with the reason."""
        target = _finite("target", target)
        if self._mode in (JogMode.CONTINUOUS, JogMode.STOPPING):
            return JogResult(False, None, refusal(Reason.RELEASE_JOG_FIRST, self.axis))
        base = self.step_base
        if target == base:
            return JogResult(True, target)
        return self._step_to(base, target, 1 if target > base else -1)

    def _step_to(self, base: float, target: float, direction: int) -> JogResult:
        refused = self._refuse_outward(direction)
        if refused:
            return JogResult(False, None, refused)
        reason = None
        if target > self._max and direction > 0:
            target = max(self._max, base)
            reason = refusal(Reason.CLIPPED_TO_UPPER_SOFT_LIMIT, self._max)
        elif target < self._min and direction < 0:
            target = min(self._min, base)
            reason = refusal(Reason.CLIPPED_TO_LOWER_SOFT_LIMIT, self._min)
        if target == base:
            return JogResult(False, None, refusal(Reason.AT_SOFT_LIMIT, self.axis))
        self._mode = JogMode.STEP
        self._direction = direction
        self._plan_to(target)
        return JogResult(True, target, reason)

    def next_position(self, dt_s: float) -> float:
        """Advance by ``dt_s`` (one period) and return the position setpoint."""
        dt_s = _finite("dt_s", dt_s, positive=True)
        if self._trajectory is None:
            return self.position
        if self._deadman_s is not None and self._mode is JogMode.CONTINUOUS:
            self._since_press_s += dt_s
            if self._since_press_s > self._deadman_s:
                self.stop()
        assert self._trajectory is not None
        self._t_s += dt_s
        duration = float(self._trajectory.duration)
        if self._t_s >= duration:
            end = (
                self._target
                if self._target is not None and self._mode is not JogMode.STOPPING
                else None
            )
            p, v, a = self._trajectory.at_time(duration)
            self._state = (end if end is not None else p[0], 0.0, 0.0)
            self._trajectory = None
            self._mode = JogMode.IDLE
            self._target = None
            return self.position
        p, v, a = self._trajectory.at_time(self._t_s)
        self._state = (p[0], v[0], a[0])
        return self.position

    # -- internals -------------------------------------------------------------------------
    def _refuse_outward(self, direction: int) -> Refusal | None:
        p = self.position
        if direction > 0 and p >= self._max - _LIMIT_TOLERANCE:
            if p > self._max + _LIMIT_TOLERANCE:
                return refusal(Reason.BEYOND_UPPER_SOFT_LIMIT, self.axis, self._max, f"{p:.3f}")
            return refusal(Reason.AT_UPPER_SOFT_LIMIT, self.axis, self._max)
        if direction < 0 and p <= self._min + _LIMIT_TOLERANCE:
            if p < self._min - _LIMIT_TOLERANCE:
                return refusal(Reason.BEYOND_LOWER_SOFT_LIMIT, self.axis, self._min, f"{p:.3f}")
            return refusal(Reason.AT_LOWER_SOFT_LIMIT, self.axis, self._min)
        return None

    def _input(self, acceleration: float | None = None) -> InputParameter:
        inp = InputParameter(1)
        p, v, a = self._state
        inp.current_position = [p]
        inp.current_velocity = [v]
        inp.current_acceleration = [a]
        inp.max_velocity = [self._velocity]
        inp.max_acceleration = [acceleration or max(self._acceleration, abs(a))]
        inp.max_jerk = [self._jerk]
        return inp

    def _start(self, inp: InputParameter) -> None:
        try:
            self._trajectory = calculate(inp, f"axis {self.axis}: jog")
        except PlannerError as exc:
            raise ValueError(str(exc)) from exc
        self._t_s = 0.0

    def _plan_to(self, target: float) -> None:
        """Position move to ``target``; if braking at the jog acceleration would run beyond
        the soft limits (the jog acceleration was just lowered while moving fast), brake
        harder, up to the axis' maximum acceleration."""
        self._target = target
        for acceleration in (None, self._max_acceleration):
            inp = self._input(acceleration)
            inp.control_interface = ControlInterface.Position
            inp.target_position = [target]
            inp.target_velocity = [0.0]
            inp.target_acceleration = [0.0]
            self._start(inp)
            assert self._trajectory is not None
            extrema = self._trajectory.position_extrema[0]
            low = min(self._min, self.position, target) - _LIMIT_TOLERANCE
            high = max(self._max, self.position, target) + _LIMIT_TOLERANCE
            if low <= extrema.min and extrema.max <= high:
                return
