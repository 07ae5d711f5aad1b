"""The Manual screen's room of the controller: entering and leaving manual mode, jogging from
the screen and from the pendant, a move to typed coordinates, the clamps and the spindle by
hand, and homing (with its way around a board on the table).

Why a layer of its own (between ``cycle_control`` and ``controller``): who may move an axis
by hand, and what keeps a hand-driven axis out of the board and the table's devices, is one
job a reviewer reads in one place; the period's sequencing and the other rooms' commands stay
in the controller.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import replace
from typing import assert_never

from app.config import MachineConfig
from app.drivers.contracts import MachineBackend, PendantDevice, WidthGauge
from app.machine import commands as cmd
from app.machine.alarms import AlarmCode
from app.machine.cycle import PlanSubmitter
from app.machine.cycle_control import CycleControl
from app.machine.executor import PathExecutor
from app.machine.homing import HomingSequence
from app.machine.homing_clearance import homing_clearance
from app.machine.manual_move import ManualMove
from app.machine.pendant.jog_sources import PendantJog
from app.machine.permissions import may_start_spindle
from app.machine.planner.keepout import KeepOutRefused, TableKeepOut
from app.machine.process_params import motion_limits, stave_limits
from app.machine.refusals import Reason, Refusal, refusal
from app.machine.states import Event, MachineState, Mode
from app.machine.store import MachineStore

log = logging.getLogger(__name__)


class ManualRoom(CycleControl):
    def __init__(
        self,
        config: MachineConfig,
        backend: MachineBackend,
        gauge: WidthGauge,
        store: MachineStore,
        wall_clock: Callable[[], float],
        submit: PlanSubmitter,
        pendant: PendantDevice | None,
    ) -> None:
        super().__init__(config, backend, gauge, store, wall_clock, submit)
        self.manual_move = ManualMove(config.axes, config.period_s)
        self.pendant_jog = PendantJog(config, pendant)

    def shutdown(self) -> None:
        super().shutdown()
        self.pendant_jog.close()

    def _handle_manual(self, command: cmd.ManualCommand) -> None:
        """One accepted command of the Manual screen (the permission rules passed)."""
        match command:
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

    def _run_manual(self) -> None:
        """One period of manual mode: homing an axis, a move to a typed position, or the
        jog (stopped by its dead-man when the screen stops refreshing it)."""
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
