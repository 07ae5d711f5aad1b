"""The main screen's barrel panel, operated as a person would: start a barrel, see it drawn
with what is left, answer the closing-stave question, in English and Slovenian."""

from __future__ import annotations

from app.geometry.barrel_section import BarrelSection
from app.machine.barrel_set import BarrelSet, BoardChoice
from app.machine.barrel_view import barrel_view
from tests.screens.helpers import find_button, wait_for


def test_start_a_barrel_and_answer_the_closing_question(qtbot, window, tap) -> None:
    main = window.page("main")
    panel = main.barrel_panel
    wait_for(qtbot, window, lambda s: s.recipe_name.startswith("Barrique"))
    assert panel.isVisibleTo(main)  # a barrel recipe: the panel offers to start one
    assert panel.staves_label.text() == "No barrel is being raised"
    tap(find_button(window, "startBarrelButton"))
    snapshot = wait_for(qtbot, window, lambda s: s.barrel is not None)
    number = snapshot.barrel.number
    assert panel.staves_label.text() == f"Barrel {number} · Staves: 0"
    assert panel.drawing.view == snapshot.barrel
    assert not panel.close_now_button.isVisibleTo(main)  # nothing to close yet

    # The question as the machine puts it once one stave closes the gap (a round 690 mm
    # barrel with 13 staves of 160 mm: what its view says, drawn by the same panel).
    barrel = BarrelSet(BarrelSection.circle(690.0), 75.0)
    for _ in range(13):
        barrel = barrel.with_stave(barrel.place(160.0))
    view = barrel_view(barrel, None, None)
    assert view.ask_closing
    panel.show_barrel(view, snapshot)
    assert panel.close_now_button.isVisibleTo(main) and panel.one_more_button.isVisibleTo(main)
    width = f"{view.closing_width_mm:.1f}"
    assert panel.question_label.text() == f"A stave of {width} mm closes it. Next board:"
    tap(panel.close_now_button)
    answered = wait_for(qtbot, window, lambda s: s.barrel.choice is BoardChoice.CLOSE_NOW)
    assert answered.barrel.choice is BoardChoice.CLOSE_NOW

    window.languages.set_language("sl")
    panel.show_barrel(barrel_view(barrel, None, answered.barrel.choice), answered)
    assert panel.close_now_button.text() == "Zapri sod zdaj"
    assert panel.close_now_button.isChecked()
