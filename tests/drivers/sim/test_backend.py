"""The adapters' lifecycle, refusals and bookkeeping, as the machine layer meets them."""

from __future__ import annotations

import math

import pytest

from app.drivers import registry
from app.drivers.contracts import (
    CommunicationError,
    LifecycleError,
    LifecycleState,
    MachineBackend,
    OutputImage,
    TimeDriven,
)
from app.drivers.sim.backend import SimMotion
from app.drivers.sim.faults import SimFaultInjector
from app.drivers.sim.world import SimWorld
from tests.drivers.sim.rig import Rig, make_config

L = LifecycleState


def fresh() -> MachineBackend:
    return registry.create_backend(make_config({"start_position": {"X": 1000.0}}))


def test_the_registry_builds_the_sim_configured_not_active() -> None:
    backend = fresh()
    assert backend.name == "sim"
    assert backend.motion.lifecycle_state is L.INACTIVE
    assert backend.io.lifecycle_state is L.INACTIVE
    assert isinstance(backend.extras["world"], SimWorld)
    assert isinstance(backend.extras["faults"], SimFaultInjector)
    assert isinstance(backend.motion, TimeDriven)  # the loop advances the world through it
    assert not isinstance(backend.io, TimeDriven)  # and through nothing else


@pytest.mark.parametrize(
    "call",
    [
        lambda m: m.write_setpoints({"X": 1.0}),
        lambda m: m.enable("X"),
        lambda m: m.fault_reset("X"),
        lambda m: m.start_homing("X"),
    ],
)
def test_motion_commands_are_refused_unless_active(call) -> None:
    backend = fresh()
    with pytest.raises(LifecycleError, match="the device is inactive, it must be active"):
        call(backend.motion)
    backend.motion.read_axes()  # reading is allowed while inactive
    backend.motion.shutdown()
    with pytest.raises(LifecycleError, match="finalized"):
        call(backend.motion)
    with pytest.raises(LifecycleError):
        backend.motion.read_axes()


def test_io_writes_are_refused_unless_active() -> None:
    backend = fresh()
    with pytest.raises(LifecycleError, match="write_outputs refused"):
        backend.io.write_outputs(OutputImage())
    assert backend.io.read_inputs().estop_ok
    backend.io.activate()
    backend.io.write_outputs(OutputImage(lamp_green=True))


def test_lifecycle_transitions_are_strict() -> None:
    backend = fresh()
    motion = backend.motion
    motion.configure()  # again: how a lost link is reopened
    motion.deactivate()  # not active: nothing to do
    assert motion.lifecycle_state is L.INACTIVE
    motion.activate()
    with pytest.raises(LifecycleError, match="activate refused: the device is active"):
        motion.activate()
    with pytest.raises(LifecycleError, match="configure refused: the device is active"):
        motion.configure()
    motion.deactivate()
    assert motion.lifecycle_state is L.INACTIVE
    motion.shutdown()
    motion.shutdown()
    assert motion.lifecycle_state is L.FINALIZED


def test_a_failed_transition_ends_in_error_and_configure_recovers() -> None:
    backend = fresh()
    faults = backend.extras["faults"]
    assert isinstance(faults, SimFaultInjector)
    faults.inject("comms_loss")
    with pytest.raises(CommunicationError, match="activate failed"):
        backend.motion.activate()
    assert backend.motion.lifecycle_state is L.ERROR
    with pytest.raises(CommunicationError):
        backend.io.activate()
    assert backend.io.lifecycle_state is L.ERROR
    faults.clear_injections()
    backend.motion.configure()
    backend.motion.activate()
    assert backend.motion.lifecycle_state is L.ACTIVE


def test_activation_sets_the_command_to_the_measured_position() -> None:
    rig = Rig.centred()
    rig.motion.write_setpoints({"X": 1234.0})  # never followed: X is not enabled
    rig.motion.deactivate()
    rig.motion.activate()
    assert rig.motion.command_positions["X"] == rig.fb("X").position == 1000.0
    rig.motion.enable("X")
    rig.motion.advance(0.5)
    assert rig.fb("X").enabled and rig.fb("X").position == pytest.approx(1000.0, abs=1e-9)


def test_deactivation_disables_the_drives_and_switches_the_outputs_off() -> None:
    rig = Rig.centred()
    rig.enable()
    rig.io.write_outputs(OutputImage(clamps_close=True, spindle_on=True))
    rig.motion.deactivate()
    rig.io.deactivate()
    rig.motion.advance(0.01)
    assert not any(fb.enabled for fb in rig.motion.read_axes().values())
    assert rig.world.outputs == OutputImage()


def test_bad_axis_names_and_setpoints_are_named() -> None:
    rig = Rig.centred()
    with pytest.raises(ValueError, match=r"axis = 'W' is not allowed: one of X, Y, Z"):
        rig.motion.enable("W")
    with pytest.raises(ValueError, match=r"setpoint X = nan is not allowed: a finite number"):
        rig.motion.write_setpoints({"X": math.nan})
    with pytest.raises(ValueError, match=r"axis = 'A'"):
        rig.motion.write_setpoints({"A": 1.0})


def test_an_enable_refused_by_the_drive_is_given_up_and_not_retried_later() -> None:
    rig = Rig.centred()
    rig.world.set_estop(True)
    rig.motion.enable("X")
    rig.run(0.1)
    rig.world.set_estop(False)
    rig.run(0.5)
    assert not rig.fb("X").enabled  # no pending request powered it after the release
    assert rig.world.drives["X"].controlword == 0x00


def test_axis_names_and_motion_type() -> None:
    rig = Rig.centred()
    assert isinstance(rig.motion, SimMotion)
    assert rig.motion.axis_names == ("X", "Y", "Z")
