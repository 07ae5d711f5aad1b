"""The operator's commands outside the Manual screen that are not the cycle's own (those are
in ``cycle_control``): Stop, Reset, choosing the recipe, the parameters the System screen
saved, the feed override, and the plan preview the screens draw for the recipe.

Why a layer of its own (between ``manual_room`` and ``controller``): what a Stop or a Reset
does in each state, and when the recipe and the parameters the screens saved reach the
machine, is one job; the period's sequencing and the dispatch stay in the controller.
"""

from __future__ import annotations

import logging
from collections.abc import Callable

from app.config import MachineConfig
from app.drivers.contracts import MachineBackend, PendantDevice, WidthGauge
from app.machine.cycle import PlanSubmitter
from app.machine.manual_room import ManualRoom
from app.machine.planner.limits import MAX_OVERRIDE_PCT
from app.machine.preview import PlanPublisher
from app.machine.process_params import jog_speeds, stave_limits
from app.machine.refusals import Reason, refusal
from app.machine.states import Event, MachineState
from app.machine.store import MachineStore

log = logging.getLogger(__name__)

STOP_LOCKOUT_S = 0.5  # a second Stop within this time is ignored (docs/MACHINE.md section 6)


class OperatorRoom(ManualRoom):
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
        super().__init__(config, backend, gauge, store, wall_clock, submit, pendant)
        self.plans = PlanPublisher()
        self._last_stop_s = -1e9

    def power_up(self) -> None:
        super().power_up()
        self._publish_recipe_preview()

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
            width_mm = self.production.last_width_mm
            self.plans.recipe(self.recipe, self.params, limits, width_mm)
