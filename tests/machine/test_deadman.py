"""The jog dead-man with a frozen screen, on the simulated clock: the axis stops within the
dead-man time and its ramp, and the frozen screen's overdue refresh does not start it again.

Measured inside the machine (what the controller sees each period): the machine time of the
last refresh, of the dead-man's W101 and of the axis standing still."""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from app.machine import commands as cmd
from app.machine.alarms import AlarmCode
from app.machine.commands import JOG_DEADMAN_S, JOG_REFRESH_S
from app.machine.permissions import SPINDLE_ON, allowed_commands
from app.machine.refusals import Reason
from app.machine.runtime import MachineRuntime
from app.machine.states import MachineState
from tests.machine.conftest import Rig

HOLD = 7


@dataclass
class RunOn:
    last_refresh_s: float
    x_at_refresh_mm: float
    deadman_s: float | None = None
    stood_s: float | None = None
    x_stood_mm: float | None = None


def run_on_bound_mm(velocity: float, acceleration: float, jerk: float, period_s: float) -> float:
    """The worst case: full speed for the dead-man time (and the period it is noticed in),
    then the jerk-limited ramp to rest, v^2/(2a) + v*a/(2j)."""
    return (
        velocity * (JOG_DEADMAN_S + period_s)
        + velocity**2 / (2 * acceleration)
        + velocity * acceleration / (2 * jerk)
    )


def _frozen_screen(rig: Rig, velocity: float, acceleration: float) -> RunOn:
    c = rig.controller
    rig.send(cmd.EnterManual())
    rig.set_parameters({"jog_xy_speed_mm_s": velocity, "jog_xy_accel_mm_s2": acceleration})
    assert c.manual.speed("XY") == (velocity, acceleration)
    hold_s = 0.3 + velocity / acceleration  # up to speed, then cruising
    held = 0.0
    while held < hold_s:  # the screen refreshes while the button is held
        rig.send(cmd.JogContinuous("X", 1, HOLD), run_s=JOG_REFRESH_S)
        held += JOG_REFRESH_S
    rig.send(cmd.JogContinuous("X", 1, HOLD), run_s=0.0)
    measured = RunOn(c.now_s, c.axes.position("X"))

    def watch(runtime: MachineRuntime) -> None:
        ctl = runtime.controller
        if measured.deadman_s is None and any(
            t.code is AlarmCode.JOG_NOT_REFRESHED for t in ctl.alarms.history[-2:]
        ):
            measured.deadman_s = ctl.now_s
        setpoint = ctl.axes.command["X"]
        if measured.deadman_s is not None and measured.stood_s is None and setpoint == previous[0]:
            measured.stood_s = ctl.now_s  # the setpoint stands: the ramp has ended
        previous[0] = setpoint

    previous = [c.axes.command["X"]]

    rig.runtime.on_tick.append(watch)
    rig.run(2.0)  # the screen is frozen (SIGSTOP): no refresh, no release
    measured.x_stood_mm = c.axes.position("X")  # where the axis came to rest
    # It wakes up: its overdue refresh of the same hold must not start the axis again.
    x_frozen = rig.positions()[0]
    rig.send(cmd.JogContinuous("X", 1, HOLD))
    assert c.message is not None and c.message.reason is Reason.JOG_HOLD_ENDED
    rig.run(0.5)
    assert rig.positions()[0] == pytest.approx(x_frozen, abs=1e-6)
    rig.runtime.on_tick.remove(watch)
    return measured


@pytest.mark.parametrize("speed", ["hand", "maximum"])
def test_a_frozen_screen_lets_the_axis_run_on_no_further_than_the_deadman_and_ramp(
    rig: Rig, speed: str
) -> None:
    c = rig.controller
    x, y = c.config.axes["X"], c.config.axes["Y"]
    if speed == "hand":  # the System screen's X-Y jog speed and acceleration, as shipped
        velocity, acceleration = c.manual.speed("XY")
        assert (velocity, acceleration) == (20.0, 200.0)
    else:  # the most the X-Y jog accepts
        velocity = min(x.max_velocity, y.max_velocity)
        acceleration = min(x.max_acceleration, y.max_acceleration)
    m = _frozen_screen(rig, velocity, acceleration)
    assert m.deadman_s is not None and m.stood_s is not None and m.x_stood_mm is not None
    period = c.config.period_s
    assert JOG_DEADMAN_S < m.deadman_s - m.last_refresh_s <= JOG_DEADMAN_S + 2 * period
    run_on = m.x_stood_mm - m.x_at_refresh_mm
    jerk = c.config.axes["X"].max_jerk
    bound = run_on_bound_mm(velocity, acceleration, jerk, period)
    print(
        f"run-on at {velocity:g} mm/s, {acceleration:g} mm/s2: {run_on:.1f} mm "
        f"(bound {bound:.1f}), stood {m.stood_s - m.last_refresh_s:.3f} s after the refresh"
    )
    assert velocity * JOG_DEADMAN_S < run_on <= bound + 1.0  # 1 mm: the drive's following

    rig.send(cmd.JogContinuous("X", 1, HOLD + 1), run_s=0.2)  # a new press moves again
    assert c.axes.feedback["X"].velocity > 0.0
    rig.send(cmd.JogRelease("X"), run_s=1.0)


def test_spindle_on_by_hand_needs_the_board_clamped_or_the_table_empty(rig: Rig) -> None:
    c = rig.controller
    rig.send(cmd.EnterManual())
    assert c.state is MachineState.MANUAL
    rig.world.load_board(150.0)
    rig.run(0.05)
    assert allowed_commands(c.facts())[SPINDLE_ON] is not None
    rig.send(cmd.SetSpindle(True))
    assert not c.outputs.spindle_on
    assert c.message is not None and c.message.reason is Reason.SPINDLE_LOOSE_BOARD
    rig.send(cmd.SetClamps(True))
    rig.until(lambda ctl: ctl.inputs.clamps_closed, 5.0)
    rig.send(cmd.SetSpindle(True))
    assert c.outputs.spindle_on
    rig.send(cmd.SetClamps(False))
    rig.until(lambda ctl: not ctl.inputs.clamps_closed, 5.0)
    rig.send(cmd.SetSpindle(False))  # off is never refused
    assert not c.outputs.spindle_on
