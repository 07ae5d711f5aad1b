"""The pure rules, without a bus (the master's are in tests/drivers/test_cia402_master.py, the
simulated drive's transition table in tests/drivers/sim/test_drive_cia402.py): the heartbeat
watchdog on a simulated clock, bus load, EMCY texts, PDO packing, the consumer heartbeat entry
and the settings reader."""

from __future__ import annotations

import pytest

from app.config import ConfigError, parse_config
from app.drivers.canopen.busload import CyclicFrame, bus_load, frame_bits
from app.drivers.canopen.master_heartbeat import (
    consumer_heartbeat_entry,
    split_consumer_heartbeat_entry,
)
from app.drivers.canopen.motion import _interpolation_period
from app.drivers.canopen.pdo import answered_sync, pack_drive_command, unpack_drive_feedback
from app.drivers.canopen.settings import settings_from_config
from app.drivers.canopen.watchdog import HeartbeatWatchdog
from app.drivers.emcy import emcy_text
from tests.drivers.canopen.conftest import machine_data

# ---- heartbeat watchdog ---------------------------------------------------------------------


def test_watchdog_reports_each_loss_and_return_once():
    now = [0.0]
    watchdog = HeartbeatWatchdog(0.15, clock=lambda: now[0])
    watchdog.watch([1, 2])
    now[0] = 0.1
    watchdog.heard(1, 5)
    assert watchdog.poll() == []
    now[0] = 0.2  # node 2 silent for 0.2 s
    changes = watchdog.poll()
    assert [(c.node_id, c.lost) for c in changes] == [(2, True)]
    assert watchdog.poll() == []  # reported once
    now[0] = 0.3  # node 1 silent 0.2 s too
    assert [(c.node_id, c.lost) for c in watchdog.poll()] == [(1, True)]
    watchdog.heard(2, 5)
    assert [(c.node_id, c.lost) for c in watchdog.poll()] == [(2, False)]
    assert watchdog.nmt_state(2) == 5
    watchdog.heard(9, 5)  # not watched: no effect
    assert watchdog.poll() == []


# ---- bus load -------------------------------------------------------------------------------


def test_frame_bits():
    assert frame_bits(0, worst_case=False) == 47
    assert frame_bits(8, worst_case=False) == 111
    assert frame_bits(8, worst_case=True) == 135
    with pytest.raises(ValueError):
        frame_bits(9, worst_case=False)


def test_bus_load_of_the_minimal_mapping():
    """The measured figure: 3 axes, controlword+target / statusword+position, SYNC, 1 Mbit/s:
    15-19 % at 4 ms, 62-75 % at 1 ms."""
    frames = [CyclicFrame("SYNC", 0, 1), CyclicFrame("RPDO", 6, 3), CyclicFrame("TPDO", 6, 3)]
    at_4ms = bus_load(frames, 0.004, 1_000_000)
    assert (round(100 * at_4ms.minimum, 1), round(100 * at_4ms.maximum, 1)) == (15.4, 18.6)
    at_1ms = bus_load(frames, 0.001, 1_000_000)
    assert 0.61 < at_1ms.minimum < 0.62 and 0.74 < at_1ms.maximum < 0.75


def test_bus_load_of_our_mapping():
    """The README's figures: the sample configuration (3 drives, the I/O node and the
    controller, heartbeats every 100 ms)."""
    from app.config import load_config
    from app.resources import resource_path

    settings = settings_from_config(load_config(resource_path("machine-canopen.toml")))
    load = settings.bus_load()
    assert (round(100 * load.minimum, 1), round(100 * load.maximum, 1)) == (19.9, 24.1)


def test_a_bus_load_too_high_is_refused(channel):
    data = machine_data(channel)
    data["backend"]["period_ms"] = 1.0
    with pytest.raises(ConfigError, match=r"backend\.canopen\.bitrate .* under 60 %"):
        settings_from_config(parse_config(data))


# ---- EMCY texts, PDO packing, interpolation period -----------------------------------------


def test_emcy_texts():
    assert emcy_text(0x8611) == "Following error"
    assert emcy_text(0x2310) == "Continuous over-current"
    assert emcy_text(0x3211) == "DC link over-voltage (code 0x3211)"
    assert emcy_text(0xFF42) == "Device specific (code 0xFF42)"
    assert emcy_text(0xA000) == "Unknown error (code 0xA000)"


def test_pdo_packing():
    assert unpack_drive_feedback(pack_drive_command(0x0F, -123456, 8)) == (0x0F, -123456, 8)
    with pytest.raises(ValueError, match="INTEGER32"):
        pack_drive_command(0x0F, 2**31, 8)


def test_which_sync_an_answer_belongs_to():
    assert answered_sync(None, 7) == 7  # first answer
    assert answered_sync(6, 7) == 7  # on time
    assert answered_sync(6, 8) == 7  # late: SYNC 8 went out before the answer to 7 came
    assert answered_sync(7, 8) == 8  # and the answer to 8 follows
    assert answered_sync(3, 8) == 7  # a SYNC never answered: at most one period off
    assert answered_sync(8, 8) == 8  # a second answer to the same SYNC (RTR) stays there


@pytest.mark.parametrize(
    ("period_s", "expected"),
    [(0.004, (4, -3)), (0.0025, (25, -4)), (0.001, (1, -3)), (0.05, (50, -3))],
)
def test_interpolation_period(period_s, expected):
    assert _interpolation_period(period_s) == expected


# ---- settings -------------------------------------------------------------------------------


def settings_error(channel, mutate) -> ConfigError:
    data = machine_data(channel)
    mutate(data["backend"]["canopen"])
    with pytest.raises(ConfigError) as caught:
        settings_from_config(parse_config(data))
    return caught.value


@pytest.mark.parametrize(
    ("mutate", "key", "allowed"),
    [
        (lambda s: s.update(bitrate=115200), "backend.canopen.bitrate", "one of 10000"),
        (lambda s: s.update(interface="udp_multicast"), "backend.canopen.interface", "'socketcan'"),
        (
            lambda s: s.update(heartbeat_timeout_ms=60),
            "backend.canopen.heartbeat_timeout_ms",
            "at least 1.5 x heartbeat_ms",
        ),
        (lambda s: s.update(channel=""), "backend.canopen.channel", "channel name"),
        (
            lambda s: s.update(master_node_id=10),
            "backend.canopen.master_node_id",
            "io.node_id has 10",
        ),
        (
            lambda s: s["axes"]["Y"].update(node_id=127),  # the default master_node_id
            "backend.canopen.master_node_id",
            "axes.Y.node_id has 127",
        ),
        (
            lambda s: s.update(master_node_id=0),
            "backend.canopen.master_node_id",
            "from 1 to 127 (the controller's own node id)",
        ),
        (
            lambda s: s.update(master_heartbeat_timeout_ms=70),
            "backend.canopen.master_heartbeat_timeout_ms",
            "at least 1.5 x heartbeat_ms (75)",
        ),
        (
            lambda s: s.update(master_heartbeat_timeout_ms=65536),
            "backend.canopen.master_heartbeat_timeout_ms",
            "from 15 to 65535",
        ),
        (lambda s: s.update(sync_period_ms=4), "backend.canopen.sync_period_ms", "a known key"),
        (
            lambda s: s["axes"]["Y"].update(node_id=1),
            "backend.canopen.axes.Y.node_id",
            "axes.X.node_id has 1",
        ),
        (lambda s: s["io"].update(node_id=3), "backend.canopen.io.node_id", "axes.Z.node_id has 3"),
        (
            lambda s: s["axes"]["X"].update(node_id=128),
            "backend.canopen.axes.X.node_id",
            "from 1 to 127",
        ),
        (
            lambda s: s["axes"]["X"].pop("counts_per_unit"),
            "backend.canopen.axes.X.counts_per_unit",
            "(required)",
        ),
        (
            lambda s: s["axes"]["X"].update(counts_per_unit=1e6),
            "backend.canopen.axes.X.counts_per_unit",
            "32-bit position",
        ),
        (
            lambda s: s["axes"]["Z"].update(homing_method=15),
            "backend.canopen.axes.Z.homing_method",
            "CiA 402 homing method",
        ),
        (lambda s: s["axes"].pop("Z"), "backend.canopen.axes.Z", "a table (required)"),
        (
            lambda s: s["io"]["inputs"].pop("estop_ok"),
            "backend.canopen.io.inputs.estop_ok",
            "(required)",
        ),
        (
            lambda s: s["io"]["inputs"].update(estop_ok=0),
            "backend.canopen.io.inputs.estop_ok",
            "part_present has 0",
        ),
        (
            lambda s: s["io"]["outputs"].update(spindle_on=32),
            "backend.canopen.io.outputs.spindle_on",
            "from 0 to 31",
        ),
        (
            lambda s: s["io"].update(inverted_inputs=["estop"]),
            "backend.canopen.io.inverted_inputs",
            "estop_ok",
        ),
    ],
)
def test_settings_errors_name_the_key(channel, mutate, key, allowed):
    error = settings_error(channel, mutate)
    assert error.key == key
    assert allowed in str(error)


def test_settings_defaults(config):
    settings = settings_from_config(config)
    assert settings.heartbeat_ms == 50 and settings.slow_feedback_every_n_sync == 5
    assert settings.master_node_id == 127 and settings.master_heartbeat_timeout_ms == 250
    assert settings.axes["X"].to_counts(1.2345) == 1234
    assert settings.axes["Z"].from_counts(-25_000) == -2.5
    assert settings.io.input_bytes == 2 and settings.io.output_bytes == 1


def test_the_drives_wait_2_5_heartbeats_for_the_controller_by_default(channel):
    data = machine_data(channel, heartbeat_ms=100)
    del data["backend"]["canopen"]["master_heartbeat_timeout_ms"]
    assert settings_from_config(parse_config(data)).master_heartbeat_timeout_ms == 250


def test_consumer_heartbeat_entry():
    assert consumer_heartbeat_entry(127, 250) == 0x007F_00FA
    assert split_consumer_heartbeat_entry(0x0064_012C) == (100, 300)
    assert split_consumer_heartbeat_entry(0) == (0, 0)
    with pytest.raises(ValueError, match="producer node id 128"):
        consumer_heartbeat_entry(128, 250)
    with pytest.raises(ValueError, match="65536 ms"):
        consumer_heartbeat_entry(127, 65536)


def test_an_inverted_axis_counts_the_other_way(channel):
    data = machine_data(channel)
    data["backend"]["canopen"]["axes"]["Y"]["invert"] = True
    axis = settings_from_config(parse_config(data)).axes["Y"]
    assert axis.to_counts(2.0) == -2000 and axis.from_counts(-2000) == 2.0


def test_the_shipped_sample_configuration_is_valid():
    from app.config import load_config
    from app.resources import resource_path

    config = load_config(resource_path("machine-canopen.toml"))
    assert config.backend == "canopen"
    settings = settings_from_config(config)
    assert settings.interface == "socketcan" and settings.bitrate == 1_000_000
    assert settings.bus_load().maximum < 0.30


def test_the_sample_configuration_stays_in_step_with_machine_toml():
    """Only the backend differs: axes, I/O timings and process values are the shipped ones."""
    from app.config import load_config
    from app.resources import resource_path

    sample = load_config(resource_path("machine-canopen.toml"))
    shipped = load_config(resource_path("machine.toml"))
    assert sample.axes == shipped.axes
    assert (sample.io, sample.process, sample.period_s) == (
        shipped.io,
        shipped.process,
        shipped.period_s,
    )
