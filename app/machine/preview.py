"""The plan view's data: the stave outline and the tool path, in machine X/Y.

Computed once per planned board in the machine process and sent to the screens with its id,
so the GUI draws without computing any geometry of the cut itself."""

from __future__ import annotations

from app.geometry.outline import stave_outline
from app.machine.cycle_plan import PlannedStave
from app.machine.snapshot import PlanPreview

PREVIEW_CHORD_MM = 0.2  # plenty for a drawing a few hundred pixels wide


def build_preview(plan_id: int, planned: PlannedStave) -> PlanPreview:
    params = planned.toolpath.params
    outline = stave_outline(planned.profile, (params.start_x_mm, params.start_y_mm))
    polyline = planned.toolpath.to_polyline(PREVIEW_CHORD_MM)
    return PlanPreview(
        plan_id=plan_id,
        outline_xy=tuple(outline),
        toolpath_xy=tuple((p[0], p[1]) for p in polyline),
        cutting_mask=tuple(bool(p[3]) for p in polyline),
    )
