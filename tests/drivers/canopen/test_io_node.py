"""The CiA 401 I/O node: inputs by function with inversion, outputs by function."""

from __future__ import annotations

from app.config import parse_config
from app.drivers.canopen import objects as obj
from app.drivers.canopen.backend import create_backend
from app.drivers.contracts import OutputImage
from tests.drivers.canopen.conftest import (
    HEALTHY_INPUTS,
    INPUT_BITS,
    OUTPUT_BITS,
    Bench,
    machine_data,
    period,
    start,
)


def test_io_node_is_mapped_and_outputs_start_off(backend, bench: Bench):
    start(backend)
    assert bench.io.read(obj.TPDO_COMM, 2) == 1  # inputs on every SYNC
    assert bench.io.read(obj.RPDO_COMM, 2) == 255  # outputs applied on receipt
    assert bench.io.read(obj.TPDO_MAPPING, 0) == 2  # 11 inputs: two bytes
    assert bench.io.read(obj.RPDO_MAPPING, 0) == 1  # 6 outputs: one byte
    assert bench.io.outputs == 0


def test_inputs_by_function(backend, bench: Bench):
    start(backend)
    bench.io.set_inputs(
        HEALTHY_INPUTS | 1 << INPUT_BITS["part_present"] | 1 << INPUT_BITS["start_button"]
    )
    _, inputs = period(backend)
    _, inputs = period(backend)
    assert inputs.part_present and inputs.start_button and inputs.estop_ok
    assert not inputs.stop_button and not inputs.clamps_closed
    bench.io.set_inputs(HEALTHY_INPUTS & ~(1 << INPUT_BITS["estop_ok"]))  # chain opened
    period(backend)
    _, inputs = period(backend)
    assert not inputs.estop_ok and not inputs.part_present


def test_outputs_by_function(backend, bench: Bench):
    start(backend)
    period(backend, outputs=OutputImage(spindle_on=True, lamp_green=True))
    assert bench.io.wait(
        lambda: (
            bench.io.outputs == (1 << OUTPUT_BITS["spindle_on"] | 1 << OUTPUT_BITS["lamp_green"])
        )
    )
    period(backend, outputs=OutputImage(clamps_close=True))
    assert bench.io.wait(lambda: bench.io.outputs == 1 << OUTPUT_BITS["clamps_close"])
    backend.io.deactivate()
    assert bench.io.wait(lambda: bench.io.outputs == 0)  # switched off on the way out


def test_inverted_inputs_and_a_different_wiring(channel, bench: Bench):
    data = machine_data(channel)
    io = data["backend"]["canopen"]["io"]
    io["inputs"]["estop_ok"], io["inputs"]["stop_button"] = 12, 15  # second input byte
    io["inverted_inputs"] = ["estop_ok", "guard_closed"]  # read 0 when healthy
    backend = create_backend(parse_config(data))
    try:
        start(backend)
        bench.io.set_inputs(1 << 15)  # stop button; estop and guard terminals at 0
        period(backend)
        _, inputs = period(backend)
        assert inputs.stop_button and inputs.estop_ok and inputs.guard_closed
    finally:
        for device in backend.devices():
            device.shutdown()
