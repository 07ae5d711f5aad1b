"""The I/O page's address table: for each backend, every input and output once, at the
terminal its driver uses (the shipped sample configurations, and one rewired)."""

from __future__ import annotations

from dataclasses import fields
from pathlib import Path

from app.config import load_config
from app.drivers.contracts import DIGITAL_INPUTS, OutputImage
from app.machine.io_table import io_table

RESOURCES = Path(__file__).resolve().parents[2] / "resources"
# Terminal bits only: the handwheel's counter and the joystick's analog values are registers.
SIGNALS = [*DIGITAL_INPUTS, *(f.name for f in fields(OutputImage))]


def _by_signal(config_path: Path) -> dict[str, str]:
    table = io_table(load_config(config_path))
    assert [p.signal for p in table] == SIGNALS
    assert [p.output for p in table] == [False] * len(DIGITAL_INPUTS) + [True] * 6
    return {p.signal: p.address for p in table}


def test_simulation_says_every_signal_is_simulated() -> None:
    table = io_table(load_config().with_backend("sim", "sim"))
    assert {p.address for p in table} == {"simulated"}


def test_modbus_names_the_unit_and_the_discrete_input_or_coil() -> None:
    addresses = _by_signal(RESOURCES / "machine-modbus.toml")
    assert addresses["part_present"] == "unit 10, discrete input 0"
    assert addresses["estop_ok"] == "unit 10, discrete input 7"
    assert addresses["spindle_on"] == "unit 10, coil 2"


def test_modbus_offsets_unwired_and_normally_closed_inputs(tmp_path: Path) -> None:
    text = (RESOURCES / "machine-modbus.toml").read_text(encoding="utf-8")
    text = text.replace("inputs_address = 0 ", "inputs_address = 100 ", 1)
    text = text.replace("inverted = []", 'inverted = ["estop_ok"]', 1)
    text = text.replace("reset_button = 10", "reset_button = -1", 1)
    path = tmp_path / "machine.toml"
    path.write_text(text, encoding="utf-8")
    addresses = _by_signal(path)
    assert addresses["part_present"] == "unit 10, discrete input 100"
    assert addresses["estop_ok"] == "unit 10, discrete input 107 (normally closed)"
    assert addresses["reset_button"] == ""  # not wired


def test_canopen_names_node_object_subindex_and_bit() -> None:
    addresses = _by_signal(RESOURCES / "machine-canopen.toml")
    assert addresses["part_present"] == "node 10, 0x6000 sub 1 bit 0"
    assert addresses["reset_button"] == "node 10, 0x6000 sub 2 bit 2"
    assert addresses["lamp_red"] == "node 10, 0x6200 sub 1 bit 5"
