"""The main screen's barrel panel, operated as a person would: start a barrel, see it drawn
with what is left, answer the closing-stave question, in English and Slovenian."""

from __future__ import annotations

from PySide6.QtCore import Qt

from app.geometry.barrel_section import BarrelSection
from app.machine.barrel_set import BarrelSet, BoardChoice
from app.machine.barrel_view import barrel_view
from app.screens.barrel_overlay import BarrelOverlay
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


def test_a_tap_on_the_drawing_shows_the_barrel_big_and_it_follows_the_machine(
    qtbot, window, tap
) -> None:
    main = window.page("main")
    panel = main.barrel_panel
    wait_for(qtbot, window, lambda s: s.recipe_name.startswith("Barrique"))
    panel.drawing.tapped.emit()  # no barrel yet: nothing to enlarge
    assert window.overlay() is None
    tap(find_button(window, "startBarrelButton"))
    snapshot = wait_for(qtbot, window, lambda s: s.barrel is not None)
    qtbot.mouseClick(panel.drawing, Qt.MouseButton.LeftButton)  # a finger on the drawing
    overlay = window.overlay()
    assert isinstance(overlay, BarrelOverlay) and overlay is panel.big_drawing
    assert overlay.drawing.view == snapshot.barrel
    assert overlay.drawing.width() > 3 * panel.drawing.width()
    assert overlay.title_label.text() == f"Barrel {snapshot.barrel.number} · Staves: 0 · " + (
        "The next board is stave 1."
    )
    barrel = BarrelSet(BarrelSection.circle(690.0), 75.0)
    for _ in range(5):
        barrel = barrel.with_stave(barrel.place(160.0))
    view = barrel_view(barrel, None, None)
    panel.show_barrel(view, snapshot)  # the machine's next view reaches the big drawing
    assert overlay.drawing.view == view and "Staves: 5 · Gap " in overlay.title_label.text()
    tap(overlay.close_button)
    assert window.overlay() is None and panel.big_drawing is None
    panel.show_barrel(view, snapshot)  # closed: nothing is drawn for it any more
