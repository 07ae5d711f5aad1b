"""Main screen, operated as a person would: pick a recipe, press Start, put a board in, watch
a whole simulated cycle finish and the counter rise."""

from __future__ import annotations

from dataclasses import replace
from datetime import UTC, datetime

from app.machine.states import MachineState
from app.screens.recipe_chooser import RecipeChooser
from app.screens.widgets.dialogs import ChoiceOverlay, ConfirmOverlay
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.lamp import LampColor
from tests.screens.helpers import WAIT_MS, find_button, home_from_main_screen, wait_for


def test_start_is_refused_with_a_reason_until_homed(window) -> None:
    snapshot = window.poller.snapshot
    start = find_button(window, "startButton")
    if not snapshot.all_homed:
        assert not start.isEnabled()
        assert start.toolTip()  # says why
        main = window.page("main")
        assert main.hint_label.text() == start.toolTip()
        for axis in ("X", "Y"):
            if not snapshot.axis(axis).homed:
                readout = getattr(main, f"axis_{axis.lower()}")
                assert readout.value_label.property("homed") == "false"
                assert readout.tag_label.isVisibleTo(main)


def test_pick_a_recipe_start_and_watch_a_whole_cycle(qtbot, window, database, tap) -> None:
    main = window.page("main")
    home_from_main_screen(qtbot, window, tap)
    recipes = database.list_recipes()
    assert len(recipes) >= 2
    for readout in (main.axis_x, main.axis_y, main.axis_z):
        assert readout.value_label.property("homed") == "true"

    # Pick the second recipe from the list.
    tap(find_button(window, "recipeList"))
    overlay = window.overlay()
    assert isinstance(overlay, RecipeChooser)
    tap(overlay.buttons[1])
    wait_for(qtbot, window, lambda s: s.recipe_id == recipes[1].id)
    assert main.number_label.text() == f"No. {recipes[1].id}"
    assert main.name_label.text() == recipes[1].name
    # Next and previous step through the list.
    tap(find_button(window, "nextRecipe"))
    expected = recipes[2 % len(recipes)].id
    wait_for(qtbot, window, lambda s: s.recipe_id == expected)
    tap(find_button(window, "prevRecipe"))
    wait_for(qtbot, window, lambda s: s.recipe_id == recipes[1].id)

    before = window.poller.snapshot
    assert before.state is MachineState.READY
    start = find_button(window, "startButton")
    wait_for(qtbot, window, lambda s: not s.allowed.get("Start"))
    tap(start)
    wait_for(qtbot, window, lambda s: s.state is MachineState.AUTOMATIC)
    assert window.top_bar.lamp.color is LampColor.GREEN
    assert not start.isEnabled() and find_button(window, "stopButton").isEnabled()
    assert main.step_label.text() == "Waiting for a board"
    tap(find_button(window, "loadBoardButton"))  # the simulated operator's hands

    running = wait_for(
        qtbot, window, lambda s: s.cycle.step is not None and s.cycle.step.name == "CUTTING_A"
    )
    assert main.plan_view.plan_id == running.plan_id > 0  # the live plan is drawn
    assert main.elapsed_label.text() != "—" and main.remaining_label.text() != "—"
    finished = wait_for(qtbot, window, lambda s: s.pieces_shift == before.pieces_shift + 1)
    assert finished.pieces_total == before.pieces_total + 1
    assert main.shift_tile.value_label.text() == str(before.pieces_shift + 1)
    assert main.total_tile.value_label.text() == str(before.pieces_total + 1)
    assert main.width_tile.value_label.text().endswith("mm")
    assert ":" in main.cycle_time_tile.value_label.text()
    # The bar shows the machine's step times of that cycle, as the snapshot brought them.
    qtbot.waitUntil(lambda: main.step_times_bar.steps != (), timeout=5000)
    shown = dict(main.step_times_bar.steps)
    assert shown == {k: v for k, v in window.poller.snapshot.last_step_times_s if v > 0}
    assert shown["side_a"] > 0 and "Side A" in main.step_times_bar.toolTip()

    # The finished board is still on the table: the next Start asks for it to be taken off,
    # and the simulated operator's hands replace it.
    tap(start)
    wait_for(qtbot, window, lambda s: s.cycle.finished_board_on_table)
    assert main.step_label.text() == "Take the finished board off"
    load = find_button(window, "loadBoardButton")
    assert load.isEnabled() and load.text().startswith("Replace the board")
    tap(load)
    wait_for(qtbot, window, lambda s: s.cycle.step is not None and s.cycle.step.name == "CENTERING")
    tap(find_button(window, "stopButton"))


def stop_in_side_a(qtbot, window, database, tap) -> None:
    """Home, pick the first recipe, Start, put a board in, and tap STOP while side A is cut."""
    home_from_main_screen(qtbot, window, tap)
    recipe_id = database.list_recipes()[0].id
    tap(find_button(window, "recipeList"))
    tap(window.overlay().buttons[0])
    wait_for(qtbot, window, lambda s: s.recipe_id == recipe_id and not s.allowed.get("Start"))
    tap(find_button(window, "startButton"))
    wait_for(qtbot, window, lambda s: s.state is MachineState.AUTOMATIC)
    tap(find_button(window, "loadBoardButton"))
    wait_for(qtbot, window, lambda s: s.cycle.step is not None and s.cycle.step.name == "CUTTING_A")
    tap(find_button(window, "stopButton"))


def test_stop_stops_a_running_cycle(qtbot, window, database, tap) -> None:
    stop_in_side_a(qtbot, window, database, tap)
    wait_for(qtbot, window, lambda s: s.state is not MachineState.AUTOMATIC)
    stopped = wait_for(qtbot, window, lambda s: s.state is not MachineState.STOPPING)
    assert stopped.pieces_shift == 0


def test_start_after_a_stop_offers_resume_or_abandon(qtbot, window, database, tap) -> None:
    stop_in_side_a(qtbot, window, database, tap)
    stopped = wait_for(qtbot, window, lambda s: s.state is MachineState.READY)
    assert "partly cut" in str(stopped.allowed["Start"])
    assert window.page("main").hint_label.text() == str(stopped.allowed["Start"])
    start = find_button(window, "startButton")
    assert start.isEnabled(), "Start offers what can be done with the board"
    tap(start)
    overlay = window.overlay()
    assert isinstance(overlay, ChoiceOverlay)
    assert [b.text() for b in overlay.buttons] == ["Resume the cut", "Abandon the board"]
    tap(overlay.buttons[0])
    wait_for(qtbot, window, lambda s: s.state is MachineState.AUTOMATIC)
    done = wait_for(qtbot, window, lambda s: s.pieces_shift == 1)
    assert "Resume" in done.allowed and str(done.allowed["Resume"]) == "no board is partly cut"


def test_new_shift_asks_first(qtbot, window, tap) -> None:
    tap(find_button(window, "resetShiftButton"))
    overlay = window.overlay()
    assert isinstance(overlay, ConfirmOverlay)
    tap(overlay.cancel_button)
    assert window.overlay() is None


def test_a_new_shift_asks_its_operator_for_his_name_and_records_name_him(
    qtbot, window, database, tap
) -> None:
    """The last shift's operator is cleared at New shift; the new one names himself, and the
    boards cut in his shift carry his name, also while a technician is logged in."""
    window.session.name_operator("ana")
    tap(find_button(window, "resetShiftButton"))
    tap(window.overlay().confirm_button)
    keyboard = window.overlay()
    assert isinstance(keyboard, TextKeyboard)
    assert keyboard.text == "" and window.session.operator_name == ""
    for char in "marko":
        tap(find_button(keyboard, f"key_{char}"))
    tap(find_button(keyboard, "okButton"))
    assert window.overlay() is None and window.session.operator_name == "marko"
    window.session.set_user(window.database.authenticate("1234"))  # a technician steps in
    stop_in_side_a(qtbot, window, database, tap)
    wait_for(qtbot, window, lambda s: s.state is MachineState.READY)
    tap(find_button(window, "startButton"))
    tap(window.overlay().buttons[1])  # Abandon the board: recorded as aborted
    everything = (datetime(2000, 1, 1, tzinfo=UTC), datetime(2100, 1, 1, tzinfo=UTC))
    qtbot.waitUntil(lambda: bool(database.list_production(*everything)), timeout=WAIT_MS)
    records = database.list_production(*everything)
    assert [(r.result.value, r.operator_name) for r in records] == [("aborted", "marko")]
    window.session.logout()


def test_new_shift_cancelled_at_the_name_leaves_no_name(qtbot, window, tap) -> None:
    window.session.name_operator("ana")
    tap(find_button(window, "resetShiftButton"))
    tap(window.overlay().confirm_button)
    tap(find_button(window.overlay(), "cancelButton"))
    assert window.overlay() is None
    assert window.session.operator_name == "" and window.session.name == "operator"


def test_the_plans_next_shift_asks_the_new_operator_once(qtbot, window, tap) -> None:
    """When the machine says the shift plan's next shift began, the last operator's name
    goes and the new operator is asked his; the same count again asks nothing."""
    window.session.name_operator("ana")
    snapshot = wait_for(qtbot, window, lambda s: True)
    window.poller.stop()  # only the snapshots below reach the window
    next_shift = replace(snapshot, plan_shifts_begun=snapshot.plan_shifts_begun + 1)
    window.on_snapshot(next_shift)
    keyboard = window.overlay()
    assert isinstance(keyboard, TextKeyboard) and keyboard.text == ""
    assert window.session.operator_name == ""
    window.on_snapshot(next_shift)  # the same shift: no second keyboard
    assert window.overlay() is keyboard
    for char in "marko":
        tap(find_button(keyboard, f"key_{char}"))
    tap(find_button(keyboard, "okButton"))
    assert window.overlay() is None and window.session.operator_name == "marko"
    window.on_snapshot(next_shift)
    assert window.overlay() is None


def test_shut_down_asks_then_closes_the_link(qtbot, window, machine, tap) -> None:
    tap(find_button(window, "nav_shutdown"))
    overlay = window.overlay()
    assert isinstance(overlay, ConfirmOverlay)
    tap(overlay.cancel_button)
    assert machine.alive()
    tap(find_button(window, "nav_shutdown"))
    with qtbot.waitSignal(window.shutdownRequested):
        tap(window.overlay().confirm_button)
    assert not machine.alive()
