"""The ISA-18.2 life cycle: every transition of the table, and the history kept."""

from __future__ import annotations

import pytest

from app.data.pin_guard import LOCKOUT_ALARM_CODE, LOCKOUT_ALARM_TEXT
from app.machine.alarms import (
    ALARM_TRANSITIONS,
    CATALOGUE,
    AlarmAction,
    AlarmCode,
    AlarmManager,
)
from app.machine.database_store import alarm_event
from app.machine.refusals import Reason, Refusal, refusal, refusal_from_json
from app.machine.snapshot import AlarmState


def make() -> tuple[AlarmManager, list]:
    seen: list = []
    return AlarmManager(on_transition=seen.append, wall_clock=lambda: 1000.0), seen


def drive_to(manager: AlarmManager, state: AlarmState) -> None:
    if state is AlarmState.NORMAL:
        return
    manager.raise_alarm("E010", "X")
    if state is AlarmState.ACTIVE_ACKED:
        manager.acknowledge()
    elif state is AlarmState.RTN_UNACKED:
        manager.clear("E010", "X")


ACT = {
    AlarmAction.CONDITION_ON: lambda m: m.raise_alarm("E010", "X"),
    AlarmAction.CONDITION_OFF: lambda m: m.clear("E010", "X"),
    AlarmAction.ACKNOWLEDGE: lambda m: m.acknowledge(),
}


@pytest.mark.parametrize(
    ("key", "target"),
    list(ALARM_TRANSITIONS.items()),
    ids=[f"{s.name}-{a.name}" for (s, a) in ALARM_TRANSITIONS],
)
def test_each_transition(key: tuple[AlarmState, AlarmAction], target: AlarmState) -> None:
    state, action = key
    manager, seen = make()
    drive_to(manager, state)
    before = len(seen)
    ACT[action](manager)
    assert len(seen) == before + 1
    assert seen[-1].from_state is state and seen[-1].to_state is target
    views = manager.views()
    if target is AlarmState.NORMAL:
        assert views == ()
    else:
        assert views[0].state is target


def test_actions_outside_the_table_change_nothing() -> None:
    manager, seen = make()
    manager.clear("E010", "X")
    assert manager.acknowledge() == 0
    manager.raise_alarm("E010", "X")
    manager.raise_alarm("E010", "X")  # already active
    assert [t.to_state for t in seen] == [AlarmState.ACTIVE_UNACKED]


def test_full_history_and_one_line_per_source() -> None:
    manager, seen = make()
    manager.raise_alarm("E010", "X", "fault code 0x2310")
    manager.raise_alarm("E010", "Y")
    assert len(manager.views()) == 2
    manager.clear("E010", "X")
    manager.acknowledge(seen[0].alarm_id)  # the X alarm, returned to normal
    assert [t.to_state for t in manager.history] == [
        AlarmState.ACTIVE_UNACKED,
        AlarmState.ACTIVE_UNACKED,
        AlarmState.RTN_UNACKED,
        AlarmState.NORMAL,
    ]
    assert "0x2310" in seen[0].text and seen[0].source == "X"


def test_catalogue_codes_are_unique_and_texts_clear() -> None:
    assert all(code == d.code and d.text for code, d in CATALOGUE.items())


def test_the_pin_lockout_the_database_records_is_the_catalogued_alarm() -> None:
    """The data layer records the PIN lockout itself (it may not import the machine layer),
    so its code and text must be the catalogue's W104."""
    entry = CATALOGUE[AlarmCode.PIN_LOCKED]
    assert (entry.code.value, entry.text) == (LOCKOUT_ALARM_CODE, LOCKOUT_ALARM_TEXT)


def test_every_transition_keeps_its_message_coded_for_the_history() -> None:
    """The stored history rows carry the reason and its arguments (and a cause's), so the
    screens translate them later; a message this software cannot read reads as none."""
    manager, seen = make()
    detail = Refusal(
        Reason.FOLLOWING_ERROR_DETAIL,
        ("X", "-2.398", "mm", "2"),
        (refusal(Reason.LATCHED_ERROR),),
    )
    manager.raise_alarm("E011", "X", detail)
    manager.raise_alarm("E010", "Y", "fault code 0x2310")  # a device's own words: no code
    manager.acknowledge()
    stored = [alarm_event(t) for t in seen]
    assert all(event.problems() == [] for event in stored)
    coded = [refusal_from_json(e.detail_json) for e in stored if e.source == "X"]
    assert coded == [detail, detail]  # raised, acknowledged
    assert {e.detail_json for e in stored if e.source == "Y"} == {None}
    for unreadable in ('{"reason": "NO_SUCH_REASON", "args": [], "causes": []}', "{}", "[", ""):
        assert refusal_from_json(unreadable) is None


def test_the_history_keeps_only_its_limit_of_newest_transitions() -> None:
    """The machine process runs for months: the in-memory history is bounded (the database
    keeps every transition)."""
    manager, seen = make()
    for _ in range(manager.history_limit):  # raised, returned, acknowledged: 3 transitions each
        manager.raise_alarm("E010", "X")
        manager.clear("E010", "X")
        manager.acknowledge()
    assert len(seen) == 3 * manager.history_limit
    assert len(manager.history) == manager.history_limit
    assert manager.history == seen[-manager.history_limit :]
