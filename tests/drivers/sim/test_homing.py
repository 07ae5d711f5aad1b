"""Homing as the drive does it: from either side of the home switch, from on it, in both
directions, with reversal at the limit switch; incremental and absolute encoders."""

from __future__ import annotations

from dataclasses import replace

import pytest

from app.drivers.cia402 import Cia402State, OperationMode
from app.drivers.contracts import AxisFeedback, DriverError
from tests.drivers.sim.rig import Rig, make_config

S = Cia402State
EDGE = 50.0  # home_switch_position of the test axis; the cam is 10 mm long


def homing_rig(
    start: float, direction: int = -1, encoder: str = "incremental", **sim: object
) -> Rig:
    axes = {
        "X": {
            "max_position": 300.0,
            "home_switch_position": EDGE,
            "homing_direction": direction,
            "homing_velocity": 40.0,
            "encoder": encoder,
        }
    }
    settings = {"start_position": {"X": start}, "home_switch_width": {"X": 10.0}, **sim}
    return Rig(make_config(settings, axes=axes))


def home(rig: Rig, axis: str = "X", timeout_s: float = 30.0) -> list[AxisFeedback]:
    """Enable, start homing, run until it ends; returns the feedback of every period."""
    rig.enable(axis)
    rig.motion.start_homing(axis)
    record: list[AxisFeedback] = []

    def ended() -> bool:
        fb = rig.fb(axis)
        record.append(fb)
        return len(record) > 3 and not fb.homing_active

    rig.run_until(ended, timeout_s)
    return record


def assert_homed_at_the_edge(rig: Rig, direction: int) -> None:
    fb = rig.fb("X")
    assert fb.homed and not fb.homing_active and fb.enabled
    # The master saw "homing attained" and "target reached", then returned to CSP.
    assert rig.world.drives["X"].mode is OperationMode.CYCLIC_SYNC_POSITION
    # Stopped just past the edge, in the homing direction (creep speed braked).
    assert 0.0 < (fb.position - EDGE) * direction < 0.05
    # The encoder now reads the machine frame: the same as a ruler on the machine.
    assert fb.position == pytest.approx(rig.world.drives["X"].true_position, abs=1e-9)


@pytest.mark.parametrize(
    ("start", "direction"),
    [
        (200.0, -1),  # on the side the search starts from
        (55.0, -1),  # close to the edge
        (20.0, -1),  # beyond the switch: reverses at the negative limit switch
        (45.0, -1),  # on the switch: moves off it first
        (20.0, 1),
        (70.0, 1),  # beyond the switch for a positive search: reverses at +limit
        (55.0, 1),  # on the switch
    ],
)
def test_homing_finds_the_switch_edge_from_anywhere(start: float, direction: int) -> None:
    rig = homing_rig(start, direction)
    record = home(rig, timeout_s=20.0)
    assert all(not fb.faulted for fb in record)
    assert any(fb.homing_active for fb in record)
    assert_homed_at_the_edge(rig, direction)


def test_from_beyond_the_switch_it_turns_at_the_limit_switch() -> None:
    rig = homing_rig(20.0, -1)
    record = home(rig)
    assert any(fb.limit_negative for fb in record)  # went to the switch, no fault
    assert_homed_at_the_edge(rig, -1)


def test_starting_on_the_switch_it_leaves_against_the_homing_direction() -> None:
    rig = homing_rig(45.0, -1)
    record = home(rig)
    assert record[0].home_switch
    first_motion = next(fb.velocity for fb in record if abs(fb.velocity) > 1.0)
    assert first_motion > 0.0  # up and off the cam, against the homing direction
    assert not any(fb.limit_negative for fb in record)
    assert_homed_at_the_edge(rig, -1)


def test_the_final_approach_is_slow() -> None:
    rig = homing_rig(200.0, -1)
    record = home(rig)
    on_switch = [i for i, fb in enumerate(record) if fb.home_switch]
    fast = max(abs(fb.velocity) for fb in record)
    assert fast == pytest.approx(40.0, rel=0.02)
    # The last entry onto the switch happens at the creep speed, a tenth of the search.
    last_entry = max(i for i in on_switch if not record[i - 1].home_switch)
    assert abs(record[last_entry - 1].velocity) == pytest.approx(4.0, rel=0.05)


def test_incremental_axis_starts_unhomed_reading_zero() -> None:
    rig = homing_rig(123.0, -1)
    fb = rig.fb("X")
    assert not fb.homed and fb.position == 0.0
    assert rig.world.drives["X"].true_position == 123.0
    home(rig)
    assert rig.fb("X").homed
    assert rig.fb("X").position == pytest.approx(EDGE, abs=0.05)


def test_absolute_axis_starts_homed_in_the_machine_frame() -> None:
    rig = homing_rig(123.0, -1, encoder="absolute")
    fb = rig.fb("X")
    assert fb.homed and fb.position == 123.0
    home(rig)  # homing an absolute axis is allowed and keeps the frame
    assert_homed_at_the_edge(rig, -1)


def test_incremental_start_positions_are_seeded_and_inside_the_travel() -> None:
    def start(seed: int) -> float:
        world = Rig(make_config({"seed": seed})).world
        return world.drives["X"].true_position

    assert start(1) == start(1)
    assert start(1) != start(2)
    assert all(-5.0 <= start(s) <= 3900.0 for s in range(5))


def test_targets_are_ignored_while_homing_and_followed_after() -> None:
    rig = homing_rig(200.0, -1)
    rig.enable("X")
    rig.motion.start_homing("X")
    rig.tick(3)
    assert rig.fb("X").homing_active
    rig.motion.write_setpoints({"X": 1000.0})  # would be a huge jump in CSP
    rig.motion.advance(0.1)
    assert rig.fb("X").homing_active and not rig.fb("X").faulted
    rig.run_until(lambda: not rig.fb("X").homing_active, 10.0)
    assert rig.fb("X").homed
    rig.command["X"] = rig.fb("X").position
    rig.move("X", 20.0, 50.0, 500.0)  # the first write switches back to CSP
    fb = rig.fb("X")
    assert fb.enabled and fb.position == pytest.approx(EDGE + 20.0, abs=0.06)
    assert rig.world.drives["X"].mode is OperationMode.CYCLIC_SYNC_POSITION
    assert fb.homed


def test_homing_fails_with_a_fault_when_no_switch_is_found() -> None:
    # The configuration is valid (the switch within the travel), but on the machine the cam
    # has been moved beyond the negative limit switch: the search reverses there and runs to
    # the positive limit switch without ever seeing it. (A configuration that puts the switch
    # there is refused before anything runs: see tests/test_config_hardening.py.)
    axes = {"X": {"max_position": 150.0, "homing_direction": -1, "homing_velocity": 40.0}}
    rig = Rig(
        make_config({"start_position": {"X": 100.0}, "home_switch_width": {"X": 5.0}}, axes=axes)
    )
    drive = rig.world.drives["X"]
    drive.params = replace(drive.params, home_cam_low=-45.0, home_cam_high=-40.0)
    record = home(rig)
    fb = rig.fb("X")
    assert fb.faulted and fb.fault_code == 0xFF03
    assert not fb.homed
    assert any(r.limit_negative for r in record)
    events = rig.motion.events()
    assert [e.code for e in events] == [0xFF03]


def test_homing_is_not_started_on_a_disabled_drive() -> None:
    rig = homing_rig(200.0, -1)
    with pytest.raises(DriverError, match="homing needs OPERATION ENABLED"):
        rig.motion.start_homing("X")
    rig.run(0.5)
    fb = rig.fb("X")
    assert not fb.homing_active and not fb.homed
    assert rig.world.drives["X"].true_position == 200.0


def test_disabling_interrupts_homing() -> None:
    rig = homing_rig(200.0, -1)
    rig.enable("X")
    rig.motion.start_homing("X")
    rig.run(0.5)
    rig.motion.disable("X")
    rig.tick(2)
    fb = rig.fb("X")
    assert not fb.homing_active and not fb.homed
    assert fb.power_state is S.SWITCH_ON_DISABLED


def test_the_tilt_axis_homes_in_degrees() -> None:
    rig = Rig(make_config({"start_position": {"Z": 3.0}}))
    home(rig, "Z", timeout_s=30.0)
    fb = rig.fb("Z")
    assert fb.homed and fb.position == pytest.approx(-15.0, abs=0.02)


@pytest.mark.parametrize("start", [250.0, 20.0])
def test_a_short_cam_overrun_while_braking_is_found_on_the_way_back(start: float) -> None:
    # 200 mm/s braked at 500 mm/s^2 runs 40 mm past a 2 mm cam: its far edge must not be
    # taken for the reference edge.
    axes = {
        "X": {
            "max_position": 300.0,
            "home_switch_position": EDGE,
            "homing_direction": -1,
            "homing_velocity": 200.0,
            "jog_acceleration": 500.0,
        }
    }
    rig = Rig(
        make_config({"start_position": {"X": start}, "home_switch_width": {"X": 2.0}}, axes=axes)
    )
    home(rig)
    fb = rig.fb("X")
    # Latched at the edge (the frame is exact), stopped 20^2 / (2 * 500) = 0.4 mm past it.
    assert fb.homed and fb.position == pytest.approx(rig.world.drives["X"].true_position)
    assert 0.3 < EDGE - fb.position < 0.5
