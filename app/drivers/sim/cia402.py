"""CiA 402 / CiA 301 facts the simulated drive implements: device control commands, the
power state transition table, statusword patterns, modes of operation and emergency codes.

Why a table: the transitions are the standard's (transition numbers in comments), they are
tested row by row, and a reader can check them against the standard without reading the
drive model (after canopen's ``profiles/p402.py``).
"""

from __future__ import annotations

import enum

from app.drivers.cia402 import Cia402State

S = Cia402State


class EmcyCode(enum.IntEnum):
    """CiA 301 emergency error codes the simulated drive sends (0xFF00-0xFFFF: vendor)."""

    CONTINUOUS_OVERCURRENT = 0x2310
    HEARTBEAT = 0x8130  # life guard / heartbeat error: the master went silent
    FOLLOWING_ERROR = 0x8611
    POSITIVE_LIMIT_SWITCH = 0xFF01
    NEGATIVE_LIMIT_SWITCH = 0xFF02
    HOMING_FAILED = 0xFF03


VENDOR_EMCY_TEXT: dict[int, str] = {
    EmcyCode.POSITIVE_LIMIT_SWITCH: "Positive limit switch",
    EmcyCode.NEGATIVE_LIMIT_SWITCH: "Negative limit switch",
    EmcyCode.HOMING_FAILED: "Homing failed: home switch not found between the limit switches",
}
"""The texts of the simulated drive's manufacturer-specific codes (its "manual"); the
standard codes' texts are :func:`app.drivers.emcy.emcy_text`'s."""


class Command(enum.Enum):
    """Device control commands decoded from the controlword (bit 7 clear)."""

    SHUTDOWN = "shutdown"  # 0xxx x110
    SWITCH_ON = "switch on / disable operation"  # 0xxx 0111
    ENABLE_OPERATION = "enable operation"  # 0xxx 1111
    DISABLE_VOLTAGE = "disable voltage"  # 0xxx xx0x
    QUICK_STOP = "quick stop"  # 0xxx x01x


def decode_controlword(controlword: int) -> Command:
    """The command a controlword with bit 7 clear encodes (CiA 402 table "device control")."""
    if not controlword & 0x02:
        return Command.DISABLE_VOLTAGE
    if not controlword & 0x04:
        return Command.QUICK_STOP
    if not controlword & 0x01:
        return Command.SHUTDOWN
    if not controlword & 0x08:
        return Command.SWITCH_ON
    return Command.ENABLE_OPERATION


# (state, command) -> (next state, CiA 402 transition number). Pairs not listed leave the
# state unchanged. Transitions 0, 1 (power-up), 13, 14 (fault) and 15 (fault reset) are
# internal or edge-triggered and handled by SimDrive itself.
TRANSITIONS: dict[tuple[Cia402State, Command], tuple[Cia402State, str]] = {
    (S.SWITCH_ON_DISABLED, Command.SHUTDOWN): (S.READY_TO_SWITCH_ON, "2"),
    (S.READY_TO_SWITCH_ON, Command.SWITCH_ON): (S.SWITCHED_ON, "3"),
    (S.READY_TO_SWITCH_ON, Command.ENABLE_OPERATION): (S.OPERATION_ENABLED, "3+4"),
    (S.SWITCHED_ON, Command.ENABLE_OPERATION): (S.OPERATION_ENABLED, "4"),
    (S.OPERATION_ENABLED, Command.SWITCH_ON): (S.SWITCHED_ON, "5"),
    (S.SWITCHED_ON, Command.SHUTDOWN): (S.READY_TO_SWITCH_ON, "6"),
    (S.READY_TO_SWITCH_ON, Command.DISABLE_VOLTAGE): (S.SWITCH_ON_DISABLED, "7"),
    (S.READY_TO_SWITCH_ON, Command.QUICK_STOP): (S.SWITCH_ON_DISABLED, "7"),
    (S.OPERATION_ENABLED, Command.SHUTDOWN): (S.READY_TO_SWITCH_ON, "8"),
    (S.OPERATION_ENABLED, Command.DISABLE_VOLTAGE): (S.SWITCH_ON_DISABLED, "9"),
    (S.SWITCHED_ON, Command.DISABLE_VOLTAGE): (S.SWITCH_ON_DISABLED, "10"),
    (S.SWITCHED_ON, Command.QUICK_STOP): (S.SWITCH_ON_DISABLED, "10"),
    (S.OPERATION_ENABLED, Command.QUICK_STOP): (S.QUICK_STOP_ACTIVE, "11"),
    (S.QUICK_STOP_ACTIVE, Command.DISABLE_VOLTAGE): (S.SWITCH_ON_DISABLED, "12"),
    (S.QUICK_STOP_ACTIVE, Command.ENABLE_OPERATION): (S.OPERATION_ENABLED, "16"),
}

STATUSWORD_BASE: dict[Cia402State, int] = {
    S.NOT_READY_TO_SWITCH_ON: 0x00,
    S.SWITCH_ON_DISABLED: 0x40,
    S.READY_TO_SWITCH_ON: 0x21,
    S.SWITCHED_ON: 0x23,
    S.OPERATION_ENABLED: 0x27,
    S.QUICK_STOP_ACTIVE: 0x07,
    S.FAULT_REACTION_ACTIVE: 0x0F,
    S.FAULT: 0x08,
}
