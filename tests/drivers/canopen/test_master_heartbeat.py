"""The controller's own heartbeat and the drives watching it (0x1016): sent from activation to
deactivation at its period, written into every drive, refused configurations named, and an
enabled drive that stops by itself when the controller dies.

The drives are the simulated world's (:mod:`tests.drivers.canopen.world_nodes`): a drive
that hears no controller faults with 0x8130 and brakes on its fault reaction ramp.

Time: the heartbeat is real time. Its period is checked on the frames' own send timestamps
over ten periods, with bounds of half and four times the nominal span, and "no more frames"
is judged against the simulated drives' heartbeats, which go on at the same period: no
sleeps, no tight timing. When the controller dies no SYNC comes any more, so the drives run
on their own clock (``own_clock``): world time follows real time, and a fault reaction ends
as it would on the machine."""

from __future__ import annotations

import threading
from collections.abc import Iterator

import pytest

from app.config import MachineConfig, parse_config
from app.drivers.canopen import objects as obj
from app.drivers.canopen.backend import create_backend
from app.drivers.cia402 import Cia402State
from app.drivers.contracts import (
    CommunicationError,
    DeviceEventKind,
    DriverError,
    LifecycleState,
    MachineBackend,
)
from app.drivers.sim.cia402 import EmcyCode
from tests.drivers.canopen.conftest import (
    enable_all,
    machine_data,
    period,
    run_until,
    start,
    world_bus,
    zero_world,
)
from tests.drivers.canopen.sim_nodes import SimNetwork
from tests.drivers.canopen.world_nodes import WorldBus, WorldDrive

S = Cia402State
TIMEOUT_S = 3.0  # bound of every wait; the consumer time in these tests is 250 ms
EMCY_HEARTBEAT = int(EmcyCode.HEARTBEAT)  # CiA 301: life guard or heartbeat error


class FrameLog:
    """Every frame of some COB-IDs the simulated side receives, with its send timestamp."""

    def __init__(self, network: SimNetwork, *cob_ids: int) -> None:
        self._cond = threading.Condition()
        self.frames: dict[int, list[tuple[float, bytes]]] = {c: [] for c in cob_ids}
        for cob_id in cob_ids:
            network.network.subscribe(cob_id, self._on_frame)

    def _on_frame(self, can_id: int, data: bytearray, timestamp: float) -> None:
        with self._cond:
            self.frames[can_id].append((timestamp, bytes(data)))
            self._cond.notify_all()

    def count(self, cob_id: int) -> int:
        with self._cond:
            return len(self.frames[cob_id])

    def wait_count(self, cob_id: int, count: int) -> bool:
        with self._cond:
            return self._cond.wait_for(lambda: len(self.frames[cob_id]) >= count, TIMEOUT_S)


def consumer_entry(drive: WorldDrive) -> int:
    return drive.read(obj.CONSUMER_HEARTBEAT_TIME, 1)


@pytest.fixture
def bus(config: MachineConfig, channel: str) -> Iterator[WorldBus]:
    """The world's drives and I/O, on their own clock while no SYNC comes."""
    created = world_bus(zero_world(config), channel, own_clock=True)
    yield created
    created.close()


@pytest.fixture
def custom_backend(channel: str, bus: WorldBus) -> Iterator[MachineBackend]:
    """Controller node 100, drives stop after 300 ms of silence, heartbeat 50 ms."""
    data = machine_data(channel, master_node_id=100, master_heartbeat_timeout_ms=300)
    created = create_backend(parse_config(data))
    yield created
    for device in created.devices():
        device.shutdown()


def test_the_heartbeat_runs_at_its_period_from_activation_to_deactivation(
    custom_backend, bus: WorldBus
):
    master = 0x700 + 100
    log = FrameLog(bus.network, master)
    for device in custom_backend.devices():
        device.configure()
    for drive in bus.drives.values():  # node 100, 300 ms
        assert consumer_entry(drive) == 100 << 16 | 300
    assert log.count(master) == 0  # nothing before activation

    for device in custom_backend.devices():
        device.activate()
    assert log.wait_count(master, 11)
    stamps = [t for t, _ in log.frames[master][:11]]
    span_s = stamps[-1] - stamps[0]  # ten periods of 50 ms
    assert 0.25 < span_s < 2.0, f"10 heartbeats took {span_s:.3f} s, expected about 0.5 s"
    assert {data for _, data in log.frames[master]} == {b"\x05"}  # OPERATIONAL
    assert all(d.consumer.watching for d in bus.drives.values())

    custom_backend.motion.deactivate()
    sent = log.count(master)
    for drive in bus.drives.values():  # switched off before the heartbeat stopped
        assert consumer_entry(drive) == 0 and not drive.consumer.watching
    # the drives go on beating every 50 ms: six of X's and at most one of ours in flight
    x = bus.drives["X"]
    beats = x.heartbeats_sent
    assert x.wait(lambda: x.heartbeats_sent >= beats + 6, TIMEOUT_S)
    assert log.count(master) <= sent + 1
    assert all(d.consumer.events == 0 for d in bus.drives.values())  # nobody timed out

    custom_backend.motion.activate()  # without configure: the consumers are on again
    assert all(consumer_entry(d) == 100 << 16 | 300 for d in bus.drives.values())
    assert log.wait_count(master, log.count(master) + 2)
    assert backend_reports_heartbeat(custom_backend).endswith(", sending")


def backend_reports_heartbeat(backend: MachineBackend) -> str:
    report = backend.extras["canopen"].probe_report()  # type: ignore[attr-defined]
    text = report["controller heartbeat"]
    assert isinstance(text, str)
    return text


def test_a_drive_without_0x1016_fails_configure_naming_it(channel, config: MachineConfig):
    bus = world_bus(zero_world(config), channel, without_consumer=("Y",))
    try:
        backend = create_backend(config)
        try:
            with pytest.raises(DriverError) as caught:
                backend.motion.configure()
            error = caught.value
            assert error.device == "Y (node 2)" and error.code == 0x06020000
            text = str(error)
            assert "writing 0x1016:01 consumer heartbeat time (controller node 127, 250 ms)" in text
            assert "Object does not exist" in text
            assert "would not stop by itself if the controller died" in text
            assert backend.motion.lifecycle_state is LifecycleState.ERROR
        finally:
            backend.motion.shutdown()
    finally:
        bus.close()


def test_a_drive_refusing_the_value_fails_configure(backend, bus: WorldBus):
    bus.drives["Z"].reject[(obj.CONSUMER_HEARTBEAT_TIME, 1)] = 0x06090030  # value range
    with pytest.raises(DriverError, match=r"Z \(node 3\): SDO abort 0x06090030 .* 0x1016:01"):
        backend.motion.configure()


@pytest.mark.parametrize(
    "death",
    [
        pytest.param("heartbeat", id="its-heartbeat-task-stops"),
        pytest.param(
            "bus",
            id="its-bus-connection-goes",
            marks=pytest.mark.filterwarnings(
                "ignore::pytest.PytestUnhandledThreadExceptionWarning"
            ),
        ),
    ],
)
def test_an_enabled_drive_stops_by_itself_when_the_controller_dies(backend, bus: WorldBus, death):
    """The controller dies with X and Y enabled and Z disabled, nobody disables anything:
    X and Y fault with 0x8130 on their own; Z, already safe, does not."""
    start(backend)
    for name in ("X", "Y"):
        backend.motion.enable(name)
    run_until(backend, lambda fb: fb["X"].enabled and fb["Y"].enabled)
    can_bus = backend.extras["canopen"]
    x, y, z = (bus.drives[n] for n in "XYZ")
    assert all(d.consumer.watching for d in (x, y, z))

    if death == "heartbeat":  # what the process's death does to the periodic task
        can_bus.master_heartbeat._task.stop()  # python-can's task, behind the backend's back
    else:  # the controller's CAN connection goes away: nothing more is sent at all
        can_bus.network.bus.shutdown()

    for drive in (x, y):
        assert drive.wait(lambda d=drive: d.drive.state is S.FAULT, TIMEOUT_S), drive.drive.state
        assert drive.record.emcy_sent == [EMCY_HEARTBEAT]
        assert drive.read(obj.ERROR_CODE) == EMCY_HEARTBEAT
    assert z.consumer.wait_events(1, TIMEOUT_S)  # Z noticed too, and stays as it was
    assert z.drive.state is S.SWITCH_ON_DISABLED and z.record.emcy_sent == []

    # the backend, still alive in this test, does not stay silent about it either
    with pytest.raises(CommunicationError) as caught:
        period(backend, settle=False)
    if death == "heartbeat":
        assert "controller's heartbeat (COB-ID 0x77F) is no longer sent" in str(caught.value)
        events = backend.motion.events()
        assert (DeviceEventKind.COMMUNICATION_LOST, can_bus.label) in [
            (e.kind, e.device) for e in events
        ]
        # both drives' EMCY reach the backend as events with the operator's text
        assert can_bus.wait(
            lambda: can_bus.last_emcy_code(1) and can_bus.last_emcy_code(2), TIMEOUT_S
        )
        events += backend.motion.events()
        emcy = {(e.device, e.code, e.text) for e in events if e.kind is DeviceEventKind.EMERGENCY}
        text = "Life guard or heartbeat error (error register 0x11)"
        assert emcy == {("X (node 1)", 0x8130, text), ("Y (node 2)", 0x8130, text)}
        # the operator's reset (the machine layer's reconnect) brings a new heartbeat
        log = FrameLog(bus.network, 0x77F)
        backend.motion.deactivate()
        backend.motion.configure()
        backend.motion.activate()
        assert log.wait_count(0x77F, 3)
        feedback, _ = period(backend)
        assert feedback["X"].power_state is S.FAULT  # nothing resets by itself


def test_a_drive_that_did_not_disable_keeps_watching_after_deactivation(backend, bus: WorldBus):
    """Deactivation switches a drive's consumer off only once the drive shows its power stage
    off; one that never took the disable is left watching, and stops when the heartbeat does."""
    start(backend)
    enable_all(backend)
    x = bus.drives["X"]
    x.rpdos_dropped = True  # X hears no controlword any more
    backend.motion.deactivate()
    assert backend.motion.lifecycle_state is LifecycleState.INACTIVE
    assert consumer_entry(x) == 127 << 16 | 250
    assert consumer_entry(bus.drives["Y"]) == 0 and consumer_entry(bus.drives["Z"]) == 0
    assert x.wait(lambda: x.drive.state is S.FAULT, TIMEOUT_S), x.drive.state
    assert x.record.emcy_sent == [EMCY_HEARTBEAT]
    assert bus.drives["Y"].drive.state is S.SWITCH_ON_DISABLED


def test_after_a_lost_node_the_heartbeat_goes_on_until_shutdown(backend, bus: WorldBus):
    """A lost node latches ERROR and quick-stops the drives, which hold with their power stage
    on: the heartbeat goes on while the controller lives, so they do not fault for nothing.
    Shutting the drives down from ERROR stops it, and the drives still holding stop for good."""
    start(backend)
    enable_all(backend)
    bus.drives["Y"].silence_heartbeat()
    with pytest.raises(CommunicationError, match="heartbeat lost"):
        run_until(backend, lambda fb: False, max_periods=2000)  # about 200 until the loss
    can_bus = backend.extras["canopen"]
    x = bus.drives["X"]
    assert x.wait(lambda: x.drive.state is S.QUICK_STOP_ACTIVE, TIMEOUT_S)
    log = FrameLog(bus.network, 0x77F)
    assert log.wait_count(0x77F, 8)  # 400 ms later: still sent, X still holding
    assert x.drive.state is S.QUICK_STOP_ACTIVE and x.consumer.events == 0
    assert backend.io.lifecycle_state is LifecycleState.ACTIVE  # keeps the bus open

    backend.motion.shutdown()
    assert not can_bus.master_heartbeat.running
    assert x.wait(lambda: x.drive.state is S.FAULT, TIMEOUT_S), x.drive.state
    assert x.record.emcy_sent == [EMCY_HEARTBEAT]
