"""``stave probe``: against the Modbus emulator and a gauge on a pty, against the simulation,
and its one-line failures with their exit codes."""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from app.cli import probe as cli_probe
from app.config import parse_config
from app.drivers.cia402 import Cia402State
from app.drivers.modbus.emulator import ModbusEmulator
from tests.drivers.serial_gauge.fake_gauge import FakeGauge
from tests.drivers.thread_guard import no_thread_left_behind  # noqa: F401 (autouse fixture)

ROOT = Path(__file__).resolve().parents[2]

MODBUS_TOML = """
[backend]
name = "modbus"
period_ms = 4.0
[backend.modbus]
host = "127.0.0.1"
port = {port}
timeout_ms = 1000.0
[backend.sim.start_position]
X = 120.5
Y = 300.0
Z = -2.5
[gauge]
name = "serial"
[gauge.serial]
port = "{gauge}"
"""


@pytest.fixture
def machine(tmp_path: Path) -> Iterator[tuple[Path, ModbusEmulator, FakeGauge]]:
    """A Modbus machine (emulated) and a serial gauge (on a pty), and a config file for them."""
    gauge = FakeGauge(reply=b"W=187.25\r\n")
    path = tmp_path / "machine.toml"
    path.write_text(MODBUS_TOML.format(port=502, gauge=gauge.path))
    import tomllib

    emulator = ModbusEmulator(parse_config(tomllib.loads(path.read_text())))
    try:
        port = emulator.serve_tcp()
        path.write_text(MODBUS_TOML.format(port=port, gauge=gauge.path))
        yield path, emulator, gauge
    finally:
        emulator.stop()
        gauge.close()


def probe(*argv: str) -> int:
    parser = argparse.ArgumentParser()
    cli_probe.add_arguments(parser)
    return cli_probe.run(parser.parse_args(list(argv)))


def test_probe_a_modbus_machine(
    machine: tuple[Path, ModbusEmulator, FakeGauge], capsys: pytest.CaptureFixture[str]
) -> None:
    path, emulator, _gauge = machine
    assert probe("--config", str(path)) == 0
    out, err = capsys.readouterr()
    assert err == ""
    lines = out.splitlines()
    assert lines[0].startswith("backend: modbus   gauge: serial")
    x = next(line for line in lines if line.startswith("X "))
    assert "switch on disabled" in x and "120.500 mm" in x and "0x0000" in x
    assert "-2.500 deg" in next(line for line in lines if line.startswith("Z "))
    assert "estop_ok=1" in out and "part_present=0" in out
    assert "gauge: 187.250 mm   (raw 'W=187.25')" in out
    assert "link_report: links tcp 127.0.0.1:" in out and "transactions per period 8" in out
    # A probe never enables a drive.
    assert all(d.state is Cia402State.SWITCH_ON_DISABLED for d in emulator.world.drives.values())


def test_probe_json(
    machine: tuple[Path, ModbusEmulator, FakeGauge], capsys: pytest.CaptureFixture[str]
) -> None:
    path, emulator, _gauge = machine
    emulator.world.drives["Y"].inject_power_stage_fault(True)
    emulator.world.load_board(150.0)
    assert probe("--config", str(path), "--json") == 0
    report = json.loads(capsys.readouterr().out)
    assert report["error"] is None and report["backend"] == "modbus"
    assert report["axes"]["X"]["position"] == pytest.approx(120.5)
    assert report["axes"]["Y"]["power_state"] in ("fault", "fault reaction active")
    assert report["axes"]["Y"]["fault_code"] == "0x2310"
    assert report["inputs"]["part_present"] is True
    assert report["gauge"] == {"width_mm": 187.25, "raw": "W=187.25", "error": ""}
    assert {
        "kind": "emergency",
        "device": "Y",
        "code": "0x2310",
        "text": "drive fault 0x2310: Continuous over-current",
    } in report["events"]


def test_a_gauge_answering_garbage_is_shown_not_failed(
    machine: tuple[Path, ModbusEmulator, FakeGauge], capsys: pytest.CaptureFixture[str]
) -> None:
    path, _emulator, gauge = machine
    gauge.reply = b"W=0.00\r\n"  # most gauges with no board in front of them
    assert probe("--config", str(path)) == 0
    assert "gauge: no width: out of range: 0 mm" in capsys.readouterr().out


def test_a_missing_gauge_fails_after_showing_the_axes(
    machine: tuple[Path, ModbusEmulator, FakeGauge], capsys: pytest.CaptureFixture[str]
) -> None:
    path, _emulator, gauge = machine
    path.write_text(path.read_text().replace(gauge.path, "/dev/no-such-gauge"))
    assert probe("--config", str(path)) == 1
    out, err = capsys.readouterr()
    assert "switch on disabled" in out
    assert err == "stave probe: gauge: cannot open /dev/no-such-gauge: No such file or directory\n"
    assert err.count("\n") == 1


def test_a_configuration_error_is_one_line_and_exit_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "machine.toml"
    path.write_text(
        '[backend]\nname = "modbus"\n[backend.modbus]\nhost = "10.0.0.1"\n'
        "[backend.modbus.drive_map]\ntarget = 0x0014\n"
    )
    assert probe("--config", str(path)) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.startswith(
        f"stave probe: {path}: backend.modbus.drive_map.target = 20 is not "
        "allowed: 0x0012, right after mode"
    )
    assert err.count("\n") == 1


def test_an_unreachable_server_is_one_line_on_stderr_and_exit_1(tmp_path: Path) -> None:
    import socket

    with socket.create_server(("127.0.0.1", 0)) as sock:
        port = sock.getsockname()[1]  # closed again at once: nothing listens there
    path = tmp_path / "machine.toml"
    path.write_text(MODBUS_TOML.format(port=port, gauge="/dev/null"))
    result = subprocess.run(
        [sys.executable, "-m", "app.cli", "probe", "--config", str(path)],
        capture_output=True,
        text=True,
        timeout=60,
        cwd=ROOT,
        check=False,
    )
    assert result.returncode == 1
    assert result.stderr == (
        f"stave probe: modbus: cannot connect to tcp 127.0.0.1:{port}: "
        "connection refused (no Modbus server on that port)\n"
    )
    assert result.stdout.startswith("backend: modbus")


def test_probe_the_simulation(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "machine.toml"
    path.write_text(
        '[backend]\nname = "sim"\n[gauge]\nname = "sim"\n[backend.sim]\nboard_present = true\n'
    )
    assert probe("--config", str(path), "--json") == 0
    report = json.loads(capsys.readouterr().out)
    assert set(report["axes"]) == {"X", "Y", "Z"}
    assert report["gauge"]["width_mm"] is not None
