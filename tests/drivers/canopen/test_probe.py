"""``stave probe`` on the CANopen backend: the shipped sample configuration pointed at the
simulated drives; it reads, reports the link, and never enables a drive."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import pytest

from app.cli import probe as cli_probe
from app.config import load_config
from app.drivers.canopen import objects as obj
from app.drivers.canopen.settings import settings_from_config
from app.drivers.sim.settings import SimSettings
from app.drivers.sim.world import SimWorld
from app.resources import resource_path
from tests.drivers.canopen.world_nodes import WorldBus


def sample_config_on(channel: str, tmp_path: Path) -> Path:
    text = resource_path("machine-canopen.toml").read_text(encoding="utf-8")
    text = text.replace('interface = "socketcan"', 'interface = "virtual"')
    text = text.replace('channel = "can0"', f'channel = "{channel}"')
    path = tmp_path / "machine-canopen.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.fixture
def sample_bus(channel: str, tmp_path: Path):
    """The world's drives and I/O with the sample's node ids, scales and wiring."""
    config = load_config(sample_config_on(channel, tmp_path))
    can = settings_from_config(config)
    world = SimWorld(config, SimSettings(start_position={"X": 0.0, "Y": 0.0, "Z": 0.0}))
    bus = WorldBus(
        world,
        channel,
        {name: axis.node_id for name, axis in can.axes.items()},
        {name: axis.counts_per_unit for name, axis in can.axes.items()},
        can.io.node_id,
        can.io.inputs,
        can.io.outputs,
    )
    yield bus
    bus.close()


def test_probe_reads_drives_and_io_without_enabling(
    channel, sample_bus: WorldBus, tmp_path, capsys
):
    bus = sample_bus
    bus.drives["Y"].move_by_hand(524_288)  # 10 mm at 52428.8 counts/mm
    bus.world.set_guard(False)  # the guard opened: the sample's wiring must show it
    path = sample_config_on(channel, tmp_path)
    code = cli_probe.run(argparse.Namespace(config=str(path), json=True))
    out = capsys.readouterr()
    assert code == 0, out.err
    report = json.loads(out.out)
    assert report["error"] is None
    axes = report["axes"]
    assert axes["Y"]["position"] == 10.0
    assert {a["power_state"] for a in axes.values()} == {"switch on disabled"}
    assert axes["Z"]["homed"] and not axes["X"]["homed"]
    assert report["inputs"]["estop_ok"] and not report["inputs"]["guard_closed"]
    link = report["link"]["canopen"]
    assert link["cyclic bus load (computed)"].startswith("19.9-24.1 %")
    assert link["Y (node 2)"] == "OPERATIONAL"
    assert link["controller heartbeat"].startswith("node 127, drives stop after 250 ms")
    for drive in bus.drives.values():  # never enabled: only "disable voltage" was sent
        assert {cw for _, cw in drive.record.controlwords} == {0x00}
        assert drive.wait(lambda d=drive: d.nmt_state == "PRE-OPERATIONAL")  # left tidy
        assert drive.read(obj.CONSUMER_HEARTBEAT_TIME, 1) == 0  # no longer watching us
        assert drive.consumer.events == 0 and drive.record.emcy_sent == []


def test_probe_names_the_node_that_does_not_answer(channel, sample_bus, tmp_path, capsys):
    path = sample_config_on(channel, tmp_path)
    path.write_text(
        path.read_text(encoding="utf-8").replace("node_id = 3", "node_id = 30"), encoding="utf-8"
    )
    code = cli_probe.run(argparse.Namespace(config=str(path), json=False))
    err = capsys.readouterr().err
    assert code == 1
    assert "Z (node 30)" in err and "no SDO answer" in err
