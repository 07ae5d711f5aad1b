""" "May I do this now?" for every operator command, as pure functions of the machine's state.

Why here and pure (after QtPyVCP's machine_actions ``ok()`` rules): the screens enable and
disable their buttons from this answer, and show the reason (a ``Refusal`` code, which they
translate) as the message; the controller refuses the same commands with the same reason.
These are the only rules: the state table (``app.machine.states``) says where each accepted
command leads, and a test checks row by row that the two agree.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from app.drivers.contracts import InputImage
from app.machine import commands as cmd
from app.machine.refusals import Reason, Refusal
from app.machine.states import LATCHED_STATES, MOVING_STATES, MachineState


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


Verdict = Refusal | None  # None: allowed now

R = Reason
_LATCHED = {MachineState.ERROR: R.LATCHED_ERROR, MachineState.EMERGENCY_STOP: R.LATCHED_ESTOP}
_BUSY = {
    MachineState.AUTOMATIC: R.BUSY_AUTOMATIC,
    MachineState.HOMING: R.BUSY_HOMING,
    MachineState.STOPPING: R.BUSY_STOPPING,
}
_NOT_POSSIBLE = {
    MachineState.HOMING: R.NOT_POSSIBLE_HOMING,
    MachineState.STOPPING: R.NOT_POSSIBLE_STOPPING,
    MachineState.NOT_HOMED: R.NOT_POSSIBLE_NOT_HOMED,
    MachineState.AUTOMATIC: R.NOT_POSSIBLE_AUTOMATIC,
    MachineState.MANUAL: R.NOT_POSSIBLE_MANUAL,
    MachineState.READY: R.NOT_POSSIBLE_READY,
}


def _no(reason: Reason) -> Refusal:
    return Refusal(reason)


def _latched(f: Facts) -> Verdict:
    """Why a latched machine refuses; it names Reset only while Reset is possible (the
    hint follows the button: with the button still pressed, Reset is disabled)."""
    if f.state is MachineState.EMERGENCY_STOP and not f.inputs.estop_ok:
        return _no(R.LATCHED_ESTOP_PRESSED)
    if f.state in _LATCHED:
        return _no(_LATCHED[f.state])
    if f.state is MachineState.POWER_UP:
        return _no(R.STARTING_UP)
    return None


def _busy(f: Facts) -> Verdict:
    return _no(_BUSY[f.state]) if f.state in _BUSY else None


def may_start(f: Facts) -> Verdict:
    if reason := _latched(f):
        return reason
    if f.state is MachineState.MANUAL:
        return _no(R.LEAVE_MANUAL_FIRST)
    if f.state is MachineState.AUTOMATIC:
        return _no(R.CYCLE_RUNNING)
    if not f.all_homed:
        return _no(R.NOT_HOMED)
    if f.state is not MachineState.READY:
        return _no(_NOT_POSSIBLE[f.state])
    if f.interrupted:
        return _no(R.PARTLY_CUT_RESUME_OR_ABANDON)
    if not f.recipe_loaded:
        return _no(R.SELECT_RECIPE_FIRST)
    if not f.inputs.guard_closed:
        return _no(R.CLOSE_GUARD_FIRST)
    return None


def may_resume(f: Facts) -> Verdict:
    if not f.interrupted:
        return _no(R.NO_BOARD_PARTLY_CUT)
    if reason := _latched(f):
        return reason
    if not f.all_homed:
        return _no(R.NOT_HOMED_ABANDON)
    if f.state is not MachineState.READY:
        return _no(_NOT_POSSIBLE[f.state])
    if f.interrupted_unclamped or not (f.inputs.part_present and f.inputs.clamps_closed):
        return _no(R.UNCLAMPED_ABANDON)
    if not f.inputs.guard_closed:
        return _no(R.CLOSE_GUARD_FIRST)
    return None


def may_abandon(f: Facts) -> Verdict:
    if not f.interrupted:
        return _no(R.NO_BOARD_PARTLY_CUT)
    if reason := _latched(f):
        return reason
    if f.state not in (MachineState.READY, MachineState.NOT_HOMED):
        return _no(_NOT_POSSIBLE[f.state])
    if f.all_homed and not f.inputs.guard_closed:
        return _no(R.CLOSE_GUARD_FIRST)
    return None


def may_stop(f: Facts) -> Verdict:
    if f.state in MOVING_STATES or f.state is MachineState.MANUAL:
        return None
    return _no(R.NOTHING_MOVING)


def may_reset(f: Facts) -> Verdict:
    if f.state not in LATCHED_STATES:
        return _no(R.NOTHING_TO_RESET)
    if not f.inputs.estop_ok:
        return _no(R.RELEASE_ESTOP_FIRST)
    return None


def may_home(f: Facts) -> Verdict:
    if reason := _latched(f) or _busy(f):
        return reason
    if not f.inputs.guard_closed and f.state is not MachineState.MANUAL:
        return _no(R.CLOSE_GUARD_FIRST)
    if f.interrupted:
        return _no(R.PARTLY_CUT_FIRST)
    if (f.inputs.part_present or f.inputs.clamps_closed) and not f.all_homed:
        return _no(R.BOARD_ON_TABLE_UNHOMED)
    return None


def may_enter_manual(f: Facts) -> Verdict:
    if reason := _latched(f):
        return reason
    if f.state is MachineState.MANUAL:
        return _no(R.ALREADY_MANUAL)
    return _busy(f)


def may_leave_manual(f: Facts) -> Verdict:
    return None if f.state is MachineState.MANUAL else _no(R.NOT_MANUAL)


def may_jog(f: Facts) -> Verdict:
    if reason := _latched(f):
        return reason
    return None if f.state is MachineState.MANUAL else _no(R.OPEN_MANUAL_TO_JOG)


def may_move_to(f: Facts) -> Verdict:
    """A typed position means nothing on an axis that does not know where it is."""
    if reason := may_jog(f):
        return reason
    return None if f.all_homed else _no(R.NOT_HOMED)


def may_spindle(f: Facts) -> Verdict:
    if reason := may_jog(f):
        return reason
    return None if f.inputs.guard_closed else _no(R.CLOSE_GUARD_FIRST)


def may_start_spindle(f: Facts) -> Verdict:
    """Spindle on by hand (Spindle off only needs ``may_spindle``): a board on the table must
    be clamped, or the cutter may catch and throw it."""
    if reason := may_spindle(f):
        return reason
    if f.inputs.part_present and not f.inputs.clamps_closed:
        return _no(R.SPINDLE_LOOSE_BOARD)
    return None


SPINDLE_ON = "SpindleOn"
"""The name of Spindle on's own rule in ``allowed_commands`` (a SetSpindle(True) command)."""


def may_select_recipe(f: Facts) -> Verdict:
    if f.cycle_running or f.state in (MachineState.AUTOMATIC, MachineState.STOPPING):
        return _no(R.WAIT_FOR_CYCLE_END)
    return None


def may_simulate(f: Facts) -> Verdict:
    return None if f.simulation else _no(R.SIMULATION_ONLY)


def may_handle_board(f: Facts) -> Verdict:
    """The simulated operator's hands: a clamped board cannot be taken off or replaced."""
    if not f.simulation:
        return _no(R.SIMULATION_ONLY)
    return _no(R.UNCLAMP_BOARD_FIRST) if f.inputs.clamps_closed else None


def always(_f: Facts) -> Verdict:
    return None


Rule = Callable[[Facts], Verdict]

# command type -> rule
RULES: dict[type[cmd.Command], Rule] = {
    cmd.Start: may_start,
    cmd.Resume: may_resume,
    cmd.Abandon: may_abandon,
    cmd.Stop: may_stop,
    cmd.Reset: may_reset,
    cmd.Home: may_home,
    cmd.EnterManual: may_enter_manual,
    cmd.LeaveManual: may_leave_manual,
    cmd.JogContinuous: may_jog,
    cmd.JogStep: may_jog,
    cmd.MoveTo: may_move_to,
    cmd.JogRelease: always,
    cmd.SetClamps: may_jog,
    cmd.SetSpindle: may_spindle,
    cmd.SelectRecipe: may_select_recipe,
    cmd.StartBarrel: may_select_recipe,
    cmd.ChooseBoard: may_select_recipe,
    cmd.SetFeedOverride: always,
    cmd.Acknowledge: always,
    cmd.ReloadParameters: always,
    cmd.ResetShiftCounter: always,
    cmd.InjectFault: may_simulate,
    cmd.ClearFaults: may_simulate,
    cmd.LoadBoard: may_handle_board,
    cmd.RemoveBoard: may_handle_board,
    cmd.SelectHandwheel: may_simulate,
    cmd.TurnHandwheel: may_simulate,
    cmd.HoldJogEnable: may_simulate,
    cmd.PushJoystick: may_simulate,
    cmd.SetUser: always,
    cmd.Shutdown: always,
}


def command_name(command: cmd.Command | type[cmd.Command]) -> str:
    """The name a command is known by in the snapshot's ``allowed`` (its class name)."""
    kind = command if isinstance(command, type) else type(command)
    return kind.__name__


def may(command: cmd.Command, facts: Facts) -> Verdict:
    """Why ``command`` is not accepted now, or None if it is (anything that is not a command,
    e.g. from a newer screen over the link, is refused)."""
    rule = RULES.get(type(command))
    return _no(R.UNKNOWN_COMMAND) if rule is None else rule(facts)


def allowed_commands(facts: Facts) -> dict[str, Verdict]:
    """Command name -> None if allowed now, or why not (what the screens enable buttons by)."""
    allowed = {command_name(kind): rule(facts) for kind, rule in RULES.items()}
    allowed[SPINDLE_ON] = may_start_spindle(facts)
    return allowed
