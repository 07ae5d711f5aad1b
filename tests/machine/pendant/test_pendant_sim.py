"""The handwheel and the joystick on the simulated machine, through the operator's and the
simulation menu's commands: exact to the count, the enable button, no lag after a fast
spin, soft limits, the jump fault, nothing after a reconnect, the arbitration with the
screen, ignored (and said so) outside manual mode, and what the Manual screen is shown."""

from __future__ import annotations

import tomllib
from collections.abc import Iterator
from pathlib import Path

import pytest

from app.config import default_config_path, parse_config
from app.machine import commands as cmd
from app.machine.refusals import Reason
from app.machine.runtime import MachineRuntime
from app.machine.snapshot import JogSource
from app.machine.states import MachineState
from tests.machine.conftest import Rig


def absolute_config():  # type: ignore[no-untyped-def]
    """The shipped simulated machine with absolute encoders: ready at power-up at home."""
    data = tomllib.loads(default_config_path().read_text(encoding="utf-8"))
    for axis in ("X", "Y"):
        data["axes"][axis]["encoder"] = "absolute"
    return parse_config(data, "machine.toml")


@pytest.fixture(scope="module")
def rig(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Rig]:
    db = Path(tmp_path_factory.mktemp("pendant")) / "stave.db"
    runtime = MachineRuntime.create(absolute_config(), db)
    runtime.start()
    r = Rig(runtime)
    yield r
    runtime.shutdown()


@pytest.fixture
def manual(rig: Rig) -> Rig:
    """In manual mode, the wheel let go and at rest, the stick centred."""
    if rig.state in (MachineState.ERROR, MachineState.EMERGENCY_STOP):
        rig.send(cmd.Reset(), run_s=0.5)
    rig.send(cmd.HoldJogEnable(False))
    rig.send(cmd.PushJoystick())
    rig.send(cmd.SelectHandwheel("", 1))
    if rig.state is not MachineState.MANUAL:
        rig.send(cmd.EnterManual())
    rig.run(0.6)
    assert rig.state is MachineState.MANUAL
    assert rig.controller.snapshot().pendant.jog_source is None
    return rig


def x(rig: Rig) -> float:
    return rig.controller.manual.position("X")


def test_1000_counts_at_x1_are_1_000_mm_exactly_and_x10_multiplies(manual: Rig) -> None:
    rig = manual
    x0 = x(rig)
    rig.send(cmd.SelectHandwheel("X", 1))
    rig.send(cmd.HoldJogEnable(True))
    rig.send(cmd.TurnHandwheel(1000, 500.0), run_s=1.0)
    assert rig.controller.snapshot().pendant.jog_source is JogSource.HANDWHEEL
    rig.run(1.5)
    assert x(rig) == x0 + 1.0  # exactly: a whole number of increments from the start
    rig.send(cmd.SelectHandwheel("X", 10))
    rig.send(cmd.TurnHandwheel(-250, 500.0), run_s=1.0)
    assert x(rig) == x0 + 1.0 - 2.5
    view = rig.controller.snapshot().pendant
    assert (view.wheel_axis, view.wheel_multiplier) == ("X", 10)
    rig.run(0.5)
    assert rig.positions()[0] == pytest.approx(x0 - 1.5, abs=0.005)  # the drive followed


def test_without_the_enable_button_nothing_moves_and_it_says_so(manual: Rig) -> None:
    rig = manual
    rig.send(cmd.SelectHandwheel("Y", 100))
    before = rig.controller.manual.position("Y")
    rig.send(cmd.TurnHandwheel(200, 500.0), run_s=0.6)
    assert rig.controller.manual.position("Y") == before
    message = rig.controller.message
    assert message is not None and message.reason is Reason.HOLD_ENABLE
    rig.send(cmd.PushJoystick(y=0.8), run_s=0.3)
    assert rig.controller.manual.position("Y") == before


def test_a_fast_spin_stops_when_the_wheel_stops_within_the_jog_ramp(manual: Rig) -> None:
    rig = manual
    rig.send(cmd.SelectHandwheel("X", 100))
    rig.send(cmd.HoldJogEnable(True))
    x0 = x(rig)
    rig.send(cmd.TurnHandwheel(1_000, 1_500.0))  # 100 mm asked at 150 mm/s
    rig.until(lambda c: not rig.world.handwheel.turning, 2.0)  # the hand has stopped
    assert x(rig) > x0
    x_cfg = rig.controller.config.axes["X"]
    jog_v, jog_a = rig.controller.manual.speed("XY")  # the Jogging parameters
    ramp_s = jog_v / jog_a + jog_a / x_cfg.max_jerk
    rig.run(ramp_s + 0.02)
    assert rig.controller.manual.at_rest
    stopped = x(rig)
    rig.run(0.3)
    assert x(rig) == stopped
    assert stopped < x0 + 100.0 - 10.0  # counts beyond the ramp's reach were dropped


def test_the_wheel_stops_at_the_soft_limit_and_turns_back_at_once(manual: Rig) -> None:
    rig = manual
    rig.send(cmd.SelectHandwheel("Z", 100))
    rig.send(cmd.HoldJogEnable(True))
    z_max = rig.controller.config.axes["Z"].max_position
    z0 = rig.controller.manual.position("Z")
    beyond = round((z_max - z0) * 10) + 20  # 2 deg past the limit, a little below jog speed
    rig.send(cmd.TurnHandwheel(beyond, 9.0 * rig.controller.manual.speed("Z")[0]))
    rig.until(lambda c: not rig.world.handwheel.turning, 5.0)
    rig.run(0.3)
    assert rig.controller.manual.position("Z") == pytest.approx(z_max)
    message = rig.controller.message
    assert message is not None and "soft limit" in str(message)
    back_rate = 5.0 * rig.controller.manual.speed("Z")[0]  # half the jog speed
    rig.send(cmd.TurnHandwheel(-10, back_rate), run_s=1.5)  # back: 1 deg at once, no unwinding
    assert rig.controller.manual.position("Z") == pytest.approx(z_max - 1.0, abs=1e-6)
    rig.send(cmd.SelectHandwheel("", 1))
    rig.send(cmd.JogStep("Z", z0 - (z_max - 1.0)), run_s=1.0)  # the screen takes it back
    rig.run(3.0)


def test_the_screen_and_the_wheel_never_fight(manual: Rig) -> None:
    rig = manual
    rig.send(cmd.SelectHandwheel("Y", 10))
    rig.send(cmd.HoldJogEnable(True))
    rig.send(cmd.TurnHandwheel(2_000, 800.0), run_s=0.5)
    y_moving = rig.controller.manual.position("Y")
    rig.send(cmd.JogContinuous("X", 1), run_s=0.05)
    message = rig.controller.message
    assert message is not None and message.reason is Reason.HANDWHEEL_HAS_JOG
    assert rig.controller.manual.position("X") == x(rig)
    rig.run(3.0)  # the wheel stops, everything rests, the jog is free again
    assert rig.controller.manual.position("Y") > y_moving
    assert rig.controller.snapshot().pendant.jog_source is None
    for _ in range(5):
        rig.send(cmd.JogContinuous("X", 1), run_s=0.05)
    assert rig.controller.snapshot().pendant.jog_source is JogSource.SCREEN
    y_screen = rig.controller.manual.position("Y")
    rig.send(cmd.TurnHandwheel(100, 800.0), run_s=0.2)
    message = rig.controller.message
    assert message is not None and message.reason is Reason.SCREEN_HAS_JOG
    assert rig.controller.manual.position("Y") == y_screen
    rig.send(cmd.JogRelease("X"), run_s=1.0)


def test_the_joystick_jogs_proportionally_and_stops_when_let_go(manual: Rig) -> None:
    rig = manual
    settings = rig.controller.config.pendant.joystick
    rig.send(cmd.HoldJogEnable(True))
    rig.send(cmd.PushJoystick(x=0.5), run_s=1.5)
    fraction = ((0.5 - settings.deadband) / (1 - settings.deadband)) ** settings.curve_exponent
    velocity = rig.controller.axes.feedback["X"].velocity
    assert velocity == pytest.approx(fraction * rig.controller.manual.speed("XY")[0], rel=0.03)
    assert rig.controller.snapshot().pendant.jog_source is JogSource.JOYSTICK
    rig.send(cmd.PushJoystick(x=0.02), run_s=0.5)  # within the deadband: stops
    assert rig.controller.manual.at_rest
    rig.send(cmd.PushJoystick(x=-0.9), run_s=0.3)
    rig.send(cmd.HoldJogEnable(False), run_s=0.5)  # the dead-man let go
    assert rig.controller.manual.at_rest


def test_outside_manual_mode_the_controls_are_ignored_and_say_so(manual: Rig) -> None:
    rig = manual
    rig.send(cmd.LeaveManual())
    assert rig.state is MachineState.READY
    before = rig.controller.axes.positions()
    rig.send(cmd.SelectHandwheel("X", 100))
    rig.send(cmd.HoldJogEnable(True))
    rig.send(cmd.TurnHandwheel(300, 800.0), run_s=0.6)
    message = rig.controller.message
    assert message is not None and message.reason is Reason.HANDWHEEL_IGNORED
    rig.send(cmd.PushJoystick(x=1.0), run_s=0.3)
    message = rig.controller.message
    assert message is not None and message.reason is Reason.JOYSTICK_IGNORED
    assert rig.controller.axes.positions() == pytest.approx(before, abs=1e-4)
    rig.send(cmd.PushJoystick())
    rig.send(cmd.EnterManual(), run_s=0.5)  # what turned meanwhile moves nothing now
    assert rig.controller.axes.positions() == pytest.approx(before, abs=1e-4)


def test_a_counter_jump_is_alarm_e060_and_moves_nothing(manual: Rig) -> None:
    rig = manual
    rig.send(cmd.SelectHandwheel("X", 1))
    rig.send(cmd.HoldJogEnable(True))
    before = x(rig)
    rig.world.handwheel.jump(5_000)
    rig.run(0.1)
    assert rig.state is MachineState.ERROR
    assert any(a.code == "E060" for a in rig.controller.snapshot().alarms)
    assert x(rig) == before
    rig.send(cmd.Reset(), run_s=0.5)
    rig.send(cmd.EnterManual(), run_s=0.5)
    assert x(rig) == before


def test_after_a_reconnect_the_first_count_moves_nothing(manual: Rig) -> None:
    rig = manual
    rig.send(cmd.SelectHandwheel("X", 1))
    rig.send(cmd.HoldJogEnable(True))
    before = x(rig)
    rig.faults.inject("comms_loss", "io")
    rig.run(0.3)
    assert rig.state is MachineState.ERROR
    rig.world.handwheel.jump(9_000)  # counted while the link was down
    rig.faults.clear_injections()
    rig.send(cmd.Reset(), run_s=0.5)
    rig.send(cmd.EnterManual(), run_s=0.5)
    assert rig.state is MachineState.MANUAL
    assert not any(
        a.code == "E060" and a.state.value == "active" for a in rig.controller.snapshot().alarms
    )
    assert x(rig) == before
    rig.send(cmd.TurnHandwheel(10, 500.0), run_s=0.5)
    assert x(rig) == before + 0.01
