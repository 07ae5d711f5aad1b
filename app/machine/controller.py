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

Bookkeeping lives beside it: ``production`` (piece records, counters), ``preview`` (the plan
the screens draw), ``snapshot_view`` (what the screens see). The controller never sleeps and
never reads a clock: the runtime hands it ``now_s`` each period, so the same code runs in
real time on the panel and on a simulated clock in tests.
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
from app.machine.cycle_control import CycleControl
from app.machine.executor import PathExecutor
from app.machine.homing import HomingFailed, HomingSequence
from app.machine.homing_clearance import homing_clearance
from app.machine.io_table import io_table
from app.machine.manual_move import ManualMove
from app.machine.pendant.jog_sources import PendantJog
from app.machine.permissions import may, may_start_spindle
from app.machine.planner.keepout import KeepOutRefused, TableKeepOut
from app.machine.planner.limits import MAX_OVERRIDE_PCT
from app.machine.preview import PlanPublisher
from app.machine.process_params import jog_speeds, motion_limits, stave_limits
from app.machine.recipe_on_machine import restore
from app.machine.refusals import Reason, Refusal, refusal
from app.machine.sim_tools import SimulationTools
from app.machine.snapshot import MachineSnapshot, PlanPreview
from app.machine.snapshot_view import build_snapshot, state_text
from app.machine.states import (
    LATCHED_STATES,
    Event,
    MachineState,
    Mode,
    lamps,
)
from app.machine.store import MachineStore, PieceRecord

log = logging.getLogger(__name__)

STOP_LOCKOUT_S = 0.5  # a second Stop within this time is ignored (docs/MACHINE.md section 6)


class MachineController(CycleControl):
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
        super().__init__(config, backend, gauge, store, wall_clock, submit)
        self.plans = PlanPublisher()
        self.sim_tools = SimulationTools(backend)
        self.manual_move = ManualMove(config.axes, config.period_s)
        self.pendant_jog = PendantJog(config, pendant)
        self.io_points = io_table(config)
        self._commands: collections.deque[cmd.Command] = collections.deque()
        self._previous_inputs = InputImage()
        self._last_stop_s = -1e9
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

    def power_up(self) -> None:
        super().power_up()
        self._publish_recipe_preview()

    def shutdown(self) -> None:
        super().shutdown()
        self.pendant_jog.close()

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
            case cmd.SelectRecipe(recipe_id=recipe_id):
                self._select_recipe(recipe_id)
            case cmd.StartBarrel():
                self._start_barrel()
            case cmd.ChooseBoard(choice=choice):
                self.board_choice = choice
            case cmd.EnterManual():
                self.mode = Mode.MANUAL
                self.manual.sync(self.axes)
                self._transition(Event.ENTER_MANUAL)
            case cmd.LeaveManual():
                self.manual.release_all()
                if self.manual_move.running:  # its setpoints end here: stop the drives now
                    self.manual_move.abandon()
                    self.axes.quick_stop_all()
                self.homing = None
                self.mode = Mode.AUTOMATIC
                self.outputs = replace(self.outputs, spindle_on=False)
                self._transition(Event.LEAVE_MANUAL)
            case cmd.JogContinuous(axis=axis, direction=direction, hold=hold):
                if not self._refuse_busy_jog():
                    self._refuse(self.manual.press(axis, direction, self.now_s, self.axes, hold))
            case cmd.JogStep(axis=axis, step=step):
                if not self._refuse_busy_jog():
                    self._refuse(self.manual.step(axis, step, self.axes))
            case cmd.MoveTo(x_mm=x, y_mm=y, z_deg=z):
                self._move_to((x, y, z))
            case cmd.JogRelease(axis=axis):
                self.manual.release(axis)
                self.manual_move.stop()
            case cmd.SetClamps(closed=closed):
                self.outputs = replace(self.outputs, clamps_close=closed)
            case cmd.SetSpindle(on=on):
                if on and (loose := may_start_spindle(self.facts())):
                    self._refuse(loose)
                else:
                    self.outputs = replace(self.outputs, spindle_on=on)
            case cmd.SetFeedOverride(percent=percent):
                self._set_feed_override(percent)
            case cmd.Acknowledge(alarm_id=alarm_id):
                self.alarms.acknowledge(alarm_id, self.user)
            case cmd.ReloadParameters():
                self._reload_parameters()
            case cmd.ResetShiftCounter():
                self.production.reset_shift()
            case cmd.InjectFault(kind=kind, target=target):
                self._refuse(self.sim_tools.inject(kind, target))
            case cmd.ClearFaults():
                self.sim_tools.clear()
            case cmd.LoadBoard(width_mm=width_mm):
                self.sim_tools.replace_board(width_mm)
            case cmd.RemoveBoard():
                self.sim_tools.remove_board()
            case cmd.SelectHandwheel() | cmd.TurnHandwheel() | cmd.HoldJogEnable():
                self._refuse(self.sim_tools.handwheel(command))
            case cmd.PushJoystick(x=x, y=y, z=z):
                self._refuse(self.sim_tools.push_joystick(x, y, z))
            case cmd.SetUser(name=name):
                self.user = name
            case cmd.Shutdown():
                pass  # the runtime ends the loop; nothing to do in the period
            case _:
                assert_never(command)

    def _move_to(self, target: tuple[float, float, float]) -> None:
        if self._refuse_busy_jog():
            return
        if not self.manual.at_rest or self.manual_move.running:
            self._refuse(Refusal(Reason.MOVE_RUNNING))
            return
        where = (self.manual.position("X"), self.manual.position("Y"), self.manual.position("Z"))
        limits = motion_limits(self.config, self.params)
        self._refuse(self.manual_move.start(where, target, self._board_keep_out(), limits))

    def _refuse_busy_jog(self) -> bool:
        """The screen may jog only while no other control owns the jog (nor a move to a
        typed position)."""
        if self.manual_move.running:
            self._refuse(Refusal(Reason.MOVE_RUNNING))
            return True
        busy = self.pendant_jog.touch_screen()
        self._refuse(busy)
        return busy is not None

    def _read_pendant(self) -> None:
        """The handwheel, the joystick and a USB pendant, every period (the wheel's counter
        is followed in every state, so entering manual mode moves nothing); they jog only in
        manual mode, not while homing."""
        jogging = self.state is MachineState.MANUAL and self.homing is None
        outcome = self.pendant_jog.tick(
            self.now_s, self.inputs, self.manual, self.axes, jogging_allowed=jogging
        )
        if outcome.jump_detail:
            if jogging:
                self._fault(AlarmCode.HANDWHEEL_JUMP, "handwheel", outcome.jump_detail)
            else:  # ignored outside manual mode, and nothing moved: only noted
                log.warning("handwheel: %s", outcome.jump_detail)
        for notice in outcome.notices:
            self._refuse(notice)

    def _home(self, axis: str) -> None:
        homing = HomingSequence.for_axes(axis, self.config.axes, self.now_s)
        board = self._board_keep_out()
        if board is not None:
            limits = motion_limits(self.config, self.params)
            try:
                where = self.axes.positions()
                axes = tuple(homing.axes_to_home)
                clearance = homing_clearance(where, board, self.config.axes, limits, axes)
            except KeepOutRefused as exc:
                self._refuse(refusal(Reason.HOMING_REFUSED, exc))
                return
            if clearance is not None:
                homing.clearance = PathExecutor(clearance, self.config.period_s)
                self.message = Refusal(Reason.HOMING_AROUND_BOARD)
        self.homing = homing
        if self.state is not MachineState.MANUAL:
            self._transition(Event.HOME)

    def _board_keep_out(self) -> TableKeepOut | None:
        """The board on the table (part sensor or clamps) as far as it is known: the widest
        the table takes, of the recipe's length; and the clamps and the centering device
        where their sensors say they are. None when nothing is in the way."""
        board = self.inputs.part_present or self.inputs.clamps_closed
        devices = self.config.table_devices.in_the_way(
            board_on_table=board,
            clamps_closed=self.inputs.clamps_closed,
            centering_retracted=self.inputs.centering_retracted,
        )
        limits = stave_limits(self.config)
        if not board:
            return TableKeepOut.devices_only(devices, self.params, limits) if devices else None
        length = self.recipe.length_mm if self.recipe is not None else None
        return TableKeepOut.largest_board(self.params, limits, length, devices)

    def _stop(self) -> None:
        if self.now_s - self._last_stop_s < STOP_LOCKOUT_S:
            log.info("second Stop within %.1f s ignored", STOP_LOCKOUT_S)
            return
        self._last_stop_s = self.now_s
        if self.state is MachineState.MANUAL:
            self.manual.release_all()
            self.manual_move.stop()
            return
        if self.state is MachineState.STOPPING:
            return
        if self.cycle is not None:
            self.cycle.request_stop()
        if self.homing is not None:
            self.homing = None
            self.axes.quick_stop_all()
        self._transition(Event.STOP)

    def _reset_requested(self) -> None:
        """Reconnect a lost link, then (next period, on fresh feedback) fault-reset the
        drives; the state unlatches once every cause is gone (see _check_reset)."""
        if not self.devices.all_up and (failure := self.devices.reconnect()):
            self._refuse(refusal(Reason.RECONNECT_FAILED, failure))
        self.pendant_jog.forget()
        self.reset.request(self.now_s)

    def _select_recipe(self, recipe_id: int) -> None:
        recipe = self.store.recipe(recipe_id)
        if recipe is None:
            self._refuse(refusal(Reason.RECIPE_MISSING, recipe_id))
            return
        if self.recipe is None or recipe.id != self.recipe.id:
            self._drop_barrel()
        self.recipe = recipe
        self.store.save_selected_recipe(recipe)
        self._publish_recipe_preview()

    def _set_feed_override(self, percent: float) -> None:
        if not 0.0 <= percent <= MAX_OVERRIDE_PCT:
            self._refuse(refusal(Reason.FEED_OVERRIDE_RANGE, percent))
            return
        self.feed_override_pct = percent
        if self.cycle is not None:
            self.cycle.set_override(percent)

    def _reload_parameters(self) -> None:
        self.params = self.store.parameters()
        self.manual.set_speeds(jog_speeds(self.config, self.params))
        self.production.follow_shifts(self.params)
        # The recipe stays the version selected: a saved recipe reaches the machine only when
        # someone selects it again (the Recipes screen asks).
        if self.cycle is None:
            self._publish_recipe_preview()

    def _publish_recipe_preview(self) -> None:
        """Show the selected recipe's stave before a board is measured."""
        if self.recipe is not None:
            limits = stave_limits(self.config)
            self.plans.recipe(self.recipe, self.params, limits, self.last_width_mm)

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
            if self.homing is not None:
                self.homing.tick(self.now_s, self.axes)
                if self.homing.done:
                    self.homing = None
                    self.manual.sync(self.axes)
            elif self.manual_move.running:
                if self.manual_move.tick(self.axes):
                    self.manual.sync(self.axes)
            elif warning := self.manual.tick(self.now_s, self.config.period_s, self.axes):
                log.warning("jog %s stopped by its dead-man: no refresh from the screen", warning)
                self.action_log.stopped(warning)
                detail = refusal(Reason.JOG_NOT_REFRESHED_DETAIL, warning)
                self.alarms.raise_alarm(AlarmCode.JOG_NOT_REFRESHED, warning, detail)
                self.alarms.clear(AlarmCode.JOG_NOT_REFRESHED, warning)
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
