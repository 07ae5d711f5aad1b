"""The machine log's lines for people's actions: a held jog once, every other accepted
command once with its user, the same refusal again within a few seconds counted, not
written."""

from __future__ import annotations

from app.machine import commands as cmd
from app.machine.action_log import NO_USER, REFUSAL_REPEAT_S, ActionLog
from app.machine.refusals import Reason, Refusal


def test_a_held_jog_is_one_action_until_released_or_stopped() -> None:
    log = ActionLog()
    press = cmd.JogContinuous("X", 1)
    assert log.accepted(press, "anna") == f"{press} by anna"
    assert log.accepted(press, "anna") is None  # the held button's refresh
    assert log.accepted(cmd.JogContinuous("X", -1), "anna") is not None  # the other way
    assert log.accepted(cmd.JogRelease("X"), "anna") is None
    assert log.accepted(press, "anna") is not None
    log.stopped("X")  # the dead-man stopped it: pressing again is a new action
    assert log.accepted(press, "anna") is not None
    log.stopped_all()
    assert log.accepted(press, "") == f"{press} by {NO_USER}"


def test_every_other_command_is_logged_each_time_with_its_user() -> None:
    log = ActionLog()
    assert log.accepted(cmd.SetSpindle(True), "ben") == "SetSpindle(on=True) by ben"
    assert log.accepted(cmd.SetSpindle(True), "ben") == "SetSpindle(on=True) by ben"
    assert log.accepted(cmd.Reset(), "ben") == "Reset() by ben"
    assert log.accepted(cmd.Acknowledge(3), "ben") == "Acknowledge(alarm_id=3) by ben"
    assert log.accepted(cmd.SetUser("cleo"), "ben") == "at the panel now: cleo"
    assert log.accepted(cmd.ReloadParameters(), "ben") is None


def test_a_repeated_refusal_is_counted_and_reported_with_the_next_line() -> None:
    log = ActionLog()
    manual = Refusal(Reason.OPEN_MANUAL_TO_JOG)
    lines = [log.refused(manual, 0.1 * i, "anna") for i in range(10)]
    assert lines[0] == "refused for anna: open the Manual screen to jog"
    assert lines[1:] == [None] * 9
    later = log.refused(manual, REFUSAL_REPEAT_S + 1.0, "anna")
    assert later is not None and "repeated 9 more times" in later
    other = log.refused(Refusal(Reason.NOTHING_TO_RESET), REFUSAL_REPEAT_S + 1.1, "anna")
    assert other == "refused for anna: nothing to reset"
