"""The controller's core: its state, and how it reacts to what supervision finds.

Why apart from the period's sequencing (``app.machine.controller``): this is the part a
safety reviewer reads with ``app.machine.supervision``: every transition goes through the
state table (power-up faults included), a fault raises its alarm, stops at once (IEC 60204-1
stop category 1: quick stop, then no power once still) and latches ERROR, the E-stop chain
latches EMERGENCY_STOP, and only the operator's Reset unlatches, once every cause is gone.
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import replace

from app.config import MachineConfig
from app.data.recipe import Recipe
from app.drivers.contracts import DriverError, InputImage, MachineBackend, OutputImage, WidthGauge
from app.machine.action_log import ActionLog
from app.machine.alarms import AlarmCode, AlarmDetail, AlarmManager
from app.machine.axes import AxisGroup
from app.machine.cycle import AutomaticCycle
from app.machine.devices import DeviceLink
from app.machine.homing import HomingSequence
from app.machine.manual import ManualControl
from app.machine.partly_cut import PartlyCut
from app.machine.permissions import Facts
from app.machine.production import Production
from app.machine.refusals import Reason, Refusal, refusal
from app.machine.reset import ResetSequence, ResetStep
from app.machine.snapshot import AlarmArgument
from app.machine.states import (
    LATCHED_STATES,
    Event,
    MachineState,
    Mode,
    TransitionRefused,
    next_state,
)
from app.machine.store import RECORD_DELAY_ALARM_S, MachineStore
from app.machine.supervision import Finding, Motion, supervise

log = logging.getLogger(__name__)


class ControllerCore:
    def __init__(
        self,
        config: MachineConfig,
        backend: MachineBackend,
        gauge: WidthGauge,
        store: MachineStore,
        wall_clock: Callable[[], float],
    ) -> None:
        self.config = config
        self.backend = backend
        self.gauge = gauge
        self.store = store
        self.wall_clock = wall_clock
        self.devices = DeviceLink(backend, gauge)
        self.alarms = AlarmManager(on_transition=store.record_alarm, wall_clock=wall_clock)
        self.axes = AxisGroup(config.axes, backend.motion)
        self.manual = ManualControl(config.axes)
        self.production = Production(store, wall_clock)
        self.partly_cut = PartlyCut(store, wall_clock)
        self.reset = ResetSequence()
        self.state = MachineState.POWER_UP
        self.mode = Mode.AUTOMATIC
        self.now_s = 0.0
        self.inputs = InputImage()
        self.outputs = OutputImage()
        self.recipe: Recipe | None = None
        self.cycle: AutomaticCycle | None = None
        self.homing: HomingSequence | None = None
        self._message: Refusal | None = None
        self.message_serial = 0
        self.user = ""  # who is at the panel (SetUser), for the records and the log
        self.action_log = ActionLog()

    @property
    def message(self) -> Refusal | None:
        """The last refusal or notice for the operator."""
        return self._message

    @message.setter
    def message(self, value: Refusal | None) -> None:
        """Every message counts, the same one again too: the screens show a message for a
        while from the moment it is given, and a second refusal of the same kind is news."""
        self._message = value
        self.message_serial += 1

    def power_up(self) -> None:
        """Configure and activate every device; the state follows from the encoders, or is
        ERROR (through the state table, like every fault) when a device does not come up."""
        try:
            feedback, self.inputs = self.devices.power_up()
        except DriverError as exc:
            log.error("power-up failed: %s", exc)
            self._fault(AlarmCode.COMMUNICATION_LOST, exc.device, str(exc))
            return
        self.axes.update(feedback)
        self._transition(Event.STARTED_HOMED if self.axes.all_homed() else Event.STARTED_UNHOMED)

    def shutdown(self) -> None:
        """Stop everything and release the devices (spindle off, drives disabled)."""
        self._abort_cycle("shutdown")
        try:
            if self.devices.comms_ok:
                self._stop_now()
                self.outputs = OutputImage(clamps_close=self.outputs.clamps_close)
                self.backend.io.write_outputs(self.outputs)
                self.axes.disable_all()
        except DriverError as exc:
            log.warning("shutdown: %s", exc)
        self.devices.release()
        self.store.close()

    def facts(self) -> Facts:
        return Facts(
            self.state,
            self.axes.all_homed(),
            self.recipe is not None,
            self.inputs,
            self.cycle is not None,
            "faults" in self.backend.extras,
            interrupted=self.partly_cut.board is not None and self.cycle is None,
            interrupted_unclamped=self.partly_cut.board is not None
            and self.partly_cut.board.unclamped,
        )

    def _refuse(self, refusal: Refusal | None) -> None:
        if refusal is not None:
            self.message = refusal
            line = self.action_log.refused(refusal, self.now_s, self.user)
            if line is not None:
                log.info("%s", line)

    # ---------------------------------------------------------------- transitions
    def _transition(self, event: Event) -> None:
        try:
            new = next_state(self.state, event, self.axes.all_homed())
        except TransitionRefused as exc:
            self._refuse(refusal(Reason.NOT_POSSIBLE_NOW, exc.event.value, exc.state.value))
            return
        if new is not self.state:
            log.info("state %s -> %s (%s)", self.state.value, new.value, event.value)
        self.state = new
        if new is not MachineState.MANUAL:
            self.mode = Mode.AUTOMATIC

    def _fault(
        self,
        code: AlarmCode,
        source: str,
        detail: AlarmDetail,
        arguments: tuple[AlarmArgument, ...] = (),
    ) -> None:
        """Raise a fault alarm, stop at once and latch ERROR (IEC 60204-1 stop category 1:
        the drives quick-stop, then lose power)."""
        self.alarms.raise_alarm(code, source, detail, arguments)
        if code is AlarmCode.GAUGE_DISCONNECTED:
            self.devices.gauge_lost()  # Reset brings the gauge up again
        if self.state in LATCHED_STATES:
            return
        log.warning("fault %s %s: %s", code, source, detail)
        self._abort_cycle(code)
        self._stop_now()
        self._transition(Event.FAULT)

    def _abort_cycle(self, reason: str | None) -> None:
        """The cycle ends before its board is cut (``reason``: the alarm code, "shutdown", or
        None for an operator's Stop): a board whose cut had begun is kept as partly cut, to
        resume or abandon; otherwise the attempt is recorded."""
        cycle = self.cycle
        if cycle is None:
            return
        if not self.partly_cut.interrupted(cycle, self.axes.positions(), reason or "stop"):
            self.production.aborted(cycle, self.now_s, reason)

    def _stop_now(self) -> None:
        if self.cycle is not None:
            self.cycle.abort()
            self.cycle = None
        self.homing = None
        self.manual.release_all(immediate=True)
        self.action_log.stopped_all()
        self.outputs = replace(self.outputs, spindle_on=False, centering_extend=False)
        if self.axes.feedback:
            self.axes.hold_where_they_are()
            self.devices.call(self.axes.quick_stop_all)

    def _apply(self, finding: Finding) -> None:
        self._fault(finding.code, finding.source, finding.detail, finding.arguments)

    def _supervise(self) -> None:
        cycle = self.cycle
        motion = Motion(
            self.state,
            cycle_moving=cycle is not None and cycle.moving,
            cycle_active=cycle is not None,
            homing=self.homing is not None,
        )
        setpoint = {n: self.axes.command[n] for n in self.axes.names}
        verdict = supervise(self.inputs, self.axes.feedback, setpoint, self.config.axes, motion)
        if verdict.estop:
            self.alarms.raise_alarm(AlarmCode.ESTOP, "E-stop chain")
            if self.state is not MachineState.EMERGENCY_STOP:
                self._abort_cycle(AlarmCode.ESTOP)
                self._stop_now()  # quick stop on the drives' ramps; power off once still
                self._transition(Event.ESTOP)
        for code, source in verdict.normal:
            self.alarms.clear(code, source)
        for finding in verdict.faults:
            self._apply(finding)
        self._watch_records()

    def _watch_records(self) -> None:
        """W103 while a record has waited too long for a busy or missing database (it is kept
        in the journal meanwhile; the machine goes on)."""
        waited_s = self.store.unstored_age_s()
        if waited_s > RECORD_DELAY_ALARM_S:
            detail = refusal(Reason.RECORDS_WAITING_DETAIL, f"{waited_s:.0f}")
            self.alarms.raise_alarm(AlarmCode.RECORDS_WAITING, "database", detail)
        elif waited_s == 0.0:
            self.alarms.clear(AlarmCode.RECORDS_WAITING, "database")

    def _check_reset(self) -> None:
        if self.state not in LATCHED_STATES:
            self.reset.cancel()
            return
        step = self.reset.step(self.now_s, self.axes.feedback, self.inputs, self.devices.comms_ok)
        if step is ResetStep.SEND_FAULT_RESET:
            self.devices.call(self.axes.fault_reset_all)
        elif step is ResetStep.DONE:
            self.alarms.clear_all_conditions(user=self.user)
            self.axes.hold_where_they_are()
            self.manual.sync(self.axes)
            self.message = Refusal(Reason.RESET_DONE)
            self._transition(Event.RESET)
        elif step is ResetStep.FAILED:
            self._refuse(Refusal(Reason.RESET_FAILED, causes=self.reset.causes))
