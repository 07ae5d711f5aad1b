"""Every fault kind injected at every cycle step where it can happen.

Each case must end with the motion stopped, the right alarm raised, the state latched, and
nothing moving again until the operator resets and starts (a Reset alone moves nothing).
Axes have absolute encoders here so that no case spends time homing."""

from __future__ import annotations

import uuid
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path

import pytest

from app.config import MachineConfig, load_config
from app.drivers.modbus.emulator import ModbusEmulator
from app.drivers.sim.faults import SimFaultInjector
from app.drivers.sim.gauge import SimGauge
from app.drivers.sim.settings import parse_gauge_settings
from app.drivers.sim.world import SimWorld
from app.machine import commands as cmd
from app.machine.database_store import open_store
from app.machine.runtime import MachineRuntime
from app.machine.states import LATCHED_STATES, CycleStep, MachineState
from tests.drivers.canopen import conftest as can_rig
from tests.drivers.modbus.helpers import tcp_modbus
from tests.machine.conftest import Rig, make_rig

S = CycleStep
BEFORE_MOTION = (S.CENTERING, S.CLAMPING, S.MEASURING, S.STARTING_SPINDLE)
MOVING = (S.CUTTING_A, S.REPOSITIONING, S.CUTTING_B, S.RETURNING)
EVERY = (*BEFORE_MOTION, *MOVING, S.UNCLAMPING)

# (kind, target, steps where it can happen, expected alarm, latched state)
MATRIX: list[tuple[str, str, tuple[CycleStep, ...], str, MachineState]] = [
    ("drive_fault", "X", EVERY, "E010", MachineState.ERROR),
    ("drive_fault", "Z", EVERY, "E010", MachineState.ERROR),
    ("following_error", "Y", (*BEFORE_MOTION, *MOVING), "E011", MachineState.ERROR),
    ("limit_switch", "X", EVERY, "E012", MachineState.ERROR),
    ("estop", "", EVERY, "E001", MachineState.EMERGENCY_STOP),
    ("comms_loss", "", EVERY, "E020", MachineState.ERROR),
    ("gauge_none", "", (S.CENTERING, S.CLAMPING, S.MEASURING), "E030", MachineState.ERROR),
    ("gauge_garbage", "", (S.CENTERING, S.CLAMPING, S.MEASURING), "E031", MachineState.ERROR),
    ("gauge_out_of_range", "", (S.CENTERING, S.CLAMPING, S.MEASURING), "E032", MachineState.ERROR),
    ("comms_loss", "gauge", (S.CENTERING, S.CLAMPING), "E033", MachineState.ERROR),
    ("clamp_sensor", "closed", (S.CENTERING, S.CLAMPING), "E040", MachineState.ERROR),
    ("clamp_sensor", "open", (*MOVING, S.UNCLAMPING), "E040", MachineState.ERROR),
    ("centering_sensor", "extended", (S.CENTERING,), "E041", MachineState.ERROR),
    (
        "centering_sensor",
        "retracted",
        (S.CENTERING, S.CLAMPING, S.MEASURING),
        "E041",
        MachineState.ERROR,
    ),
    # The spindle runs up during the approach ("cutting side A" from its first period on):
    # failing then, it never reports running, and the cutter waits at the lead-in (E042).
    ("spindle", "", (*BEFORE_MOTION, S.CUTTING_A), "E042", MachineState.ERROR),
    ("spindle", "", (S.REPOSITIONING, S.CUTTING_B), "E043", MachineState.ERROR),
]

CASES = [
    (kind, target, step, code, state)
    for kind, target, steps, code, state in MATRIX
    for step in steps
]
COVERED: list[str] = []


# On Modbus every period is real TCP exchanges with the emulator (eight transactions), so
# the matrix runs there on the pairs that go through the drive layer and the coupler while
# the cutter moves: a drive fault, a following error, a limit switch, the E-stop (safe
# torque off), the link lost, a clamp sensor and the spindle seen over the coupler. The
# gauge rows are the gauge's, whatever the motion backend, and stay on the simulation.
MODBUS_PAIRS: tuple[tuple[str, str, CycleStep], ...] = (
    ("drive_fault", "X", S.CUTTING_A),
    ("following_error", "Y", S.CUTTING_B),
    ("estop", "", S.CUTTING_A),
    ("comms_loss", "", S.CUTTING_B),
    ("clamp_sensor", "open", S.CUTTING_A),
    ("limit_switch", "X", S.RETURNING),
    ("spindle", "", S.CUTTING_B),
)
FIELDBUS_CASES = [case for case in CASES if case[:3] in MODBUS_PAIRS]
"""The pairs run on Modbus and on CANopen too (CANopen runs its heartbeats and TPDO waits in
real time, so it gets the same few pairs as Modbus)."""


@pytest.fixture(scope="module")
def absolute_config():  # type: ignore[no-untyped-def]
    config = load_config()
    axes = {n: replace(a, absolute_encoder=True) for n, a in config.axes.items()}
    return replace(config, axes=axes)


@contextmanager
def sim_rig(config: MachineConfig, tmp_path: Path) -> Iterator[Rig]:
    rig = make_rig(tmp_path, config)
    try:
        yield rig
    finally:
        rig.runtime.shutdown()


@contextmanager
def modbus_rig(config: MachineConfig, tmp_path: Path) -> Iterator[Rig]:
    """The same machine behind the Modbus backend: the emulator serves the simulated world
    over loopback TCP, faults are injected into that world (a comms_loss cuts the wire)."""

    def on_modbus(port: int) -> MachineConfig:
        modbus = tcp_modbus(port, timeout_ms=250.0, retries=0)
        return replace(
            config,
            backend="modbus",
            backend_settings={**config.backend_settings, "modbus": modbus},
            period_s=0.05,  # fewer periods: each one is real TCP exchanges with every device
        )

    emulator = ModbusEmulator(on_modbus(502))
    runtime: MachineRuntime | None = None
    try:
        machine = on_modbus(emulator.serve_tcp())
        # The gauge measures the emulated world's board, as the sim gauge does on the sim.
        gauge = SimGauge(parse_gauge_settings({}), emulator.world, machine.period_s)
        gauge.configure()
        store = open_store(tmp_path / "stave.db", machine, threaded=False)
        runtime = MachineRuntime(machine, store, gauge=gauge)
        runtime.on_tick.append(lambda rt: emulator.emulation.follow_clock(rt.time_s))
        runtime.start()
        yield Rig(runtime, emulator.world, SimFaultInjector(emulator.world))
    finally:
        if runtime is not None:
            runtime.shutdown()
        emulator.stop()


@contextmanager
def canopen_rig(config: MachineConfig, tmp_path: Path) -> Iterator[Rig]:
    """The same machine behind the CANopen backend: the world's drives and I/O as CANopen
    nodes on python-can's virtual bus (a channel of this test's own)."""
    channel = f"stave-matrix-{uuid.uuid4().hex[:12]}"
    settings = can_rig.canopen_settings(
        channel, heartbeat_ms=100, heartbeat_timeout_ms=1000, master_heartbeat_timeout_ms=1000
    )
    machine = replace(
        config,
        backend="canopen",
        backend_settings={**config.backend_settings, "canopen": settings},
        period_s=0.01,
    )
    world = SimWorld.from_config(machine)
    bus = can_rig.world_bus(world, channel)
    runtime: MachineRuntime | None = None
    try:
        gauge = SimGauge(parse_gauge_settings({}), world, machine.period_s)
        gauge.configure()
        store = open_store(tmp_path / "stave.db", machine, threaded=False)
        runtime = MachineRuntime(machine, store, gauge=gauge)
        runtime.on_tick.append(lambda rt: bus.follow_clock(rt.time_s))
        runtime.start()
        yield Rig(runtime, world, SimFaultInjector(world))
    finally:
        if runtime is not None:
            runtime.shutdown()
        bus.close()


RIGS = {"sim": sim_rig, "modbus": modbus_rig, "canopen": canopen_rig}
"""How each backend's machine is put together for one case."""

BACKEND_CASES = [("sim", *case) for case in CASES] + [
    (backend, *case) for backend in ("modbus", "canopen") for case in FIELDBUS_CASES
]


@pytest.mark.parametrize(
    ("backend", "kind", "target", "step", "code", "latched"),
    BACKEND_CASES,
    ids=[f"{b}-{k}:{t}@{s.name.lower()}" for b, k, t, s, _c, _l in BACKEND_CASES],
)
def test_fault_at_step(
    backend: str,
    kind: str,
    target: str,
    step: CycleStep,
    code: str,
    latched: MachineState,
    absolute_config,
    tmp_path: Path,
) -> None:
    config = absolute_config
    if step is S.RETURNING:  # only a machine that goes home between boards returns
        config = replace(config, cycle=replace(config.cycle, return_home_between_boards=True))
    with RIGS[backend](config, tmp_path) as rig:
        run_case(rig, kind, target, step, code, latched)
    if backend == "sim":
        COVERED.append(f"{kind}:{target}@{step.name.lower()}")


def run_case(
    rig: Rig, kind: str, target: str, step: CycleStep, code: str, latched: MachineState
) -> None:
    """Start a cycle, inject at ``step``, check the stop, the alarm, the latch, and that a
    Reset alone moves nothing."""
    assert rig.state is MachineState.READY
    rig.select("Barrique 225 l Bordeaux")
    rig.load(150.0)
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is step, 120.0)
    rig.faults.inject(kind, target)
    rig.until(lambda c: c.state in LATCHED_STATES, 30.0)
    assert rig.state is latched
    rig.run(3.0)  # stopping ramps end (and a lost link's watchdogs act)
    # The right alarm, once every backend's feedback is in (CANopen's slow TPDO brings the
    # limit switch bits a few SYNCs after the fault's statusword).
    codes = {a.code for a in rig.controller.snapshot().alarms}
    assert code in codes, f"expected {code}, got {codes}"
    assert not rig.world.outputs.spindle_on
    still = rig.positions()
    rig.run(3.0)
    assert rig.positions() == pytest.approx(still, abs=0.01), "moved while latched"
    assert not rig.moving()

    rig.faults.clear_injections()
    rig.send(cmd.Reset(), run_s=1.0)
    assert rig.state in (MachineState.READY, MachineState.NOT_HOMED), rig.controller.message
    rig.run(2.0)
    assert rig.positions() == pytest.approx(still, abs=0.01), "moved after Reset alone"
    assert not any(a.enabled for a in rig.controller.snapshot().axes)


def test_matrix_report(capsys: pytest.CaptureFixture[str]) -> None:
    """Prints how many cases the matrix covered (runs after the cases, in file order)."""
    with capsys.disabled():
        print(
            f"\nfault matrix: {len(COVERED)} of {len(CASES)} cases passed "
            f"({len({c.split('@')[0] for c in COVERED})} fault kinds and targets)"
        )
    assert len(CASES) >= 80
