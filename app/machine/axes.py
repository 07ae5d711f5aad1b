"""The three axes as the controller sees them: feedback of this period, command positions,
and the power requests that only operator actions may trigger.

Why command positions live here: whatever drives the axes this period (the path executor,
the jogger, homing, or nothing), one setpoint per axis is written every period. An axis that
is not enabled or is homing is commanded to where it is, so that enabling it later never
makes it jump (ros2_control issues 931 and 2318).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from app.config import AxisConfig
from app.drivers.cia402 import Cia402State
from app.drivers.contracts import AxisFeedback, MotionBackend


@dataclass
class AxisGroup:
    configs: Mapping[str, AxisConfig]
    motion: MotionBackend
    feedback: dict[str, AxisFeedback] = field(default_factory=dict)
    command: dict[str, float] = field(default_factory=dict)
    _enable_requested: set[str] = field(default_factory=set)

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(self.configs)

    def update(self, feedback: Mapping[str, AxisFeedback]) -> None:
        previous = self.feedback
        self.feedback = dict(feedback)
        for name, fb in self.feedback.items():
            before = previous.get(name)
            # Homing moves the encoder into the machine frame, possibly within one period
            # and in the period homing ends: the command follows the position until the
            # first period after homing, so the frame change never becomes a setpoint jump.
            frame_changed = before is not None and (
                before.homing_active or before.homed != fb.homed
            )
            if not fb.enabled or fb.homing_active or frame_changed or name not in self.command:
                self.command[name] = fb.position

    def position(self, name: str) -> float:
        return self.feedback[name].position

    def positions(self) -> tuple[float, float, float]:
        return (self.position("X"), self.position("Y"), self.position("Z"))

    def all_homed(self) -> bool:
        return bool(self.feedback) and all(fb.homed for fb in self.feedback.values())

    def all_enabled(self) -> bool:
        return bool(self.feedback) and all(fb.enabled for fb in self.feedback.values())

    def standing_still(self, tolerance: float = 1e-3) -> bool:
        return all(abs(fb.velocity) <= tolerance for fb in self.feedback.values())

    def request_enable(self) -> bool:
        """Ask every axis that is not enabled to enable; True once all are.

        Called only while carrying out an operator's command (Start, Home, a jog): a drive
        is never enabled by the machine on its own."""
        for name, fb in self.feedback.items():
            if fb.faulted:
                continue
            if not fb.enabled and (
                name not in self._enable_requested
                or fb.power_state is Cia402State.SWITCH_ON_DISABLED
            ):
                self.motion.enable(name)
                self._enable_requested.add(name)
        if self.all_enabled():
            self._enable_requested.clear()
            return True
        return False

    def quick_stop_all(self) -> None:
        """Every axis, whatever its state: a backend always takes a quick stop (the safe
        direction), and an axis still walking to enabled is stopped too."""
        self._enable_requested.clear()
        for name in self.feedback:
            self.motion.quick_stop(name)

    def disable_all(self) -> None:
        self._enable_requested.clear()
        for name in self.feedback:
            self.motion.disable(name)  # always accepted, in every state

    def fault_reset_all(self) -> None:
        for name, fb in self.feedback.items():
            if fb.faulted:
                self.motion.fault_reset(name)

    def hold_where_they_are(self) -> None:
        for name, fb in self.feedback.items():
            self.command[name] = fb.position

    def write(self) -> None:
        self.motion.write_setpoints(dict(self.command))
