"""The top bar's machine message expires: shown for ten seconds from the moment it was given,
again when it is given again, and gone at once on a change of screen."""

from __future__ import annotations

from app.machine.refusals import Reason, Refusal
from app.screens.top_bar_message import MESSAGE_S, ExpiringMessage


def test_a_message_shows_for_its_lifetime_from_when_it_was_given() -> None:
    now = [100.0]
    shown = ExpiringMessage(clock=lambda: now[0])
    resuming = Refusal(Reason.RESUMING)
    assert shown.current(None, 0) is None
    assert shown.current(resuming, 1) == resuming
    now[0] += MESSAGE_S - 0.1
    assert shown.current(resuming, 1) == resuming
    now[0] += 0.2
    assert shown.current(resuming, 1) is None  # expired, though the machine still holds it
    assert shown.current(resuming, 2) == resuming  # the same message given again is new
    shown.dismiss()
    assert shown.current(resuming, 2) is None  # another screen: gone at once
    assert shown.current(Refusal(Reason.RESET_DONE), 3) == Refusal(Reason.RESET_DONE)
