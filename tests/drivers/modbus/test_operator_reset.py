"""What an operator meets on the Modbus machine when the link goes, through the machine
layer and the operator's Reset: the emulator's server stops mid-run (E020 latches), starts
again, and ONE Reset brings the machine back; a single exception reply is a refusal with its
code (E021), not a lost link."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from app.config import parse_config
from app.drivers.modbus.emulator import ModbusEmulator
from app.machine import commands as cmd
from app.machine.runtime import MachineRuntime
from app.machine.states import LATCHED_STATES, MachineState
from tests.drivers.modbus.helpers import machine_table, tcp_modbus, with_port

ILLEGAL_ADDRESS = 0x02
ABSOLUTE = {name: {"encoder": "absolute"} for name in "XYZ"}


@pytest.fixture
def table() -> dict[str, Any]:
    return machine_table(tcp_modbus(), period_ms=20.0, axes=ABSOLUTE)


@pytest.fixture
def emulator(table: dict[str, Any]) -> Iterator[ModbusEmulator]:
    emulator = ModbusEmulator(parse_config(table))
    yield emulator
    emulator.stop()


@pytest.fixture
def runtime(
    table: dict[str, Any], emulator: ModbusEmulator, tmp_path: Path
) -> Iterator[MachineRuntime]:
    port = emulator.serve_tcp()
    runtime = MachineRuntime.create(with_port(table, port), tmp_path / "stave.db")
    runtime.port = port  # type: ignore[attr-defined]
    runtime.start()
    yield runtime
    runtime.shutdown()


def alarm_codes(runtime: MachineRuntime) -> set[str]:
    return {a.code for a in runtime.controller.snapshot().alarms}


def test_the_first_reset_after_the_link_came_back_works(
    runtime: MachineRuntime, emulator: ModbusEmulator
) -> None:
    c = runtime.controller
    assert c.state is MachineState.READY, c.state_text()
    emulator.stop()  # the server goes away mid-run
    assert runtime.run_until(lambda m: m.state in LATCHED_STATES, 5.0)
    assert c.state is MachineState.ERROR and "E020" in alarm_codes(runtime)
    runtime.run_for(0.5)  # the machine keeps running its periods with the link gone

    c.post(cmd.Reset())  # pressed too early: the server is still away
    runtime.run_for(0.2)
    assert c.state is MachineState.ERROR and "reconnection failed" in str(c.message)

    emulator.serve_tcp(port=runtime.port)  # type: ignore[attr-defined]
    c.post(cmd.Reset())  # once
    runtime.run_for(1.0)
    assert c.state is MachineState.READY, c.message
    runtime.run_for(1.0)  # and no old news latches it again
    assert c.state is MachineState.READY, c.message


def test_one_exception_reply_is_a_refusal_with_its_code_not_a_lost_link(
    runtime: MachineRuntime, emulator: ModbusEmulator
) -> None:
    c = runtime.controller
    assert c.state is MachineState.READY, c.state_text()
    emulator.inject_exception("Y", ILLEGAL_ADDRESS)
    assert runtime.run_until(lambda m: m.state in LATCHED_STATES, 2.0)
    codes = alarm_codes(runtime)
    assert "E021" in codes and "E020" not in codes, codes
    alarm = next(a for a in c.snapshot().alarms if a.code == "E021")
    assert alarm.source == "Y" and "refused" in alarm.text
    assert "exception 0x02 (illegal data address)" in alarm.text
    c.post(cmd.Reset())  # the link never went: no reconnection needed
    runtime.run_for(1.0)
    assert c.state is MachineState.READY, c.message
