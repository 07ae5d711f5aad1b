"""The simulated devices around the axes: cylinders, spindle, buttons, safety chain, lamps.

Why physical devices and not flags: the machine layer waits for sensors with timeouts, and a
sensor that never arrives must look exactly like the real one (the output is on, the device
moves, the sensor stays off). Every device here therefore has the command the output gives it,
a physical state that changes with time, and sensors read from that state.

Choices, as the real machine is wired:

- Centering device and clamps are single-acting pneumatic cylinders on monostable valves: the
  output on moves them to the extended / closed end in ``centering_time_s`` / ``clamp_time_s``,
  output off moves them back in the same time. Each end has a sensor that is on only in that
  end position. A dead sensor (fault injection) stays off.
- The spindle contactor is a seal-in circuit fed through the E-stop chain: it pulls in on a
  rising edge of the ``spindle_on`` output while the chain is closed and drops when the output
  goes off or the chain opens; after an E-stop it needs a fresh off-on of the output. The
  running feedback (speed relay) comes ``spindle_runup_s`` after the contactor pulled in and
  goes off with the contactor. A spindle that does not start (fault injection: tripped motor
  protection) never gives the feedback.
- Push buttons are momentary: pressed for :data:`BUTTON_PRESS_S` of simulated time.
- The E-stop button latches (``set_estop(True)`` until ``set_estop(False)``); ``estop_ok`` is
  the chain's state. The guard switch is only an input: the machine layer decides.
- Lamps are outputs only; the last written ones can be read back for a display.
"""

from __future__ import annotations

from app.drivers.contracts import InputImage, OutputImage

BUTTON_PRESS_S = 0.1


class Cylinder:
    """A pneumatic cylinder with an end sensor at each end; position 0 = retracted."""

    def __init__(self, stroke_time_s: float) -> None:
        self.stroke_time_s = stroke_time_s
        self.command = False
        self.position = 0.0
        self.dead_extended_sensor = False
        self.dead_retracted_sensor = False

    def step(self, dt: float) -> None:
        if self.command:
            if self.position < 1.0:
                rate = dt / self.stroke_time_s if self.stroke_time_s > 0 else 1.0
                self.position = min(1.0, self.position + rate)
        elif self.position > 0.0:
            rate = dt / self.stroke_time_s if self.stroke_time_s > 0 else 1.0
            self.position = max(0.0, self.position - rate)

    @property
    def extended_sensor(self) -> bool:
        return self.position >= 1.0 and not self.dead_extended_sensor

    @property
    def retracted_sensor(self) -> bool:
        return self.position <= 0.0 and not self.dead_retracted_sensor


class Spindle:
    """The router spindle: seal-in contactor behind the E-stop chain, running feedback."""

    def __init__(self, runup_s: float) -> None:
        self.runup_s = runup_s
        self.contactor = False
        self.on_s = 0.0
        self.does_not_start = False
        self._command = False

    def step(self, dt: float, command: bool, chain_ok: bool) -> None:
        if not chain_ok or not command:
            self.contactor = False
        elif not self._command:
            self.contactor = True  # rising edge of the output with the chain closed
        self._command = command
        self.on_s = self.on_s + dt if self.contactor else 0.0

    @property
    def running(self) -> bool:
        return self.contactor and self.on_s >= self.runup_s and not self.does_not_start


class MomentaryButton:
    def __init__(self) -> None:
        self.released_at_s = -1.0

    def press(self, now_s: float) -> None:
        self.released_at_s = now_s + BUTTON_PRESS_S

    def pressed(self, now_s: float) -> bool:
        return now_s < self.released_at_s


class MachineIO:
    """Every discrete device of the machine; the world steps it and reads its sensors."""

    def __init__(
        self, centering_time_s: float, clamp_time_s: float, spindle_runup_s: float
    ) -> None:
        self.centering = Cylinder(centering_time_s)
        self.clamps = Cylinder(clamp_time_s)
        self.spindle = Spindle(spindle_runup_s)
        self.start_button = MomentaryButton()
        self.stop_button = MomentaryButton()
        self.reset_button = MomentaryButton()
        self.estop_pressed = False
        self.guard_closed = True
        self.outputs = OutputImage()

    def apply_outputs(self, outputs: OutputImage) -> None:
        self.outputs = outputs
        self.centering.command = outputs.centering_extend
        self.clamps.command = outputs.clamps_close

    def switch_outputs_off(self) -> None:
        """The I/O coupler's watchdog: without the master every output goes off."""
        self.apply_outputs(OutputImage())

    def step(self, dt: float) -> None:
        self.centering.step(dt)
        self.clamps.step(dt)
        self.spindle.step(dt, self.outputs.spindle_on, not self.estop_pressed)

    def inputs(self, now_s: float, part_present: bool) -> InputImage:
        return InputImage(
            part_present=part_present,
            centering_extended=self.centering.extended_sensor,
            centering_retracted=self.centering.retracted_sensor,
            clamps_closed=self.clamps.extended_sensor,
            clamps_open=self.clamps.retracted_sensor,
            spindle_running=self.spindle.running,
            guard_closed=self.guard_closed,
            estop_ok=not self.estop_pressed,
            start_button=self.start_button.pressed(now_s),
            stop_button=self.stop_button.pressed(now_s),
            reset_button=self.reset_button.pressed(now_s),
        )
