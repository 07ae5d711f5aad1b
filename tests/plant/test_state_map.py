"""The OPC 40550-1 unit state of every machine state, row by row (the README's table)."""

from __future__ import annotations

from dataclasses import replace

import pytest

from app.config import load_config
from app.drivers.contracts import InputImage
from app.machine.local_link import LocalMachineLink
from app.machine.snapshot import MachineSnapshot
from app.machine.states import CycleStep, MachineState, Mode
from app.plant.state_map import (
    FLAGS_BY_STATE,
    OFFLINE_FLAGS,
    WwUnitMode,
    WwUnitState,
    unit_flags,
    unit_mode,
    unit_state,
)


@pytest.fixture(scope="module")
def ready(tmp_path_factory: pytest.TempPathFactory) -> MachineSnapshot:
    config = load_config().with_backend("sim", "sim")
    axes = {n: replace(a, absolute_encoder=True) for n, a in config.axes.items()}
    link = LocalMachineLink.create(
        replace(config, axes=axes), tmp_path_factory.mktemp("s") / "s.db"
    )
    try:
        snapshot = link.run_for(0.5)
    finally:
        link.close()
    assert snapshot.state is MachineState.READY and snapshot.all_homed
    return snapshot


# machine state, all axes homed, E-stop chain closed -> unit state, unit mode (README table)
ROWS = [
    (MachineState.POWER_UP, False, True, WwUnitState.STANDBY, WwUnitMode.OTHER),
    (MachineState.NOT_HOMED, False, True, WwUnitState.STANDBY, WwUnitMode.AUTOMATIC),
    (MachineState.HOMING, False, True, WwUnitState.STANDBY, WwUnitMode.SETUP),
    (MachineState.READY, True, True, WwUnitState.READY, WwUnitMode.AUTOMATIC),
    (MachineState.AUTOMATIC, True, True, WwUnitState.WORKING, WwUnitMode.AUTOMATIC),
    (MachineState.MANUAL, True, True, WwUnitState.READY, WwUnitMode.MANUAL),
    (MachineState.MANUAL, False, True, WwUnitState.STANDBY, WwUnitMode.MANUAL),
    (MachineState.STOPPING, True, True, WwUnitState.WORKING, WwUnitMode.AUTOMATIC),
    (MachineState.ERROR, True, True, WwUnitState.ERROR, WwUnitMode.AUTOMATIC),
    (MachineState.EMERGENCY_STOP, True, False, WwUnitState.ERROR, WwUnitMode.AUTOMATIC),
]


@pytest.mark.parametrize(("state", "homed", "estop_ok", "expected", "mode"), ROWS)
def test_unit_state_of_each_machine_state(
    ready: MachineSnapshot,
    state: MachineState,
    homed: bool,
    estop_ok: bool,
    expected: WwUnitState,
    mode: WwUnitMode,
) -> None:
    axes = tuple(replace(a, homed=homed) for a in ready.axes)
    step = CycleStep.CUTTING_A if state in (MachineState.AUTOMATIC, MachineState.STOPPING) else None
    snapshot = replace(
        ready,
        state=state,
        axes=axes,
        mode=Mode.MANUAL if state is MachineState.MANUAL else Mode.AUTOMATIC,
        inputs=replace(InputImage(), estop_ok=estop_ok),
        cycle=replace(ready.cycle, step=step),
    )
    flags = unit_flags(snapshot)
    assert unit_state(flags) is expected
    assert unit_mode(snapshot) is mode
    assert flags.emergency is (not estop_ok or state is MachineState.EMERGENCY_STOP)
    assert flags.moving is (step is not None or state is MachineState.HOMING)


def test_every_machine_state_has_a_row() -> None:
    assert {row[0] for row in ROWS} == set(MachineState) == set(FLAGS_BY_STATE)


def test_no_snapshot_is_offline() -> None:
    assert unit_state(unit_flags(None)) is WwUnitState.OFFLINE
    assert OFFLINE_FLAGS.as_browse_names()["MachineOn"] is False


def test_spec_formulas_error_needs_initialized() -> None:
    flags = replace(OFFLINE_FLAGS, machine_on=True, error=True, machine_initialized=False)
    assert unit_state(flags) is WwUnitState.STANDBY
    assert unit_state(replace(flags, machine_initialized=True)) is WwUnitState.ERROR
    assert unit_state(replace(flags, machine_initialized=True, energy_saving=True)) is (
        WwUnitState.STANDBY
    )
