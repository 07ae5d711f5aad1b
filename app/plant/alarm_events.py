"""Alarm transitions seen from the plant: the difference between two snapshots' alarms.

Why from snapshots: the server runs in its own process and gets what the screens get, the
alarms that are not NORMAL. Every ISA-18.2 transition shows there as a changed state, and the
return to NORMAL as an alarm that is no longer listed. A snapshot is sent at 50 Hz, and an
alarm's state changes at most on an operator's action or a condition, so nothing is lost
between two of them except a raise and clear within 20 ms, which the database keeps anyway.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.machine.snapshot import AlarmState, AlarmView


@dataclass(frozen=True)
class AlarmChange:
    alarm: AlarmView  # as last seen (for a return to NORMAL: as it was before)
    from_state: AlarmState
    to_state: AlarmState


def alarm_changes(before: tuple[AlarmView, ...], after: tuple[AlarmView, ...]) -> list[AlarmChange]:
    """Changes from ``before`` to ``after``, oldest alarm first."""
    old = {a.alarm_id: a for a in before}
    new = {a.alarm_id: a for a in after}
    changes = []
    for alarm_id in sorted(set(old) | set(new)):
        was = old.get(alarm_id)
        now = new.get(alarm_id)
        if now is None and was is not None:
            changes.append(AlarmChange(was, was.state, AlarmState.NORMAL))
        elif now is not None and (was is None or was.state is not now.state):
            changes.append(
                AlarmChange(now, AlarmState.NORMAL if was is None else was.state, now.state)
            )
    return changes
