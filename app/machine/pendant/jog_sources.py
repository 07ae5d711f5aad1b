"""The machine's own jog controls, read once per period and arbitrated with the screen.

Why one place: the handwheel, the joystick and a USB pendant each turn inputs into jog
commands for :class:`~app.machine.manual.ManualControl` (the screen jog's own code, so the
soft limits, the limit-switch rule and the dead-man are the same), and
:class:`~app.machine.pendant.arbitration.JogArbiter` decides which of them (or the screen)
may. Outside manual mode nothing of this moves anything; a control that is touched then
says once that it is ignored. Messages are said once per touch, not every period.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.config import MachineConfig
from app.drivers.contracts import InputImage, PendantDevice, PendantReading
from app.machine.axes import AxisGroup
from app.machine.manual import ManualControl
from app.machine.pendant.arbitration import JogArbiter
from app.machine.pendant.handwheel import Handwheel, WheelFollower, WheelSelection
from app.machine.pendant.joystick import Joystick, shaped
from app.machine.refusals import Reason, Refusal, refusal
from app.machine.snapshot import JogSource, PendantView

IGNORED: dict[JogSource, Reason] = {
    JogSource.HANDWHEEL: Reason.HANDWHEEL_IGNORED,
    JogSource.JOYSTICK: Reason.JOYSTICK_IGNORED,
    JogSource.PENDANT: Reason.PENDANT_IGNORED,
}


@dataclass
class JogOutcome:
    """What one period's reading asks of the controller: a fault (the handwheel's counter
    jumped: its detail), and messages for the operator."""

    jump_detail: str = ""
    notices: list[Refusal] = field(default_factory=list)


class PendantJog:
    def __init__(self, config: MachineConfig, device: PendantDevice | None = None) -> None:
        settings = config.pendant
        self.handwheel = (
            Handwheel(settings.handwheel, config.period_s) if settings.handwheel.fitted else None
        )
        self.joystick = Joystick(settings.joystick) if settings.joystick.fitted else None
        self.device = device
        self.arbiter = JogArbiter()
        self._wheel = WheelFollower(config.period_s)
        self._pendant_wheel = WheelFollower(config.period_s)
        self.selection = WheelSelection("", 1)
        self._stick_shape = (settings.evdev.deadband, settings.evdev.curve_exponent)
        self._enable = False
        self._said: set[Reason] = set()

    # -- what the controller asks --------------------------------------------------------
    def forget(self) -> None:
        """No reading this period (a lost link), or a Reset: the wheel's next count is a
        first read, and nothing jogs."""
        if self.handwheel is not None:
            self.handwheel.forget()
        self.arbiter.leave()
        self._wheel.reset()
        self._pendant_wheel.reset()

    def touch_screen(self) -> Refusal | None:
        """The screen wants to jog: None if it may."""
        return self.arbiter.touch(JogSource.SCREEN)

    def view(self) -> PendantView:
        return PendantView(
            jog_source=self.arbiter.owner,
            wheel_axis=self.selection.axis,
            wheel_multiplier=self.selection.multiplier,
            handwheel_fitted=self.handwheel is not None,
            joystick_fitted=self.joystick is not None,
            pendant_connected=self.device is not None and self.device.connected,
        )

    def close(self) -> None:
        if self.device is not None:
            self.device.close()

    # -- the period ----------------------------------------------------------------------
    def tick(
        self,
        now_s: float,
        inputs: InputImage,
        manual: ManualControl,
        axes: AxisGroup,
        *,
        jogging_allowed: bool,
    ) -> JogOutcome:
        """Read every control; jog from the one that owns the jog when ``jogging_allowed``
        (manual mode, not homing), else only say what is ignored."""
        outcome = JogOutcome()
        increments = 0
        if self.handwheel is not None:
            turn = self.handwheel.read(inputs)
            self.selection = turn.selection
            if turn.jump_counts:
                self.forget()
                limit = self.handwheel.unwrap.max_step_counts
                outcome.jump_detail = str(refusal(Reason.HANDWHEEL_JUMPED, turn.jump_counts, limit))
                return outcome
            increments = turn.increments if turn.selection.axis else 0
        sticks = self.joystick.read(inputs) if self.joystick is not None else {}
        if self.joystick is not None and self.joystick.off_centre is not None:
            axis, offset = self.joystick.off_centre
            self._say(outcome, refusal(Reason.JOYSTICK_NOT_CENTRED, axis, offset))
        reading = self.device.read() if self.device is not None else PendantReading()
        deadband, exponent = self._stick_shape
        pendant_sticks = {a: shaped(d, deadband, exponent) for a, d in reading.sticks.items()}
        pendant_moving = bool(reading.increments and reading.axis) or any(pendant_sticks.values())
        touched = {
            JogSource.HANDWHEEL: increments != 0,
            JogSource.JOYSTICK: any(sticks.values()),
            JogSource.PENDANT: pendant_moving,
        }
        enable_dropped = self._enable and not inputs.jog_enable
        self._enable = inputs.jog_enable
        if not any(touched.values()):
            self._said.clear()
        if not jogging_allowed:
            for source, on in touched.items():
                if on:
                    self._say(outcome, Refusal(IGNORED[source]))
            self.arbiter.leave()
            self._wheel.reset()
            self._pendant_wheel.reset()
            return outcome
        owner = self.arbiter.owner
        if enable_dropped and owner in (JogSource.HANDWHEEL, JogSource.JOYSTICK):
            manual.release_all()  # the dead-man let go: decelerate now
        if (touched[JogSource.HANDWHEEL] or touched[JogSource.JOYSTICK]) and not inputs.jog_enable:
            self._say(outcome, Refusal(Reason.HOLD_ENABLE))
        if pendant_moving and not reading.enable:
            self._say(outcome, Refusal(Reason.HOLD_ENABLE))
        enabled = {
            JogSource.HANDWHEEL: touched[JogSource.HANDWHEEL] and inputs.jog_enable,
            JogSource.JOYSTICK: touched[JogSource.JOYSTICK] and inputs.jog_enable,
            JogSource.PENDANT: touched[JogSource.PENDANT] and reading.enable,
        }
        for source, wants in enabled.items():
            if wants and (busy := self.arbiter.touch(source)) is not None:
                self._say(outcome, busy)
        owner = self.arbiter.owner
        if owner is JogSource.HANDWHEEL and enabled[JogSource.HANDWHEEL]:
            self._say(outcome, self._wheel.turn(self.selection.axis, increments, manual, axes))
        elif owner is JogSource.JOYSTICK and self.joystick is not None:
            for axis in self.joystick.axes:
                fraction = sticks.get(axis, 0.0) if inputs.jog_enable else 0.0
                self._say(outcome, manual.drive(axis, fraction, now_s, axes))
        elif owner is JogSource.PENDANT:
            self._jog_pendant(outcome, reading, pendant_sticks, now_s, manual, axes)
        at_rest = not any(enabled.values()) and manual.at_rest
        self.arbiter.tick(now_s, at_rest)
        if self.arbiter.owner is None:
            self._wheel.reset()
            self._pendant_wheel.reset()
        return outcome

    def _jog_pendant(
        self,
        outcome: JogOutcome,
        reading: PendantReading,
        sticks: dict[str, float],
        now_s: float,
        manual: ManualControl,
        axes: AxisGroup,
    ) -> None:
        if not reading.enable:
            manual.release_all()
            return
        if reading.increments and reading.axis:
            turn = self._pendant_wheel.turn(reading.axis, reading.increments, manual, axes)
            self._say(outcome, turn)
        for axis, fraction in sticks.items():
            self._say(outcome, manual.drive(axis, fraction, now_s, axes))

    def _say(self, outcome: JogOutcome, message: Refusal | None) -> None:
        if message is not None and message.reason not in self._said:
            self._said.add(message.reason)
            outcome.notices.append(message)
