"""Manual (hold and release a jog button, step jog), Alarms (acknowledge, reset, history),
System (PIN lock, a logged change) and the language switch, operated as a person would."""

from __future__ import annotations

import sqlite3
from contextlib import closing
from datetime import UTC, datetime, timedelta

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton

from app.data.database import Database
from app.data.records import AlarmState as AlarmRecordState
from app.data.records import format_utc
from app.data.users import Role
from app.machine.commands import InjectFault
from app.machine.snapshot import AlarmState
from app.machine.states import MachineState
from app.screens.alarm_detail import AlarmDetailOverlay
from app.screens.texts import alarm_help, alarm_line, machine_text
from app.screens.widgets.dialogs import ChoiceOverlay, ConfirmOverlay
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.keypad import KeypadMode
from tests.screens.helpers import enter_pin, find_button, is_keypad, open_pin_pad, wait_for


def keys(tap, overlay, text: str) -> None:
    for key in text:
        tap(find_button(overlay, f"key_{key}"))


def log_in(qtbot, window, tap, pin: str) -> None:
    open_pin_pad(qtbot, window, tap)
    assert is_keypad(window.overlay(), KeypadMode.PIN)
    enter_pin(qtbot, window, tap, pin)
    assert window.overlay() is None


# -- manual ----------------------------------------------------------------------------------


def open_manual(qtbot, window, tap):
    tap(find_button(window, "nav_manual"))
    return wait_for(qtbot, window, lambda s: s.state is MachineState.MANUAL)


def test_hold_and_release_a_jog_button(qtbot, window, machine, tap) -> None:
    start = open_manual(qtbot, window, tap)
    # Machine time at about real time, so the hold's refresh (every 0.1 s of wall time)
    # is what keeps the jog alive against the machine's dead-man timer.
    machine.advance_per_poll_s = 0.002
    window.poller.set_interval_ms(2)
    button = find_button(window, "jog_Xplus")
    wait_for(qtbot, window, lambda s: not s.allowed.get("JogContinuous"))
    x0 = start.axis("X").position
    qtbot.mousePress(button, Qt.MouseButton.LeftButton)
    assert button.held
    held = wait_for(qtbot, window, lambda s: s.axis("X").position > x0 + 2.0)
    assert not any(a.code == "W101" for a in held.alarms), "the refresh kept the jog alive"
    qtbot.mouseRelease(button, Qt.MouseButton.LeftButton)
    assert not button.held
    released_at = window.poller.snapshot.machine_time_s
    settled = wait_for(qtbot, window, lambda s: s.machine_time_s > released_at + 1.0)
    x_stop = settled.axis("X").position
    later = wait_for(qtbot, window, lambda s: s.machine_time_s > settled.machine_time_s + 0.5)
    assert later.axis("X").position == pytest.approx(x_stop, abs=0.01), "stopped on release"
    assert not any(a.code == "W101" for a in later.alarms)


def test_spindle_on_by_hand_asks_first(qtbot, window, tap) -> None:
    open_manual(qtbot, window, tap)
    spindle = find_button(window, "spindleButton")
    wait_for(qtbot, window, lambda s: not s.allowed.get("SpindleOn"))
    tap(spindle)
    question = window.overlay()
    assert isinstance(question, ConfirmOverlay)
    assert not window.poller.snapshot.outputs.spindle_on  # nothing turns before the answer
    tap(question.confirm_button)
    wait_for(qtbot, window, lambda s: s.outputs.spindle_on)
    tap(spindle)  # off at once
    wait_for(qtbot, window, lambda s: not s.outputs.spindle_on)


def test_step_jog_moves_by_the_step(qtbot, window, tap) -> None:
    start = open_manual(qtbot, window, tap)
    tap(find_button(window, "stepMode"))
    tap(find_button(window, "step_10"))
    wait_for(qtbot, window, lambda s: not s.allowed.get("JogStep"))
    y0 = start.axis("Y").position
    tap(find_button(window, "jog_Yplus"))
    wait_for(qtbot, window, lambda s: abs(s.axis("Y").position - (y0 + 10.0)) < 0.01)
    z0 = start.axis("Z").position
    tap(find_button(window, "jog_Zplus"))  # the tilt steps at most 1 degree
    wait_for(qtbot, window, lambda s: abs(s.axis("Z").position - (z0 + 1.0)) < 0.01)


def test_jog_speed_set_on_the_keypad(qtbot, window, tap) -> None:
    open_manual(qtbot, window, tap)
    tap(find_button(window, "jogXYSpeed"))
    keypad = window.overlay()
    assert is_keypad(keypad, KeypadMode.NUMBER)
    keys(tap, keypad, "42")
    tap(find_button(keypad, "okButton"))
    wait_for(qtbot, window, lambda s: s.jog_xy[0] == 42.0)


def test_leaving_the_manual_screen_leaves_manual_mode(qtbot, window, tap) -> None:
    open_manual(qtbot, window, tap)
    tap(find_button(window, "nav_main"))
    wait_for(qtbot, window, lambda s: s.state is not MachineState.MANUAL)


# -- alarms ----------------------------------------------------------------------------------


def test_acknowledge_an_alarm_and_reset(qtbot, window, database, tap) -> None:
    log_in(qtbot, window, tap, "1234")
    assert window.session.role is Role.TECHNICIAN
    tap(find_button(window, "nav_system"))
    tap(find_button(window, "group_simulation"))
    tap(find_button(window, "inject_drive_fault"))
    alarmed = wait_for(qtbot, window, lambda s: bool(s.alarms) and s.state is MachineState.ERROR)
    alarm = alarmed.alarms[0]
    assert window.banner.isVisible() and alarm.code in window.banner.text()
    assert f"axis {alarm.source}," in window.banner.text()  # the banner names the axis
    assert window.banner.property("severity") == "fault"
    # The Manual screen says on screen, under the control, why it is refused.
    manual = window.page("manual")
    manual.update_snapshot(alarmed)
    assert machine_text(alarmed.allowed["Home"]) in manual.reason_label.text()
    assert manual.reason_label.isVisibleTo(manual) and manual.reason_label.text()

    tap(window.banner)  # the banner leads to the Alarms screen
    screen = window.page("alarms")
    assert window.current_screen is screen
    assert screen.active_table.rowCount() == len(alarmed.alarms)
    assert screen.ack_button(alarm.alarm_id) is not None
    # Tapping the row opens the whole alarm; it is acknowledged from there.
    table = screen.active_table
    cell = table.visualItemRect(table.item(0, 2)).center()
    qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton, pos=cell)
    detail = window.overlay()
    assert isinstance(detail, AlarmDetailOverlay)
    help_ = alarm_help(alarm.code)
    assert help_ is not None and detail.remedy_label.text() == help_.remedy
    assert all(cause in detail.causes_label.text() for cause in help_.causes)
    assert f"axis {alarm.source}, fault code 0x" in detail.found_label.text()
    tap(detail.ack_button)
    wait_for(
        qtbot,
        window,
        lambda s: all(
            a.state is not AlarmState.ACTIVE_UNACKED
            for a in s.alarms
            if a.alarm_id == alarm.alarm_id
        ),
    )
    assert screen.ack_button(alarm.alarm_id) is None

    tap(find_button(window, "nav_system"))
    tap(find_button(window, "clearFaults"))
    tap(find_button(window, "nav_alarms"))
    wait_for(qtbot, window, lambda s: not s.allowed.get("Reset"))
    tap(find_button(window, "alarmsResetButton"))
    wait_for(qtbot, window, lambda s: s.state is not MachineState.ERROR)
    if window.poller.snapshot.unacknowledged_alarms:
        tap(find_button(window, "ackAllButton"))
    wait_for(qtbot, window, lambda s: not s.alarms)
    assert not window.banner.isVisible()
    screen.refresh_history()
    assert screen.history_count >= 2  # raised, acknowledged, ... each a row
    codes = {screen.history_table.item(r, 1).text() for r in range(screen.history_count)}
    assert alarm.code in codes
    tap(find_button(window, "period_hour"))
    tap(find_button(window, "sourceFilter"))
    choice = window.overlay()
    assert isinstance(choice, ChoiceOverlay)
    tap(next(b for b in choice.buttons if b.text() == alarm.source))
    assert screen.history_count >= 1
    assert all(
        screen.history_table.item(r, 3).text() == alarm.source for r in range(screen.history_count)
    )
    # A history row opens the same view: the occurrence's times, and who acknowledged it.
    old_detail = screen.open_history(screen.history_count - 1)
    assert old_detail is not None and window.overlay() is old_detail
    assert window.session.name in old_detail.history_label.text()
    tap(old_detail.close_button)
    window.session.logout()


def test_the_operator_names_himself_and_is_recorded(qtbot, window, database, tap) -> None:
    """No PIN at operator level: the operator of the shift names himself, and his
    acknowledgement is stored with that name (it was stored with none)."""
    tap(window.top_bar.user_button)
    choice = window.overlay()
    assert isinstance(choice, ChoiceOverlay)
    tap(find_button(choice, "choice_1"))  # Name the operator of this shift
    keyboard = window.overlay()
    assert isinstance(keyboard, TextKeyboard)
    keys(tap, keyboard, "ana")
    tap(find_button(keyboard, "okButton"))
    assert window.overlay() is None
    assert window.session.name == "ana" and "ana" in window.top_bar.user_button.text()
    window.link.send(InjectFault("drive_fault", "X"))  # the simulation menu's fault
    alarmed = wait_for(qtbot, window, lambda s: bool(s.alarms))
    window.show_screen("alarms")
    ack = window.page("alarms").ack_button(alarmed.alarms[0].alarm_id)
    assert ack is not None
    tap(ack)
    wait_for(qtbot, window, lambda s: s.unacknowledged_alarms == 0)
    acks = [
        e
        for e in database.list_alarm_events()
        if e.to_state.value in ("active_acked", "normal") and e.from_state.value != "normal"
    ]
    assert acks and {e.user_name for e in acks} == {"ana"}


# -- system ----------------------------------------------------------------------------------


def test_system_is_locked_until_a_technician_pin(qtbot, window, database, tap) -> None:
    tap(find_button(window, "nav_system"))
    screen = window.page("system")
    assert screen.body.currentWidget() is screen.locked_page
    tap(find_button(window, "unlockButton"))
    pad = window.overlay()
    enter_pin(qtbot, window, tap, "0000")
    assert pad.is_open and "Technician" in pad.error_label.text()
    enter_pin(qtbot, window, tap, "1234")
    assert not pad.is_open
    assert screen.body.currentWidget() is screen.settings_page

    tap(find_button(window, "group_tool"))
    assert not find_button(window, "param_machine_height_mm").isEnabled()  # service only
    tap(find_button(window, "param_tool_radius_mm"))
    keypad = window.overlay()
    assert is_keypad(keypad, KeypadMode.NUMBER)
    keys(tap, keypad, "500")
    tap(find_button(keypad, "okButton"))
    assert keypad.is_open  # the catalogue allows 1 to 150 mm
    tap(find_button(keypad, "key_clear"))
    keys(tap, keypad, "30")
    tap(find_button(keypad, "okButton"))
    assert database.get_parameter("tool_radius_mm") == 30.0
    change = database.parameter_history(name="tool_radius_mm")[0]
    assert change.new_value == 30.0 and change.user_name == "technician"
    assert find_button(window, "param_tool_radius_mm").text() == "30 mm"
    assert window.findChild(QPushButton, "param_solver_tolerance_mm") is None  # never read
    tap(find_button(window, "group_limits"))  # what the machine enforces, read-only
    limits = database.limits
    for name, shown in (("x_max_mm", limits.x_max_mm), ("z_min_deg", limits.z_min_deg)):
        button = find_button(window, f"param_{name}")
        assert not button.isEnabled() and button.text().startswith(f"{shown:g} ")
    tap(find_button(window, "group_log"))
    assert screen.log_table.item(0, 1).text() == "tool_radius_mm"

    tap(find_button(window, "lockButton"))
    assert screen.body.currentWidget() is screen.locked_page


# -- language --------------------------------------------------------------------------------


def test_switching_to_slovenian_retranslates_the_visible_screen(qtbot, window, tap) -> None:
    main = window.page("main")
    assert find_button(window, "nav_recipes").text() == "Recipes"
    assert main.start_button.text().endswith("START")
    tap(find_button(window, "languageButton"))
    choice = window.overlay()
    assert isinstance(choice, ChoiceOverlay)
    tap(choice.buttons[1])  # Slovenščina
    assert window.languages.language == "sl"
    assert find_button(window, "nav_recipes").text() == "Recepti"
    assert main.start_button.text().endswith("ZAGON")
    assert main.shift_tile.caption_label.text() == "Kosov v izmeni"
    assert window.top_bar.state_label.text() in ("NI REFERENCIRANO", "PRIPRAVLJEN")
    assert find_button(window, "languageButton").text() == "SL"
    tap(find_button(window, "languageButton"))
    tap(window.overlay().buttons[0])
    assert find_button(window, "nav_recipes").text() == "Recipes"
    assert main.start_button.text().endswith("START")


def test_the_alarm_history_speaks_the_interface_language(qtbot, window, database) -> None:
    """History rows keep the message coded: in Slovenian a row reads as the active alarm's
    line does, with no English left, and its detail view too."""
    window.link.send(InjectFault("drive_fault", "X"))
    alarmed = wait_for(qtbot, window, lambda s: bool(s.alarms))
    alarm = alarmed.alarms[0]
    assert alarm.detail is not None
    english = alarm_line(alarm)
    window.languages.set_language("sl")
    window.show_screen("alarms")
    screen = window.page("alarms")
    screen.refresh_history()
    slovenian = alarm_line(alarm)
    assert slovenian != english
    rows = [screen.history_table.item(r, 2).text() for r in range(screen.history_count)]
    assert rows and set(rows) == {slovenian}
    detail = screen.open_history(0)
    assert detail is not None
    assert detail.found_label.text().startswith(machine_text(alarm.detail))
    assert "fault code" not in detail.found_label.text()  # English: "axis X, fault code ..."
    detail.reject()
    window.languages.set_language("en")
    screen.refresh_history()
    assert {screen.history_table.item(r, 2).text() for r in range(screen.history_count)} == {
        english
    }


def test_the_pin_pad_is_locked_like_every_other_way_in(qtbot, window, database, tap) -> None:
    tap(find_button(window, "nav_system"))
    screen = window.page("system")
    tap(find_button(window, "unlockButton"))
    pad = window.overlay()
    enter_pin(qtbot, window, tap, "5555")
    assert database.pin_guard_state().failures == 1  # the pad's attempt counted
    now = datetime.now(UTC)
    with Database.open(database.path, clock=lambda: now) as other:
        while other.pin_guard_state().locked_until is None:
            assert other.authenticate("5555") is None
            now += timedelta(seconds=120)  # past each delay, on the clock of that connection
    enter_pin(qtbot, window, tap, "1234")  # right, but PIN entry is locked
    assert pad.is_open and "locked" in pad.error_label.text()
    assert screen.body.currentWidget() is screen.locked_page


def test_a_service_user_lifts_the_pin_lockout_on_the_system_screen(
    qtbot, window, database, tap
) -> None:
    log_in(qtbot, window, tap, "9999")  # service, before the lockout
    # Wrong PINs typed elsewhere locked PIN entry: the stored row as the guard leaves it (the
    # way there, ten scrypt-checked attempts, is the previous test's and the data layer's).
    until = format_utc(datetime.now(UTC) + timedelta(minutes=15))
    with closing(sqlite3.connect(database.path)) as conn, conn:
        conn.execute("UPDATE pin_guard SET failures = 10, locked_until = ?", (until,))
    tap(find_button(window, "nav_system"))
    screen = window.page("system")
    bar = screen.pin_lockout
    assert bar.isVisible() and "locked" in bar.text_label.text()
    tap(find_button(window, "unlockPinEntry"))
    assert database.pin_guard_state().locked_until is None
    assert database.pin_guard_state().failures == 0
    assert not bar.isVisible()
    events = database.list_alarm_events()
    [lifted] = [e for e in events if e.code == "W104" and e.to_state is AlarmRecordState.NORMAL]
    assert lifted.user_name == "service"  # who lifted it, in the alarm history
