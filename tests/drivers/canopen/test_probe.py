"""``stave probe`` on the CANopen backend: the shipped sample configuration pointed at the
simulated drives; it reads, reports the link, and never enables a drive."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from app.cli import probe as cli_probe
from app.drivers.canopen import objects as obj
from app.resources import resource_path
from tests.drivers.canopen.conftest import Bench


def sample_config_on(channel: str, tmp_path: Path) -> Path:
    text = resource_path("machine-canopen.toml").read_text(encoding="utf-8")
    text = text.replace('interface = "socketcan"', 'interface = "virtual"')
    text = text.replace('channel = "can0"', f'channel = "{channel}"')
    path = tmp_path / "machine-canopen.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_probe_reads_drives_and_io_without_enabling(channel, bench: Bench, tmp_path, capsys):
    bench.drives["Y"].position = 524_288  # 10 mm at 52428.8 counts/mm
    bench.io.set_inputs(1 << 7 | 1 << 6)  # estop_ok, guard_closed in the sample's wiring
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
    assert report["inputs"]["estop_ok"] and report["inputs"]["guard_closed"]
    link = report["link"]["canopen"]
    assert link["cyclic bus load (computed)"].startswith("19.9-24.1 %")
    assert link["Y (node 2)"] == "OPERATIONAL"
    assert link["controller heartbeat"].startswith("node 127, drives stop after 250 ms")
    for drive in bench.drives.values():  # never enabled: only "disable voltage" was sent
        assert {cw for _, cw in drive.record.controlwords} == {0x00}
        assert drive.wait(lambda d=drive: d.nmt_state == "PRE-OPERATIONAL")  # left tidy
        assert drive.read(obj.CONSUMER_HEARTBEAT_TIME, 1) == 0  # no longer watching us
        assert drive.consumer.events == 0 and drive.record.emcy_sent == []


def test_probe_names_the_node_that_does_not_answer(channel, bench: Bench, tmp_path, capsys):
    path = sample_config_on(channel, tmp_path)
    path.write_text(
        path.read_text(encoding="utf-8").replace("node_id = 3", "node_id = 30"), encoding="utf-8"
    )
    code = cli_probe.run(argparse.Namespace(config=str(path), json=False))
    err = capsys.readouterr().err
    assert code == 1
    assert "Z (node 30)" in err and "no SDO answer" in err
