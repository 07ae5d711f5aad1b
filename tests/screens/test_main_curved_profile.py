"""Main screen: a recipe with a curved side profile, cut as the operator would, and the plan
view drawing the fitted curve and its tool path while the cutter is on side A."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from app.data.recipe_profile import RecipeProfile
from app.data.users import Role
from app.geometry.profile_kinds import ProfileKind
from app.screens.recipe_chooser import RecipeChooser
from tests.screens.helpers import find_button, home_from_main_screen, wait_for


def test_plan_view_draws_the_parabola_while_cutting(qtbot, window, database, tap) -> None:
    base = database.list_recipes()[0]
    service = next(u for u in database.list_users() if u.role is Role.SERVICE)
    parabola = database.save_recipe(
        replace(base, id=None, name="Parabola side", profile=RecipeProfile(ProfileKind.PARABOLA)),
        service,
    )
    main = window.page("main")
    home_from_main_screen(qtbot, window, tap)
    tap(find_button(window, "recipeList"))
    overlay = window.overlay()
    assert isinstance(overlay, RecipeChooser)
    tap(find_button(overlay, f"chooseRecipe_{parabola.id}"))
    wait_for(qtbot, window, lambda s: s.recipe_id == parabola.id)
    start = find_button(window, "startButton")
    wait_for(qtbot, window, lambda s: not s.allowed.get("Start"))
    tap(start)
    wait_for(qtbot, window, lambda s: s.cycle.step is not None)
    tap(find_button(window, "loadBoardButton"))
    running = wait_for(
        qtbot, window, lambda s: s.cycle.step is not None and s.cycle.step.name == "CUTTING_A"
    )
    qtbot.waitUntil(lambda: main.plan_view.plan_id == running.plan_id, timeout=5000)

    xs, ys = main.plan_view.outline_item.getData()
    outline = np.column_stack([xs, ys])
    outline = outline[np.isfinite(outline).all(axis=1)]
    x0 = outline[:, 0].min()
    centre_y = (outline[:, 1].max() + outline[:, 1].min()) / 2
    side_a = outline[outline[:, 1] > centre_y]
    x, half = side_a[:, 0] - x0, side_a[:, 1] - centre_y
    belly, head = half.max(), half[np.argmin(x)]
    u = (x - base.length_mm / 2) / (base.length_mm / 2)
    assert len(side_a) > 50  # a drawn curve, not a line-arc-line's few points
    assert np.abs(half - (head + (belly - head) * (1 - u * u))).max() < 0.01
    cut_x, cut_y = main.plan_view.cut_item.getData()
    cut = np.column_stack([cut_x, cut_y])
    cut = cut[np.isfinite(cut).all(axis=1)]
    assert cut[:, 0].min() < x0 < x0 + base.length_mm < cut[:, 0].max()  # leads beyond heads
    # Over the board, side A's cutter centre keeps one height from the parabola (the offset
    # r/cos(tilt) along a normal that turns by at most 4 deg here, and the pivot shift): a
    # line-arc-line's path would stray from it by a millimetre and more.
    over = cut[(cut[:, 1] > centre_y) & (cut[:, 0] > x0) & (cut[:, 0] < x0 + base.length_mm)]
    assert len(over) >= 6
    v = (over[:, 0] - x0 - base.length_mm / 2) / (base.length_mm / 2)
    gap = over[:, 1] - centre_y - (head + (belly - head) * (1 - v * v))
    assert np.ptp(gap) < 0.2
    tap(find_button(window, "stopButton"))
