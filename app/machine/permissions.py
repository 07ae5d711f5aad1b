""" "May I do this now?" for every operator command, as pure functions of the machine's state.

Why here and pure (after QtPyVCP's machine_actions ``ok()`` rules): the screens enable and
disable their buttons from this answer, and show the reason as the message; the controller
refuses the same commands with the same reason. One rule, tested without Qt.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.drivers.contracts import InputImage
from app.machine.states import LATCHED_STATES, MachineState


@dataclass(frozen=True)
class Facts:
    state: MachineState
    all_homed: bool
    recipe_loaded: bool
    inputs: InputImage
    cycle_running: bool  # an automatic cycle is between its first and its last step
    simulation: bool
    interrupted: bool = False  # a board on the table is partly cut (resume or abandon it)
    interrupted_unclamped: bool = False  # ... and the clamps have opened since


def _latched(facts: Facts) -> str:
    if facts.state in LATCHED_STATES:
        return f"machine is in {facts.state.value}: press Reset first"
    if facts.state is MachineState.POWER_UP:
        return "machine is still starting up"
    return ""


def may_start(f: Facts) -> str:
    if reason := _latched(f):
        return reason
    if f.state is MachineState.MANUAL:
        return "leave manual mode first"
    if f.state is MachineState.AUTOMATIC:
        return "a cycle is already running"
    if f.state is not MachineState.READY or not f.all_homed:
        return (
            "axes are not homed: home the machine first"
            if not f.all_homed
            else f"not possible while {f.state.value}"
        )
    if f.interrupted:
        return "a board is partly cut: Resume or Abandon it"
    if not f.recipe_loaded:
        return "select a recipe first"
    if not f.inputs.guard_closed:
        return "close the guard first"
    return ""


def may_resume(f: Facts) -> str:
    if not f.interrupted:
        return "no board is partly cut"
    if reason := _latched(f):
        return reason
    if f.state is not MachineState.READY or not f.all_homed:
        return (
            "axes are not homed: abandon the board (their position is unknown)"
            if not f.all_homed
            else f"not possible while {f.state.value}"
        )
    if f.interrupted_unclamped or not (f.inputs.part_present and f.inputs.clamps_closed):
        return "the board was unclamped: it may have moved, abandon it"
    if not f.inputs.guard_closed:
        return "close the guard first"
    return ""


def may_abandon(f: Facts) -> str:
    if not f.interrupted:
        return "no board is partly cut"
    if reason := _latched(f):
        return reason
    if f.state not in (MachineState.READY, MachineState.NOT_HOMED):
        return f"not possible while {f.state.value}"
    if f.all_homed and not f.inputs.guard_closed:
        return "close the guard first"
    return ""


def may_stop(f: Facts) -> str:
    if f.state in (
        MachineState.AUTOMATIC,
        MachineState.HOMING,
        MachineState.STOPPING,
        MachineState.MANUAL,
    ):
        return ""
    return "nothing is moving"


def may_reset(f: Facts) -> str:
    if f.state not in LATCHED_STATES:
        return "nothing to reset"
    if not f.inputs.estop_ok:
        return "release the emergency stop first"
    return ""


def may_home(f: Facts) -> str:
    if reason := _latched(f):
        return reason
    if f.state not in (MachineState.NOT_HOMED, MachineState.READY, MachineState.MANUAL):
        return f"machine is busy ({f.state.value}): stop it first"
    if not f.inputs.guard_closed and f.state is not MachineState.MANUAL:
        return "close the guard first"
    if f.interrupted:
        return "a board is partly cut: Resume or Abandon it first"
    if (f.inputs.part_present or f.inputs.clamps_closed) and not f.all_homed:
        return (
            "a board is on the table and the axes do not know where they are: "
            "take the board off before homing"
        )
    return ""


def may_enter_manual(f: Facts) -> str:
    if reason := _latched(f):
        return reason
    if f.state is MachineState.MANUAL:
        return "already in manual mode"
    if f.state not in (MachineState.NOT_HOMED, MachineState.READY):
        return f"machine is busy ({f.state.value}): stop it first"
    return ""


def may_leave_manual(f: Facts) -> str:
    return "" if f.state is MachineState.MANUAL else "not in manual mode"


def may_jog(f: Facts) -> str:
    if reason := _latched(f):
        return reason
    return "" if f.state is MachineState.MANUAL else "open the Manual screen to jog"


def may_spindle(f: Facts) -> str:
    if reason := may_jog(f):
        return reason
    return "" if f.inputs.guard_closed else "close the guard first"


def may_select_recipe(f: Facts) -> str:
    if f.cycle_running or f.state in (MachineState.AUTOMATIC, MachineState.STOPPING):
        return "wait until the cycle has ended"
    return ""


def may_simulate(f: Facts) -> str:
    return "" if f.simulation else "only on the simulated machine"


def always(_f: Facts) -> str:
    return ""


# command class name -> rule
RULES = {
    "Start": may_start,
    "Resume": may_resume,
    "Abandon": may_abandon,
    "Stop": may_stop,
    "Reset": may_reset,
    "Home": may_home,
    "EnterManual": may_enter_manual,
    "LeaveManual": may_leave_manual,
    "JogContinuous": may_jog,
    "JogStep": may_jog,
    "JogRelease": always,
    "SetJogSpeed": always,
    "SetClamps": may_jog,
    "SetSpindle": may_spindle,
    "SelectRecipe": may_select_recipe,
    "StartBarrel": may_select_recipe,
    "ChooseBoard": may_select_recipe,
    "SetFeedOverride": always,
    "Acknowledge": always,
    "ReloadParameters": always,
    "ResetShiftCounter": always,
    "InjectFault": may_simulate,
    "ClearFaults": may_simulate,
    "LoadBoard": may_simulate,
    "SetUser": always,
    "Shutdown": always,
}


def allowed_commands(facts: Facts) -> dict[str, str]:
    return {name: rule(facts) for name, rule in RULES.items()}
