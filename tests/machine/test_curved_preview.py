"""The main screen's plan view data for a curved profile: the machine sends the fitted outline
and tool path of the selected recipe (the same stave_drawing the recipe screen draws)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from app.data.recipe_profile import RecipeProfile
from app.geometry.profile_kinds import ProfileKind
from app.machine import commands as cmd
from tests.machine.conftest import BARRIQUE, Rig


def test_selected_parabola_recipe_is_previewed_on_its_curve(rig: Rig) -> None:
    base = rig.controller.store.recipe_by_name(BARRIQUE)
    assert base is not None
    parabola = rig.controller.store.save_recipe(
        replace(
            base, id=None, name="Barrique parabola", profile=RecipeProfile(ProfileKind.PARABOLA)
        )
    )
    assert parabola.id is not None
    rig.send(cmd.SelectRecipe(parabola.id))
    snapshot = rig.controller.snapshot()
    preview = rig.controller.plan_preview(snapshot.plan_id)
    assert preview is not None
    outline = np.array(preview.outline_xy)
    x0 = outline[:, 0].min()
    centre_y = (outline[:, 1].max() + outline[:, 1].min()) / 2
    side_a = outline[outline[:, 1] > centre_y]
    x = side_a[:, 0] - x0
    half = side_a[:, 1] - centre_y
    length = base.length_mm
    belly, head = half.max(), half[np.argmin(x)]
    u = (x - length / 2) / (length / 2)
    expected = head + (belly - head) * (1 - u * u)
    assert np.abs(half - expected).max() < 0.01
    assert len(preview.toolpath_xy) > 20 and any(preview.cutting_mask)
