"""When the link fails: heartbeat loss, a rebooted node, missing TPDOs, a dead receive
thread, SDO aborts and timeouts. Each one must become an event and an error, be latched, and
recover only through configure() and activate(). The nodes are the simulated world's."""

from __future__ import annotations

import time

import pytest

from app.config import parse_config
from app.drivers.canopen.backend import create_backend
from app.drivers.cia402 import Cia402State
from app.drivers.contracts import (
    CommunicationError,
    DeviceEventKind,
    DriverError,
    LifecycleError,
    LifecycleState,
)
from tests.drivers.canopen.conftest import enable_all, machine_data, period, run_until, start
from tests.drivers.canopen.world_nodes import WorldBus

S = Cia402State


def periods_until_error(backend, seconds: float = 3.0) -> CommunicationError:
    """Run periods (real time passes) until the backend raises; fails after ``seconds``."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        try:
            period(backend, settle=False)
        except CommunicationError as exc:
            return exc
    raise AssertionError(f"no CommunicationError within {seconds} s")


def events_until(device, kind: DeviceEventKind, seconds: float = 2.0) -> list:
    """Poll ``device.events()`` until one of ``kind`` came (real time passes between polls,
    spent waiting on the bus condition, not sleeping)."""
    bus_wait = device._bus.wait  # the condition the receive thread notifies on every frame
    deadline = time.monotonic() + seconds
    events: list = []
    while not any(e.kind is kind for e in events):
        assert time.monotonic() < deadline, f"no {kind} event within {seconds} s: {events}"
        events += device.events()
        bus_wait(lambda: False, 0.01)
    return events


def kinds(events) -> list[tuple[DeviceEventKind, str]]:
    return [(e.kind, e.device) for e in events]


def test_heartbeat_loss_latches_until_reconfigured(backend, bus: WorldBus):
    start(backend)
    enable_all(backend)
    bus.drives["Y"].silence_heartbeat()
    error = periods_until_error(backend)
    assert error.device == "Y (node 2)" and "heartbeat lost" in str(error)
    assert (DeviceEventKind.COMMUNICATION_LOST, "Y (node 2)") in kinds(backend.motion.events())
    assert backend.motion.lifecycle_state is LifecycleState.ERROR
    # the drives still reachable were told to quick stop; nothing restarts them
    assert bus.drives["X"].wait(lambda: bus.drives["X"].drive.state is S.QUICK_STOP_ACTIVE)
    assert bus.drives["Z"].drive.state is S.QUICK_STOP_ACTIVE
    with pytest.raises(CommunicationError, match="heartbeat lost"):
        backend.motion.read_axes()
    with pytest.raises(CommunicationError):
        backend.motion.write_setpoints({"X": 0.0})
    with pytest.raises(CommunicationError):
        backend.motion.enable("X")
    with pytest.raises(LifecycleError):
        backend.motion.activate()  # configure first: the node may have lost its mapping

    bus.drives["Y"].silence_heartbeat(False)  # the heartbeat comes back
    events = events_until(backend.motion, DeviceEventKind.COMMUNICATION_RESTORED)
    assert (DeviceEventKind.COMMUNICATION_RESTORED, "Y (node 2)") in kinds(events)
    with pytest.raises(CommunicationError):  # heard again, but still latched
        backend.motion.read_axes()

    backend.motion.deactivate()  # the machine layer's reconnect: no exception
    backend.motion.configure()
    backend.motion.activate()
    feedback, _ = period(backend)
    assert not any(f.enabled for f in feedback.values())  # comes back disabled


def test_a_rebooted_drive_is_lost_and_forgets_homing(backend, bus: WorldBus):
    start(backend)
    enable_all(backend)
    backend.motion.start_homing("X")
    run_until(backend, lambda fb: fb["X"].homed and not fb["X"].homing_active, 2000)
    bus.drives["X"].reboot()
    error = periods_until_error(backend)
    assert "left OPERATIONAL" in str(error) or "heartbeat" in str(error)
    backend.motion.deactivate()
    backend.motion.configure()
    backend.motion.activate()
    assert not backend.motion.read_axes()["X"].homed


def test_missing_tpdos_are_a_lost_node(channel, bus: WorldBus):
    config = parse_config(machine_data(channel, pdo_miss_limit=3))
    backend = create_backend(config)
    try:
        start(backend)
        with bus.drives["Z"].lock:  # Z stops answering SYNC, its heartbeat goes on
            bus.drives["Z"].node.data_store[0x1800][1] = (0x183 | 1 << 31).to_bytes(4, "little")
        error = periods_until_error(backend)
        assert error.device == "Z (node 3)" and "no cyclic TPDO for 3 SYNCs" in str(error)
    finally:
        for device in backend.devices():
            device.shutdown()


@pytest.mark.filterwarnings("ignore::pytest.PytestUnhandledThreadExceptionWarning")
def test_a_dead_receive_thread_is_an_event_not_silence(backend, bus: WorldBus):
    start(backend)
    period(backend)
    can_bus = backend.extras["canopen"]
    can_bus.network.bus.shutdown()  # the interface goes away under the notifier
    periods_until_error(backend, 2.0)  # a send may notice it first: any error will do
    events = events_until(backend.motion, DeviceEventKind.RECEIVE_THREAD_DIED)
    events += backend.io.events()
    died = [e for e in events if e.kind is DeviceEventKind.RECEIVE_THREAD_DIED]
    assert len(died) == 1 and died[0].device == "CAN virtual:" + can_bus.settings.channel
    assert "CanOperationError" in died[0].text
    with pytest.raises(CommunicationError):
        backend.io.read_inputs()


def test_an_sdo_abort_fails_configure_with_its_code(backend, bus: WorldBus):
    bus.drives["Z"].reject[(0x6065, 0)] = 0x08000022
    with pytest.raises(DriverError) as caught:
        backend.motion.configure()
    error = caught.value
    assert error.device == "Z (node 3)" and error.code == 0x08000022
    assert "0x6065:00 following error window" in str(error)
    assert "present device state" in str(error)
    assert backend.motion.lifecycle_state is LifecycleState.ERROR
    del bus.drives["Z"].reject[(0x6065, 0)]
    backend.motion.configure()  # from ERROR, once the cause is gone
    backend.motion.activate()
    assert backend.motion.lifecycle_state is LifecycleState.ACTIVE


def test_an_unsupported_homing_method_is_refused_by_the_drive(channel, bus: WorldBus):
    data = machine_data(channel)
    data["backend"]["canopen"]["axes"]["X"]["homing_method"] = 24  # valid CiA, not this drive
    backend = create_backend(parse_config(data))
    try:
        with pytest.raises(
            DriverError,
            match=r"SDO abort 0x06090030 \(Value range of "
            r"parameter exceeded\) writing 0x6098:00",
        ):
            backend.motion.configure()
    finally:
        backend.motion.shutdown()


def test_a_node_that_does_not_answer(channel, bus: WorldBus):
    data = machine_data(channel, sdo_timeout_ms=50)
    data["backend"]["canopen"]["axes"]["Z"]["node_id"] = 4  # nobody there
    backend = create_backend(parse_config(data))
    try:
        with pytest.raises(CommunicationError, match=r"Z \(node 4\).*no SDO answer"):
            backend.motion.configure()
        assert backend.motion.lifecycle_state is LifecycleState.ERROR
    finally:
        backend.motion.shutdown()


def test_io_node_loss_stops_the_io_not_silently(backend, bus: WorldBus):
    start(backend)
    period(backend)
    bus.io.silence_heartbeat()
    error = periods_until_error(backend)
    assert error.device == "I/O (node 10)"
    assert (DeviceEventKind.COMMUNICATION_LOST, "I/O (node 10)") in kinds(backend.io.events())
    assert backend.motion.lifecycle_state is LifecycleState.ACTIVE
