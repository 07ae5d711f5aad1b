"""The automatic work of the controller: starting a cycle, resuming or abandoning a partly
cut board, and finishing a cycle (counting, recording, forgetting the board).

Why a layer of its own (between ``core`` and ``controller``): what a cycle is given to plan
with, and how a finished, resumed or abandoned board is booked, is one job; the period's
sequencing and the command dispatch stay in the controller.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import replace
from typing import Any

from app.config import MachineConfig
from app.data.recipe import Recipe
from app.drivers.contracts import MachineBackend, WidthGauge
from app.geometry.limits import StaveLimits
from app.machine.barrel_book import BarrelBook
from app.machine.barrel_job import new_barrel, plan_barrel_board
from app.machine.barrel_set import BarrelSet, BoardChoice
from app.machine.board_resume import continue_job
from app.machine.core import ControllerCore
from app.machine.cycle import AutomaticCycle, PlanSubmitter
from app.machine.cycle_plan import PlannedStave, plan_board
from app.machine.planner.limits import MotionLimits
from app.machine.process_params import motion_limits, stave_limits
from app.machine.refusals import Reason, Refusal, refusal
from app.machine.states import Event
from app.machine.store import MachineStore


class CycleControl(ControllerCore):
    def __init__(
        self,
        config: MachineConfig,
        backend: MachineBackend,
        gauge: WidthGauge,
        store: MachineStore,
        wall_clock: Callable[[], float],
        submit: PlanSubmitter,
    ) -> None:
        super().__init__(config, backend, gauge, store, wall_clock)
        self._submit = submit
        self.params: dict[str, float] = store.parameters()
        self.feed_override_pct = 100.0
        self._finished_board_on_table = False
        self.barrel: BarrelSet | None = None  # the barrel being raised (None: single staves)
        self.board_choice: BoardChoice | None = None  # the answer to E034, for the next board
        self.barrels = BarrelBook(store, wall_clock)

    def _start(self) -> None:
        assert self.recipe is not None
        if self.recipe.id is not None and self.store.recipe(self.recipe.id) is None:
            # Deleted since it was selected: it is not cut without someone choosing it.
            self._refuse(refusal(Reason.SELECTED_RECIPE_DELETED, repr(self.recipe.name)))
            return
        recipe, params, limits_stave, limits_motion = self._planning(self.recipe)
        if self.barrel is not None and self.barrel.closed:
            # The board after a closed barrel starts the next one.
            self.barrel = replace(self.barrel.next_barrel(), number=self.barrels.next_number())
            self.barrels.started(self.barrel, recipe)
        barrel, choice = self.barrel, self.board_choice
        clamps = self.config.table_devices.clamps  # closed on the board while the cutter moves

        def plan_job(width_mm: float, start: tuple[float, float, float]) -> PlannedStave:
            if barrel is None:
                return plan_board(
                    recipe, width_mm, params, limits_stave, limits_motion, start, devices=clamps
                )
            return plan_barrel_board(
                barrel, choice, recipe, width_mm, params, limits_stave, limits_motion, start
            )

        cycle = self._new_cycle(
            recipe=recipe, plan_job=plan_job, board_already_cut=self._finished_board_on_table
        )
        self._begin(cycle, None)

    def _planning(
        self, recipe: Recipe
    ) -> tuple[Recipe, dict[str, float], StaveLimits, MotionLimits]:
        """What a cycle plans with: the parameters as they are now, the machine's limits."""
        self.params = self.store.parameters()
        return recipe, dict(self.params), *self._limits()

    def _limits(self) -> tuple[StaveLimits, MotionLimits]:
        return stave_limits(self.config), motion_limits(self.config, self.params)

    def _new_cycle(self, **job: Any) -> AutomaticCycle:
        """A cycle on this machine now; ``job`` says what it cuts and how it is planned."""
        return functools.partial(
            AutomaticCycle,
            config=self.config,
            gauge=self.gauge,
            submit=self._submit,
            started_s=self.now_s,
            feed_override_pct=self.feed_override_pct,
        )(**job)

    def _begin(self, cycle: AutomaticCycle, message: Refusal | None) -> None:
        self.cycle = cycle
        self.message = message
        self._transition(Event.START)

    def _start_barrel(self) -> None:
        if self.recipe is None:
            self._refuse(Refusal(Reason.SELECT_RECIPE_FIRST))
            return
        barrel = new_barrel(self.recipe, stave_limits(self.config), self.barrels.next_number())
        if barrel is None:
            self._refuse(refusal(Reason.FIXED_TILT_NO_BARREL, repr(self.recipe.name)))
            return
        self.barrel, self.board_choice = barrel, None
        self.barrels.started(barrel, self.recipe)

    def _drop_barrel(self) -> None:
        """A barrel is raised from one recipe's staves: another recipe gives it up."""
        if self.barrel is not None:
            self.barrels.dropped()
        self.barrel, self.board_choice = None, None

    def _restore_barrel(self) -> None:
        """Carry on with the barrel open before the restart, with its recipe selected, if
        that recipe still makes this barrel (edited or deleted since: the barrel is given up)."""
        restored = self.barrels.restore()
        if restored is None:
            return
        recipe = None if restored.recipe_id is None else self.store.recipe(restored.recipe_id)
        if recipe is None or recipe.barrel_section != restored.barrel.section:
            self.barrels.dropped()
            return
        self.recipe, self.barrel = recipe, restored.barrel

    def _abandon(self) -> None:
        board = self.partly_cut.board
        assert board is not None
        if not self.axes.all_homed() or self.partly_cut.recipe() is None or board.width_mm <= 0:
            # Where the cutter is, or what the board looks like, is unknown: nothing moves.
            self.outputs = replace(self.outputs, clamps_close=False, spindle_on=False)
            self.partly_cut.end("aborted", recorded=False)
            self._finished_board_on_table = True
            self.message = Refusal(Reason.ABANDONED_UNCLAMPED)
            return
        self._continue_board(resume=False)

    def _continue_board(self, *, resume: bool) -> None:
        board, recipe = self.partly_cut.board, self.partly_cut.recipe()
        assert board is not None
        if recipe is None:
            self._refuse(refusal(Reason.RECIPE_GONE_ABANDON, repr(board.recipe_name)))
            return
        recipe, params, limits_stave, limits_motion = self._planning(recipe)
        job = continue_job(
            recipe,
            board,
            params,
            limits_stave,
            limits_motion,
            resume=resume,
            devices=self.config.table_devices.clamps,  # closed: the board is clamped
        )
        cycle = self._new_cycle(
            recipe=recipe,
            plan_job=None,
            continue_job=job,
            resume=resume,
            interrupted_phase=board.phase,
        )
        self._begin(cycle, Refusal(Reason.RESUMING if resume else Reason.ABANDONING))

    def _finish_cycle(self, cycle: AutomaticCycle) -> None:
        board = self.partly_cut.board
        if cycle.is_continuation and not cycle.resume:  # abandoned: taken clear, given up
            alarm = board.reason if board and board.reason != "stop" else None
            self.production.abandoned(cycle, self.now_s, alarm)
            self.partly_cut.end("aborted", recorded=True)
            self.message = Refusal(Reason.ABANDONED)
        else:
            if board is not None:
                self.partly_cut.end("ok", recorded=True)
            self.production.finished(cycle, self.now_s)
            placed = cycle.planned.barrel_stave if cycle.planned is not None else None
            if self.barrel is not None and placed is not None:
                self.barrel, self.board_choice = self.barrel.with_stave(placed), None
                self.barrels.stave_cut(placed, self.barrel)
        self.cycle = None
        self._finished_board_on_table = True
        self._transition(Event.CYCLE_DONE)
