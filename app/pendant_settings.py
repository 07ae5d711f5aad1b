"""The ``[pendant]`` table of the machine configuration: the handwheel, the joystick and a
USB pendant or gamepad, which of them are fitted and how they are scaled.

Why strict like every other key: a misspelt ``deadband`` that fell back to a default would
make a joystick creep at rest, a wrong counter rate would turn a fast spin into a fault or a
counter reset into motion. Every key is checked, unknown keys are refused with their name.

Which terminal carries the selector, the multiplier and the enable button is the I/O map's
business (``[backend.*.io.inputs]``: the functions ``handwheel_x``, ``handwheel_y``,
``handwheel_z``, ``handwheel_x10``, ``handwheel_x100``, ``jog_enable``); where the count and
the analog values come from too (a Modbus input register, a CiA 401 object, the simulation).
This table says what is fitted and how to read it.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Protocol


class Section(Protocol):
    """What these settings read of a table (``app.config.Section``, which imports this
    module: a protocol keeps the imports one way)."""

    def error(self, name: str, value: object, allowed: str) -> Exception: ...

    def number(self, name: str, default: float, minimum: float, maximum: float) -> float: ...

    def integer(self, name: str, default: int, minimum: int, maximum: int) -> int: ...

    def boolean(self, name: str, default: bool) -> bool: ...

    def text(self, name: str, default: str, choices: tuple[str, ...] | None = None) -> str: ...

    def table(self, name: str) -> Section: ...

    def finish(self) -> None: ...


@dataclass(frozen=True)
class HandwheelSettings:
    fitted: bool = False
    max_counts_per_s: float = 2000.0  # the fastest a hand spins it (100 lines at 20 rev/s)
    counts_per_increment: int = 1  # encoder counts per 0.001 mm (or deg) at x1


@dataclass(frozen=True)
class JoystickSettings:
    fitted: bool = False
    z_fitted: bool = False  # a third analog input for the tilt
    full_scale_counts: int = 10000  # analog counts from centre to full deflection
    deadband: float = 0.05  # fraction of full deflection that commands nothing
    curve_exponent: float = 2.0  # speed = deflection ** exponent (1: linear)
    centre_tolerance_counts: int = 1500  # at start-up the stick must rest this close to mid-scale
    mid_scale_counts: int = 0  # where the centre should read (0 for a signed +-10 V input)


EVDEV_CODE = re.compile(r"^(ABS|REL|BTN|KEY)_[A-Z0-9_]+$")


@dataclass(frozen=True)
class EvdevSettings:
    """A USB pendant or gamepad read through the Linux input layer (evdev). ``device`` is a
    path (``/dev/input/by-id/...``) or the name the device reports; empty: none."""

    device: str = ""
    enable: str = "BTN_TL"
    stick_x: str = "ABS_X"
    stick_y: str = "ABS_Y"
    stick_z: str = ""
    wheel: str = ""
    select_off: str = ""
    select_x: str = ""
    select_y: str = ""
    select_z: str = ""
    step_x1: str = ""
    step_x10: str = ""
    step_x100: str = ""
    deadband: float = 0.1
    curve_exponent: float = 2.0

    def code_names(self) -> dict[str, str]:
        """Mapped role -> event code name (the unmapped ones left out)."""
        roles = {
            "enable": self.enable,
            "stick_x": self.stick_x,
            "stick_y": self.stick_y,
            "stick_z": self.stick_z,
            "wheel": self.wheel,
            "select_off": self.select_off,
            "select_x": self.select_x,
            "select_y": self.select_y,
            "select_z": self.select_z,
            "step_x1": self.step_x1,
            "step_x10": self.step_x10,
            "step_x100": self.step_x100,
        }
        return {role: name for role, name in roles.items() if name}


@dataclass(frozen=True)
class PendantSettings:
    handwheel: HandwheelSettings = field(default_factory=HandwheelSettings)
    joystick: JoystickSettings = field(default_factory=JoystickSettings)
    evdev: EvdevSettings = field(default_factory=EvdevSettings)


def _read_handwheel(s: Section) -> HandwheelSettings:
    d = HandwheelSettings()
    settings = HandwheelSettings(
        fitted=s.boolean("fitted", d.fitted),
        max_counts_per_s=s.number("max_counts_per_s", d.max_counts_per_s, 1.0, 100_000.0),
        counts_per_increment=s.integer("counts_per_increment", d.counts_per_increment, 1, 100),
    )
    s.finish()
    return settings


def _read_joystick(s: Section) -> JoystickSettings:
    d = JoystickSettings()
    settings = JoystickSettings(
        fitted=s.boolean("fitted", d.fitted),
        z_fitted=s.boolean("z_fitted", d.z_fitted),
        full_scale_counts=s.integer("full_scale_counts", d.full_scale_counts, 10, 32767),
        deadband=s.number("deadband", d.deadband, 0.0, 0.5),
        curve_exponent=s.number("curve_exponent", d.curve_exponent, 1.0, 4.0),
        centre_tolerance_counts=s.integer(
            "centre_tolerance_counts", d.centre_tolerance_counts, 0, 32767
        ),
        mid_scale_counts=s.integer("mid_scale_counts", d.mid_scale_counts, -32768, 65535),
    )
    s.finish()
    if settings.centre_tolerance_counts >= settings.full_scale_counts:
        raise s.error(
            "centre_tolerance_counts",
            settings.centre_tolerance_counts,
            f"less than full_scale_counts ({settings.full_scale_counts})",
        )
    return settings


def _read_evdev(s: Section) -> EvdevSettings:
    d = EvdevSettings()
    names: dict[str, str] = {}
    for role in (
        "enable",
        "stick_x",
        "stick_y",
        "stick_z",
        "wheel",
        "select_off",
        "select_x",
        "select_y",
        "select_z",
        "step_x1",
        "step_x10",
        "step_x100",
    ):
        value = s.text(role, getattr(d, role))
        if value and not EVDEV_CODE.match(value):
            raise s.error(role, value, "an input event code name such as BTN_TL, ABS_X, REL_DIAL")
        names[role] = value
    for role in ("stick_x", "stick_y", "stick_z"):
        if names[role] and not names[role].startswith("ABS_"):
            raise s.error(role, names[role], "an absolute axis code (ABS_...)")
    if names["wheel"] and not names["wheel"].startswith("REL_"):
        raise s.error("wheel", names["wheel"], "a relative axis code (REL_...)")
    settings = EvdevSettings(
        device=s.text("device", d.device),
        deadband=s.number("deadband", d.deadband, 0.0, 0.5),
        curve_exponent=s.number("curve_exponent", d.curve_exponent, 1.0, 4.0),
        **names,
    )
    s.finish()
    return settings


def read_pendant_settings(section: Section) -> PendantSettings:
    """Check every key of ``[pendant]`` and its tables (unknown keys refused by finish)."""
    settings = PendantSettings(
        handwheel=_read_handwheel(section.table("handwheel")),
        joystick=_read_joystick(section.table("joystick")),
        evdev=_read_evdev(section.table("evdev")),
    )
    section.finish()
    return settings
