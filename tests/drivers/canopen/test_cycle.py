"""A full automatic cycle on the CANopen backend: the real machine layer (state machine,
homing, cycle, planner, executor) drives the simulated world's CiA 402 drives and I/O over
python-can's virtual bus, one SYNC per period, as it would on the machine.

The machine runs on its simulated clock as fast as the bus answers (each read waits for the
drives' answers to the previous SYNC); heartbeats and their watchdog run in real time beside
it. The world advances one period per SYNC, so its travel times (centering device, clamps,
spindle run-up) and the drives' homing are machine time.

Homing is the physical drive's: it latches the home switch's reference edge while creeping
onto it and then brakes to a stop, so the axis rests a little past the edge, as a real drive
does. A drive that stops exactly on the edge (methods 35/37) leaves the first move on a
profile boundary of the trajectory generator; that start is covered by
``tests/machine/planner/test_point_to_point.py``
(``test_a_move_exactly_on_a_ruckig_profile_boundary_is_planned``)."""

from __future__ import annotations

from pathlib import Path

from app.cli.simulate import Watch
from app.config import parse_config
from app.drivers.cia402 import Cia402State
from app.drivers.sim.gauge import SimGauge
from app.drivers.sim.settings import SimSettings, parse_gauge_settings
from app.drivers.sim.world import SimWorld
from app.machine import commands as cmd
from app.machine.database_store import open_store
from app.machine.runtime import MachineRuntime
from app.machine.states import MachineState
from tests.drivers.canopen.conftest import machine_data, world_bus
from tests.drivers.cycle_helpers import cut_one_board, select_sample_recipe

BOARD_MM = 150.0
PERIOD_MS = 10.0  # fewer periods keep the test short; the cycle is the same at 4 ms


def test_full_automatic_cycle_on_canopen(channel: str, tmp_path: Path) -> None:
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
    config = parse_config(data)
    # X and Y stand at 40 mm and 30 mm, their incremental encoders count from 0 at power-up
    world = SimWorld(config, SimSettings(start_position={"X": 40.0, "Y": 30.0, "Z": 0.0}))
    bus = world_bus(world, channel)
    runtime: MachineRuntime | None = None
    spindle_seen: list[bool] = []
    try:
        gauge = SimGauge(parse_gauge_settings({"noise_mm": 0.0}), world, config.period_s)
        gauge.configure()
        store = open_store(tmp_path / "cycle.db", config, threaded=False)
        runtime = MachineRuntime(config, store, gauge=gauge)
        runtime.on_tick.append(lambda rt: bus.follow_clock(rt.time_s))
        assert runtime.backend.name == "canopen"
        watch = Watch()
        runtime.on_tick.append(watch.observe)
        runtime.on_tick.append(lambda _rt: spindle_seen.append(world.outputs.spindle_on))
        runtime.start()
        c = runtime.controller
        select_sample_recipe(runtime)
        assert c.state is MachineState.NOT_HOMED, c.state_text()
        c.post(cmd.Home())  # X and Y have incremental encoders: homed through the drives
        assert runtime.run_until(lambda m: m.state is MachineState.READY, 120.0), c.state_text()
        assert c.axes.all_homed()
        for name in ("X", "Y"):  # at rest on the switch, a creep's braking past its edge
            drive = world.drives[name]
            assert drive.homed and drive.home_switch
            assert -5.1 < drive.position < -5.0, (name, drive.position)
        syncs_before = bus.drives["X"].sync_count
        world.load_board(BOARD_MM)  # the operator puts a board in
        runtime.run_for(0.1)
        cut_one_board(runtime, watch, BOARD_MM)
        # everything went over the bus: SYNCs, the spindle on and off through the I/O node,
        # the drives moved and none faulted, and the station's clamps are open again
        assert bus.drives["X"].sync_count - syncs_before > 1000
        assert any(spindle_seen) and not world.outputs.spindle_on
        xs = [t for _, t in bus.drives["X"].record.targets]
        assert max(xs) - min(xs) > 500_000  # X travelled more than 500 mm
        assert all(d.state is not Cia402State.FAULT for d in world.drives.values())
        assert world.io.clamps.position <= 0.0
    finally:
        if runtime is not None:
            runtime.shutdown()
        bus.close()
