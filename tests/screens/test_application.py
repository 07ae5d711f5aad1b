"""The application entry points: kiosk window, refresh rate, a dead machine, screenshots."""

from __future__ import annotations

from datetime import UTC, datetime, timedelta

from PySide6.QtCore import QCoreApplication, QEvent, Qt
from PySide6.QtGui import QImage

from app.data.records import PieceResult
from app.screens.application import create_main_window
from app.screens.main_window import SCREEN_KEYS, MainWindow
from app.screens.poller import REFRESH_HZ
from app.screens.screenshots import render_screenshots
from app.screens.widgets.dialogs import ConfirmOverlay


def test_kiosk_window_is_frameless_and_closes_only_through_shut_down(
    qtbot, machine, database
) -> None:
    window = create_main_window(machine, database, kiosk=True)
    assert isinstance(window, MainWindow)
    qtbot.addWidget(window)
    assert window.windowFlags() & Qt.WindowType.FramelessWindowHint
    window.show()
    window.close()  # Alt+F4 or a window manager: refused, the confirmation opens instead
    assert window.isVisible()
    overlay = window.overlay()
    assert isinstance(overlay, ConfirmOverlay)
    with qtbot.waitSignal(window.shutdownRequested):
        overlay.accept()
    assert not window.isVisible()
    assert not machine.alive()


def test_the_screens_refresh_at_least_20_times_a_second() -> None:
    assert REFRESH_HZ >= 20


def test_a_dead_machine_is_shown(qtbot, window, machine) -> None:
    machine.close()
    qtbot.waitUntil(lambda: window.poller.lost, timeout=5000)
    assert window.top_bar.state_label.text() == "NO MACHINE"
    assert window.top_bar.message_label.text() == "The machine is not running."


def test_screenshots_of_every_screen_in_a_realistic_state(
    qtbot, machine, database, tmp_path
) -> None:
    files = render_screenshots(tmp_path / "shots", (1024, 768), machine, database)
    names = [f.name for f in files]
    assert names == [
        "01-main-running.png",
        "02-recipes.png",
        "03-recipes-keypad.png",
        "04-system.png",
        "05-main-alarm.png",
        "06-alarms.png",
        "07-manual.png",
        "08-recipes-drawn-profile.png",
        "09-io.png",
        "10-system-opcua.png",
        "11-system-limits.png",
        "12-alarm-detail.png",
        "13-system-simulation.png",
        "14-production.png",
        "15-recipes-search.png",
        "16-main-recipe-chooser.png",
        "17-main-closing-question.png",
        "18-main-barrel-drawing.png",
    ]
    shown = {name.split("-", 1)[1].split("-")[0].removesuffix(".png") for name in names}
    assert set(SCREEN_KEYS) <= shown
    for path in files:
        image = QImage(str(path))
        assert (image.width(), image.height()) == (1024, 768), path.name
    snapshot = machine.latest()
    assert snapshot is not None and snapshot.pieces_total >= 1  # a board was really cut
    # The Production picture shows a shift of simulated history, not empty charts.
    now = datetime.now(UTC)
    history = database.list_production(now - timedelta(days=2), now)
    assert sum(r.result is PieceResult.OK for r in history) > 500
    assert {r.alarm_code for r in history} >= {"E032"}


def test_service_user_leaves_the_kiosk_with_exit_status_64(qtbot, machine, database, tap) -> None:
    window = create_main_window(machine, database, kiosk=True)
    assert isinstance(window, MainWindow)
    try:
        _leave_the_kiosk(qtbot, window, machine, tap)
    finally:
        # Destroy it now: a shut-down window left for later would still receive the next
        # test's language change and read its closed database.
        window.deleteLater()
        QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete.value)


def _leave_the_kiosk(qtbot, window, machine, tap) -> None:  # type: ignore[no-untyped-def]
    from app.screens.main_window import EXIT_LEAVE_KIOSK
    from app.screens.widgets.dialogs import ChoiceOverlay
    from tests.screens.helpers import enter_pin, find_button, open_pin_pad

    window.show()
    open_pin_pad(qtbot, window, tap)
    enter_pin(qtbot, window, tap, "1234")  # a technician is offered only Log out
    tap(window.top_bar.user_button)
    assert isinstance(window.overlay(), ConfirmOverlay)
    window.overlay().reject()
    window.session.logout()
    open_pin_pad(qtbot, window, tap)
    enter_pin(qtbot, window, tap, "9999")  # service
    tap(window.top_bar.user_button)
    choice = window.overlay()
    assert isinstance(choice, ChoiceOverlay)
    tap(find_button(choice, "choice_1"))  # Leave the kiosk
    confirm = window.overlay()
    assert isinstance(confirm, ConfirmOverlay)
    with qtbot.waitSignal(window.shutdownRequested):
        confirm.accept()
    assert window.exit_code == EXIT_LEAVE_KIOSK == 64
    assert not machine.alive()
