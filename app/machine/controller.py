"""The machine controller: one period of the machine, from inputs to outputs.

What the original PLC's Main, Input, Output, Step and Manual routines did, in one place that
runs every period (4 ms) in the machine process:

1. read every device (a device that does not answer is alarm E020, latched);
2. supervise: E-stop chain, guard, drive faults, following error, homing (faults latch the
   state and stop at once; nothing restarts without an operator's Reset and then a Start);
3. carry out the operator's commands that the current state accepts (the rules are in
   :mod:`app.machine.permissions`, the states in :mod:`app.machine.states`);
4. run the current activity: the automatic cycle, homing, manual jog, or nothing;
5. write the setpoints and the outputs.

The controller never sleeps and never reads a clock: the runtime hands it ``now_s`` each
period, so the same code runs in real time on the panel and on a simulated clock in tests.
"""

from __future__ import annotations

import collections
import logging
import time
from collections.abc import Callable
from dataclasses import replace

from app.config import MachineConfig
from app.data.recipe import Recipe
from app.drivers.contracts import (
    CommunicationError,
    DeviceEvent,
    DeviceEventKind,
    DriverError,
    InputImage,
    MachineBackend,
    OutputImage,
    WidthGauge,
)
from app.machine import commands as cmd
from app.machine.alarms import AlarmManager
from app.machine.axes import AxisGroup
from app.machine.barrel_job import new_barrel, plan_barrel_board
from app.machine.barrel_set import BarrelSet, BoardChoice
from app.machine.board_resume import continue_job, interruption
from app.machine.cycle import AutomaticCycle, CycleFault, PlanSubmitter, run_now
from app.machine.cycle_plan import PlannedStave, plan_board
from app.machine.executor import PathExecutor, ViolationKind, check_feedback
from app.machine.homing import HomingFailed, HomingSequence
from app.machine.homing_clearance import homing_clearance
from app.machine.interrupted import InterruptedBoard, InterruptedRecordError
from app.machine.manual import ManualControl
from app.machine.permissions import Facts, allowed_commands
from app.machine.planner.keepout import KeepOutRefused, TableKeepOut
from app.machine.planner.trajectory import Phase
from app.machine.preview import build_preview, recipe_preview
from app.machine.process_params import motion_limits, stave_limits
from app.machine.sim_tools import SimulationTools
from app.machine.snapshot import MachineSnapshot, PlanPreview
from app.machine.snapshot_view import build_snapshot, state_text
from app.machine.states import (
    LATCHED_STATES,
    CycleStep,
    Event,
    MachineState,
    Mode,
    TransitionRefused,
    next_state,
)
from app.machine.store import RECORD_DELAY_ALARM_S, MachineStore, PieceRecord

log = logging.getLogger(__name__)

STOP_LOCKOUT_S = 0.5  # a second Stop within this time is ignored (docs/MACHINE.md section 6)
RESET_TIMEOUT_S = 1.0  # how long a Reset waits for the drives to leave FAULT
FOLLOWING_ERROR_FAULT = 0x8611  # CiA 402 "following error" emergency code
VIOLATION_ALARMS = {
    ViolationKind.NO_FEEDBACK: "E020",
    ViolationKind.DRIVE_FAULT: "E010",
    ViolationKind.NOT_ENABLED: "E013",
    ViolationKind.FOLLOWING_ERROR: "E011",
    ViolationKind.LIMIT_POSITIVE: "E012",
    ViolationKind.LIMIT_NEGATIVE: "E012",
    ViolationKind.SOFT_LIMIT: "E050",
}
EMERGENCY_TEXTS = {
    0x8611: "following error",
    0x7300: "sensor",
    0x8130: "heartbeat / life guard",
    0x2310: "over-current",
    0x3210: "DC link over-voltage",
    0x4310: "drive over-temperature",
    0xFF01: "limit switch",
}


class MachineController:
    def __init__(
        self,
        config: MachineConfig,
        backend: MachineBackend,
        gauge: WidthGauge,
        store: MachineStore,
        *,
        submit: PlanSubmitter = run_now,
        wall_clock: Callable[[], float] = time.time,
    ) -> None:
        self.config = config
        self.backend = backend
        self.gauge = gauge
        self.store = store
        self._submit = submit
        self.wall_clock = wall_clock
        self.alarms = AlarmManager(on_transition=store.record_alarm, wall_clock=wall_clock)
        self.axes = AxisGroup(config.axes, backend.motion)
        self.manual = ManualControl(config.axes)
        self.state = MachineState.POWER_UP
        self.mode = Mode.AUTOMATIC
        self.now_s = 0.0
        self.inputs = InputImage()
        self.outputs = OutputImage()
        self.params: dict[str, float] = store.parameters()
        self.recipe: Recipe | None = None
        self.cycle: AutomaticCycle | None = None
        self.homing: HomingSequence | None = None
        self.feed_override_pct = 100.0
        self.message = ""
        self.user = ""
        self.last_width_mm: float | None = None
        self.last_cycle_time_s: float | None = None
        self.shift_start = wall_clock()
        self.pieces_shift, self.pieces_total = store.piece_counts(self.shift_start)
        self._commands: collections.deque[cmd.Command] = collections.deque()
        self._previous_inputs = InputImage()
        self._last_stop_s = -1e9
        self._reset_pending_since: float | None = None
        self._reset_faults_sent = False
        self._comms_ok = True
        self._gauge_lost = False
        self._plans: dict[int, PlanPreview] = {}
        self._plan_id = 0
        self._seq = 0
        self._moved_since_latch = False
        self._finished_board_on_table = False
        self.barrel: BarrelSet | None = None  # the barrel being raised (None: single staves)
        self.board_choice: BoardChoice | None = None  # the answer to E034, for the next board
        self.sim_tools = SimulationTools(backend)
        self.finished_cycles: list[tuple[PieceRecord, AutomaticCycle]] = []
        recipe_id = store.first_recipe_id()
        if recipe_id is not None:
            self.recipe = store.recipe(recipe_id)
        self.interrupted = self._load_interrupted()
        if self.interrupted is not None:
            # Keep the partly cut board clamped: unclamped, it may move and cannot be resumed.
            self.outputs = replace(self.outputs, clamps_close=True)
            self.message = f"{self.interrupted.describe()}: Resume or Abandon"

    def _load_interrupted(self) -> InterruptedBoard | None:
        try:
            board = self.store.interrupted_board()
        except InterruptedRecordError:
            # Unreadable: assume the worst (a partly cut board of unknown shape); it can only
            # be abandoned, and nothing moves for it.
            return InterruptedBoard(None, "unknown", 0.0, Phase.CUT_A, 0.0, 0.0, 0.0, "unreadable")
        if board is not None and not board.reason:
            # Recorded during the cut and never ended: the machine stopped without knowing why.
            board = replace(board, reason="restart")
        return board

    # ---------------------------------------------------------------- lifecycle
    def power_up(self) -> None:
        """Configure and activate every device; the state follows from the encoders."""
        try:
            for device in (*self.backend.devices(), self.gauge):
                device.configure()
            for device in (*self.backend.devices(), self.gauge):
                device.activate()
            self.axes.update(self.backend.motion.read_axes())
            self.inputs = self.backend.io.read_inputs()
        except DriverError as exc:
            log.error("power-up failed: %s", exc)
            self._comms_ok = False
            self.alarms.raise_alarm("E020", exc.device, str(exc))
            self.state = MachineState.ERROR
            return
        event = Event.STARTED_HOMED if self.axes.all_homed() else Event.STARTED_UNHOMED
        self._transition(event)
        self._publish_recipe_preview()

    def shutdown(self) -> None:
        """Stop everything and release the devices (spindle off, drives disabled)."""
        if self.cycle is not None:
            self._record_abort("shutdown")
        try:
            if self._comms_ok:
                self._stop_now()
                self.outputs = OutputImage(clamps_close=self.outputs.clamps_close)
                self.backend.io.write_outputs(self.outputs)
                self.axes.disable_all()
        except DriverError as exc:
            log.warning("shutdown: %s", exc)
        for device in (self.gauge, *self.backend.devices()):
            device.shutdown()  # deactivates an active device first; never raises
        self.store.close()

    # ---------------------------------------------------------------- commands
    def post(self, command: cmd.Command) -> None:
        self._commands.append(command)

    def facts(self) -> Facts:
        return Facts(
            self.state,
            self.axes.all_homed(),
            self.recipe is not None,
            self.inputs,
            self.cycle is not None,
            "faults" in self.backend.extras,
            interrupted=self.interrupted is not None and self.cycle is None,
            interrupted_unclamped=self.interrupted is not None and self.interrupted.unclamped,
        )

    def _refuse(self, reason: str) -> None:
        self.message = reason
        log.info("refused: %s", reason)

    def _handle(self, command: cmd.Command) -> None:
        name = type(command).__name__
        reason = allowed_commands(self.facts()).get(name, "unknown command")
        if reason:
            if not (isinstance(command, cmd.Stop) and reason == "nothing is moving"):
                self._refuse(reason)
            return
        handler = getattr(self, f"_on_{name}", None)
        if handler is not None:
            handler(command)

    def _on_Start(self, _c: cmd.Start) -> None:
        assert self.recipe is not None
        self.params = self.store.parameters()
        recipe = self.recipe
        limits_stave = stave_limits(self.config)
        limits_motion = motion_limits(self.config, self.params)
        params = dict(self.params)

        if self.barrel is not None and self.barrel.closed:
            self.barrel = self.barrel.next_barrel()  # the board after a closed barrel starts one
        barrel, choice = self.barrel, self.board_choice

        def plan_job(width_mm: float, start: tuple[float, float, float]) -> PlannedStave:
            if barrel is None:
                return plan_board(recipe, width_mm, params, limits_stave, limits_motion, start)
            return plan_barrel_board(
                barrel, choice, recipe, width_mm, params, limits_stave, limits_motion, start
            )

        self.cycle = AutomaticCycle(
            recipe=recipe,
            config=self.config,
            gauge=self.gauge,
            plan_job=plan_job,
            submit=self._submit,
            started_s=self.now_s,
            feed_override_pct=self.feed_override_pct,
            board_already_cut=self._finished_board_on_table,
        )
        self.message = ""
        self._transition(Event.START)

    def _on_Resume(self, _c: cmd.Resume) -> None:
        self._continue_board(resume=True)

    def _on_Abandon(self, _c: cmd.Abandon) -> None:
        board = self.interrupted
        assert board is not None
        recipe = self.store.recipe(board.recipe_id) if board.recipe_id is not None else None
        if not self.axes.all_homed() or recipe is None or board.width_mm <= 0.0:
            # Where the cutter is, or what the board looks like, is unknown: nothing moves.
            self.outputs = replace(self.outputs, clamps_close=False, spindle_on=False)
            self._end_interrupted("aborted", None)
            self.message = (
                "board abandoned and unclamped: take it off (nothing moved: check that the "
                "cutter is clear of it)"
            )
            return
        self._continue_board(resume=False)

    def _continue_board(self, *, resume: bool) -> None:
        board = self.interrupted
        assert board is not None
        recipe = self.store.recipe(board.recipe_id) if board.recipe_id is not None else None
        if recipe is None:
            self._refuse(f"recipe {board.recipe_name!r} no longer exists: abandon the board")
            return
        self.params = self.store.parameters()
        job = continue_job(
            recipe,
            board,
            self.params,
            stave_limits(self.config),
            motion_limits(self.config, self.params),
            resume=resume,
        )
        self.cycle = AutomaticCycle(
            recipe=recipe,
            config=self.config,
            gauge=self.gauge,
            plan_job=None,
            submit=self._submit,
            started_s=self.now_s,
            feed_override_pct=self.feed_override_pct,
            continue_job=job,
            resume=resume,
            interrupted_phase=board.phase,
        )
        self.message = "resuming the board" if resume else "abandoning the board"
        self._transition(Event.START)

    def _interrupt_alarm(self) -> str | None:
        """The alarm code that interrupted the board, for its production record."""
        reason = self.interrupted.reason if self.interrupted is not None else ""
        return reason if reason.startswith(("E", "W")) else None

    def _end_interrupted(self, result: str, cycle: AutomaticCycle | None) -> None:
        """The interrupted board is finished (resumed) or abandoned: record it, forget it."""
        board = self.interrupted
        assert board is not None
        if cycle is None:
            piece = PieceRecord(
                self.wall_clock(),
                board.recipe_id,
                board.recipe_name,
                board.width_mm or None,
                None,
                None,
                None,
                0.0,
                result,
                self._interrupt_alarm(),
            )
            self.store.record_piece(piece)
        self.interrupted = None
        self.store.save_interrupted_board(None)
        self._finished_board_on_table = True

    def _on_Stop(self, _c: cmd.Stop) -> None:
        if self.now_s - self._last_stop_s < STOP_LOCKOUT_S:
            log.info("second Stop within %.1f s ignored", STOP_LOCKOUT_S)
            return
        self._last_stop_s = self.now_s
        if self.state is MachineState.MANUAL:
            self.manual.release_all()
            return
        if self.state is MachineState.STOPPING:
            return
        if self.cycle is not None:
            self.cycle.request_stop()
        if self.homing is not None:
            self.homing = None
            self.axes.quick_stop_all()
        self._transition(Event.STOP)

    def _on_Reset(self, _c: cmd.Reset) -> None:
        """Reconnect a lost link, then (next period, on fresh feedback) fault-reset the
        drives; the state unlatches once every cause is gone (see _check_reset)."""
        if not self._comms_ok or self._gauge_lost:
            self._reconnect()
        self._reset_pending_since = self.now_s
        self._reset_faults_sent = False

    def _on_Home(self, c: cmd.Home) -> None:
        homing = HomingSequence.for_axes(c.axis, self.config.axes, self.now_s)
        if self.inputs.part_present or self.inputs.clamps_closed:
            try:
                clearance = homing_clearance(
                    self.axes.positions(),
                    self._table_keep_out(),
                    self.config.axes,
                    motion_limits(self.config, self.params),
                    tuple(homing.axes_to_home),
                )
            except KeepOutRefused as exc:
                self._refuse(str(exc))
                return
            if clearance is not None:
                homing.clearance = PathExecutor(clearance, self.config.period_s)
                self.message = "a board is on the table: moving clear of it before homing"
        self.homing = homing
        if self.state is not MachineState.MANUAL:
            self._transition(Event.HOME)

    def _table_keep_out(self) -> TableKeepOut:
        """The board on the table as far as it is known: the widest the table takes, of the
        selected recipe's length."""
        length = self.recipe.length_mm if self.recipe is not None else None
        return TableKeepOut.largest_board(self.params, stave_limits(self.config), length)

    def _on_SelectRecipe(self, c: cmd.SelectRecipe) -> None:
        recipe = self.store.recipe(c.recipe_id)
        if recipe is None:
            self._refuse(f"recipe {c.recipe_id} does not exist")
            return
        if self.recipe is None or recipe.id != self.recipe.id:
            self.barrel = None  # a barrel is raised from one recipe's staves
        self.recipe = recipe
        self._publish_recipe_preview()

    def _on_StartBarrel(self, _c: cmd.StartBarrel) -> None:
        if self.recipe is None:
            self._refuse("select a recipe first")
            return
        number = 1 if self.barrel is None else self.barrel.number + 1
        barrel = new_barrel(self.recipe, stave_limits(self.config), number)
        if barrel is None:
            self._refuse(f"recipe {self.recipe.name!r} has a fixed tilt: it makes no barrel")
            return
        self.barrel, self.board_choice = barrel, None

    def _on_ChooseBoard(self, c: cmd.ChooseBoard) -> None:
        self.board_choice = c.choice

    def _publish_recipe_preview(self) -> None:
        """Show the selected recipe's stave before a board is measured."""
        if self.recipe is None:
            return
        preview = recipe_preview(
            self._plan_id + 1,
            self.recipe,
            self.params,
            stave_limits(self.config),
            self.last_width_mm,
        )
        if preview is not None:
            self._plan_id += 1
            self._plans = {self._plan_id: preview}

    def _on_EnterManual(self, _c: cmd.EnterManual) -> None:
        self.mode = Mode.MANUAL
        self.manual.sync(self.axes)
        self._transition(Event.ENTER_MANUAL)

    def _on_LeaveManual(self, _c: cmd.LeaveManual) -> None:
        self.manual.release_all()
        self.homing = None
        self.mode = Mode.AUTOMATIC
        self.outputs = replace(self.outputs, spindle_on=False)
        self._transition(Event.LEAVE_MANUAL)

    def _on_JogContinuous(self, c: cmd.JogContinuous) -> None:
        if reason := self.manual.press(c.axis, c.direction, self.now_s, self.axes):
            self._refuse(reason)

    def _on_JogStep(self, c: cmd.JogStep) -> None:
        if reason := self.manual.step(c.axis, c.step, self.axes):
            self._refuse(reason)

    def _on_JogRelease(self, c: cmd.JogRelease) -> None:
        self.manual.release(c.axis)

    def _on_SetJogSpeed(self, c: cmd.SetJogSpeed) -> None:
        if reason := self.manual.set_speed(c.group, c.velocity, c.acceleration):
            self._refuse(reason)

    def _on_SetClamps(self, c: cmd.SetClamps) -> None:
        self.outputs = replace(self.outputs, clamps_close=c.closed)

    def _on_SetSpindle(self, c: cmd.SetSpindle) -> None:
        self.outputs = replace(self.outputs, spindle_on=c.on)

    def _on_SetFeedOverride(self, c: cmd.SetFeedOverride) -> None:
        if not 0.0 <= c.percent <= 120.0:
            self._refuse(f"feed override {c.percent:g} % is not allowed: 0 to 120 %")
            return
        self.feed_override_pct = c.percent
        if self.cycle is not None:
            self.cycle.set_override(c.percent)

    def _on_Acknowledge(self, c: cmd.Acknowledge) -> None:
        self.alarms.acknowledge(c.alarm_id, self.user)

    def _on_ReloadParameters(self, _c: cmd.ReloadParameters) -> None:
        self.params = self.store.parameters()
        if self.recipe is not None and self.recipe.id is not None:
            self.recipe = self.store.recipe(self.recipe.id) or self.recipe
        if self.cycle is None:
            self._publish_recipe_preview()

    def _on_ResetShiftCounter(self, _c: cmd.ResetShiftCounter) -> None:
        self.shift_start = self.wall_clock()
        self.pieces_shift = 0

    def _on_InjectFault(self, c: cmd.InjectFault) -> None:
        if reason := self.sim_tools.inject(c.kind, c.target):
            self._refuse(reason)

    def _on_ClearFaults(self, _c: cmd.ClearFaults) -> None:
        self.sim_tools.clear()

    def _on_LoadBoard(self, c: cmd.LoadBoard) -> None:
        self.sim_tools.replace_board(c.width_mm)

    def _on_SetUser(self, c: cmd.SetUser) -> None:
        self.user = c.name

    # ---------------------------------------------------------------- transitions
    def _transition(self, event: Event) -> None:
        try:
            new = next_state(self.state, event, self.axes.all_homed())
        except TransitionRefused as exc:
            self._refuse(exc.reason)
            return
        if new is not self.state:
            log.info("state %s -> %s (%s)", self.state.value, new.value, event.value)
        if new in LATCHED_STATES and self.state not in LATCHED_STATES:
            self._moved_since_latch = False
        self.state = new
        if new is not MachineState.MANUAL:
            self.mode = Mode.AUTOMATIC

    def _fault(self, code: str, source: str, detail: str) -> None:
        """Raise a fault alarm, stop at once and latch ERROR (IEC 60204-1 stop category 1:
        the drives quick-stop, then lose power)."""
        self.alarms.raise_alarm(code, source, detail)
        if code == "E033":
            self._gauge_lost = True  # Reset brings the gauge up again
        if self.state in LATCHED_STATES:
            return
        log.warning("fault %s %s: %s", code, source, detail)
        if self.cycle is not None:
            self._record_abort(code)
        self._stop_now()
        self._transition(Event.FAULT)

    def _stop_now(self) -> None:
        if self.cycle is not None:
            self.cycle.abort()
            self.cycle = None
        self.homing = None
        self.manual.release_all(immediate=True)
        self.outputs = replace(self.outputs, spindle_on=False, centering_extend=False)
        if self.axes.feedback:
            self.axes.hold_where_they_are()
            self._device_call(self.axes.quick_stop_all)

    def _device_call(self, action: Callable[[], None]) -> None:
        """A stop or power request while the link may be gone: a failure is logged, never
        raised, because the latched state already holds and the drives stop on their own
        watchdog when the link is lost."""
        if not self._comms_ok:
            return
        try:
            action()
        except DriverError as exc:
            log.warning("%s", exc)

    # ---------------------------------------------------------------- the period
    def tick(self, now_s: float) -> None:
        self.now_s = now_s
        try:
            self._read()
        except DriverError as exc:
            self._comms_lost(exc)
            self._process_commands()
            return
        if not self.inputs.part_present:
            self._finished_board_on_table = False
        self._watch_interrupted_clamps()
        self.sim_tools.tick(self.inputs.part_present)
        self._process_buttons()
        self._supervise()
        self._process_commands()
        self._check_reset()
        try:
            self._run_activity()
        except CycleFault as exc:
            self._fault(exc.code, exc.source, exc.detail)
        except HomingFailed as exc:
            self._fault("E015", exc.axis, exc.detail)
        self._watch_latched_motion()
        self._lamps()
        try:
            self.axes.write()
            self.backend.io.write_outputs(self.outputs)
        except DriverError as exc:
            self._comms_lost(exc)

    def _read(self) -> None:
        feedback = self.backend.motion.read_axes()
        self.inputs = self.backend.io.read_inputs()
        self.axes.update(feedback)
        for device in (*self.backend.devices(), self.gauge):
            for event in device.events():
                self._device_event(event, from_gauge=device is self.gauge)

    def _device_event(self, event: DeviceEvent, from_gauge: bool = False) -> None:
        if event.kind in (DeviceEventKind.COMMUNICATION_LOST, DeviceEventKind.RECEIVE_THREAD_DIED):
            if from_gauge:
                # The axes and I/O still answer; only a new measurement is impossible.
                self._fault("E033", "gauge", event.text or event.kind.value)
                return
            self._comms_ok = False
            self._fault("E020", event.device, event.text or event.kind.value)
        elif event.kind is DeviceEventKind.EMERGENCY and event.code:
            text = event.text or EMERGENCY_TEXTS.get(event.code, "")
            log.warning("EMCY %s 0x%04X %s", event.device, event.code, text)
        elif event.kind is DeviceEventKind.COMMUNICATION_RESTORED:
            log.info("communication restored: %s (reset needed)", event.device)

    def _comms_lost(self, exc: DriverError) -> None:
        """A failed exchange: a lost link (E020), or a device that answered and refused the
        request (E021, with its code: a Modbus exception reply, an SDO abort), whose link
        still works."""
        if not isinstance(exc, CommunicationError):
            self._fault("E021", exc.device, str(exc))
            return
        self._comms_ok = False
        self._fault("E020", exc.device, str(exc))

    def _reconnect(self) -> None:
        """Operator's Reset after a lost link: bring the devices up again (disabled)."""
        devices = [*self.backend.devices(), self.gauge] if not self._comms_ok else [self.gauge]
        try:
            for device in devices:
                device.deactivate()
                device.configure()
                device.activate()
            self._comms_ok = True
            self._gauge_lost = False
        except DriverError as exc:
            self._refuse(f"reconnection failed: {exc}")

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
            command = self._commands.popleft()
            if isinstance(command, cmd.Shutdown):
                continue
            self._handle(command)

    def _supervise(self) -> None:
        inputs = self.inputs
        if not inputs.estop_ok:
            self.alarms.raise_alarm("E001", "E-stop chain")
            if self.state is not MachineState.EMERGENCY_STOP:
                if self.cycle is not None:
                    self._record_abort("E001")
                self._stop_now()  # quick stop on the drives' ramps; power off once still
                self._transition(Event.ESTOP)
        else:
            self.alarms.clear("E001", "E-stop chain")
        moving = self.state in (MachineState.AUTOMATIC, MachineState.HOMING)
        if (
            not inputs.guard_closed
            and moving
            and (self.cycle is None or self.cycle.moving or self.homing is not None)
        ):
            self._fault("E002", "guard", "guard opened")
        elif inputs.guard_closed:
            self.alarms.clear("E002", "guard")
        for name, fb in self.axes.feedback.items():
            if fb.faulted:
                code = (
                    "E012"
                    if (fb.limit_positive or fb.limit_negative)
                    else ("E011" if fb.fault_code == FOLLOWING_ERROR_FAULT else "E010")
                )
                text = EMERGENCY_TEXTS.get(fb.fault_code, "")
                self._fault(code, name, f"fault code 0x{fb.fault_code:04X} {text}".strip())
            else:
                # The drive is out of FAULT: those conditions have returned to normal (the
                # alarms stay shown until acknowledged). E013 is an event, cleared by Reset.
                for code in ("E010", "E011", "E012"):
                    self.alarms.clear(code, name)
        self._supervise_records()
        if self.cycle is not None and self.cycle.moving:
            setpoint = {n: self.axes.command[n] for n in self.axes.names}
            for violation in check_feedback(self.axes.feedback, setpoint, self.config.axes):
                self._fault(VIOLATION_ALARMS[violation.kind], violation.axis, violation.message)
            if not self.axes.all_homed():
                self._fault("E016", "axes", "an axis lost its home position")

    def _supervise_records(self) -> None:
        """W103 while a record has waited too long for a busy or missing database (it is kept
        in the journal meanwhile; the machine goes on)."""
        waited_s = self.store.unstored_age_s()
        if waited_s > RECORD_DELAY_ALARM_S:
            self.alarms.raise_alarm("W103", "database", f"oldest waiting {waited_s:.0f} s")
        elif waited_s == 0.0:
            self.alarms.clear("W103", "database")

    def _check_reset(self) -> None:
        if self._reset_pending_since is None:
            return
        if self.state not in LATCHED_STATES:
            self._reset_pending_since = None
            return
        if not self._reset_faults_sent:
            self._reset_faults_sent = True
            self._device_call(self.axes.fault_reset_all)
            return
        causes = [
            f"{n} still in fault 0x{fb.fault_code:04X}"
            for n, fb in self.axes.feedback.items()
            if fb.faulted
        ]
        if not self.inputs.estop_ok:
            causes.append("emergency stop still pressed")
        if not self._comms_ok:
            causes.append("communication not restored")
        if not causes:
            self._reset_pending_since = None
            self.alarms.clear_all_conditions()
            self.axes.hold_where_they_are()
            self.manual.sync(self.axes)
            self.message = "reset done"
            self._transition(Event.RESET)
        elif self.now_s - self._reset_pending_since > RESET_TIMEOUT_S:
            self._reset_pending_since = None
            self._refuse("reset failed: " + "; ".join(causes))

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
            else:
                warning = self.manual.tick(self.now_s, self.config.period_s, self.axes)
                if warning:
                    self.alarms.raise_alarm("W101", warning)
                    self.alarms.clear("W101", warning)
        elif self.state is MachineState.AUTOMATIC and self.cycle is not None:
            self.outputs = self.cycle.tick(self.now_s, self.inputs, self.outputs, self.axes)
            self._remember_cut()
            self._publish_plan()
            if self.cycle.finished:
                self._finish_cycle()
        elif self.state is MachineState.STOPPING:
            self._run_stopping()

    def _run_stopping(self) -> None:
        cycle = self.cycle
        if cycle is not None:
            if cycle.moving and not cycle.stopped:
                self.outputs = cycle.tick(self.now_s, self.inputs, self.outputs, self.axes)
                return
            self._record_abort("")
            self.cycle = None
        if self.axes.standing_still(tolerance=0.5):
            self.outputs = replace(self.outputs, spindle_on=False, centering_extend=False)
            self.axes.hold_where_they_are()
            self._transition(Event.STOPPED)

    def _publish_plan(self) -> None:
        cycle = self.cycle
        if cycle is None or cycle.planned is None or cycle.plan_counter == 0:
            return
        if getattr(cycle, "_published", False):
            return
        cycle._published = True  # type: ignore[attr-defined]
        self._plan_id += 1
        self._plans = {self._plan_id: build_preview(self._plan_id, cycle.planned.toolpath)}

    def _watch_interrupted_clamps(self) -> None:
        """A partly cut board whose clamps open (a lost I/O coupler switches its outputs off,
        an operator unclamps in Manual) may move: from then on it can only be abandoned."""
        board = self.interrupted
        if board is None or board.unclamped or self.inputs.clamps_closed:
            return
        if self.cycle is not None and self.cycle.step is CycleStep.UNCLAMPING:
            return
        self.interrupted = replace(board, unclamped=True)
        self.store.save_interrupted_board(self.interrupted)

    def _remember_cut(self) -> None:
        """Persist the board's phase each time the cut enters a new one, so that a crash or a
        power loss leaves a record of a partly cut board."""
        cycle = self.cycle
        if cycle is None or not cycle.board_partly_cut:
            return
        phase = cycle.cut_phase
        if self.interrupted is not None and self.interrupted.phase is phase:
            return
        record = interruption(cycle, self.axes.positions(), "", self.interrupted)
        if record is not None:
            self.interrupted = record
            self.store.save_interrupted_board(record)

    def _finish_cycle(self) -> None:
        cycle = self.cycle
        assert cycle is not None
        cycle_time_s = self.now_s - cycle.started_s
        if cycle.is_continuation and not cycle.resume:
            board = self.interrupted
            piece = self._piece_record(
                cycle,
                cycle_time_s,
                "aborted",
                board.reason if board and board.reason != "stop" else None,
            )
            self.store.record_piece(piece)
            self.finished_cycles.append((piece, cycle))
            del self.finished_cycles[:-10]
            self._end_interrupted("aborted", cycle)
            self.cycle = None
            self.message = "board abandoned: take it off"
            self._transition(Event.CYCLE_DONE)
            return
        piece = self._piece_record(cycle, cycle_time_s, "ok", None)
        if cycle.is_continuation:
            piece = replace(piece, resumed=True)
        if self.interrupted is not None:
            self._end_interrupted("ok", cycle)
        self.store.record_piece(piece)
        placed = cycle.planned.barrel_stave if cycle.planned is not None else None
        if self.barrel is not None and placed is not None:
            self.barrel, self.board_choice = self.barrel.with_stave(placed), None
        self.pieces_shift += 1
        self.pieces_total += 1
        self.last_width_mm = cycle.outcome.width_mm
        self.last_cycle_time_s = cycle_time_s
        self.finished_cycles.append((piece, cycle))
        del self.finished_cycles[:-10]
        self.cycle = None
        self._finished_board_on_table = True
        self._transition(Event.CYCLE_DONE)

    def _piece_record(
        self, cycle: AutomaticCycle, cycle_time_s: float, result: str, alarm: str | None
    ) -> PieceRecord:
        o = cycle.outcome
        return PieceRecord(
            self.wall_clock(),
            cycle.recipe.id,
            cycle.recipe.name,
            o.width_mm,
            o.d_mm,
            o.r_mm,
            o.tilt_deg,
            cycle_time_s,
            result,
            alarm,
        )

    def _record_abort(self, alarm_code: str) -> None:
        cycle = self.cycle
        if cycle is None:
            return
        record = interruption(cycle, self.axes.positions(), alarm_code or "stop", self.interrupted)
        if record is not None:
            # Not a piece yet: a board partly cut, to resume or abandon (Start offers both).
            self.interrupted = record
            self.store.save_interrupted_board(record)
            return
        if cycle.step.name == "WAIT_FOR_PART":
            return
        result = "rejected" if cycle.planned is None else "aborted"
        piece = self._piece_record(cycle, self.now_s - cycle.started_s, result, alarm_code or None)
        self.store.record_piece(piece)
        self.finished_cycles.append((piece, cycle))
        del self.finished_cycles[:-10]

    def _watch_latched_motion(self) -> None:
        """Latched states: once the axes stand still, take their power (stop category 1)."""
        if self.state in LATCHED_STATES and self.axes.standing_still(tolerance=0.5):
            self._device_call(self.axes.disable_all)

    def _lamps(self) -> None:
        running = self.state in (MachineState.AUTOMATIC, MachineState.HOMING)
        self.outputs = replace(
            self.outputs,
            lamp_green=running,
            lamp_yellow=self.state
            in (MachineState.MANUAL, MachineState.STOPPING, MachineState.NOT_HOMED),
            lamp_red=self.state in LATCHED_STATES,
        )

    # ---------------------------------------------------------------- the picture
    def state_text(self) -> str:
        return state_text(self)

    def snapshot(self) -> MachineSnapshot:
        self._seq += 1
        return build_snapshot(self, self._seq)

    @property
    def plan_id(self) -> int:
        return self._plan_id

    def plan_preview(self, plan_id: int) -> PlanPreview | None:
        return self._plans.get(plan_id)
