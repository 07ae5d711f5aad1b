"""The joystick: analog deflection to a fraction of the jog velocity.

Why a deadband and a curve: a stick never reads exactly its centre (offset, drift, a glove
resting on it), so a band around the centre commands nothing; beyond it the speed rises as a
power of the deflection (``curve_exponent``: 1 linear, 2 or 3 leave fine control near the
centre and full speed at the end), and reaches the full jog velocity at full deflection.

Why a calibration at start-up: the centre a stick reads differs from stick to stick and
from mid-scale; it is taken at the first read, and only if the stick rests near mid-scale
then (a stick held or stuck at start-up must not become "the centre" that moves the axis
when it is let go). Until it is calibrated the joystick moves nothing and says why.
"""

from __future__ import annotations

import math

from app.drivers.contracts import InputImage
from app.pendant_settings import JoystickSettings


def shaped(deflection: float, deadband: float, exponent: float) -> float:
    """The speed fraction (-1..1) for a deflection (-1..1, clipped): 0 within the deadband,
    then ``((|d| - deadband) / (1 - deadband)) ** exponent`` with the deflection's sign."""
    if not math.isfinite(deflection):
        return 0.0
    magnitude = min(1.0, abs(deflection))
    if magnitude <= deadband:
        return 0.0
    fraction = ((magnitude - deadband) / (1.0 - deadband)) ** exponent
    return math.copysign(fraction, deflection)


def stick_axes(settings: JoystickSettings) -> tuple[str, ...]:
    return ("X", "Y", "Z") if settings.z_fitted else ("X", "Y")


def raw_values(inputs: InputImage) -> dict[str, int | None]:
    return {"X": inputs.joystick_x, "Y": inputs.joystick_y, "Z": inputs.joystick_z}


class Joystick:
    def __init__(self, settings: JoystickSettings) -> None:
        self.settings = settings
        self.axes = stick_axes(settings)
        self.centre: dict[str, int] | None = None
        self.off_centre: tuple[str, int] | None = None  # why it is not calibrated yet

    def calibrate(self, raw: dict[str, int]) -> bool:
        """Take ``raw`` as the centre if every axis rests near mid-scale."""
        s = self.settings
        for axis in self.axes:
            offset = raw[axis] - s.mid_scale_counts
            if abs(offset) > s.centre_tolerance_counts:
                self.off_centre = (axis, offset)
                return False
        self.centre = {axis: raw[axis] for axis in self.axes}
        self.off_centre = None
        return True

    def read(self, inputs: InputImage) -> dict[str, float]:
        """Speed fraction per axis (-1..1); empty while unwired, unread or uncalibrated."""
        values = raw_values(inputs)
        raw: dict[str, int] = {}
        for axis in self.axes:
            value = values[axis]
            if value is None:
                return {}
            raw[axis] = value
        if self.centre is None and not self.calibrate(raw):
            return {}
        assert self.centre is not None
        s = self.settings
        return {
            axis: shaped(
                (raw[axis] - self.centre[axis]) / s.full_scale_counts, s.deadband, s.curve_exponent
            )
            for axis in self.axes
        }
