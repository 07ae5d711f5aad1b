"""The machine's state in the terms of OPC 40550-1: unit flags, unit state and unit mode.

Why flags first: the specification (section 7.7) defines the unit state only through the
flags, "do not rely on the transitions, only the logic of the unit flags counts". So each
machine state contributes its flags (one table, ``FLAGS_BY_STATE``), the rest come from the
snapshot (inputs, axes, alarms), and :func:`unit_state` applies the specification's formulas
literally. The README lists the resulting table and a test checks it row by row.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from app.machine.snapshot import AlarmState, MachineSnapshot
from app.machine.states import CycleStep, MachineState, Mode


class WwUnitState(enum.IntEnum):
    """WwUnitStateEnumeration (ns Woodworking, i=21): values as in the NodeSet."""

    OFFLINE = 0
    STANDBY = 1
    READY = 2
    WORKING = 3
    ERROR = 4


class WwUnitMode(enum.IntEnum):
    """WwUnitModeEnumeration (ns Woodworking, i=20): values as in the NodeSet."""

    OTHER = 0
    AUTOMATIC = 1
    SEMIAUTOMATIC = 2
    MANUAL = 3
    SETUP = 4
    SLEEP = 5


@dataclass(frozen=True)
class StateFlags:
    """What a machine state says by itself about the flags that decide the unit state."""

    initialized: bool  # MachineInitialized: the controller and drives have started up
    error: bool  # Error: a reason exists that prevents the machine from working
    recipe_in_run: bool  # RecipeInRun: the automatic cycle runs
    mode: WwUnitMode


FLAGS_BY_STATE: dict[MachineState, StateFlags] = {
    MachineState.POWER_UP: StateFlags(False, False, False, WwUnitMode.OTHER),
    MachineState.NOT_HOMED: StateFlags(True, False, False, WwUnitMode.AUTOMATIC),
    MachineState.HOMING: StateFlags(True, False, False, WwUnitMode.SETUP),
    MachineState.READY: StateFlags(True, False, False, WwUnitMode.AUTOMATIC),
    MachineState.AUTOMATIC: StateFlags(True, False, True, WwUnitMode.AUTOMATIC),
    MachineState.MANUAL: StateFlags(True, False, False, WwUnitMode.MANUAL),
    # A stop ends the cycle along the path: the recipe still runs until the axes stand.
    MachineState.STOPPING: StateFlags(True, False, True, WwUnitMode.AUTOMATIC),
    MachineState.ERROR: StateFlags(True, True, False, WwUnitMode.AUTOMATIC),
    MachineState.EMERGENCY_STOP: StateFlags(True, True, False, WwUnitMode.AUTOMATIC),
}

_MOTION_STEPS = frozenset(
    {CycleStep.CUTTING_A, CycleStep.REPOSITIONING, CycleStep.CUTTING_B, CycleStep.RETURNING}
)
_CUTTING_STEPS = frozenset({CycleStep.CUTTING_A, CycleStep.CUTTING_B})
_AT_REST_MM = 1e-3


@dataclass(frozen=True)
class UnitFlags:
    """IWwUnitFlagsType: the mandatory flags and the optional ones the jointer knows."""

    machine_on: bool
    power_present: bool
    machine_initialized: bool
    emergency: bool
    calibrated: bool
    error: bool
    alarm: bool
    warning: bool
    recipe_in_run: bool
    moving: bool = False
    workpiece_present: bool = False
    feed_runs: bool = False
    safety: bool = False
    wait_load: bool = False
    manual_activity_required: bool = False
    energy_saving: bool = False  # the jointer has no energy-saving mode

    def as_browse_names(self) -> dict[str, bool]:
        """Flag name as in the NodeSet (``MachineOn``) -> value."""
        return {
            "".join(part.capitalize() for part in name.split("_")): value
            for name, value in self.__dict__.items()
        }


OFFLINE_FLAGS = UnitFlags(
    machine_on=False,
    power_present=False,
    machine_initialized=False,
    emergency=False,
    calibrated=False,
    error=False,
    alarm=False,
    warning=False,
    recipe_in_run=False,
)


def unit_flags(snapshot: MachineSnapshot | None) -> UnitFlags:
    """The flags for one snapshot; no snapshot (the machine process is gone): machine off."""
    if snapshot is None:
        return OFFLINE_FLAGS
    by_state = FLAGS_BY_STATE[snapshot.state]
    shown = [a for a in snapshot.alarms if a.state is not AlarmState.NORMAL]
    step = snapshot.cycle.step
    in_cycle = snapshot.state in (MachineState.AUTOMATIC, MachineState.STOPPING)
    recipe_in_run = by_state.recipe_in_run and (
        snapshot.state is MachineState.AUTOMATIC or step is not None
    )
    moving = snapshot.state in (MachineState.HOMING, MachineState.STOPPING) or (
        in_cycle and step in _MOTION_STEPS
    )
    moving = moving or any(abs(a.command - a.position) > _AT_REST_MM for a in snapshot.axes)
    calibrated = snapshot.all_homed and snapshot.state is not MachineState.HOMING
    return UnitFlags(
        machine_on=True,
        power_present=snapshot.inputs.estop_ok,
        machine_initialized=by_state.initialized,
        emergency=snapshot.state is MachineState.EMERGENCY_STOP or not snapshot.inputs.estop_ok,
        calibrated=calibrated,
        error=by_state.error,
        alarm=any(a.severity == "fault" for a in shown),
        warning=any(a.severity == "warning" for a in shown),
        recipe_in_run=recipe_in_run,
        moving=moving,
        workpiece_present=snapshot.inputs.part_present,
        feed_runs=in_cycle and step in _CUTTING_STEPS,
        safety=not snapshot.inputs.guard_closed,
        wait_load=snapshot.state is MachineState.AUTOMATIC and step is CycleStep.WAIT_FOR_PART,
        manual_activity_required=snapshot.unacknowledged_alarms > 0,
    )


def unit_state(flags: UnitFlags) -> WwUnitState:
    """OPC 40550-1 section 7.7, the formulas as written (EnergySaving is always False)."""
    if not flags.machine_on:
        return WwUnitState.OFFLINE
    base = flags.machine_initialized and not flags.energy_saving
    if base and flags.error:
        return WwUnitState.ERROR
    if base and flags.calibrated:
        return WwUnitState.WORKING if flags.recipe_in_run else WwUnitState.READY
    return WwUnitState.STANDBY


def unit_mode(snapshot: MachineSnapshot | None) -> WwUnitMode:
    if snapshot is None:
        return WwUnitMode.OTHER
    mode = FLAGS_BY_STATE[snapshot.state].mode
    if snapshot.state in (MachineState.ERROR, MachineState.EMERGENCY_STOP):
        return WwUnitMode.MANUAL if snapshot.mode is Mode.MANUAL else WwUnitMode.AUTOMATIC
    return mode
