"""``stave simulate --handwheel / --joystick``: jog the simulated machine by hand, in manual mode.

Why in the simulator: the handwheel's promise (exact to the count, x1/x10/x100, nothing
without the enable button, the jog ramp) is checked in the office the same way the cycle is.
Each option is a hand on the simulated machine's handwheel or joystick, sent as the
simulation's commands; the machine layer decides what moves, and the run reports where the
axes ended (commanded and actual) after each.
"""

from __future__ import annotations

import argparse
import math
from dataclasses import dataclass
from typing import Any

from app.drivers.sim.world import SimWorld
from app.machine import commands as cmd
from app.machine.runtime import MachineRuntime
from app.machine.states import MachineState

WHEEL_AXES = ("X", "Y", "Z")
WHEEL_MULTIPLIERS = (1, 10, 100)
MAX_WHEEL_COUNTS = 100_000
MAX_STICK_S = 60.0
SETTLE_TIMEOUT_S = 120.0  # the longest a turn or a push takes to come to rest


class JogOptionError(ValueError):
    """A --handwheel or --joystick value that is not allowed (one line)."""


@dataclass(frozen=True)
class WheelTurn:
    axis: str
    counts: int
    multiplier: int


@dataclass(frozen=True)
class StickPush:
    axis: str
    fraction: float
    seconds: float


HandJog = WheelTurn | StickPush


def add_jog_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--handwheel",
        action="append",
        default=[],
        metavar="AXIS:COUNTS[:MULT]",
        help="in manual mode, turn the simulated handwheel on AXIS (X, Y, Z) by COUNTS "
        "(negative: the other way) at multiplier MULT (1, 10 or 100; default 1), the enable "
        "held; repeatable, in order",
    )
    parser.add_argument(
        "--joystick",
        action="append",
        default=[],
        metavar="AXIS:FRACTION:SECONDS",
        help="in manual mode, hold the simulated joystick on AXIS (X, Y) at FRACTION of full "
        "deflection (-1 to 1) for SECONDS, the enable held; repeatable, after the handwheel's",
    )


def parse_wheel(text: str) -> WheelTurn:
    parts = text.split(":")
    allowed = "AXIS:COUNTS[:MULT], AXIS one of X, Y, Z"
    if len(parts) not in (2, 3):
        raise JogOptionError(f"--handwheel {text!r} is not allowed: {allowed}")
    axis = parts[0].strip().upper()
    if axis not in WHEEL_AXES:
        raise JogOptionError(f"--handwheel {text!r}: axis {parts[0]!r} is not allowed: {allowed}")
    try:
        counts = int(parts[1])
    except ValueError:
        counts = 0
    if counts == 0 or abs(counts) > MAX_WHEEL_COUNTS:
        raise JogOptionError(
            f"--handwheel {text!r}: counts {parts[1]!r} is not allowed: a whole number, "
            f"not 0, from -{MAX_WHEEL_COUNTS} to {MAX_WHEEL_COUNTS}"
        )
    multiplier_text = parts[2] if len(parts) == 3 else "1"
    try:
        multiplier = int(multiplier_text)
    except ValueError:
        multiplier = 0
    if multiplier not in WHEEL_MULTIPLIERS:
        raise JogOptionError(
            f"--handwheel {text!r}: multiplier {multiplier_text!r} is not allowed: 1, 10 or 100"
        )
    return WheelTurn(axis, counts, multiplier)


def parse_stick(text: str, stick_axes: tuple[str, ...]) -> StickPush:
    parts = text.split(":")
    allowed = f"AXIS:FRACTION:SECONDS, AXIS one of {', '.join(stick_axes)}"
    if len(parts) != 3:
        raise JogOptionError(f"--joystick {text!r} is not allowed: {allowed}")
    axis = parts[0].strip().upper()
    if axis not in stick_axes:
        raise JogOptionError(f"--joystick {text!r}: axis {parts[0]!r} is not allowed: {allowed}")
    fraction, seconds = (_number(part) for part in parts[1:])
    if not (math.isfinite(fraction) and 0 < abs(fraction) <= 1):
        raise JogOptionError(
            f"--joystick {text!r}: fraction {parts[1]!r} is not allowed: -1 to 1, not 0"
        )
    if not (math.isfinite(seconds) and 0 < seconds <= MAX_STICK_S):
        raise JogOptionError(
            f"--joystick {text!r}: seconds {parts[2]!r} is not allowed: more than 0, "
            f"at most {MAX_STICK_S:g}"
        )
    return StickPush(axis, fraction, seconds)


def _number(text: str) -> float:
    try:
        return float(text)
    except ValueError:
        return math.nan


def hand_jogs(args: argparse.Namespace, stick_axes: tuple[str, ...]) -> list[HandJog]:
    """The options' jogs, in the order they run: the handwheel's, then the joystick's."""
    jogs: list[HandJog] = [parse_wheel(text) for text in args.handwheel]
    jogs.extend(parse_stick(text, stick_axes) for text in args.joystick)
    return jogs


def _at_rest(runtime: MachineRuntime) -> bool:
    world = runtime.backend.extras.get("world")
    wheel = world.handwheel if isinstance(world, SimWorld) else None
    c = runtime.controller
    return (
        (wheel is None or not wheel.turning)
        and c.snapshot().pendant.jog_source is None
        and c.manual.at_rest
    )


def run_hand_jogs(runtime: MachineRuntime, jogs: list[HandJog]) -> list[dict[str, Any]]:
    """Each jog in manual mode, as a technician's hand would do it; where the axes ended."""
    c = runtime.controller
    if c.state is not MachineState.MANUAL:
        c.post(cmd.EnterManual())
        runtime.run_for(2 * runtime.period_s)
    if c.state is not MachineState.MANUAL:
        raise RuntimeError(f"manual mode refused: {c.message}")
    c.post(cmd.HoldJogEnable(True))
    reports: list[dict[str, Any]] = []
    for jog in jogs:
        said_before = c.message
        start = c.manual.position(jog.axis)
        if isinstance(jog, WheelTurn):
            c.post(cmd.SelectHandwheel(jog.axis, jog.multiplier))
            runtime.run_for(2 * runtime.period_s)
            c.post(cmd.TurnHandwheel(jog.counts))
            entry: dict[str, Any] = {
                "source": "handwheel",
                "axis": jog.axis,
                "counts": jog.counts,
                "multiplier": jog.multiplier,
            }
        else:
            deflection = {jog.axis.lower(): jog.fraction}
            c.post(cmd.PushJoystick(**deflection))
            runtime.run_for(jog.seconds)
            c.post(cmd.PushJoystick())
            entry = {
                "source": "joystick",
                "axis": jog.axis,
                "fraction": jog.fraction,
                "seconds": jog.seconds,
            }
        runtime.run_for(2 * runtime.period_s)
        if not runtime.run_until(lambda _m: _at_rest(runtime), SETTLE_TIMEOUT_S):
            raise RuntimeError(f"the {entry['source']} jog did not come to rest")
        message = c.message
        actual = dict(zip(("X", "Y", "Z"), c.axes.positions(), strict=True))
        entry["command"] = {axis: c.manual.position(axis) for axis in ("X", "Y", "Z")}
        entry["actual"] = actual
        entry["moved"] = c.manual.position(jog.axis) - start  # mm, or deg for Z
        # What the machine said about this jog (a refusal, the soft limit), if anything.
        entry["message"] = (
            str(message) if message is not None and message is not said_before else None
        )
        reports.append(entry)
        if isinstance(jog, WheelTurn):
            c.post(cmd.SelectHandwheel("", 1))
    c.post(cmd.HoldJogEnable(False))
    c.post(cmd.LeaveManual())
    runtime.run_for(2 * runtime.period_s)
    return reports


def describe_jog(entry: dict[str, Any]) -> str:
    what = (
        f"handwheel {entry['axis']} {entry['counts']:+d} counts x{entry['multiplier']}"
        if entry["source"] == "handwheel"
        else f"joystick {entry['axis']} {entry['fraction']:+g} for {entry['seconds']:g} s"
    )
    where = ", ".join(f"{axis} {value:.3f}" for axis, value in entry["actual"].items())
    return f"{what}: moved {entry['moved']:+.3f}, axes at {where}"
