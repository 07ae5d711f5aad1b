"""One contract, three backends: the master's and the lifecycle's rules, checked on the
simulation, on Modbus TCP against the emulator (loopback) and on CANopen on python-can's
virtual bus. A rule that holds on one backend and not on another fails here.

Each backend is wrapped in a :class:`Bench` with the same four gestures (one machine period,
a drive fault injected, its cause cleared, the backend's devices), so that the tests read the
same for all three."""

from __future__ import annotations

import uuid
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

import pytest

from app.config import parse_config
from app.drivers.canopen.backend import create_backend as create_canopen
from app.drivers.cia402 import Cia402State
from app.drivers.contracts import (
    AxisFeedback,
    CommunicationError,
    DriverError,
    LifecycleError,
    LifecycleState,
    MachineBackend,
    OutputImage,
)
from app.drivers.modbus.backend import create_backend as create_modbus
from app.drivers.modbus.emulator import ModbusEmulator
from app.drivers.sim.backend import create_backend as create_sim
from app.drivers.sim.world import SimWorld
from tests.drivers.canopen import conftest as can_rig
from tests.drivers.modbus.helpers import machine_table, tcp_modbus, with_port
from tests.drivers.sim.rig import make_config

S = Cia402State
L = LifecycleState
OVERCURRENT = 0x2310
AXIS = "Y"
LINK_LOSS_PERIODS = 100  # more than any backend needs to notice a silent bus


@dataclass
class Bench:
    """A backend under test and the simulated machine behind it."""

    backend: MachineBackend
    world: SimWorld  # the machine behind the bus, the same model on every backend
    inject_fault: Callable[[str], None]
    clear_fault: Callable[[str], None]
    advance: Callable[[], None]  # lets the machine behind the bus move on by one period

    def period(self) -> dict[str, AxisFeedback]:
        """One machine period: read everything, then write everything (the machine loop)."""
        feedback = dict(self.backend.motion.read_axes())
        self.backend.io.read_inputs()
        self.backend.motion.write_setpoints({n: fb.position for n, fb in feedback.items()})
        self.backend.io.write_outputs(OutputImage())
        self.advance()
        return feedback

    def until(self, done: Callable[[AxisFeedback], bool], periods: int = 200) -> AxisFeedback:
        for _ in range(periods):
            feedback = self.period()[AXIS]
            if done(feedback):
                return feedback
        raise AssertionError(f"not reached in {periods} periods: {feedback}")

    def start(self) -> None:
        for device in self.backend.devices():
            device.configure()
        for device in self.backend.devices():
            device.activate()


def sim_bench() -> Iterator[Bench]:
    config = make_config({"start_position": {"X": 1000.0, "Y": 300.0, "Z": 0.0}})
    backend = create_sim(config)
    world = backend.extras["world"]
    assert isinstance(world, SimWorld)
    drives = world.drives
    yield Bench(
        backend,
        world,
        lambda axis: drives[axis].inject_power_stage_fault(True),
        lambda axis: drives[axis].inject_power_stage_fault(False),
        lambda: backend.motion.advance(config.period_s),  # type: ignore[attr-defined]
    )
    for device in backend.devices():
        device.shutdown()


def modbus_bench(**modbus: Any) -> Iterator[Bench]:
    table: dict[str, Any] = machine_table(tcp_modbus(**modbus), period_ms=20.0)
    emulator = ModbusEmulator(parse_config(table))
    try:
        backend = create_modbus(with_port(table, emulator.serve_tcp()))
        drives = emulator.world.drives
        yield Bench(
            backend,
            emulator.world,
            lambda axis: drives[axis].inject_power_stage_fault(True),
            lambda axis: drives[axis].inject_power_stage_fault(False),
            lambda: None,  # the emulator advances when the drives are read
        )
        for device in backend.devices():
            device.shutdown()
    finally:
        emulator.stop()


def canopen_bench() -> Iterator[Bench]:
    """The world's drives and I/O as CANopen nodes on a virtual channel of this test's own."""
    channel = f"stave-contract-{uuid.uuid4().hex[:12]}"
    config = parse_config(can_rig.machine_data(channel))
    world = SimWorld.from_config(config)
    bus = can_rig.world_bus(world, channel)
    drives = world.drives
    try:
        backend = create_canopen(config)
        canopen = backend.extras["canopen"]
        yield Bench(
            backend,
            world,
            lambda axis: drives[axis].inject_power_stage_fault(True),
            lambda axis: drives[axis].inject_power_stage_fault(False),
            lambda: None if canopen.wait_for_answers(1.0) else pytest.fail("no TPDO answers"),
        )
        for device in backend.devices():
            device.shutdown()
    finally:
        bus.close()


BENCHES = {"sim": sim_bench, "modbus": modbus_bench, "canopen": canopen_bench}


@pytest.fixture(params=list(BENCHES))
def bench(request: pytest.FixtureRequest) -> Iterator[Bench]:
    yield from BENCHES[request.param]()


@pytest.fixture(params=list(BENCHES))
def silent_bench(request: pytest.FixtureRequest) -> Iterator[Bench]:
    """A bench whose silence is noticed quickly: Modbus gives up on a reply after 100 ms
    (silence is what the test makes, so the generous timeout would only cost time)."""
    if request.param == "modbus":
        yield from modbus_bench(timeout_ms=100.0, retries=0)
    else:
        yield from BENCHES[request.param]()


# ---- the lifecycle ---------------------------------------------------------------------------


def test_the_lifecycle_transitions(bench: Bench) -> None:
    motion = bench.backend.motion
    for device in bench.backend.devices():
        device.configure()
        device.configure()  # again: how a lost link is reopened
        device.deactivate()  # not active: nothing to do
        assert device.lifecycle_state is L.INACTIVE
    for device in bench.backend.devices():
        device.activate()
        assert device.lifecycle_state is L.ACTIVE
    with pytest.raises(LifecycleError):
        motion.activate()
    with pytest.raises(LifecycleError):
        motion.configure()
    for device in bench.backend.devices():
        device.deactivate()
        device.deactivate()
        assert device.lifecycle_state is L.INACTIVE
        device.shutdown()
        device.shutdown()
        assert device.lifecycle_state is L.FINALIZED
    with pytest.raises(LifecycleError):
        motion.configure()


def test_requests_that_move_need_an_active_backend_the_safe_ones_do_not(bench: Bench) -> None:
    motion = bench.backend.motion
    for device in bench.backend.devices():
        device.configure()
    for request in (motion.enable, motion.fault_reset, motion.start_homing):
        with pytest.raises(LifecycleError):
            request(AXIS)
    motion.disable(AXIS)  # the safe direction: always accepted
    motion.quick_stop(AXIS)


# ---- the master ------------------------------------------------------------------------------


def test_enable_reaches_operation_enabled_and_disable_leaves_it(bench: Bench) -> None:
    bench.start()
    bench.period()
    bench.backend.motion.enable(AXIS)
    bench.until(lambda fb: fb.enabled, 50)
    bench.backend.motion.disable(AXIS)
    bench.until(lambda fb: fb.power_state is S.SWITCH_ON_DISABLED, 50)


def test_homing_needs_an_enabled_drive(bench: Bench) -> None:
    bench.start()
    bench.period()
    with pytest.raises(DriverError, match="homing needs OPERATION ENABLED"):
        bench.backend.motion.start_homing(AXIS)


def test_a_fault_is_kept_enable_is_refused_and_reset_ends_disabled(bench: Bench) -> None:
    motion = bench.backend.motion
    bench.start()
    bench.period()
    motion.enable(AXIS)
    bench.until(lambda fb: fb.enabled, 50)
    bench.inject_fault(AXIS)
    faulted = bench.until(lambda fb: fb.faulted, 100)
    assert faulted.fault_code == OVERCURRENT
    with pytest.raises(DriverError, match="fault reset comes first"):
        motion.enable(AXIS)
    bench.clear_fault(AXIS)
    for _ in range(20):  # the cause is gone: nothing resets or enables the drive by itself
        assert bench.period()[AXIS].faulted
    motion.fault_reset(AXIS)  # an operator's Reset
    bench.until(lambda fb: fb.power_state is S.SWITCH_ON_DISABLED, 50)
    for _ in range(20):
        assert bench.period()[AXIS].power_state is S.SWITCH_ON_DISABLED  # not enabled
    motion.enable(AXIS)  # a new request walks it up again
    bench.until(lambda fb: fb.enabled, 50)


def test_quick_stop_holds_and_enable_goes_through_switch_on_disabled(bench: Bench) -> None:
    motion = bench.backend.motion
    bench.start()
    bench.period()
    motion.enable(AXIS)
    bench.until(lambda fb: fb.enabled, 50)
    motion.quick_stop(AXIS)
    bench.until(lambda fb: fb.power_state is S.QUICK_STOP_ACTIVE, 50)
    for _ in range(5):
        assert bench.period()[AXIS].power_state is S.QUICK_STOP_ACTIVE  # held
    motion.enable(AXIS)
    states = []
    feedback = bench.until(lambda fb: states.append(fb.power_state) or fb.enabled, 50)
    assert feedback.enabled and S.SWITCH_ON_DISABLED in states


def test_a_call_that_fails_with_the_link_down_latches_error(silent_bench: Bench) -> None:
    """The call that finds the link down leaves the device in ERROR: once the link is back,
    nothing goes on as if it had not happened until configure has reopened it."""
    bench = silent_bench
    motion = bench.backend.motion
    bench.start()
    bench.period()
    bench.world.set_link("drives", False)
    with pytest.raises(CommunicationError):
        for _ in range(LINK_LOSS_PERIODS):
            feedback = motion.read_axes()
            motion.write_setpoints({n: fb.position for n, fb in feedback.items()})
    assert motion.lifecycle_state is L.ERROR
    bench.world.set_link("drives", True)
    assert motion.lifecycle_state is L.ERROR  # still latched with the link back
    with pytest.raises(DriverError):
        motion.enable(AXIS)
    for device in bench.backend.devices():  # the operator's Reset reopens what was lost
        if device.lifecycle_state is not L.ACTIVE:
            device.configure()
            device.activate()
    assert motion.lifecycle_state is L.ACTIVE
    assert not bench.period()[AXIS].faulted
