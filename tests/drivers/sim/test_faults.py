"""Every fault kind, injected through ``extras["faults"]``, shows what the real hardware would:
a statusword fault, an EMCY code, a missing reply, a sensor that stays off."""

from __future__ import annotations

import pytest

from app.drivers.cia402 import SW_FOLLOWING_ERROR, Cia402State
from app.drivers.contracts import (
    FAULT_KINDS,
    CommunicationError,
    DeviceEventKind,
    FaultInjector,
    LifecycleState,
    OutputImage,
)
from app.drivers.sim.faults import fault_targets
from tests.drivers.sim.rig import Rig

S = Cia402State


def reset(rig: Rig, axis: str) -> None:
    rig.motion.fault_reset(axis)
    rig.tick(3)


def test_the_injector_is_a_fault_injector_and_knows_every_kind() -> None:
    rig = Rig.centred()
    assert isinstance(rig.faults, FaultInjector)
    for kind in FAULT_KINDS:
        for target in fault_targets(kind):
            rig.faults.inject(kind, target)
        rig.motion.advance(0.2)
        rig.faults.clear_injections()
        assert rig.faults.active == ()
    assert rig.world.link_ok("drives") and rig.world.link_ok("io")
    assert rig.io.read_inputs().estop_ok


@pytest.mark.parametrize(
    ("kind", "target", "allowed"),
    [
        ("melted_cable", "", "one of drive_fault, following_error"),
        ("drive_fault", "", "one of 'X', 'Y', 'Z'"),
        ("drive_fault", "W", "one of 'X', 'Y', 'Z'"),
        ("limit_switch", "X*", "'X+', 'X-'"),
        ("estop", "X", "one of ''"),
        ("comms_loss", "modem", "'drives', 'io', 'gauge'"),
    ],
)
def test_bad_kinds_and_targets_are_named_with_what_is_allowed(
    kind: str, target: str, allowed: str
) -> None:
    rig = Rig.centred()
    with pytest.raises(ValueError) as info:
        rig.faults.inject(kind, target)
    assert repr(kind if kind == "melted_cable" else target) in str(info.value)
    assert allowed in str(info.value)


@pytest.mark.parametrize("axis", ["X", "Y", "Z"])
def test_drive_fault_faults_at_once_and_resets_only_once_cleared(axis: str) -> None:
    rig = Rig.centred()
    rig.enable()
    rig.faults.inject("drive_fault", axis)
    rig.tick()
    fb = rig.fb(axis)
    assert fb.power_state is S.FAULT and fb.fault_code == 0x2310
    assert [(e.kind, e.device, e.code) for e in rig.motion.events()] == [
        (DeviceEventKind.EMERGENCY, axis, 0x2310)
    ]
    others = [a for a in "XYZ" if a != axis]
    assert all(rig.fb(a).enabled for a in others)
    reset(rig, axis)
    assert rig.state(axis) is S.FAULT  # the cause is still there
    rig.faults.clear_injections()
    assert rig.state(axis) is S.FAULT  # latched until reset
    reset(rig, axis)
    assert rig.state(axis) is S.SWITCH_ON_DISABLED and rig.fb(axis).fault_code == 0
    rig.run(0.5)
    assert rig.state(axis) is S.SWITCH_ON_DISABLED  # nothing re-enables by itself


def test_following_error_fault_comes_from_a_jam_when_the_axis_is_moved() -> None:
    rig = Rig.centred()
    rig.enable("Y")
    rig.faults.inject("following_error", "Y")
    rig.run(0.5)
    assert rig.fb("Y").enabled  # standing still, a jam shows nothing
    bits = []
    start = rig.command["Y"]
    for i in range(1, 200):
        rig.command["Y"] = start + 0.2 * i
        rig.tick()
        fb = rig.fb("Y")
        bits.append(bool(fb.statusword & SW_FOLLOWING_ERROR))
        if fb.faulted:
            break
    fb = rig.fb("Y")
    assert fb.faulted and fb.fault_code == 0x8611
    assert any(bits)
    assert rig.world.drives["Y"].true_position == 300.0  # it never moved
    assert [e.code for e in rig.motion.events()] == [0x8611]


@pytest.mark.parametrize(
    ("target", "code", "flag", "away"),
    [
        ("X", 0xFF01, "limit_positive", -5.0),
        ("X+", 0xFF01, "limit_positive", -5.0),
        ("X-", 0xFF02, "limit_negative", 5.0),
        ("Y+", 0xFF01, "limit_positive", -5.0),
    ],
)
def test_limit_switch_hit(target: str, code: int, flag: str, away: float) -> None:
    axis = target[0]
    rig = Rig.centred()
    rig.enable(axis)
    rig.faults.inject("limit_switch", target)
    rig.tick()
    fb = rig.fb(axis)
    assert fb.faulted and fb.fault_code == code and getattr(fb, flag)
    reset(rig, axis)
    rig.command[axis] = rig.fb(axis).position
    rig.enable(axis)
    rig.move(axis, away, 20.0, 200.0)  # away from the switch: allowed
    assert rig.fb(axis).enabled
    rig.move(axis, -away, 20.0, 200.0)  # back towards it: refused
    assert rig.fb(axis).faulted and rig.fb(axis).fault_code == code
    rig.faults.clear_injections()
    assert not getattr(rig.fb(axis), flag)


def test_estop_brakes_the_axes_then_removes_torque_and_nothing_restarts() -> None:
    rig = Rig.centred()
    rig.enable()
    rig.io.write_outputs(OutputImage(spindle_on=True))
    start = rig.command["X"]
    for i in range(1, 60):  # X accelerates to about 150 mm/s
        rig.command["X"] = start + 0.01 * i * i
        rig.tick()
    rig.faults.inject("estop")
    rig.tick()
    assert not rig.io.read_inputs().estop_ok
    assert rig.state("X") is S.QUICK_STOP_ACTIVE  # stop category 1: braking first
    rig.run(0.2)
    assert all(rig.state(a) is S.SWITCH_ON_DISABLED for a in "XYZ")
    assert rig.fb("X").velocity == 0.0
    assert not rig.world.io.spindle.contactor
    rig.motion.enable("X")
    rig.run(0.1)
    assert rig.state("X") is S.SWITCH_ON_DISABLED  # refused while the chain is open
    rig.faults.clear_injections()
    rig.run(0.5)
    assert rig.io.read_inputs().estop_ok
    assert all(rig.state(a) is S.SWITCH_ON_DISABLED for a in "XYZ")
    assert not rig.io.read_inputs().spindle_running
    rig.command["X"] = rig.fb("X").position
    rig.enable("X")  # an operator's action enables again
    assert rig.fb("X").enabled and rig.fb("X").fault_code == 0


def test_estop_removes_torque_after_the_relay_time_even_while_still_moving() -> None:
    rig = Rig.centred(estop_stop_time_s=0.0)
    rig.enable("X")
    start = rig.command["X"]
    for i in range(1, 60):
        rig.command["X"] = start + 0.01 * i * i
        rig.tick()
    rig.world.set_estop(True)
    rig.tick()
    fb = rig.fb("X")
    assert fb.power_state is S.SWITCH_ON_DISABLED and fb.velocity > 100.0  # coasting


def test_comms_loss_makes_every_call_fail_and_drives_fault_on_heartbeat() -> None:
    rig = Rig.centred()
    rig.enable()
    rig.io.write_outputs(OutputImage(clamps_close=True, lamp_green=True))
    rig.faults.inject("comms_loss")
    for call in (
        rig.motion.read_axes,
        rig.io.read_inputs,
        lambda: rig.motion.write_setpoints({"X": 1000.0}),
        lambda: rig.motion.enable("X"),
        lambda: rig.motion.fault_reset("X"),
        lambda: rig.io.write_outputs(OutputImage()),
    ):
        with pytest.raises(CommunicationError, match=r"no reply|the link was lost"):
            call()
    assert rig.motion.lifecycle_state is LifecycleState.ERROR  # latched by the first call
    assert rig.io.lifecycle_state is LifecycleState.ERROR
    assert [e.kind for e in rig.motion.events()] == [DeviceEventKind.COMMUNICATION_LOST]
    assert [e.kind for e in rig.io.events()] == [DeviceEventKind.COMMUNICATION_LOST]
    rig.motion.advance(0.05)
    assert rig.world.outputs.clamps_close  # the coupler waits for its watchdog...
    rig.motion.advance(0.1)
    assert rig.world.outputs == OutputImage()  # ...then switches every output off
    rig.faults.clear_injections()
    with pytest.raises(CommunicationError, match="the link was lost"):
        rig.motion.read_axes()  # the link is back, the loss stays latched until configure
    events = rig.motion.events()  # the EMCYs were sent while nobody listened: lost
    assert [e.kind for e in events] == [DeviceEventKind.COMMUNICATION_RESTORED]
    assert [e.kind for e in rig.io.events()] == [DeviceEventKind.COMMUNICATION_RESTORED]
    for device in (rig.motion, rig.io):  # the operator's reset reopens the links
        device.configure()
        device.activate()
    feedback = rig.motion.read_axes()
    assert all(fb.faulted and fb.fault_code == 0x8130 for fb in feedback.values())
    for axis in "XYZ":
        reset(rig, axis)
    assert all(rig.state(a) is S.SWITCH_ON_DISABLED for a in "XYZ")


def test_a_short_comms_loss_leaves_the_drives_running() -> None:
    rig = Rig.centred()
    rig.enable("X")
    rig.faults.inject("comms_loss", "drives")
    rig.motion.advance(0.05)  # shorter than the 0.1 s heartbeat timeout
    assert rig.io.read_inputs().estop_ok  # the I/O link is still up
    rig.faults.clear_injections()
    assert rig.fb("X").enabled


def test_comms_loss_of_the_io_alone() -> None:
    rig = Rig.centred()
    rig.faults.inject("comms_loss", "io")
    with pytest.raises(CommunicationError):
        rig.io.read_inputs()
    rig.tick()  # motion still works
    assert rig.motion.events() == []


@pytest.mark.parametrize(
    ("kind", "target", "output", "dead", "alive"),
    [
        ("clamp_sensor", "", "clamps_close", "clamps_closed", "clamps_open"),
        ("clamp_sensor", "closed", "clamps_close", "clamps_closed", "clamps_open"),
        ("clamp_sensor", "open", "clamps_close", "clamps_open", "clamps_closed"),
        ("centering_sensor", "", "centering_extend", "centering_extended", "centering_retracted"),
        (
            "centering_sensor",
            "retracted",
            "centering_extend",
            "centering_retracted",
            "centering_extended",
        ),
    ],
)
def test_a_sensor_that_never_arrives(
    kind: str, target: str, output: str, dead: str, alive: str
) -> None:
    rig = Rig.centred()
    rig.faults.inject(kind, target)
    seen: set[str] = set()
    for command in (True, False, True, False):
        rig.io.write_outputs(OutputImage(**{output: command}))
        for _ in range(500):  # 2 s, far longer than any stroke
            rig.tick()
            image = rig.io.read_inputs()
            seen |= {name for name in (dead, alive) if getattr(image, name)}
    assert dead not in seen and alive in seen  # the device moved, one sensor is dead
    rig.faults.clear_injections()
    rig.io.write_outputs(OutputImage(**{output: dead in ("clamps_closed", "centering_extended")}))
    rig.run(2.0)
    assert getattr(rig.io.read_inputs(), dead)


def test_spindle_that_does_not_start() -> None:
    rig = Rig.centred()
    rig.faults.inject("spindle")
    rig.io.write_outputs(OutputImage(spindle_on=True))
    rig.run(5.0)
    assert rig.world.io.spindle.contactor and not rig.io.read_inputs().spindle_running
    rig.faults.clear_injections()
    rig.run(2.1)
    assert rig.io.read_inputs().spindle_running
