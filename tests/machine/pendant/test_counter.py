"""The handwheel counter's unwrap: every step a wheel can turn between two reads, anywhere
on the 16-bit range and across any number of wraps, both ways; the jump fault; nothing moves
on a first read, after ``forget`` (a reconnect) or for a missing value."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.machine.pendant.counter import (
    COUNTER_MODULUS,
    MAX_STEP_LIMIT,
    CounterUnwrap,
    max_step_per_read,
    wrapped_step,
)

MAX_STEP = 400


def raw_after(start: int, moved: int) -> int:
    return (start + moved) % COUNTER_MODULUS


@settings(max_examples=200, deadline=None)
@given(
    start=st.integers(0, COUNTER_MODULUS - 1),
    steps=st.lists(st.integers(-MAX_STEP, MAX_STEP), min_size=1, max_size=400),
)
def test_unwrap_follows_every_turn_across_the_whole_range(start: int, steps: list[int]) -> None:
    counter = CounterUnwrap(MAX_STEP)
    assert counter.read(start).counts == 0  # the first read moves nothing
    moved = 0
    for step in steps:
        moved += step
        result = counter.read(raw_after(start, moved))
        assert result.counts == step
        assert not result.jumped
    assert counter.total_counts == moved


@settings(max_examples=50, deadline=None)
@given(start=st.integers(0, COUNTER_MODULUS - 1), direction=st.sampled_from([-1, 1]))
def test_many_wraps_in_one_direction_add_up(start: int, direction: int) -> None:
    """Ten full turns of the counter at the largest step a read may show."""
    counter = CounterUnwrap(MAX_STEP_LIMIT)
    counter.read(start)
    moved = 0
    for _ in range(10 * COUNTER_MODULUS // MAX_STEP_LIMIT):
        moved += direction * MAX_STEP_LIMIT
        assert counter.read(raw_after(start, moved)).counts == direction * MAX_STEP_LIMIT
    assert abs(counter.total_counts) > 9 * COUNTER_MODULUS


@pytest.mark.parametrize(
    ("previous", "current", "step"),
    [(65535, 0, 1), (0, 65535, -1), (65530, 5, 11), (5, 65530, -11), (100, 100, 0)],
)
def test_wrapped_step_takes_the_shorter_way(previous: int, current: int, step: int) -> None:
    assert wrapped_step(previous, current) == step


@settings(max_examples=100, deadline=None)
@given(
    start=st.integers(0, COUNTER_MODULUS - 1),
    jump=st.integers(MAX_STEP + 1, COUNTER_MODULUS // 2).flatmap(
        lambda n: st.sampled_from([n, -n])
    ),
)
def test_a_jump_larger_than_a_hand_turns_is_a_fault_and_moves_nothing(
    start: int, jump: int
) -> None:
    counter = CounterUnwrap(MAX_STEP)
    counter.read(start)
    result = counter.read(raw_after(start, jump))
    assert result.jumped and result.counts == 0
    assert abs(result.jump_counts) > MAX_STEP
    # What follows a jump is a first read: no motion from the new base either.
    assert counter.read(raw_after(start, jump)).counts == 0
    assert counter.read(raw_after(start, jump + 3)).counts == 3


def test_nothing_moves_after_a_reconnect_or_a_missing_value() -> None:
    counter = CounterUnwrap(MAX_STEP)
    counter.read(1000)
    assert counter.read(1010).counts == 10
    counter.forget()  # the link came back: the coupler may have counted meanwhile
    assert counter.read(30000).counts == 0
    assert counter.read(30005).counts == 5
    assert counter.read(None).counts == 0  # unwired or unreadable
    assert counter.read(31000).counts == 0
    assert counter.total_counts == 15


@pytest.mark.parametrize("bad", [0, -1, MAX_STEP_LIMIT + 1, True, 1.5])
def test_the_largest_step_must_leave_the_unwrap_unambiguous(bad: object) -> None:
    with pytest.raises(ValueError, match="max_step_counts"):
        CounterUnwrap(bad)  # type: ignore[arg-type]


def test_a_value_outside_the_counter_is_refused_with_its_value() -> None:
    with pytest.raises(ValueError, match="65536"):
        CounterUnwrap(MAX_STEP).read(COUNTER_MODULUS)


def test_the_largest_step_per_read_comes_from_the_spin_rate_and_the_period() -> None:
    assert max_step_per_read(2000.0, 0.004) == 16  # 8 counts a period, one skipped read
    assert max_step_per_read(2000.0, 0.05) == 200
    assert max_step_per_read(1.0, 0.004) == 2
    assert max_step_per_read(100_000.0, 1.0) == MAX_STEP_LIMIT
