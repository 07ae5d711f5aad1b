"""The machine controller: one period of the machine, from inputs to outputs.

What the original PLC's Main, Input, Output, Step and Manual routines did, in one place that
runs every period (4 ms) in the machine process:

1. read every device (``devices``: a device that does not answer is alarm E020, latched);
2. supervise (``supervision``: E-stop chain, guard, drive faults, following error, limit
   switches, lost home); a fault latches the state and stops at once; nothing restarts
   without an operator's Reset (``reset``) and then a Start;
3. carry out the operator's commands that the current state accepts (the rules are in
   :mod:`app.machine.permissions`, the states in :mod:`app.machine.states`), dispatched by
   their type;
4. run the current activity: the automatic cycle, homing, manual jog, or nothing;
5. write the setpoints and the outputs.

The commands are carried out by the layers below, one job each: ``core`` (state, faults,
Reset), ``cycle_control`` (starting, resuming, abandoning and finishing a cycle),
``manual_room`` (the Manual screen: jog, move to, clamps, spindle, homing),
``operator_room`` (Stop, Reset, recipe, parameters, feed override) and ``sim_tools`` (the
simulation page). Bookkeeping lives beside it: ``production`` (piece records, counters),
``preview`` (the plan the screens draw), ``snapshot_view`` (what the screens see). The
controller never sleeps and never reads a clock: the runtime hands it ``now_s`` each period,
so the same code runs in real time on the panel and on a simulated clock in tests.
"""

from __future__ import annotations

import collections
import logging
import time
from collections.abc import Callable
from dataclasses import replace
from typing import assert_never

from app.config import MachineConfig
from app.drivers.contracts import (
    DriverError,
    InputImage,
    MachineBackend,
    PendantDevice,
    WidthGauge,
)
from app.machine import commands as cmd
from app.machine.alarms import AlarmCode
from app.machine.cycle import AutomaticCycle, CycleFault, PlanSubmitter, run_now
from app.machine.homing import HomingFailed
from app.machine.io_table import io_table
from app.machine.operator_room import OperatorRoom
from app.machine.permissions import may
from app.machine.process_params import jog_speeds
from app.machine.recipe_on_machine import restore
from app.machine.refusals import Reason, refusal
from app.machine.sim_tools import SimulationTools
from app.machine.snapshot import MachineSnapshot, PlanPreview
from app.machine.snapshot_view import build_snapshot, state_text
from app.machine.states import (
    LATCHED_STATES,
    Event,
    MachineState,
    lamps,
)
from app.machine.store import MachineStore, PieceRecord

log = logging.getLogger(__name__)


class MachineController(OperatorRoom):
    def __init__(
        self,
        config: MachineConfig,
        backend: MachineBackend,
        gauge: WidthGauge,
        store: MachineStore,
        *,
        submit: PlanSubmitter = run_now,
        wall_clock: Callable[[], float] = time.time,
        pendant: PendantDevice | None = None,
    ) -> None:
        super().__init__(config, backend, gauge, store, wall_clock, submit, pendant)
        self.sim_tools = SimulationTools(backend)
        self.io_points = io_table(config)
        self._commands: collections.deque[cmd.Command] = collections.deque()
        self._previous_inputs = InputImage()
        self._seq = 0
        self.manual.set_speeds(jog_speeds(config, self.params))
        self.production.follow_shifts(self.params)
        restored = restore(store)
        self.recipe, self.message = restored.recipe, restored.message
        self._restore_barrel()  # an open barrel brings its own recipe
        if self.recipe is not None and (restored.message is None or self.recipe != restored.recipe):
            store.save_selected_recipe(self.recipe)
        if self.partly_cut.board is not None:
            # Keep the partly cut board clamped: unclamped, it may move and cannot be resumed.
            self.outputs = replace(self.outputs, clamps_close=True)
            self.message = refusal(Reason.INTERRUPTED_BOARD, self.partly_cut.board.describe())

    # ---------------------------------------------------------------- commands
    def post(self, command: cmd.Command) -> None:
        self._commands.append(command)

    def _handle(self, command: cmd.Command) -> None:
        refused = may(command, self.facts())
        if refused is not None:
            if refused.reason is not Reason.NOTHING_MOVING:  # a spare Stop is no news
                self._refuse(refused)
            return
        if (line := self.action_log.accepted(command, self.user)) is not None:
            log.info("action: %s", line)
        match command:
            case cmd.Start():
                self._start()
            case cmd.Resume():
                self._continue_board(resume=True)
            case cmd.Abandon():
                self._abandon()
            case cmd.Stop():
                self._stop()
            case cmd.Reset():
                self._reset_requested()
            case cmd.Home(axis=axis):
                self._home(axis)
            case (
                cmd.EnterManual()
                | cmd.LeaveManual()
                | cmd.JogContinuous()
                | cmd.JogStep()
                | cmd.MoveTo()
                | cmd.JogRelease()
                | cmd.SetClamps()
                | cmd.SetSpindle()
            ):
                self._handle_manual(command)
            case cmd.SelectRecipe(recipe_id=recipe_id):
                self._select_recipe(recipe_id)
            case cmd.StartBarrel():
                self._start_barrel()
            case cmd.ChooseBoard(choice=choice):
                self.board_choice = choice
            case cmd.SetFeedOverride(percent=percent):
                self._set_feed_override(percent)
            case cmd.Acknowledge(alarm_id=alarm_id):
                self.alarms.acknowledge(alarm_id, self.user)
            case cmd.ReloadParameters():
                self._reload_parameters()
            case cmd.ResetShiftCounter():
                self.production.reset_shift()
            case (
                cmd.InjectFault()
                | cmd.ClearFaults()
                | cmd.LoadBoard()
                | cmd.RemoveBoard()
                | cmd.SelectHandwheel()
                | cmd.TurnHandwheel()
                | cmd.HoldJogEnable()
                | cmd.PushJoystick()
            ):
                self._refuse(self.sim_tools.handle(command))
            case cmd.SetUser(name=name, operator=operator):
                self.user = name
                self.production.operator_name = operator or name
            case cmd.Shutdown():
                pass  # the runtime ends the loop; nothing to do in the period
            case _:
                assert_never(command)

    # ---------------------------------------------------------------- the period
    def tick(self, now_s: float) -> None:
        self.now_s = now_s
        self.production.tick(now_s)
        try:
            feedback, self.inputs, findings = self.devices.read()
        except DriverError as exc:
            self._apply(self.devices.lost(exc))
            self.pendant_jog.forget()  # after the link is back the counter may be anywhere
            self._process_commands()
            return
        self.axes.update(feedback)
        for finding in findings:
            self._apply(finding)
        if not self.inputs.part_present:
            self._finished_board_on_table = False
        self.partly_cut.watch_clamps(self.inputs, self.cycle)
        self.sim_tools.tick(self.inputs.part_present)
        self._process_buttons()
        self._supervise()
        if self.state is MachineState.MANUAL:
            self.manual.keep_out = self._board_keep_out()  # jogs stay out of it
        self._process_commands()
        self._check_reset()
        self._read_pendant()
        try:
            self._run_activity()
        except CycleFault as exc:
            self._fault(exc.code, exc.source, exc.detail)
        except HomingFailed as exc:
            self._fault(AlarmCode.HOMING_INCOMPLETE, exc.axis, exc.detail)
        if self.state in LATCHED_STATES and self.axes.standing_still(tolerance=0.5):
            self.devices.call(self.axes.disable_all)  # stop category 1: still, then no power
        self.outputs = replace(self.outputs, **lamps(self.state))
        try:
            self.axes.write()
            self.backend.io.write_outputs(self.outputs)
        except DriverError as exc:
            self._apply(self.devices.lost(exc))

    def _process_buttons(self) -> None:
        before, now = self._previous_inputs, self.inputs
        self._previous_inputs = now
        if now.stop_button and not before.stop_button:
            self._commands.appendleft(cmd.Stop())
        if now.start_button and not before.start_button:
            self._commands.append(cmd.Start())
        if now.reset_button and not before.reset_button:
            self._commands.append(cmd.Reset())

    def _process_commands(self) -> None:
        while self._commands:
            self._handle(self._commands.popleft())

    def _run_activity(self) -> None:
        if self.state is MachineState.HOMING and self.homing is not None:
            self.homing.tick(self.now_s, self.axes)
            if self.homing.done:
                self.homing = None
                self._transition(Event.HOMING_DONE)
        elif self.state is MachineState.MANUAL:
            self._run_manual()
        elif self.state is MachineState.AUTOMATIC and self.cycle is not None:
            self.outputs = self.cycle.tick(self.now_s, self.inputs, self.outputs, self.axes)
            self.partly_cut.remember(self.cycle, self.axes.positions())
            if self.cycle.planned is not None:
                self.plans.board(self.cycle.planned)
            if self.cycle.finished:
                self._finish_cycle(self.cycle)
        elif self.state is MachineState.STOPPING:
            self._run_stopping()

    def _run_stopping(self) -> None:
        cycle = self.cycle
        if cycle is not None:
            if cycle.moving and not cycle.stopped:
                self.outputs = cycle.tick(self.now_s, self.inputs, self.outputs, self.axes)
                return
            self._abort_cycle(None)
            self.cycle = None
        if self.axes.standing_still(tolerance=0.5):
            self.outputs = replace(self.outputs, spindle_on=False, centering_extend=False)
            self.axes.hold_where_they_are()
            self._transition(Event.STOPPED)

    # ---------------------------------------------------------------- the picture
    @property
    def last_width_mm(self) -> float | None:
        return self.production.last_width_mm

    @property
    def last_cycle_time_s(self) -> float | None:
        return self.production.last_cycle_time_s

    @property
    def last_wait_s(self) -> float | None:
        return self.production.last_wait_s

    @property
    def last_step_times_s(self) -> dict[str, float]:
        return self.production.last_step_times_s

    @property
    def pieces_shift(self) -> int:
        return self.production.pieces_shift

    @property
    def plan_shifts_begun(self) -> int:
        return self.production.plan_shifts_begun

    @property
    def pieces_total(self) -> int:
        return self.production.pieces_total

    @property
    def finished_cycles(self) -> list[tuple[PieceRecord, AutomaticCycle]]:
        return self.production.finished_cycles

    def state_text(self) -> str:
        return state_text(self)

    def snapshot(self) -> MachineSnapshot:
        self._seq += 1
        return build_snapshot(self, self._seq)

    @property
    def plan_id(self) -> int:
        return self.plans.plan_id

    def plan_preview(self, plan_id: int) -> PlanPreview | None:
        return self.plans.get(plan_id)
