"""Every row of the state table, and every refusal, with its reason."""

from __future__ import annotations

import pytest

from app.machine.states import (
    LATCHED_STATES,
    TRANSITIONS,
    Event,
    MachineState,
    TransitionRefused,
    next_state,
)

ROWS = sorted(TRANSITIONS.items(), key=lambda kv: (kv[0][0].name, kv[0][1].name))


@pytest.mark.parametrize(("key", "target"), ROWS, ids=[f"{s.name}-{e.name}" for (s, e), _ in ROWS])
def test_every_transition_row(key: tuple[MachineState, Event], target: object) -> None:
    state, event = key
    homed = next_state(state, event, all_homed=True)
    unhomed = next_state(state, event, all_homed=False)
    if isinstance(target, tuple):
        assert (homed, unhomed) == target
    else:
        assert homed is target and unhomed is target


REFUSED = [(s, e) for s in MachineState for e in Event if (s, e) not in TRANSITIONS]


@pytest.mark.parametrize(
    ("state", "event"), REFUSED, ids=[f"{s.name}-{e.name}" for s, e in REFUSED]
)
def test_every_event_the_table_lacks_is_refused(state: MachineState, event: Event) -> None:
    with pytest.raises(TransitionRefused) as info:
        next_state(state, event, all_homed=True)
    assert info.value.state is state and info.value.event is event
    assert str(info.value) == f"{event.value} is not possible while {state.value}"


def test_latched_states_are_left_only_by_reset() -> None:
    for state in LATCHED_STATES:
        leaving = [
            e
            for (s, e), t in TRANSITIONS.items()
            if s is state and next_state(s, e, True) is not state
        ]
        assert set(leaving) <= {Event.RESET, Event.ESTOP}


def test_estop_and_fault_reach_from_every_state() -> None:
    for state in MachineState:
        assert (
            next_state(state, Event.ESTOP, True) is MachineState.EMERGENCY_STOP
            if state is not MachineState.EMERGENCY_STOP
            else True
        )
        if state not in LATCHED_STATES:
            assert next_state(state, Event.FAULT, True) is MachineState.ERROR
