"""Where each digital input and output is wired on the configured backend, in the words a
technician checks against the wiring diagram (docs/MACHINE.md section 4: the original's Input
and Output routines map terminals to machine functions).

Why in the machine layer: the mapping is the backend's configuration (``[backend.modbus.io]``,
``[backend.canopen.io]``), which the screens may not read; the table is computed once at
start-up and travels in the snapshot, so the I/O page shows exactly what the drivers use.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import fields

from app.config import MachineConfig
from app.drivers.contracts import DIGITAL_INPUTS, OutputImage
from app.machine.snapshot import IoPoint

INPUT_SIGNALS: tuple[str, ...] = DIGITAL_INPUTS  # the counts and analog values are no terminal bit
OUTPUT_SIGNALS: tuple[str, ...] = tuple(f.name for f in fields(OutputImage))
CANOPEN_READ_INPUTS = 0x6000  # CiA 401 read input 8-bit
CANOPEN_WRITE_OUTPUTS = 0x6200  # CiA 401 write output 8-bit
NORMALLY_CLOSED = "normally closed"


def _table(inputs: Mapping[str, str], outputs: Mapping[str, str]) -> tuple[IoPoint, ...]:
    return tuple(IoPoint(name, False, inputs.get(name, "")) for name in INPUT_SIGNALS) + tuple(
        IoPoint(name, True, outputs.get(name, "")) for name in OUTPUT_SIGNALS
    )


def _modbus(config: MachineConfig) -> tuple[IoPoint, ...]:
    from app.drivers.modbus.settings import parse_modbus_settings

    coupler = parse_modbus_settings(config.backend_settings.get("modbus", {}), config).coupler
    unit = f"unit {coupler.device_id}"
    inputs = {}
    for name, bit in coupler.input_bits.items():
        address = f"{unit}, discrete input {coupler.inputs_address + bit}"
        inputs[name] = address + (f" ({NORMALLY_CLOSED})" if name in coupler.inverted else "")
    outputs = {
        name: f"{unit}, coil {coupler.outputs_address + bit}"
        for name, bit in coupler.output_bits.items()
    }
    return _table(inputs, outputs)


def _canopen_bit(node_id: int, index: int, bit: int) -> str:
    """A CiA 401 terminal: bit 0 is sub-index 1 bit 0, bit 8 sub-index 2 bit 0."""
    return f"node {node_id}, 0x{index:04X} sub {bit // 8 + 1} bit {bit % 8}"


def _canopen(config: MachineConfig) -> tuple[IoPoint, ...]:
    from app.drivers.canopen.settings import settings_from_config

    io = settings_from_config(config).io
    inputs = {}
    for name, bit in io.inputs.items():
        address = _canopen_bit(io.node_id, CANOPEN_READ_INPUTS, bit)
        inputs[name] = address + (f" ({NORMALLY_CLOSED})" if name in io.inverted_inputs else "")
    outputs = {
        name: _canopen_bit(io.node_id, CANOPEN_WRITE_OUTPUTS, bit)
        for name, bit in io.outputs.items()
    }
    return _table(inputs, outputs)


def io_table(config: MachineConfig) -> tuple[IoPoint, ...]:
    """Every input, then every output, with its address on ``config.backend``; the
    simulation's signals are all "simulated". The configuration was checked at start-up,
    so reading it again here cannot fail on a running machine."""
    if config.backend == "modbus":
        return _modbus(config)
    if config.backend == "canopen":
        return _canopen(config)
    simulated = {name: "simulated" for name in (*INPUT_SIGNALS, *OUTPUT_SIGNALS)}
    return _table(simulated, simulated)
