"""The position loop as the machine layer meets it through SimMotion: tracking, following
error, the current limit, quick stop, disabling while moving."""

from __future__ import annotations

import pytest

from app.drivers.cia402 import SW_FOLLOWING_ERROR, Cia402State
from app.drivers.contracts import AxisFeedback, DeviceEventKind
from app.drivers.sim.cia402 import EmcyCode
from tests.drivers.sim.rig import Rig, trapezoid

S = Cia402State


def following_errors(
    rig: Rig, axis: str, distance: float, velocity: float, acceleration: float
) -> list[AxisFeedback]:
    record: list[AxisFeedback] = []
    rig.move(axis, distance, velocity, acceleration, record=record.append)
    return record


def test_following_error_is_small_at_constant_velocity_and_grows_with_acceleration() -> None:
    peaks = []
    for acceleration in (500.0, 2000.0):
        rig = Rig.centred()
        rig.enable("X")
        record = following_errors(rig, "X", 400.0, 200.0, acceleration)
        accelerating = record[: round(200.0 / acceleration / rig.period_s)]
        cruising = [fb for fb in record if abs(fb.velocity - 200.0) < 1e-3]
        assert len(cruising) > 100
        # Velocity feed-forward: without it the error would be v / Kp = 3.3 mm.
        assert max(abs(fb.following_error) for fb in cruising) < 0.005
        peaks.append(max(abs(fb.following_error) for fb in accelerating))
        assert rig.fb("X").enabled and rig.fb("X").fault_code == 0
    assert peaks[0] > 0.002  # readable, not zero...
    assert peaks[1] > 2.5 * peaks[0]  # ...and larger with a larger acceleration


def test_the_axis_reaches_the_target_and_the_integral_removes_the_error() -> None:
    rig = Rig.centred()
    rig.enable("Y")
    rig.move("Y", 50.0, 100.0, 1000.0)
    rig.run(1.0)
    fb = rig.fb("Y")
    assert fb.position == pytest.approx(350.0, abs=2e-3)
    assert abs(fb.following_error) < 2e-3
    assert rig.world.drives["Y"].true_position == pytest.approx(fb.position)


def test_an_acceleration_beyond_the_current_limit_trips_following_error() -> None:
    rig = Rig.centred()
    rig.enable("X")
    # 300 mm/s from standstill within one period: 75 000 mm/s^2 against a 5 000 limit.
    bits = []
    for i in range(1, 40):
        rig.command["X"] = 1000.0 + 1.2 * i
        rig.tick()
        fb = rig.fb("X")
        bits.append(bool(fb.statusword & SW_FOLLOWING_ERROR))
        if fb.faulted:
            break
    fb = rig.fb("X")
    assert fb.faulted
    assert fb.fault_code == EmcyCode.FOLLOWING_ERROR == 0x8611
    assert any(bits)  # bit 13 was readable before the fault
    events = rig.motion.events()
    assert [(e.kind, e.device, e.code) for e in events] == [
        (DeviceEventKind.EMERGENCY, "X", 0x8611)
    ]
    rig.run(0.5)
    assert rig.state("X") is S.FAULT
    assert rig.fb("X").following_error == 0.0  # no torque, no demand


def test_quick_stop_brakes_and_holds_then_enable_continues() -> None:
    rig = Rig.centred()
    rig.enable("X")
    for position in trapezoid(400.0, 200.0, 2000.0, rig.period_s)[:300]:  # cruising
        rig.command["X"] = 1000.0 + position
        rig.tick()
    assert rig.fb("X").velocity == pytest.approx(200.0, abs=0.01)
    braking_from = rig.fb("X").position
    rig.motion.quick_stop("X")
    rig.tick()
    assert rig.state("X") is S.QUICK_STOP_ACTIVE
    rig.run(0.3)
    fb = rig.fb("X")
    assert fb.power_state is S.QUICK_STOP_ACTIVE and abs(fb.velocity) < 0.1
    # 200 mm/s braked at 0.6 x 2.5 x 2000 mm/s^2 = 3000 mm/s^2: 6.7 mm, plus one period.
    assert 6.5 < fb.position - braking_from < 8.0
    stopped_at = fb.position
    rig.run(0.5)
    assert rig.fb("X").position == pytest.approx(stopped_at, abs=0.01)  # held, not coasting
    rig.command["X"] = stopped_at
    rig.motion.enable("X")  # through SWITCH ON DISABLED: transitions 12, 2, 3, 4
    rig.tick(5)
    assert rig.fb("X").enabled


def test_disable_while_moving_lets_the_load_coast_against_friction() -> None:
    rig = Rig.centred()
    rig.enable("X")
    for position in trapezoid(400.0, 100.0, 2000.0, rig.period_s)[:300]:  # cruising
        rig.command["X"] = 1000.0 + position
        rig.tick()
    disabled_at = rig.fb("X").position
    rig.motion.disable("X")
    rig.tick()
    assert rig.state("X") is S.SWITCH_ON_DISABLED
    velocity = rig.fb("X").velocity
    assert velocity > 90.0  # no torque: nothing brakes but friction
    rig.run(5.0)
    assert rig.fb("X").velocity == 0.0
    # Coulomb friction 0.02 * 2000 mm/s^2: about v^2 / 2f = 125 mm of coasting.
    assert 100.0 < rig.fb("X").position - disabled_at < 150.0


def test_setpoints_are_ignored_until_enabled() -> None:
    rig = Rig.centred()
    rig.command["Y"] = 400.0
    rig.motion.write_setpoints(rig.command)
    rig.motion.advance(0.5)
    assert rig.fb("Y").position == 300.0


def test_enable_walks_shutdown_switch_on_enable_one_sync_each() -> None:
    rig = Rig.centred()
    rig.tick()
    seen = []
    rig.motion.enable("Z")
    for _ in range(4):
        rig.tick()
        seen.append(rig.state("Z"))
    assert seen == [S.READY_TO_SWITCH_ON, S.SWITCHED_ON, S.OPERATION_ENABLED, S.OPERATION_ENABLED]
    assert rig.world.drives["Z"].controlword == 0x0F


def test_all_axes_receive_their_targets_at_the_same_sync() -> None:
    rig = Rig.centred()
    rig.enable()
    rig.motion.write_setpoints({"X": 1000.4, "Y": 300.4, "Z": 0.04})
    rig.motion.advance(0.001)  # the SYNC is on the first substep of the period
    drives = rig.world.drives
    moved = [
        drives[a].position_demand - start for a, start in (("X", 1000.0), ("Y", 300.0), ("Z", 0.0))
    ]
    assert moved == pytest.approx([0.1, 0.1, 0.01])
