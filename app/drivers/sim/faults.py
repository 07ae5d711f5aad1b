"""Fault injection into the simulated world, for tests, ``stave simulate`` and a technician's
menu (it implements :class:`app.drivers.contracts.FaultInjector`).

Why physical causes and not flags: each kind changes the world the way the real fault would,
and the machine layer sees only its consequences through the ordinary contracts (statusword,
fault code, EMCY event, a missing reply, a sensor that stays off). An injection is a
*condition* that lasts until :meth:`SimFaultInjector.clear_injections`; what it caused in the
drives (a latched fault) stays until the machine layer resets it, as on the real machine.

Kinds (``contracts.FAULT_KINDS``) and targets:

=====================  ======================  ==============================================
kind                   target                  what happens
=====================  ======================  ==============================================
drive_fault            X, Y or Z               power stage fault: FAULT at once (torque off),
                                               EMCY 0x2310; a fault reset is refused while
                                               the injection lasts
following_error        X, Y or Z               the axis jams mechanically: the next commanded
                                               motion builds a following error, bit 13, then
                                               FAULT with EMCY 0x8611
limit_switch           X+, X-, Y+, ... (X = X+)  the limit switch reads active: enabled ->
                                               FAULT 0xFF01/0xFF02; afterwards only motion
                                               away from it is allowed
estop                  (none)                  the E-stop is pressed: chain open, spindle
                                               contactor drops, drives brake and get STO
comms_loss             "" (drives and I/O),    no reply: every call raises CommunicationError,
                       drives, io, gauge       COMMUNICATION_LOST is queued; powered drives
                                               fault 0x8130 after the heartbeat timeout and
                                               the I/O coupler switches its outputs off;
                                               "gauge" unplugs the gauge
gauge_none             (none)                  the gauge never answers (poll stays None)
gauge_garbage          (none)                  the gauge answers "#?!x"
gauge_out_of_range     (none)                  the gauge answers ``out_of_range_mm`` (999)
clamp_sensor           closed (default), open  that sensor of the clamps never comes on
centering_sensor       extended (default),     that sensor of the centering device never
                       retracted               comes on
spindle                (none)                  the spindle never gives its running feedback
=====================  ======================  ==============================================
"""

from __future__ import annotations

from app.drivers.contracts import AXIS_NAMES, FAULT_KINDS
from app.drivers.sim.world import GaugeMode, SimWorld

_AXIS_KINDS = ("drive_fault", "following_error")
_GAUGE_MODES = {
    "gauge_none": GaugeMode.NO_REPLY,
    "gauge_garbage": GaugeMode.GARBAGE,
    "gauge_out_of_range": GaugeMode.OUT_OF_RANGE,
}


def fault_targets(kind: str) -> tuple[str, ...]:
    """The targets ``kind`` accepts (for a menu); ``""`` means "no target"/the default."""
    _check_kind(kind)
    if kind in _AXIS_KINDS:
        return AXIS_NAMES
    if kind == "limit_switch":
        return tuple(f"{a}{s}" for a in AXIS_NAMES for s in ("+", "-")) + AXIS_NAMES
    if kind == "comms_loss":
        return ("", "drives", "io", "gauge")
    if kind == "clamp_sensor":
        return ("", "closed", "open")
    if kind == "centering_sensor":
        return ("", "extended", "retracted")
    return ("",)


def _check_kind(kind: str) -> None:
    if kind not in FAULT_KINDS:
        raise ValueError(f"fault kind = {kind!r} is not allowed: one of {', '.join(FAULT_KINDS)}")


class SimFaultInjector:
    """Injects and clears fault conditions in one :class:`SimWorld`."""

    def __init__(self, world: SimWorld) -> None:
        self._world = world
        self._active: list[tuple[str, str]] = []

    @property
    def active(self) -> tuple[tuple[str, str], ...]:
        """The injections in force, as (kind, target), in the order they were made."""
        return tuple(self._active)

    def inject(self, kind: str, target: str = "") -> None:
        """Make the fault happen; see the module docstring for kinds and targets."""
        allowed = fault_targets(kind)
        if target not in allowed:
            shown = ", ".join(repr(t) for t in allowed)
            raise ValueError(
                f"target = {target!r} of fault {kind!r} is not allowed: one of {shown}"
            )
        self._apply(kind, target, on=True)
        if (kind, target) not in self._active:
            self._active.append((kind, target))

    def clear_injections(self) -> None:
        """End every injected condition; latched drive faults stay until reset."""
        for kind, target in reversed(self._active):
            self._apply(kind, target, on=False)
        self._active.clear()

    def _apply(self, kind: str, target: str, *, on: bool) -> None:
        world = self._world
        if kind == "drive_fault":
            world.drives[target].inject_power_stage_fault(on)
        elif kind == "following_error":
            world.drives[target].set_jammed(on)
        elif kind == "limit_switch":
            world.drives[target[0]].stick_limit_switch(not target.endswith("-"), on)
        elif kind == "estop":
            world.set_estop(on)
        elif kind == "comms_loss":
            for link in ("drives", "io") if target == "" else (target,):
                world.set_link(link, not on)
        elif kind in _GAUGE_MODES:
            world.gauge_line.mode = _GAUGE_MODES[kind] if on else GaugeMode.NORMAL
        elif kind == "clamp_sensor":
            if target == "open":
                world.io.clamps.dead_retracted_sensor = on
            else:
                world.io.clamps.dead_extended_sensor = on
        elif kind == "centering_sensor":
            if target == "retracted":
                world.io.centering.dead_retracted_sensor = on
            else:
                world.io.centering.dead_extended_sensor = on
        elif kind == "spindle":
            world.io.spindle.does_not_start = on
