"""The main screen while the machine works, as the snapshot brings it: homing axis by axis,
the wait for the board apart, the board's width once measured, progress only along the path,
the distance to go and the path speed, and the feed override (steps and slider) that the
machine applies; all of it within 1024x768."""

from __future__ import annotations

from PySide6.QtCore import QRect, QSize, Qt
from PySide6.QtWidgets import QApplication, QPushButton

from app.geometry.barrel_section import BarrelSection
from app.machine.barrel_set import BarrelSet
from app.machine.barrel_view import barrel_view
from app.machine.commands import LoadBoard, SelectRecipe, StartBarrel
from app.machine.states import CycleStep, MachineState
from app.screens.formatting import format_duration
from app.screens.main_window import MainWindow
from app.screens.texts import step_text
from tests.screens.helpers import find_button, home_from_main_screen, wait_for
from tests.screens.test_layout import cut_texts

TOP_BAR_BUTTON_PX = 60
"""The top bar's buttons as touch targets of 60 px (50 today): the main screen keeps room."""


def _step(snapshot, step: CycleStep) -> bool:  # type: ignore[no-untyped-def]
    return snapshot.cycle.step is step


def start_with_barrel(qtbot, window: MainWindow, machine, database, tap) -> None:  # type: ignore[no-untyped-def]
    """Home, pick the first recipe (a barrel recipe: its panel shows), start a barrel and a
    cycle; the machine then waits for a board."""
    home_from_main_screen(qtbot, window, tap)
    recipe = database.list_recipes()[0]
    machine.send(SelectRecipe(recipe.id))
    wait_for(qtbot, window, lambda s: s.recipe_id == recipe.id and not s.allowed.get("Start"))
    if recipe.barrel_section is not None:
        machine.send(StartBarrel())
        wait_for(qtbot, window, lambda s: s.barrel is not None)
    tap(find_button(window, "startButton"))
    wait_for(qtbot, window, lambda s: s.state is MachineState.AUTOMATIC)


def test_homing_names_each_axis_as_it_homes(qtbot, window, tap) -> None:
    main = window.page("main")
    wait_for(qtbot, window, lambda s: not s.allowed.get("Home"))
    tap(find_button(window, "homeButton"))
    wait_for(qtbot, window, lambda s: s.homing is not None and s.homing.current == "Y")
    assert main.step_label.text() == "Homing axis Y"
    captions = [c.text() for c in (main.move_caption, main.phase_caption, main.speed_caption)]
    values = [v.text() for v in (main.move_label, main.phase_label, main.speed_label)]
    assert captions == ["Axis Z", "Axis Y", "Axis X"]
    assert values == ["homed ✓", "homing…", "waiting"]
    wait_for(qtbot, window, lambda s: s.state is MachineState.READY and s.homing is None)
    assert main.step_label.text() == "No cycle running"
    assert main.move_caption.text() == "Move to go" and main.move_label.text() == "—"


def test_waiting_cutting_and_the_last_cycle_as_the_operator_sees_them(
    qtbot, window, machine, database, tap
) -> None:
    main = window.page("main")
    start_with_barrel(qtbot, window, machine, database, tap)
    waiting = wait_for(qtbot, window, lambda s: s.cycle.waited_s >= 3.0)
    assert main.step_label.text() == "Waiting for a board"
    assert not main.progress.isVisible(), "a wait for a board has no length: no bar"
    assert main.elapsed_label.text() == "0:00" and main.remaining_label.text() == "—"
    assert main.waited_label.text() != "0:00"
    assert main.move_label.text() == "—" and main.speed_label.text() == "—"
    assert main.width_tile.caption_label.text() == "Last width"
    assert waiting.last_width_mm is None and main.width_tile.value_label.text() == "—"

    machine.send(LoadBoard(141.0))
    measured = wait_for(qtbot, window, lambda s: s.cycle.width_mm is not None)
    assert measured.pieces_total == 0
    assert main.width_tile.caption_label.text() == "Board width"
    assert main.width_tile.value_label.text() == f"{measured.cycle.width_mm:.1f} mm"

    wait_for(
        qtbot,
        window,
        lambda s: _step(s, CycleStep.CUTTING_A) and (s.cycle.path_velocity_mm_s or 0) > 10,
    )
    cutting = window.poller.snapshot  # the one the screen shows now
    assert main.progress.isVisible()
    assert main.progress.value() == round(1000 * cutting.cycle.progress)
    assert main.move_label.text() == f"{cutting.cycle.move_to_go_mm:.0f} mm"
    assert main.phase_label.text() == f"{cutting.cycle.phase_to_go_mm:.0f} mm"
    assert main.speed_label.text() == f"{cutting.cycle.path_velocity_mm_s:.0f} mm/s"
    assert main.feed_override.isVisible()

    done = wait_for(qtbot, window, lambda s: s.pieces_total == 1)
    assert done.last_wait_s is not None and done.last_wait_s >= 3.0
    assert done.last_work_time_s is not None
    assert main.cycle_time_tile.value_label.text() == format_duration(done.last_work_time_s)
    assert main.last_wait_label.text() == f"+{format_duration(done.last_wait_s)} waiting"
    assert main.width_tile.caption_label.text() == "Last width"


def test_the_feed_override_steps_and_slider_set_the_machines_override(
    qtbot, window, machine, database, tap
) -> None:
    main = window.page("main")
    override = main.feed_override
    home_from_main_screen(qtbot, window, tap)
    assert not override.isVisible(), "shown while a cycle runs"
    start_with_barrel(qtbot, window, machine, database, tap)
    wait_for(qtbot, window, lambda s: s.state is MachineState.AUTOMATIC)
    QApplication.processEvents()
    assert override.isVisible() and override.value_label.text() == "100 %"
    tap(override.minus_button)
    wait_for(qtbot, window, lambda s: s.feed_override_pct == 90.0)
    tap(override.minus_button)
    wait_for(qtbot, window, lambda s: s.feed_override_pct == 80.0)
    assert override.value_label.text() == "80 %" and override.slider.value() == 80
    override.slider.setValue(57)  # where a finger let the slider go
    wait_for(qtbot, window, lambda s: s.feed_override_pct == 57.0)
    for expected in (67.0, 77.0, 87.0, 97.0, 107.0, 117.0, 120.0):  # never beyond the top
        tap(override.plus_button)
        wait_for(qtbot, window, lambda s, pct=expected: s.feed_override_pct == pct)
    assert not override.plus_button.isEnabled()
    tap(override.full_button)
    wait_for(qtbot, window, lambda s: s.feed_override_pct == 100.0)
    # The machine cuts at it: a board at 50 % runs at half the path speed.
    override.slider.setValue(50)
    wait_for(qtbot, window, lambda s: s.feed_override_pct == 50.0)
    machine.send(LoadBoard())
    slow = wait_for(
        qtbot,
        window,
        lambda s: _step(s, CycleStep.CUTTING_A) and s.cycle.move_to_go_mm is not None,
    )
    assert slow.feed_override_pct == 50.0


def test_the_running_main_screen_fits_1024x768_in_both_languages(
    qtbot, window, machine, database, tap
) -> None:
    main = window.page("main")
    for button in window.top_bar.findChildren(QPushButton):
        button.setMinimumHeight(TOP_BAR_BUTTON_PX)
    start_with_barrel(qtbot, window, machine, database, tap)
    machine.send(LoadBoard())
    wait_for(qtbot, window, lambda s: _step(s, CycleStep.CUTTING_A))
    assert window.top_bar.height() >= TOP_BAR_BUTTON_PX
    for language in ("en", "sl"):
        window.languages.set_language(language)
        wait_for(qtbot, window, lambda s: _step(s, CycleStep.CUTTING_A))
        qtbot.wait(50)
        assert window.size() == QSize(1024, 768)
        assert main.barrel_panel.isVisible() and main.feed_override.isVisible()
        assert cut_texts(main) == [], language
        assert main.minimumSizeHint().height() <= main.height()
        # Every step the line can say, whole on its one line.
        step_texts = [step_text(step) for step in CycleStep] + [
            main.tr("Take the finished board off"),
            main.tr("No cycle running"),
            main.tr("Moving clear of the board"),
        ]
        metrics = main.step_label.fontMetrics()
        too_long = [t for t in step_texts if metrics.horizontalAdvance(t) > main.step_label.width()]
        assert too_long == [], language
        for label in (main.barrel_panel.gap_label, main.barrel_panel.left_label):
            assert label.sizeHint().height() <= label.height(), "a barrel line is clipped"
    # The closing question, as the machine puts it 13 staves into a round 690 mm barrel (its
    # view built by the machine layer's own function), with both answers whole in both
    # languages.
    window.poller.stop()
    shown = window.poller.snapshot
    barrel = BarrelSet(BarrelSection.circle(690.0), 75.0)
    for _ in range(13):
        barrel = barrel.with_stave(barrel.place(160.0))
    asking = barrel_view(barrel, None, None)
    assert asking.ask_closing
    for language in ("en", "sl"):
        window.languages.set_language(language)
        qtbot.wait(50)  # the tap on the language button is an event of its own
        main.barrel_panel.show_barrel(asking, shown)
        qtbot.wait(50)
        assert window.size() == QSize(1024, 768)
        assert main.barrel_panel.close_now_button.isVisible()
        assert cut_texts(main.barrel_panel) == [], language
        question = main.barrel_panel.question_label
        wrapped = question.fontMetrics().boundingRect(
            QRect(0, 0, question.width(), 1000), Qt.TextFlag.TextWordWrap, question.text()
        )
        lines = round(wrapped.height() / question.fontMetrics().height())
        assert lines <= question.lines, f"{language}: the question is cut"
    window.languages.set_language("en")
