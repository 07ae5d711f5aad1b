"""A full automatic cycle on the CANopen backend: the real machine layer (state machine,
homing, cycle, planner, executor) drives the simulated CiA 402 drives and the I/O station
over python-can's virtual bus, one SYNC per period, as it would on the machine.

The machine runs on its simulated clock as fast as the bus answers (each read waits for the
drives' answers to the previous SYNC); heartbeats and their watchdog run in real time beside
it. The simulated station counts its travel times in SYNCs, i.e. in machine time."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from app.cli.simulate import Watch
from app.config import parse_config
from app.drivers.cia402 import Cia402State
from app.machine import commands as cmd
from app.machine.runtime import MachineRuntime
from app.machine.states import MachineState
from tests.drivers.canopen.conftest import (
    INPUT_BITS,
    IO_NODE,
    NODE_IDS,
    OUTPUT_BITS,
    Bench,
    machine_data,
)
from tests.drivers.canopen.sim_drive import SimDrive, SimStationIo
from tests.drivers.canopen.sim_nodes import SimNetwork
from tests.drivers.cycle_helpers import cut_one_board, select_sample_recipe

BOARD_MM = 150.0
PERIOD_MS = 10.0  # fewer periods keep the test short; the cycle is the same at 4 ms


@pytest.fixture(
    params=[
        pytest.param(-3, id="homing-stops-past-the-edge"),
        pytest.param(0, id="homing-stops-exactly-at-the-edge"),
    ]
)
def station(channel: str, request: pytest.FixtureRequest) -> Iterator[Bench]:
    network = SimNetwork(channel)
    start_counts = {"X": 40_000, "Y": 30_000, "Z": 0}  # 40 mm, 30 mm, 0 degrees
    # real drives stop a few counts past the home switch's edge; method 35/37 drives exactly
    drives = {
        name: SimDrive(
            network, node, position_counts=start_counts[name], homing_overshoot_counts=request.param
        )
        for name, node in NODE_IDS.items()
    }
    io = SimStationIo(network, IO_NODE, INPUT_BITS, OUTPUT_BITS, travel_syncs=20)
    for node in network.nodes:
        node.boot()
    yield Bench(network, drives, io)  # type: ignore[arg-type]
    network.close()


def test_full_automatic_cycle_on_canopen(channel: str, station: Bench, tmp_path: Path) -> None:
    data = machine_data(channel)
    data["backend"]["period_ms"] = PERIOD_MS
    # a long test: a busy CI machine must not starve a heartbeat into a false loss
    data["backend"]["canopen"].update(
        heartbeat_ms=100, heartbeat_timeout_ms=1000, master_heartbeat_timeout_ms=1000
    )
    # as the shipped machine.toml: the drives' homing leaves each axis at its home switch
    data["axes"]["X"].update(min_position=-10.0, home_switch_position=-5.0)
    data["axes"]["Y"].update(min_position=-10.0, home_switch_position=-5.0)
    data["axes"]["Z"].update(home_switch_position=-12.0)
    data["gauge"] = {
        "name": "sim",
        "sim": {"width_mean_mm": BOARD_MM, "width_sd_mm": 0.0, "noise_mm": 0.0},
    }
    config = parse_config(data)
    io: SimStationIo = station.io  # type: ignore[assignment]
    runtime = MachineRuntime.create(config, tmp_path / "cycle.db")
    spindle_seen: list[bool] = []
    try:
        assert runtime.backend.name == "canopen"
        watch = Watch()
        runtime.on_tick.append(watch.observe)
        runtime.on_tick.append(lambda _rt: spindle_seen.append(io._on("spindle_on")))
        runtime.start()
        c = runtime.controller
        select_sample_recipe(runtime)
        assert c.state is MachineState.NOT_HOMED, c.state_text()
        c.post(cmd.Home())  # X and Y have incremental encoders: homed through the drives
        assert runtime.run_until(lambda m: m.state is MachineState.READY, 120.0), c.state_text()
        assert c.axes.all_homed()
        syncs_before = station.drives["X"].sync_count
        io.part_present = True  # the operator puts a board in
        runtime.run_for(0.1)
        cut_one_board(runtime, watch, BOARD_MM)
        # everything went over the bus: SYNCs, the spindle on and off through the I/O node,
        # the drives moved and none faulted, and the station's clamps are open again
        assert station.drives["X"].sync_count - syncs_before > 1000
        assert any(spindle_seen) and not io._on("spindle_on")
        xs = [t for _, t in station.drives["X"].record.targets]
        assert max(xs) - min(xs) > 500_000  # X travelled more than 500 mm
        assert all(d.state is not Cia402State.FAULT for d in station.drives.values())
    finally:
        runtime.shutdown()
