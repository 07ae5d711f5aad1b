"""The automatic cycle as a sequence of steps (docs/MACHINE.md section 4, the Step routine).

Each period the controller calls :meth:`AutomaticCycle.tick` with what the inputs read; the
cycle sets the outputs and the axis commands, and either carries on, ends (the piece is done),
or raises :class:`CycleFault` naming the alarm. Every wait has a timeout: a sensor that never
arrives is an alarm, never a machine that waits for ever.

Steps: wait for a board (and the Start that began the cycle) -> centre -> clamp -> measure ->
plan (on a worker, the axes stand still) -> start the spindle -> cut side A -> reposition and
tilt -> cut side B -> return (spindle off) -> unclamp -> done.
"""

from __future__ import annotations

import concurrent.futures
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

from app.config import MachineConfig
from app.data.recipe import Recipe
from app.drivers.contracts import CommunicationError, InputImage, OutputImage, WidthGauge
from app.machine.alarms import AlarmCode, AlarmDetail
from app.machine.axes import AxisGroup
from app.machine.cycle_plan import PlannedStave, PlanningError
from app.machine.cycle_times import StepClock, timed_step
from app.machine.executor import ExecutorOutput, PathExecutor
from app.machine.planner.continuation import Continuation
from app.machine.planner.keepout import KeepOutRefused, TableKeepOut
from app.machine.planner.trajectory import Phase
from app.machine.refusals import Reason, Refusal
from app.machine.states import CycleStep, TimedStep

PlanJob = Callable[[], Any]
PlanSubmitter = Callable[[PlanJob], "concurrent.futures.Future[Any]"]
ContinueJob = Callable[[tuple[float, float, float]], tuple[PlannedStave, Continuation]]

GAUGE_TIMEOUT_S = 2.0

_PHASE_STEPS: dict[Phase, CycleStep] = {
    Phase.APPROACH: CycleStep.CUTTING_A,
    Phase.CUT_A: CycleStep.CUTTING_A,
    Phase.REPOSITION: CycleStep.REPOSITIONING,
    Phase.CUT_B: CycleStep.CUTTING_B,
    Phase.RETURN: CycleStep.RETURNING,
    Phase.POINT_TO_POINT: CycleStep.CUTTING_A,
    Phase.RETRACT: CycleStep.RETRACTING,
}

_PATH_STEPS = frozenset(
    {CycleStep.CUTTING_A, CycleStep.REPOSITIONING, CycleStep.CUTTING_B, CycleStep.RETURNING}
)
"""The steps in which the axes follow the planned stave."""


def run_now(job: PlanJob) -> concurrent.futures.Future[Any]:
    """Plan on the calling thread (simulated clock: deterministic and instant)."""
    future: concurrent.futures.Future[Any] = concurrent.futures.Future()
    try:
        future.set_result(job())
    except Exception as exc:
        future.set_exception(exc)
    return future


class CycleFault(Exception):
    """The cycle cannot go on: raise alarm ``code`` at ``source``."""

    def __init__(self, code: AlarmCode, detail: AlarmDetail, source: str = "") -> None:
        super().__init__(str(detail))
        self.code = code
        self.detail = detail
        self.source = source


@dataclass
class CycleOutcome:
    """What a finished cycle reports (for the counter, the record and the screen)."""

    width_mm: float | None = None
    d_mm: float | None = None
    r_mm: float | None = None
    tilt_deg: float | None = None
    cut_time_a_s: float = 0.0
    cut_time_b_s: float = 0.0
    cut_length_a_mm: float = 0.0
    cut_length_b_mm: float = 0.0
    step_times_s: dict[str, float] = field(default_factory=dict)
    """Where the cycle's time went: timed step name -> seconds (they add up to the cycle)."""


class AutomaticCycle:
    """One board through the machine."""

    def __init__(
        self,
        *,
        recipe: Recipe,
        config: MachineConfig,
        gauge: WidthGauge,
        plan_job: Callable[[float, tuple[float, float, float]], PlannedStave] | None,
        submit: PlanSubmitter,
        started_s: float,
        feed_override_pct: float,
        board_already_cut: bool = False,
        continue_job: ContinueJob | None = None,
        resume: bool = False,
        interrupted_phase: Phase | None = None,
    ) -> None:
        self.recipe = recipe
        self._config = config
        self._gauge = gauge
        self._plan_job = plan_job
        self._submit = submit
        self.started_s = started_s
        self.step = CycleStep.WAIT_FOR_PART
        self._step_started_s = started_s
        self._plan_future: concurrent.futures.Future[PlannedStave] | None = None
        self.planned: PlannedStave | None = None
        self.executor: PathExecutor | None = None
        self.last_output: ExecutorOutput | None = None
        self.outcome = CycleOutcome()
        self.finished = False
        self._stop_requested = False
        self._override_pct = feed_override_pct
        # The board on the table is the one just finished: wait until it is taken off.
        self.board_already_cut = board_already_cut
        self.plan_counter = 0
        # An interrupted board: clear of it first (spindle off), then resume or abandon.
        self._continue_job = continue_job
        self.resume = resume
        self._continue_future: concurrent.futures.Future[Any] | None = None
        self.continuation: Continuation | None = None
        self._cut_executor: PathExecutor | None = None
        self._interrupted_phase = interrupted_phase
        self._clock = StepClock(started_s)
        self._spindle_on_s: float | None = None
        self._waiting_since_s: float | None = None
        self._keep_out: TableKeepOut | None = None
        self._entered_last_cut = False
        self._clamps_released = False
        self._spindle_ran = False  # the spindle has reported running since it was switched on
        # When the board was there and the cycle's work began (None: still waiting for it).
        self.board_arrived_s: float | None = None

    @property
    def is_continuation(self) -> bool:
        """True for the cycle that resumes or abandons an interrupted board."""
        return self._continue_job is not None

    @property
    def board_partly_cut(self) -> bool:
        """True once the cut has begun on this board (or it had begun before)."""
        return self.is_continuation or self._cut_executor is not None

    @property
    def cut_phase(self) -> Phase | None:
        """The phase of the cut the board is in (where a resume must go on from)."""
        if self._cut_executor is not None:
            return self._cut_executor.last_output.phase
        return self._interrupted_phase

    # -- helpers ---------------------------------------------------------------------------
    def _go(self, step: CycleStep, now_s: float) -> None:
        if self.board_arrived_s is None and step is not CycleStep.WAIT_FOR_PART:
            self.board_arrived_s = now_s
        self.step = step
        self._step_started_s = now_s

    def _waited(self, now_s: float) -> float:
        return now_s - self._step_started_s

    def _wait_sensor(
        self, ok: bool, now_s: float, travel_s: float, code: AlarmCode, what: Reason
    ) -> bool:
        if ok:
            return True
        limit_s = travel_s + self._config.io.sensor_timeout_s
        if self._waited(now_s) > limit_s:
            raise CycleFault(code, Refusal(what, (f"{limit_s:.1f}",)))
        return False

    @property
    def moving(self) -> bool:
        """True while the path executor drives the axes."""
        return self.executor is not None and not self.executor.done

    def waited_s(self, now_s: float) -> float:
        """The time from Start until the board was there (so far, while still waiting)."""
        arrived_s = now_s if self.board_arrived_s is None else self.board_arrived_s
        return max(arrived_s - self.started_s, 0.0)

    def working_s(self, now_s: float) -> float:
        """The cycle's time without the wait for the board: from its arrival to now."""
        return 0.0 if self.board_arrived_s is None else max(now_s - self.board_arrived_s, 0.0)

    def path_progress(self) -> float | None:
        """0 .. 1 along the planned path while the axes follow it; None while the step has
        no known length (waiting for a board, a sensor, the gauge, the spindle) or while the
        cycle is stopping (its end is not the plan's)."""
        executor = self.following_executor
        if self._stop_requested or executor is None:
            return None
        return executor.progress

    @property
    def following_executor(self) -> PathExecutor | None:
        """The executor the axes follow now (None before the path starts and after it)."""
        executor = self.executor
        following = self.step is CycleStep.RETRACTING or self.step in _PATH_STEPS
        return executor if following and executor is not None and not executor.done else None

    def remaining_s(self) -> float:
        if self.executor is not None:
            return self.executor.remaining_s
        if self.planned is not None:
            return self.planned.plan.duration_s
        return 0.0

    def set_override(self, percent: float) -> None:
        self._override_pct = percent
        if self.executor is not None:
            self.executor.set_override(percent)

    def request_stop(self) -> None:
        """Controlled stop: along the path if cutting, at once otherwise."""
        self._stop_requested = True
        if self.executor is not None:
            self.executor.request_stop()

    @property
    def stopped(self) -> bool:
        if not self._stop_requested:
            return False
        return self.executor is None or self.executor.stopped or self.executor.done

    def abort(self) -> None:
        """Immediate stop (E-stop, fault): freeze the setpoints where they are."""
        self._stop_requested = True
        if self.executor is not None:
            self.executor.abort()
        for future in (self._plan_future, self._continue_future):
            if future is not None:
                future.cancel()

    # -- the sequence ----------------------------------------------------------------------
    def tick(
        self, now_s: float, inputs: InputImage, outputs: OutputImage, axes: AxisGroup
    ) -> OutputImage:
        """Advance the cycle by one period; returns the outputs to write."""
        io = self._config.io
        step = self.step
        self._clock.book(now_s, self._timed_step())
        if (
            step is not CycleStep.WAIT_FOR_PART
            and step is not CycleStep.UNCLAMPING
            and not inputs.part_present
        ):
            raise CycleFault(AlarmCode.BOARD_REMOVED, Refusal(Reason.PART_SENSOR_OFF))

        if step is CycleStep.WAIT_FOR_PART and self._continue_job is not None:
            if not inputs.part_present:
                raise CycleFault(AlarmCode.BOARD_REMOVED, Refusal(Reason.PARTLY_CUT_GONE))
            outputs = replace(outputs, spindle_on=False)
            # Enabled and planned from rest only: an axis still running down after the
            # interruption would start the retract from a position it has already left.
            if not axes.standing_still(0.01):
                return outputs
            if axes.request_enable() and axes.all_enabled():
                job, start = self._continue_job, axes.positions()
                self._continue_future = self._submit(lambda: job(start))
                self._go(CycleStep.RETRACTING, now_s)
        elif step is CycleStep.RETRACTING:
            outputs = self._retract(now_s, outputs, axes)
        elif step is CycleStep.WAIT_FOR_PART:
            axes.request_enable()
            if not inputs.part_present:
                self.board_already_cut = False
            if inputs.part_present and not self.board_already_cut and axes.all_enabled():
                outputs = replace(outputs, clamps_close=False, centering_extend=True)
                self._go(CycleStep.CENTERING, now_s)
        elif step is CycleStep.CENTERING:
            outputs = replace(outputs, centering_extend=True)
            if self._wait_sensor(
                inputs.centering_extended,
                now_s,
                io.centering_time_s,
                AlarmCode.CENTERING_SENSOR,
                Reason.CENTERING_EXTENDED,
            ):
                outputs = self._clamp(outputs)
                self._go(CycleStep.CLAMPING, now_s)
        elif step is CycleStep.CLAMPING:
            outputs = self._clamp(outputs)
            if self._wait_sensor(
                inputs.clamps_closed,
                now_s,
                io.clamp_time_s,
                AlarmCode.CLAMPS_SENSOR,
                Reason.CLAMPS_CLOSED,
            ):
                outputs = replace(outputs, centering_extend=False)
                self._request_width()
                self._go(CycleStep.MEASURING, now_s)
        elif step is CycleStep.MEASURING:
            outputs = self._measure(now_s, inputs, outputs, axes)
        elif step is CycleStep.STARTING_SPINDLE:
            outputs = replace(outputs, spindle_on=True)
            if self._spindle_on_s is None:
                self._spindle_on_s = now_s
            # The cutter passes where the centering device stood: it must be back first.
            if self._wait_sensor(
                inputs.centering_retracted,
                now_s,
                io.centering_time_s,
                AlarmCode.CENTERING_SENSOR,
                Reason.CENTERING_RETRACTED,
            ):
                self._start_path(now_s)
        elif step in _PATH_STEPS:
            outputs = self._cut(now_s, inputs, outputs, axes)
        elif step is CycleStep.UNCLAMPING:
            outputs = replace(outputs, clamps_close=False, spindle_on=False)
            if self._wait_sensor(
                inputs.clamps_open,
                now_s,
                io.clamp_time_s,
                AlarmCode.CLAMPS_SENSOR,
                Reason.CLAMPS_OPENED,
            ):
                self.finished = True
                self._step_started_s = now_s
                self.outcome.step_times_s = self._clock.seconds()
        return outputs

    def _timed_step(self) -> TimedStep:
        """What the machine did during the period that has just passed."""
        executor = self.executor
        following = self.step is CycleStep.RETRACTING or self.step in _PATH_STEPS
        if not following or executor is None or executor.done:
            return timed_step(self.step, None, False)
        return timed_step(self.step, executor.last_output.phase, executor.dwelling)

    def step_times_s(self) -> dict[str, float]:
        """The step times so far (the whole cycle's once it has finished)."""
        return self._clock.seconds()

    def _clamp(self, outputs: OutputImage) -> OutputImage:
        """Close the clamps. Overlap (a configuration choice, for mechanics that hold the
        board throughout): the centering device retracts while they close, so the cutter
        need not wait for its stroke after the board is clamped."""
        overlap = self._config.cycle.centering_retract_while_clamping
        return replace(outputs, clamps_close=True, centering_extend=not overlap)

    def _start_path(self, now_s: float) -> None:
        """Start the planned motion with the spindle still running up.

        Overlap: the spindle runs up during the approach instead of before it. Safe because
        the executor waits at the first point of every cut (the lead-in, outside the board's
        keep-out) until the spindle reports running and the axes have settled
        (:meth:`_release_cut`); a spindle that never comes up leaves the cutter standing
        there, clear of the board, and raises E042 (spindle did not start).
        Overlap: unless the configuration asks for the original return home between boards,
        the path ends with side B; the next board's approach starts from there (planned
        around that board's keep-out like any approach)."""
        assert self.planned is not None
        home = self._config.cycle.return_home_between_boards
        self.executor = PathExecutor(
            self.planned.plan,
            self._config.period_s,
            wait_before_cuts=True,
            end_before=None if home else Phase.RETURN,
        )
        self.executor.set_override(self._override_pct)
        self._cut_executor = self.executor
        self._keep_out = TableKeepOut.around_toolpath(self.planned.toolpath)
        self._go(_PHASE_STEPS[self.executor.phase], now_s)

    def _release_cut(self, now_s: float, inputs: InputImage, axes: AxisGroup) -> None:
        """At a cut's first point: cut once the spindle runs and the following error of every
        axis has settled below the configured threshold (instead of a fixed dwell: usually
        a few periods), or ``settle_max_s`` after arriving at the latest."""
        executor = self.executor
        assert executor is not None
        if self._waiting_since_s is None:
            self._waiting_since_s = now_s
        if not inputs.spindle_running:
            if self._spindle_ran:  # it ran and stopped: not a slow start
                raise CycleFault(
                    AlarmCode.SPINDLE_STOPPED, Refusal(Reason.SPINDLE_FEEDBACK_LOST), "spindle"
                )
            spindle_on_s = now_s if self._spindle_on_s is None else self._spindle_on_s
            limit_s = self._config.io.spindle_runup_s + self._config.io.sensor_timeout_s
            if now_s - spindle_on_s > limit_s:
                raise CycleFault(
                    AlarmCode.SPINDLE_NOT_STARTED,
                    Refusal(Reason.SPINDLE_RUNNING, (f"{limit_s:.1f}",)),
                    "spindle",
                )
            return
        settings = self._config.cycle
        settled = all(
            abs(fb.following_error)
            <= (settings.settle_error_deg if name == "Z" else settings.settle_error_mm)
            for name, fb in axes.feedback.items()
        )
        if settled or now_s - self._waiting_since_s >= settings.settle_max_s - 1e-9:
            executor.release()
            self._waiting_since_s = None

    def _clear_of_board(self, out: ExecutorOutput, axes: AxisGroup) -> bool:
        """True once the cutter has left the board for good: on the return, or out of the
        board's keep-out again after the plan's last cut (side B's last pass) entered it,
        measured at the actual position. Not between two passes: another cut follows."""
        if out.phase is Phase.RETURN:
            return True
        executor = self.executor
        if executor is None or not executor.in_last_cut or self._keep_out is None:
            return False
        inside = self._keep_out.inside(axes.positions())
        if inside:
            self._entered_last_cut = True
        return self._entered_last_cut and not inside

    def _request_width(self) -> None:
        try:
            self._gauge.request()
        except CommunicationError as exc:
            raise CycleFault(AlarmCode.GAUGE_DISCONNECTED, str(exc), "gauge") from exc

    def _measure(
        self, now_s: float, inputs: InputImage, outputs: OutputImage, axes: AxisGroup
    ) -> OutputImage:
        if self._plan_future is None:
            try:
                reading = self._gauge.poll()
            except CommunicationError as exc:
                raise CycleFault(AlarmCode.GAUGE_DISCONNECTED, str(exc), "gauge") from exc
            if reading is None:
                if self._waited(now_s) > GAUGE_TIMEOUT_S:
                    raise CycleFault(
                        AlarmCode.GAUGE_NO_READING,
                        Refusal(Reason.GAUGE_NO_READING_DETAIL, (f"{GAUGE_TIMEOUT_S:.1f}",)),
                        "gauge",
                    )
                return outputs
            if not reading.ok or reading.width_mm is None:
                raise CycleFault(
                    AlarmCode.GAUGE_UNREADABLE,
                    f"{reading.error or 'no width'} (raw {reading.raw!r})",
                    "gauge",
                )
            width_mm = reading.width_mm
            self.outcome.width_mm = width_mm
            start = axes.positions()
            plan_job = self._plan_job
            if plan_job is None:
                raise CycleFault(AlarmCode.INTERNAL_ERROR, "the cycle has no planning job", "cycle")
            self._plan_future = self._submit(lambda: plan_job(width_mm, start))
            return outputs
        if not self._plan_future.done():
            return outputs
        try:
            planned = self._plan_future.result()
        except PlanningError as exc:
            raise CycleFault(exc.code, str(exc), "recipe") from exc
        except Exception as exc:
            raise CycleFault(
                AlarmCode.PLANNING_FAILED, f"{type(exc).__name__}: {exc}", "planner"
            ) from exc
        self.planned = planned
        self.plan_counter += 1
        self.outcome.d_mm = planned.profile.D
        self.outcome.r_mm = planned.profile.R
        self.outcome.tilt_deg = planned.tilt_deg
        self.outcome.cut_length_a_mm = planned.plan.cut_length_mm("A")
        self.outcome.cut_length_b_mm = planned.plan.cut_length_mm("B")
        self._go(CycleStep.STARTING_SPINDLE, now_s)
        return replace(outputs, spindle_on=True)

    def _retract(self, now_s: float, outputs: OutputImage, axes: AxisGroup) -> OutputImage:
        """Spindle off: back along the cut and around the board to the next lead-in (resume)
        or to home (abandon); then start the spindle, or unclamp."""
        outputs = replace(outputs, spindle_on=False)
        if self.continuation is None:
            future = self._continue_future
            if future is None or not future.done():
                return outputs
            try:
                planned, continuation = future.result()
            except PlanningError as exc:
                raise CycleFault(exc.code, str(exc), "recipe") from exc
            except KeepOutRefused as exc:
                raise CycleFault(AlarmCode.APPROACH_CROSSES_BOARD, str(exc), "keep-out") from exc
            except Exception as exc:
                raise CycleFault(
                    AlarmCode.PLANNING_FAILED, f"{type(exc).__name__}: {exc}", "planner"
                ) from exc
            self.continuation = continuation
            self.outcome.width_mm = planned.width_mm
            self.outcome.d_mm = planned.profile.D
            self.outcome.r_mm = planned.profile.R
            self.outcome.tilt_deg = planned.tilt_deg
            if continuation.cut is not None:
                self.planned = replace(planned, plan=continuation.cut)
                self.plan_counter += 1
            if continuation.clear is not None:
                self.executor = PathExecutor(continuation.clear, self._config.period_s)
                self.executor.set_override(self._override_pct)
        executor = self.executor
        if executor is not None and not executor.done:
            out = executor.step()
            self.last_output = out
            axes.command.update({"X": out.x, "Y": out.y, "Z": out.z})
            if not out.done:
                return outputs
        if self.continuation.cut is not None:
            self._go(CycleStep.STARTING_SPINDLE, now_s)
            return outputs
        self._go(CycleStep.UNCLAMPING, now_s)
        return replace(outputs, clamps_close=False)

    def _cut(
        self, now_s: float, inputs: InputImage, outputs: OutputImage, axes: AxisGroup
    ) -> OutputImage:
        executor = self.executor
        assert executor is not None
        if executor.waiting:
            self._release_cut(now_s, inputs, axes)
        self._spindle_ran = self._spindle_ran or inputs.spindle_running
        out = executor.step()
        self.last_output = out
        axes.command.update({"X": out.x, "Y": out.y, "Z": out.z})
        step = _PHASE_STEPS[out.phase]
        if step is not self.step:
            self._go(step, now_s)
        if out.cutting and not inputs.spindle_running:
            raise CycleFault(
                AlarmCode.SPINDLE_STOPPED, Refusal(Reason.SPINDLE_FEEDBACK_LOST), "spindle"
            )
        # Overlap: the clamps open as soon as the cutter is clear of the board, while it
        # still runs out along the lead-out (or returns), not after it has stopped.
        if not self._clamps_released and self._clear_of_board(out, axes):
            self._clamps_released = True
        if self._clamps_released:
            outputs = replace(outputs, clamps_close=False)
        if out.phase is Phase.RETURN:
            outputs = replace(outputs, spindle_on=False)
        if out.done:
            plan = self.planned.plan if self.planned else None
            if plan is not None:
                self.outcome.cut_time_a_s = plan.cut_time_s("A")
                self.outcome.cut_time_b_s = plan.cut_time_s("B")
            outputs = replace(outputs, spindle_on=False, clamps_close=False)
            self._go(CycleStep.UNCLAMPING, now_s)
        return outputs
