"""Manual mode: continuous and step jog per axis, with a dead-man on the screen's refresh.

Why a dead-man here: the screen repeats JogContinuous while the button is held. If the
release is lost (a glove slides off the panel, the link hiccups, the GUI freezes), no refresh
arrives and the axis stops after JOG_DEADMAN_S on its own (the single most requested jog
behaviour in the CNC HMI issue trackers).

Jog speed and acceleration are manual mode's own, set for X-Y together and for Z by the
System screen's Jogging parameters (the Manual screen edits the same parameters), and never
change the automatic ones. The motion itself (jerk-limited, soft limits, back out of a limit
only in the safe direction) is the planner's :class:`~app.machine.planner.jog.Jogger`.
"""

from __future__ import annotations

from collections.abc import Mapping

from app.config import AxisConfig
from app.machine.axes import AxisGroup
from app.machine.commands import JOG_DEADMAN_S
from app.machine.planner.jog import Jogger, JogMode, ramp_distance
from app.machine.planner.jog_keepout import jog_reach
from app.machine.planner.keepout import TableKeepOut
from app.machine.refusals import Reason, Refusal, refusal

GROUPS: dict[str, tuple[str, ...]] = {"XY": ("X", "Y"), "Z": ("Z",)}
_AT_KEEP_OUT = 1e-6  # a jog with less room than this toward the board is refused
MIN_SPEED_FRACTION = 0.01  # a stick just outside its deadband still moves (1 % of jog speed)
SPEED_CHANGE_FRACTION = 0.01  # the jog is replanned when the stick's speed changes this much


class ManualControl:
    def __init__(self, configs: Mapping[str, AxisConfig]) -> None:
        self._configs = configs
        self._joggers: dict[str, Jogger] = {
            name: Jogger.from_axis_config(cfg, cfg.home_position) for name, cfg in configs.items()
        }
        self._speeds: dict[str, tuple[float, float]] = {
            "XY": (configs["X"].jog_velocity, configs["X"].jog_acceleration),
            "Z": (configs["Z"].jog_velocity, configs["Z"].jog_acceleration),
        }
        self._last_refresh_s: dict[str, float] = {}
        self._holds: dict[str, int] = {}  # the hold each continuous jog belongs to
        self._ended_holds: dict[str, int] = {}  # the last hold the dead-man ended, per axis
        self.keep_out: TableKeepOut | None = None  # the board on the table (None: none there)

    def speed(self, group: str) -> tuple[float, float]:
        return self._speeds[group]

    def set_speeds(self, speeds: Mapping[str, tuple[float, float]]) -> None:
        """Jog speed and acceleration per group ("XY", "Z"), from the Jogging parameters
        (see :func:`app.machine.process_params.jog_speeds`, which keeps them within what the
        axes allow)."""
        for group, (velocity, acceleration) in speeds.items():
            self._speeds[group] = (velocity, acceleration)
            for name in GROUPS[group]:
                self._joggers[name].set_limits(velocity, acceleration)

    def _reset(self, name: str, position: float) -> None:
        """The jogger of ``name`` takes over the measured position, abandoning any motion
        (used where the drive is not following setpoints anyway)."""
        jogger = self._joggers[name]
        if jogger.moving:
            velocity, acceleration = self._speeds["Z" if name == "Z" else "XY"]
            jogger = Jogger.from_axis_config(self._configs[name], position)
            jogger.set_limits(velocity, acceleration)
            self._joggers[name] = jogger
        else:
            jogger.set_position(position)

    def sync(self, axes: AxisGroup) -> None:
        """Start every jogger from where its axis is (entering manual, after homing)."""
        for name in self._joggers:
            if name in axes.feedback:
                self._reset(name, axes.position(name))

    def _check_axis(self, axis: str, axes: AxisGroup) -> Refusal | None:
        """Refuse an unknown axis; ask the drives to enable (the jog is the operator's
        action that allows it; the motion starts once they are enabled)."""
        if axis not in self._joggers:
            return refusal(Reason.AXIS_UNKNOWN, repr(axis))
        axes.request_enable()
        return None

    @staticmethod
    def _toward_active_switch(axis: str, direction: int, axes: AxisGroup) -> Refusal | None:
        """After a limit trip the axis may only be jogged away from the switch."""
        fb = axes.feedback.get(axis)
        if fb is not None and fb.limit_positive and direction > 0:
            return refusal(Reason.LIMIT_SWITCH_POSITIVE, axis)
        if fb is not None and fb.limit_negative and direction < 0:
            return refusal(Reason.LIMIT_SWITCH_NEGATIVE, axis)
        return None

    def press(
        self,
        axis: str,
        direction: int,
        now_s: float,
        axes: AxisGroup,
        hold: int = 0,
    ) -> Refusal | None:
        if axis in self._ended_holds and hold and self._ended_holds[axis] == hold:
            # A refresh of a hold the dead-man ended (a frozen screen catching up): only a
            # new press starts the axis again.
            return refusal(Reason.JOG_HOLD_ENDED, axis, JOG_DEADMAN_S)
        if reason := self._check_axis(axis, axes):
            return reason
        if direction not in (-1, 1):
            return refusal(Reason.JOG_DIRECTION_INVALID, direction)
        if reason := self._toward_active_switch(axis, direction, axes):
            return reason
        jogger = self._joggers[axis]
        limit = jogger.limits[1] if direction > 0 else jogger.limits[0]
        stop_at = self._reach(axis, limit)
        if stop_at is not None and abs(stop_at - jogger.position) < _AT_KEEP_OUT:
            return refusal(Reason.JOG_AT_BOARD, axis)
        self._last_refresh_s[axis] = now_s
        self._holds[axis] = hold
        refused = jogger.press(direction, stop_at).reason
        if refused is None and stop_at is not None:
            return refusal(Reason.JOG_STOPS_AT_BOARD, axis, f"{stop_at:.1f}")
        return refused

    def _reach(self, axis: str, target: float) -> float | None:
        """Where the board's keep-out cuts a jog of ``axis`` toward ``target`` short (None:
        no board, or the way is clear)."""
        if self.keep_out is None or not all(n in self._joggers for n in ("X", "Y", "Z")):
            return None
        xyz = tuple(self._joggers[n].position for n in ("X", "Y", "Z"))
        reach = jog_reach(self.keep_out, xyz, axis, target)
        return None if reach == target else reach

    def step(self, axis: str, distance: float, axes: AxisGroup) -> Refusal | None:
        if reason := self._check_axis(axis, axes):
            return reason
        if reason := self._toward_active_switch(axis, 1 if distance > 0 else -1, axes):
            return reason
        target = self._joggers[axis].step_base + distance
        if (reach := self._reach(axis, target)) is not None:
            return refusal(Reason.JOG_STEP_INTO_BOARD, axis, f"{reach:.1f}")
        result = self._joggers[axis].step(distance)
        return None if result.accepted else result.reason

    def follow(self, axis: str, target: float, axes: AxisGroup) -> tuple[float, Refusal | None]:
        """Move ``axis`` to ``target`` with the jog ramp (the handwheel); the same soft limits,
        limit-switch rule and board keep-out as the screen's jog (the wheel stops at the
        board's edge, as a held jog does). Returns the target taken (clipped at a soft limit
        or the keep-out, or where the axis already goes when refused) and why, if not all."""
        jogger = self._joggers.get(axis)
        if jogger is None:
            return target, refusal(Reason.AXIS_UNKNOWN, repr(axis))
        base = jogger.step_base
        if target == base:
            return target, None
        axes.request_enable()
        if reason := self._toward_active_switch(axis, 1 if target > base else -1, axes):
            return base, reason
        stopped: Refusal | None = None
        if (reach := self._reach(axis, target)) is not None:  # the board's keep-out
            if abs(reach - jogger.position) < _AT_KEEP_OUT:
                return base, refusal(Reason.JOG_AT_BOARD, axis)
            target, stopped = reach, refusal(Reason.JOG_STOPS_AT_BOARD, axis, f"{reach:.1f}")
        result = jogger.move_to(target)
        if not result.accepted or result.target is None:
            return base, result.reason
        return result.target, result.reason or stopped

    def drive(self, axis: str, fraction: float, now_s: float, axes: AxisGroup) -> Refusal | None:
        """Jog ``axis`` at ``fraction`` (-1..1) of its jog velocity (a joystick): a
        continuous jog whose speed follows the stick; 0 releases it."""
        jogger = self._joggers.get(axis)
        if jogger is None:
            return refusal(Reason.AXIS_UNKNOWN, repr(axis))
        velocity, acceleration = self._speeds["Z" if axis == "Z" else "XY"]
        if fraction == 0.0:
            if jogger.mode is JogMode.CONTINUOUS:
                jogger.release()
                self._last_refresh_s.pop(axis, None)
            jogger.set_limits(velocity, acceleration)
            return None
        speed = max(abs(fraction), MIN_SPEED_FRACTION) * velocity
        if abs(speed - jogger.velocity_limit) > SPEED_CHANGE_FRACTION * velocity:
            jogger.set_limits(speed, acceleration)
        return self.press(axis, 1 if fraction > 0 else -1, now_s, axes)

    def stopping_distance(self, axis: str) -> float:
        """How far ``axis`` runs when braking from its jog velocity on the jog ramp."""
        velocity, acceleration = self._speeds["Z" if axis == "Z" else "XY"]
        return ramp_distance(velocity, acceleration, self._configs[axis].max_jerk)

    def position(self, axis: str) -> float:
        """Where the jog has the axis now (its setpoint)."""
        return self._joggers[axis].position

    def jog_target(self, axis: str) -> float:
        """Where the axis's jog ends: a running step's target, else where it is."""
        return self._joggers[axis].step_base

    @property
    def at_rest(self) -> bool:
        return not any(jogger.moving for jogger in self._joggers.values())

    def release(self, axis: str = "") -> None:
        for name, jogger in self._joggers.items():
            if not axis or axis == name:
                jogger.release()
                self._last_refresh_s.pop(name, None)

    def release_all(self, immediate: bool = False) -> None:
        """Stop every jog: decelerating, or (``immediate``, the drives are being stopped by
        the controller) abandoned where the setpoints are."""
        for name, jogger in list(self._joggers.items()):
            if immediate:
                self._reset(name, jogger.position)
            else:
                jogger.stop()
        self._last_refresh_s.clear()

    def tick(self, now_s: float, period_s: float, axes: AxisGroup) -> str:
        """Advance every jogger by one period; returns an axis name whose dead-man expired."""
        expired = ""
        for name, last_s in list(self._last_refresh_s.items()):
            if now_s - last_s > JOG_DEADMAN_S:
                self._joggers[name].release()
                del self._last_refresh_s[name]
                self._ended_holds[name] = self._holds.pop(name, 0)
                expired = name
        enabled = axes.all_enabled()
        for name, jogger in self._joggers.items():
            if name not in axes.feedback:
                continue
            if not enabled:
                if jogger.moving:
                    axes.request_enable()
                    continue
                self._reset(name, axes.position(name))
                continue
            axes.command[name] = jogger.next_position(period_s)
        return expired
