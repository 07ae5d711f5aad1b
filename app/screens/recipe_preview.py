"""What the recipe screen previews for a chosen board width: the stave and its tool path.

Why computed in the GUI (and no Qt here): a preview is geometry only, solved in well under a
millisecond, and the operator wants it to follow every keypad entry; no motion is planned.
It is the machine's own composition (``cut_stave``: bevel, validation, profile, tool path and
travel check), so the editor cannot show a stave that the machine then refuses.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from app.data.recipe import Recipe
from app.geometry.limits import StaveLimits
from app.geometry.outline import stave_drawing
from app.geometry.stave_cut import StaveCutRefused, cut_stave
from app.screens.texts import rule_message

Point = tuple[float, float]


@dataclass(frozen=True)
class RecipePreview:
    """Outline and tool path in machine X/Y, the solved numbers, or why there are none."""

    width_mm: float
    outline: tuple[Point, ...] = ()
    toolpath: tuple[Point, ...] = ()
    cutting: tuple[bool, ...] = ()
    tilt_deg: float | None = None  # side A's bevel
    tilt_b_deg: float | None = None  # side B's (an oval barrel's differ)
    head_width_mm: float | None = None
    d_mm: float | None = None
    r_mm: float | None = None
    errors: tuple[str, ...] = field(default_factory=tuple)

    @property
    def ok(self) -> bool:
        return not self.errors


def preview_recipe(
    recipe: Recipe, width_mm: float, params: Mapping[str, float], limits: StaveLimits
) -> RecipePreview:
    """Solve ``recipe`` for a board of ``width_mm``; never raises for bad input (the reasons
    are in ``errors``, one line each in the user's language, saying the value and what is
    allowed)."""
    try:
        cut = cut_stave(recipe.stave, width_mm, params, limits)
    except StaveCutRefused as exc:
        tilts = exc.tilts
        return RecipePreview(
            width_mm,
            tilt_deg=None if tilts is None else tilts.a_deg,
            tilt_b_deg=None if tilts is None else tilts.b_deg,
            errors=tuple(rule_message(e) for e in exc.errors),  # in words, translated
        )
    drawing = stave_drawing(cut.toolpath)
    return RecipePreview(
        width_mm=width_mm,
        outline=drawing.outline_xy,
        toolpath=drawing.toolpath_xy,
        cutting=drawing.cutting_mask,
        tilt_deg=cut.tilts.a_deg,
        tilt_b_deg=cut.tilts.b_deg,
        head_width_mm=cut.profile.W1,
        d_mm=cut.profile.D,
        r_mm=cut.profile.R,
    )
