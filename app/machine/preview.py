"""The plan view's data: the stave outline and the tool path, in machine X/Y.

Computed in the machine process once per planned board (and for the selected recipe at a
nominal width, so the operator sees the stave before the first board is measured), and sent
to the screens with its id: the GUI draws without computing the geometry of the cut."""

from __future__ import annotations

from collections.abc import Mapping

from app.data.recipe import Recipe
from app.geometry.limits import StaveLimits
from app.geometry.outline import stave_drawing
from app.geometry.stave_cut import StaveCutRefused, cut_stave
from app.geometry.toolpath import ToolPath
from app.machine.cycle_plan import PlannedStave
from app.machine.snapshot import PlanPreview


def build_preview(plan_id: int, toolpath: ToolPath) -> PlanPreview:
    drawing = stave_drawing(toolpath)
    return PlanPreview(plan_id, drawing.outline_xy, drawing.toolpath_xy, drawing.cutting_mask)


def nominal_width_mm(recipe: Recipe, limits: StaveLimits, last_width_mm: float | None) -> float:
    """The board width a recipe is shown with before a board is measured: the last measured
    width, else a typical 150 mm raised until the head is wide enough, within the limits."""
    if last_width_mm is not None:
        return last_width_mm
    needed = limits.min_head_width_mm / max(recipe.width_ratio.value, 1e-9) + 1.0
    return min(limits.max_width_mm, max(150.0, needed))


def recipe_preview(
    plan_id: int,
    recipe: Recipe,
    params: Mapping[str, float],
    limits: StaveLimits,
    last_width_mm: float | None,
) -> PlanPreview | None:
    """The selected recipe drawn for its nominal width, or None when it cannot be cut at
    that width (the screens then show no stave until a board is measured)."""
    width_mm = nominal_width_mm(recipe, limits, last_width_mm)
    try:
        cut = cut_stave(recipe.stave, width_mm, params, limits)
    except StaveCutRefused:
        return None
    return build_preview(plan_id, cut.toolpath)


class PlanPublisher:
    """The one plan the screens may fetch, by id: the selected recipe's at its nominal width
    until a board is planned, then each planned board's, once."""

    def __init__(self) -> None:
        self.plan_id = 0
        self._plans: dict[int, PlanPreview] = {}
        self._published: PlannedStave | None = None

    def recipe(
        self,
        recipe: Recipe,
        params: Mapping[str, float],
        limits: StaveLimits,
        last_width_mm: float | None,
    ) -> None:
        preview = recipe_preview(self.plan_id + 1, recipe, params, limits, last_width_mm)
        if preview is not None:
            self._publish(preview)

    def board(self, planned: PlannedStave) -> None:
        """A planned board, published the first time only."""
        if planned is self._published:
            return
        self._published = planned
        self._publish(build_preview(self.plan_id + 1, planned.toolpath))

    def _publish(self, preview: PlanPreview) -> None:
        self.plan_id = preview.plan_id
        self._plans = {self.plan_id: preview}

    def get(self, plan_id: int) -> PlanPreview | None:
        return self._plans.get(plan_id)
