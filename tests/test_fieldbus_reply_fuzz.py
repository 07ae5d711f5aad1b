"""Whatever a drive answers on the fieldbus, the CiA 402 master and the register codec turn
it into a state and a command or a number, never an exception: any 16-bit registers in any
type and word order, any statusword and mode display, in any order, whatever was asked."""

from __future__ import annotations

import contextlib

from hypothesis import given, settings
from hypothesis import strategies as st

from app.drivers.cia402 import (
    Cia402Master,
    Cia402State,
    RequestRefusedError,
    decode_statusword,
)
from app.drivers.modbus.codec import decode
from app.drivers.modbus.settings import DataType, WordOrder

word = st.integers(min_value=0, max_value=0xFFFF)
actions = st.sampled_from(["enable", "disable", "quick_stop", "fault_reset", "start_homing", None])


@settings(max_examples=150, deadline=None)
@given(
    st.sampled_from(list(DataType)),
    st.sampled_from(list(WordOrder)),
    st.lists(word, min_size=2, max_size=2),
)
def test_any_registers_decode_to_a_number(
    data_type: DataType, order: WordOrder, words: list[int]
) -> None:
    value = decode(words[: data_type.registers], data_type, order)
    assert isinstance(value, float | int)


@settings(max_examples=100, deadline=None)
@given(
    st.booleans(),
    st.lists(st.tuples(word, st.one_of(st.none(), st.integers(-128, 127)), actions), max_size=40),
)
def test_any_statusword_sequence_keeps_the_master_consistent(
    reports_mode: bool, replies: list[tuple[int, int | None, str | None]]
) -> None:
    master = Cia402Master(reports_mode=reports_mode)
    for statusword, mode, action in replies:
        if action is not None:
            with contextlib.suppress(RequestRefusedError):  # a refusal with its reason: fine
                getattr(master, action)()
        master.observe(statusword, mode if reports_mode else None)
        assert isinstance(master.state, Cia402State)
        assert master.state is decode_statusword(statusword)
        command = master.command()
        assert 0 <= command.controlword <= 0xFFFF
