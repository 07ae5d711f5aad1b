"""The jog arbitration's table, row by row, and the arbiter's settling rule."""

from __future__ import annotations

import pytest

from app.machine.pendant.arbitration import (
    OWNER,
    SETTLE_S,
    TOUCH,
    TRANSITIONS,
    ArbiterEvent,
    ArbiterState,
    JogArbiter,
)
from app.machine.refusals import Reason
from app.machine.snapshot import JogSource

S, E = ArbiterState, ArbiterEvent
ROWS = [
    (S.FREE, E.TOUCH_SCREEN, S.SCREEN),
    (S.FREE, E.TOUCH_HANDWHEEL, S.HANDWHEEL),
    (S.FREE, E.TOUCH_JOYSTICK, S.JOYSTICK),
    (S.FREE, E.TOUCH_PENDANT, S.PENDANT),
    (S.FREE, E.AT_REST, S.FREE),
    (S.FREE, E.LEAVE, S.FREE),
]
for owner in (S.SCREEN, S.HANDWHEEL, S.JOYSTICK, S.PENDANT):
    ROWS += [(owner, event, owner) for event in TOUCH.values()]  # the owner keeps it
    ROWS += [(owner, E.AT_REST, S.FREE), (owner, E.LEAVE, S.FREE)]


@pytest.mark.parametrize(("state", "event", "expected"), ROWS)
def test_transition_row(state: ArbiterState, event: ArbiterEvent, expected: ArbiterState) -> None:
    assert TRANSITIONS[state, event] is expected


def test_the_rows_are_the_whole_table() -> None:
    assert {(s, e) for s, e, _ in ROWS} == set(TRANSITIONS)
    assert len(TRANSITIONS) == len(ArbiterState) * len(ArbiterEvent)


@pytest.mark.parametrize("first", list(JogSource))
def test_one_source_at_a_time_and_switching_needs_all_at_rest(first: JogSource) -> None:
    arbiter = JogArbiter()
    assert arbiter.touch(first) is None and arbiter.owner is first
    for other in JogSource:
        if other is not first:
            refused = arbiter.touch(other)
            assert refused is not None and refused.reason.name.endswith("_HAS_JOG")
            assert arbiter.owner is first
    arbiter.tick(1.0, at_rest=True)
    arbiter.tick(1.0 + SETTLE_S / 2, at_rest=True)
    assert arbiter.owner is first, "a pause shorter than the settling time keeps the jog"
    arbiter.tick(1.0 + SETTLE_S / 2 + 0.01, at_rest=False)
    arbiter.tick(1.0 + SETTLE_S, at_rest=True)
    assert arbiter.owner is first, "motion restarted the settling time"
    arbiter.tick(1.0 + 2 * SETTLE_S + 0.01, at_rest=True)
    assert arbiter.owner is None
    second = next(s for s in JogSource if s is not first)
    assert arbiter.touch(second) is None and arbiter.owner is second


def test_leaving_manual_frees_the_jog_and_each_owner_has_its_reason() -> None:
    arbiter = JogArbiter()
    arbiter.touch(JogSource.JOYSTICK)
    refused = arbiter.touch(JogSource.SCREEN)
    assert refused is not None and refused.reason is Reason.JOYSTICK_HAS_JOG
    arbiter.leave()
    assert arbiter.state is ArbiterState.FREE
    assert set(OWNER) == set(JogSource)
