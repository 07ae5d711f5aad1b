"""The CiA 401 I/O node over the simulated world's terminals: inputs by function with
inversion, outputs by function."""

from __future__ import annotations

from app.config import parse_config
from app.drivers.canopen import objects as obj
from app.drivers.canopen.backend import create_backend
from app.drivers.contracts import OutputImage
from tests.drivers.canopen.conftest import (
    OUTPUT_BITS,
    machine_data,
    period,
    start,
    world_bus,
    zero_world,
)
from tests.drivers.canopen.world_nodes import WorldBus


def test_io_node_is_mapped_and_outputs_start_off(backend, bus: WorldBus):
    start(backend)
    assert bus.io.read(obj.TPDO_COMM, 2) == 1  # inputs on every SYNC
    assert bus.io.read(obj.RPDO_COMM, 2) == 255  # outputs applied on receipt
    assert bus.io.read(obj.TPDO_MAPPING, 0) == 2  # 11 inputs: two bytes
    assert bus.io.read(obj.RPDO_MAPPING, 0) == 1  # 6 outputs: one byte
    assert bus.io.outputs == 0


def test_inputs_by_function(backend, bus: WorldBus):
    start(backend)
    with bus.lock:
        bus.world.load_board(100.0)
        bus.world.press_start()
    _, inputs = period(backend)
    _, inputs = period(backend)
    assert inputs.part_present and inputs.start_button and inputs.estop_ok
    assert not inputs.stop_button and not inputs.clamps_closed
    with bus.lock:
        bus.world.set_estop(True)  # chain opened
        bus.world.remove_board()
    period(backend)
    _, inputs = period(backend)
    assert not inputs.estop_ok and not inputs.part_present


def test_outputs_by_function(backend, bus: WorldBus):
    start(backend)
    period(backend, outputs=OutputImage(spindle_on=True, lamp_green=True))
    assert bus.io.wait(
        lambda: bus.io.outputs == (1 << OUTPUT_BITS["spindle_on"] | 1 << OUTPUT_BITS["lamp_green"])
    )
    assert bus.world.outputs == OutputImage(spindle_on=True, lamp_green=True)
    period(backend, outputs=OutputImage(clamps_close=True))
    assert bus.io.wait(lambda: bus.io.outputs == 1 << OUTPUT_BITS["clamps_close"])
    backend.io.deactivate()
    assert bus.io.wait(lambda: bus.io.outputs == 0)  # switched off on the way out


def test_inverted_inputs_and_a_different_wiring(channel):
    data = machine_data(channel)
    io = data["backend"]["canopen"]["io"]
    io["inputs"]["estop_ok"], io["inputs"]["stop_button"] = 12, 15  # second input byte
    io["inverted_inputs"] = ["estop_ok", "guard_closed"]  # read 0 when healthy
    config = parse_config(data)
    bus = world_bus(
        zero_world(config), channel, io["inputs"], inverted_inputs=io["inverted_inputs"]
    )
    backend = create_backend(config)
    try:
        start(backend)
        with bus.lock:
            bus.world.press_stop()
        period(backend)
        _, inputs = period(backend)
        assert bus.io.inputs >> 12 & 1 == 0  # the healthy chain's terminal reads 0
        assert inputs.stop_button and inputs.estop_ok and inputs.guard_closed
        with bus.lock:
            bus.world.set_guard(False)
        period(backend)
        _, inputs = period(backend)
        assert not inputs.guard_closed and inputs.estop_ok
    finally:
        for device in backend.devices():
            device.shutdown()
        bus.close()
