"""Hardware limit switches: where they sit, the fault they cause, and the way out."""

from __future__ import annotations

import pytest

from app.drivers.cia402 import SW_INTERNAL_LIMIT, SW_WARNING, Cia402State
from app.drivers.contracts import DeviceEventKind
from tests.drivers.sim.rig import Rig, make_config

S = Cia402State


def rig_at(x: float, **axis_x: object) -> Rig:
    axes = {"X": {"encoder": "absolute", **axis_x}, "Y": {"encoder": "absolute"}}
    return Rig(make_config({"start_position": {"X": x, "Y": 300.0}}, axes=axes))


def reset_and_enable(rig: Rig, axis: str) -> None:
    rig.motion.fault_reset(axis)
    rig.tick(3)
    assert rig.state(axis) is S.SWITCH_ON_DISABLED
    rig.command[axis] = rig.fb(axis).position
    rig.enable(axis)


@pytest.mark.parametrize(
    ("start", "distance", "code", "flag"),
    [
        (3890.0, 30.0, 0xFF01, "limit_positive"),
        (5.0, -30.0, 0xFF02, "limit_negative"),
    ],
)
def test_running_onto_a_limit_switch_faults_where_the_switch_is(
    start: float, distance: float, code: int, flag: str
) -> None:
    rig = rig_at(start)
    rig.enable("X")
    rig.move("X", distance, 50.0, 500.0)
    fb = rig.fb("X")
    assert fb.faulted and fb.fault_code == code
    assert getattr(fb, flag)
    assert fb.statusword & SW_WARNING and fb.statusword & SW_INTERNAL_LIMIT
    switch = 3905.0 if distance > 0 else -10.0  # max + margin, min - margin
    assert abs(fb.position - switch) < 1.0  # stopped just past the switch
    events = rig.motion.events()
    assert [(e.kind, e.code) for e in events] == [(DeviceEventKind.EMERGENCY, code)]


def test_after_a_reset_motion_into_the_switch_faults_again_and_away_is_allowed() -> None:
    rig = rig_at(3890.0)
    rig.enable("X")
    rig.move("X", 30.0, 50.0, 500.0)
    assert rig.fb("X").fault_code == 0xFF01
    reset_and_enable(rig, "X")
    fb = rig.fb("X")
    assert fb.enabled and fb.limit_positive  # enabling on the switch is allowed
    rig.command["X"] += 0.05  # further in: refused by faulting again
    rig.tick(2)
    assert rig.fb("X").faulted and rig.fb("X").fault_code == 0xFF01
    reset_and_enable(rig, "X")
    rig.move("X", -10.0, 20.0, 200.0)  # away from the switch
    fb = rig.fb("X")
    assert fb.enabled and not fb.limit_positive and fb.fault_code == 0
    assert fb.position < 3900.0


def test_the_switch_position_follows_the_margin() -> None:
    rig = rig_at(3890.0, limit_switch_margin=0.0)
    rig.enable("X")
    rig.move("X", 9.0, 50.0, 500.0)  # to 3899: inside
    assert rig.fb("X").enabled
    rig.move("X", 2.0, 20.0, 500.0)  # to 3901: past max_position = the switch
    assert rig.fb("X").fault_code == 0xFF01


def test_a_disabled_axis_on_a_switch_shows_it_without_a_fault() -> None:
    rig = rig_at(-10.0)  # exactly on the negative switch
    rig.tick()
    fb = rig.fb("X")
    assert fb.limit_negative and not fb.limit_positive
    assert fb.power_state is S.SWITCH_ON_DISABLED and fb.fault_code == 0
    rig.enable("X")
    rig.move("X", 5.0, 10.0, 200.0)
    assert rig.fb("X").enabled and not rig.fb("X").limit_negative
