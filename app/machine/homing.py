"""Homing one axis or all of them, one after the other, through the drives' homing method.

Why one at a time and in the order Z, Y, X: the tilt is brought upright first so that the
cutter cannot touch the table edge while Y and X travel to their switches; a single axis
moving at a time is also what a technician watching the machine expects.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

from app.config import AxisConfig
from app.machine.axes import AxisGroup
from app.machine.executor import PathExecutor
from app.machine.refusals import Reason, Refusal, refusal
from app.machine.snapshot import HomingView
from app.machine.supervision import fault_code_text

HOMING_ORDER: tuple[str, ...] = ("Z", "Y", "X")


class HomingFailed(Exception):
    def __init__(self, axis: str, detail: Refusal) -> None:
        super().__init__(str(detail))
        self.axis = axis
        self.detail = detail


def homing_timeout_s(config: AxisConfig) -> float:
    """The longest a correct homing can take: the whole travel at homing speed, there and
    back, plus the slow approach."""
    travel = config.max_position - config.min_position + 2 * config.limit_switch_margin
    return 2.5 * travel / config.homing_velocity + 5.0


@dataclass
class HomingSequence:
    axes_to_home: Sequence[str]
    configs: Mapping[str, AxisConfig]
    started_s: float
    _index: int = 0
    _phase: str = "enable"  # enable -> start -> running
    _phase_started_s: float = 0.0
    done: bool = False
    log: list[str] = field(default_factory=list)
    # With a board on the table: the move clear of it (spindle off) that comes first.
    clearance: PathExecutor | None = None

    @classmethod
    def for_axes(cls, axis: str, configs: Mapping[str, AxisConfig], now_s: float) -> HomingSequence:
        order = [a for a in HOMING_ORDER if not axis or a == axis]
        return cls(order, configs, now_s, _phase_started_s=now_s)

    @property
    def current_axis(self) -> str:
        return self.axes_to_home[self._index] if self._index < len(self.axes_to_home) else ""

    def view(self, now_s: float) -> HomingView:
        """This run as the snapshot carries it."""
        return HomingView(
            tuple(self.axes_to_home),
            tuple(self.axes_to_home[: self._index]),
            self.current_axis,
            self.clearance is not None,
            now_s - self.started_s,
        )

    def _next_phase(self, phase: str, now_s: float) -> None:
        self._phase = phase
        self._phase_started_s = now_s

    def _clear(self, now_s: float, axes: AxisGroup) -> None:
        assert self.clearance is not None
        if not axes.request_enable():
            if now_s - self._phase_started_s > 2.0:
                raise HomingFailed(
                    self.current_axis,
                    refusal(Reason.DRIVE_DID_NOT_ENABLE_DETAIL, self.current_axis, 2),
                )
            return
        out = self.clearance.step()
        axes.command.update({"X": out.x, "Y": out.y, "Z": out.z})
        if out.done:
            self.log.append(f"moved clear of the board to X {out.x:.1f} Y {out.y:.1f}")
            self.clearance = None
            self._next_phase("enable", now_s)

    def tick(self, now_s: float, axes: AxisGroup) -> None:
        """Advance; raises HomingFailed on a timeout or a drive that refuses."""
        if self.done:
            return
        if self.clearance is not None:
            self._clear(now_s, axes)
            return
        name = self.current_axis
        feedback = axes.feedback[name]
        waited_s = now_s - self._phase_started_s
        if feedback.faulted:
            raise HomingFailed(
                name,
                refusal(
                    Reason.DRIVE_FAULT_WHILE_HOMING, name, fault_code_text(feedback.fault_code)
                ),
            )
        if self._phase == "enable":
            if axes.request_enable():
                axes.motion.start_homing(name)
                self._next_phase("start", now_s)
            elif waited_s > 2.0:
                raise HomingFailed(name, refusal(Reason.DRIVE_DID_NOT_ENABLE_DETAIL, name, 2))
        elif self._phase == "start":
            if feedback.homing_active:
                self._next_phase("running", now_s)
            elif waited_s > 1.0:
                raise HomingFailed(name, refusal(Reason.HOMING_DID_NOT_START, name, 1))
        elif self._phase == "running":
            if not feedback.homing_active and feedback.homed:
                self.log.append(f"{name} homed at {feedback.position:.3f}")
                self._index += 1
                if self._index >= len(self.axes_to_home):
                    self.done = True
                else:
                    self._next_phase("enable", now_s)
            elif not feedback.homing_active:
                raise HomingFailed(name, refusal(Reason.HOME_SWITCH_NOT_FOUND, name))
            elif waited_s > homing_timeout_s(self.configs[name]):
                raise HomingFailed(name, refusal(Reason.HOMING_TIMEOUT, name, f"{waited_s:.0f}"))
