"""Start-up against the simulated world's drives: NMT, SDO configuration, PDO mapping, first
feedback."""

from __future__ import annotations

import struct

import canopen
import pytest

from app.drivers.canopen import objects as obj
from app.drivers.canopen.pdo import DRIVE_RPDO1, DRIVE_TPDO1, PDO_NOT_VALID, drive_tpdo2
from app.drivers.cia402 import Cia402State
from app.drivers.contracts import LifecycleError, LifecycleState
from tests.drivers.canopen.conftest import COUNTS, NODE_IDS, enable_all, period, start
from tests.drivers.canopen.world_nodes import WorldBus


def test_the_canopen_name_is_the_library_not_our_package():
    assert "site-packages" in canopen.__file__


def test_configure_maps_pdos_and_sets_heartbeat(backend, bus: WorldBus):
    backend.motion.configure()
    assert backend.motion.lifecycle_state is LifecycleState.INACTIVE
    for name, drive in bus.drives.items():
        node = NODE_IDS[name]
        assert drive.nmt_state == "PRE-OPERATIONAL"
        assert drive.read(obj.PRODUCER_HEARTBEAT_TIME) == 50
        # watches the controller (node 127) with a 250 ms timeout
        assert drive.read(obj.CONSUMER_HEARTBEAT_TIME, 1) == 0x007F_00FA
        assert drive.read(obj.RPDO_COMM, 1) == 0x200 + node
        assert drive.read(obj.RPDO_COMM, 2) == 1  # taken at the next SYNC
        assert drive.read(obj.TPDO_COMM, 1) & 0x7FF == 0x180 + node
        assert drive.read(obj.TPDO_COMM, 2) == 1  # every SYNC
        assert drive.read(obj.TPDO_COMM + 1, 2) == 5  # slow feedback every 5th SYNC
        for layout in (DRIVE_RPDO1, DRIVE_TPDO1, drive_tpdo2(5)):
            entries = [drive.read(layout.map_index, s) for s in range(1, len(layout.entries) + 1)]
            assert drive.read(layout.map_index, 0) == len(layout.entries)
            assert entries == [e.map_value for e in layout.entries]
        for unused in (obj.RPDO_COMM + 1, obj.RPDO_COMM + 3, obj.TPDO_COMM + 2):
            assert drive.read(unused, 1) & PDO_NOT_VALID
        limit = {"X": 2.0, "Y": 2.0, "Z": 0.5}[name]  # following_error_limit defaults
        assert drive.read(obj.FOLLOWING_ERROR_WINDOW) == round(limit * COUNTS[name])
        assert drive.read(obj.HOMING_METHOD) == 21  # homing_direction -1: home switch
        assert drive.read(obj.INTERPOLATION_TIME_PERIOD, 1) == 4
        assert drive.read(obj.INTERPOLATION_TIME_PERIOD, 2) == -3
        assert drive.read(obj.COMM_CYCLE_PERIOD) == 4000
    assert bus.io.read(obj.PRODUCER_HEARTBEAT_TIME) == 0  # the I/O is the other device's


def test_activate_starts_nodes_and_reads_scaled_positions(backend, bus: WorldBus):
    bus.drives["X"].move_by_hand(123_456)  # counts
    bus.drives["Z"].move_by_hand(-25_000)
    start(backend)
    assert all(d.nmt_state == "OPERATIONAL" for d in bus.network.nodes)
    feedback = backend.motion.read_axes()
    assert feedback["X"].position == pytest.approx(123.456)
    assert feedback["Y"].position == 0.0
    assert feedback["Z"].position == pytest.approx(-2.5)
    assert all(f.power_state is Cia402State.SWITCH_ON_DISABLED for f in feedback.values())
    assert not any(f.homed for n, f in feedback.items() if n != "Z")
    assert feedback["Z"].homed  # absolute encoder in the default configuration
    inputs = backend.io.read_inputs()
    assert inputs.estop_ok and inputs.guard_closed and not inputs.start_button


def test_reads_without_writes_send_their_own_sync(backend, bus: WorldBus):
    """A tool (stave probe) that only reads still gets fresh positions."""
    start(backend)
    backend.motion.read_axes()
    bus.drives["Y"].move_by_hand(5000)
    assert backend.motion.read_axes()["Y"].position == pytest.approx(5.0)


def test_one_sync_per_period_and_targets_taken_together(backend, bus: WorldBus):
    start(backend)
    enable_all(backend)
    before = {n: d.sync_count for n, d in bus.drives.items()}
    for n in range(1, 21):
        period(backend, {"X": 0.1 * n, "Y": 0.1 * n})
    assert all(
        d.wait(lambda d=d, n=n: d.sync_count - before[n] == 20) for n, d in bus.drives.items()
    )
    x_targets = dict(bus.drives["X"].record.targets)
    y_targets = dict(bus.drives["Y"].record.targets)
    moving = [k for k in x_targets if k > before["X"]]
    assert len(moving) >= 19
    # each SYNC made X and Y take the setpoints of the same period: no skew
    assert [x_targets[k] for k in moving] == [y_targets[k] for k in moving]
    assert [x_targets[k] for k in moving] == sorted(x_targets[k] for k in moving)
    # the answer to SYNC k is sampled as the drive takes target k: it shows target k-1 (the
    # drive's load follows its interpolated demand closely, not exactly: 0.01 mm)
    feedback = backend.motion.read_axes()
    assert feedback["X"].position == pytest.approx(1.9, abs=0.01)
    assert feedback["Y"].position == pytest.approx(1.9, abs=0.01)


def test_motion_commands_need_an_active_backend(backend):
    with pytest.raises(LifecycleError):
        backend.motion.read_axes()
    with pytest.raises(LifecycleError):
        backend.motion.enable("X")
    backend.motion.configure()
    with pytest.raises(LifecycleError):
        backend.motion.write_setpoints({"X": 0.0})


def test_configure_rejects_a_device_that_is_not_a_drive(backend, bus: WorldBus):
    bus.drives["Y"].node.data_store.setdefault(obj.DEVICE_TYPE, {})[0] = struct.pack(
        "<I", 0x00030191
    )
    with pytest.raises(Exception, match=r"Y \(node 2\).*not a CiA 402"):
        backend.motion.configure()
    assert backend.motion.lifecycle_state is LifecycleState.ERROR


def test_shutdown_twice_and_from_any_state(backend):
    start(backend)
    for device in backend.devices():
        device.shutdown()
        device.shutdown()
        assert device.lifecycle_state is LifecycleState.FINALIZED
