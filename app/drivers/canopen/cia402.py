"""Which controlword one drive gets this period: the CiA 402 walk, fault reset and homing.

Why a pure class and a table: this is where a drive could be re-enabled by accident, so the
rule must be readable in one place and tested row by row. The table maps (what the machine
asked for, the state the drive reports) to the controlword; it never contains the fault
reset bit. Bit 7 is set only by :meth:`AxisCommander.fault_reset`, which the machine calls on
an operator's action: controlword 0x00 for one SYNC, then 0x80 (the rising edge) until the
drive leaves FAULT, ending in SWITCH ON DISABLED with the request latched at DISABLED.

Unlike canopen's ``BaseNode402.state = 'OPERATION ENABLED'`` (which silently sends a fault
reset and re-enables a faulted drive) nothing here waits or loops: one call gives one
controlword, and a FAULT seen in the statusword drops the request to DISABLED, so a drive that
faulted stays disabled after its reset until the machine asks again.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from app.drivers.canopen.objects import CW_HOMING_START, MODE_CSP, MODE_HOMING, SW_HOMING_ERROR
from app.drivers.contracts import (
    CW_DISABLE_VOLTAGE,
    CW_ENABLE_OPERATION,
    CW_FAULT_RESET,
    CW_QUICK_STOP,
    CW_SHUTDOWN,
    CW_SWITCH_ON,
    SW_HOMING_ATTAINED,
    SW_TARGET_REACHED,
    Cia402State,
    decode_statusword,
)

S = Cia402State
FAULT_STATES = (S.FAULT, S.FAULT_REACTION_ACTIVE)
RESET_EDGE_PERIODS = 25  # hold bit 7 this many SYNCs at most while the drive leaves FAULT


class PowerRequest(enum.Enum):
    """What the machine asked this drive to be."""

    DISABLED = "disabled"
    ENABLED = "enabled"
    QUICK_STOP = "quick stop"


# (request, reported state) -> controlword. CiA 402 transition numbers in the comments.
NEXT_CONTROLWORD: dict[tuple[PowerRequest, Cia402State], int] = {
    (PowerRequest.ENABLED, S.NOT_READY_TO_SWITCH_ON): CW_DISABLE_VOLTAGE,  # wait for 1
    (PowerRequest.ENABLED, S.SWITCH_ON_DISABLED): CW_SHUTDOWN,  # 2
    (PowerRequest.ENABLED, S.READY_TO_SWITCH_ON): CW_SWITCH_ON,  # 3
    (PowerRequest.ENABLED, S.SWITCHED_ON): CW_ENABLE_OPERATION,  # 4
    (PowerRequest.ENABLED, S.OPERATION_ENABLED): CW_ENABLE_OPERATION,  # stay
    (PowerRequest.ENABLED, S.QUICK_STOP_ACTIVE): CW_ENABLE_OPERATION,  # 16
    (PowerRequest.ENABLED, S.FAULT_REACTION_ACTIVE): CW_DISABLE_VOLTAGE,  # never bit 7
    (PowerRequest.ENABLED, S.FAULT): CW_DISABLE_VOLTAGE,  # never bit 7
    (PowerRequest.DISABLED, S.NOT_READY_TO_SWITCH_ON): CW_DISABLE_VOLTAGE,
    (PowerRequest.DISABLED, S.SWITCH_ON_DISABLED): CW_DISABLE_VOLTAGE,  # stay
    (PowerRequest.DISABLED, S.READY_TO_SWITCH_ON): CW_DISABLE_VOLTAGE,  # 7
    (PowerRequest.DISABLED, S.SWITCHED_ON): CW_DISABLE_VOLTAGE,  # 10
    (PowerRequest.DISABLED, S.OPERATION_ENABLED): CW_DISABLE_VOLTAGE,  # 9
    (PowerRequest.DISABLED, S.QUICK_STOP_ACTIVE): CW_DISABLE_VOLTAGE,  # 12
    (PowerRequest.DISABLED, S.FAULT_REACTION_ACTIVE): CW_DISABLE_VOLTAGE,
    (PowerRequest.DISABLED, S.FAULT): CW_DISABLE_VOLTAGE,
    (PowerRequest.QUICK_STOP, S.NOT_READY_TO_SWITCH_ON): CW_DISABLE_VOLTAGE,
    (PowerRequest.QUICK_STOP, S.SWITCH_ON_DISABLED): CW_DISABLE_VOLTAGE,  # stay
    (PowerRequest.QUICK_STOP, S.READY_TO_SWITCH_ON): CW_QUICK_STOP,  # 7
    (PowerRequest.QUICK_STOP, S.SWITCHED_ON): CW_QUICK_STOP,  # 10
    (PowerRequest.QUICK_STOP, S.OPERATION_ENABLED): CW_QUICK_STOP,  # 11
    (PowerRequest.QUICK_STOP, S.QUICK_STOP_ACTIVE): CW_QUICK_STOP,  # stay
    (PowerRequest.QUICK_STOP, S.FAULT_REACTION_ACTIVE): CW_DISABLE_VOLTAGE,
    (PowerRequest.QUICK_STOP, S.FAULT): CW_DISABLE_VOLTAGE,
}


class ResetPhase(enum.Enum):
    NONE = "none"
    ZERO = "controlword 0x00"  # next SYNC carries 0x00: bit 7 low before the edge
    EDGE = "controlword 0x80"  # bit 7 high until the drive leaves FAULT


class HomingPhase(enum.Enum):
    IDLE = "idle"
    SELECT_MODE = "select homing mode"  # mode 6 sent, waiting for the mode display
    START = "start"  # next SYNC carries controlword bit 4 (rising edge starts homing)
    RUNNING = "running"  # bit 4 held; waiting for homing attained or homing error
    RETURN = "return to CSP"  # mode 8 sent, waiting for the mode display


class CommandRefusedError(Exception):
    """A power request the drive's present state does not allow."""


@dataclass
class AxisCommander:
    """Controlword and mode of one drive, derived each period from the machine's request
    and the statusword last received."""

    request: PowerRequest = PowerRequest.DISABLED
    reset: ResetPhase = ResetPhase.NONE
    reset_edges: int = 0
    homing: HomingPhase = HomingPhase.IDLE
    homing_seen_running: bool = False
    homed: bool = False
    statusword: int = 0
    mode_display: int = 0

    @property
    def state(self) -> Cia402State:
        return decode_statusword(self.statusword)

    @property
    def homing_active(self) -> bool:
        return self.homing is not HomingPhase.IDLE

    # ---- requests from the machine (never from the backend itself) ----
    def enable(self) -> None:
        if self.state in FAULT_STATES:
            raise CommandRefusedError(
                "the drive is in FAULT: an operator's fault reset comes first"
            )
        if self.reset is not ResetPhase.NONE:
            raise CommandRefusedError("a fault reset is in progress")
        self.request = PowerRequest.ENABLED

    def disable(self) -> None:
        self.request = PowerRequest.DISABLED
        self._abort_homing()

    def quick_stop(self) -> None:
        self.request = PowerRequest.QUICK_STOP
        self._abort_homing()

    def fault_reset(self) -> None:
        self.request = PowerRequest.DISABLED
        self._abort_homing()
        self.reset = ResetPhase.ZERO
        self.reset_edges = 0

    def start_homing(self) -> None:
        if self.state is not Cia402State.OPERATION_ENABLED:
            raise CommandRefusedError(
                f"homing needs OPERATION ENABLED, the drive is {self.state.value}"
            )
        if self.homing in (HomingPhase.SELECT_MODE, HomingPhase.START, HomingPhase.RUNNING):
            return
        self.homing = HomingPhase.SELECT_MODE
        self.homing_seen_running = False
        self.homed = False

    def _abort_homing(self) -> None:
        if self.homing is not HomingPhase.IDLE:
            self.homing = HomingPhase.RETURN

    # ---- the period ----
    def observe(self, statusword: int, mode_display: int) -> None:
        """Take the drive's latest statusword and mode display (from TPDO1)."""
        self.statusword = statusword
        self.mode_display = mode_display
        state = self.state
        if state in FAULT_STATES:
            self.request = PowerRequest.DISABLED  # latched: only the machine enables again
            self._abort_homing()
        elif (
            self.homing is not HomingPhase.IDLE
            and self.homing is not HomingPhase.RETURN
            and (
                state is not Cia402State.OPERATION_ENABLED
                or self.request is not PowerRequest.ENABLED
            )
        ):
            self._abort_homing()
        if self.homing is HomingPhase.SELECT_MODE and mode_display == MODE_HOMING:
            self.homing = HomingPhase.START
        elif self.homing is HomingPhase.RUNNING and mode_display == MODE_HOMING:
            if statusword & SW_HOMING_ERROR:
                self.homing = HomingPhase.RETURN
            elif not statusword & SW_HOMING_ATTAINED:
                self.homing_seen_running = True
            elif self.homing_seen_running and statusword & SW_TARGET_REACHED:
                self.homed = True
                self.homing = HomingPhase.RETURN
        elif self.homing is HomingPhase.RETURN and mode_display == MODE_CSP:
            self.homing = HomingPhase.IDLE

    def command(self) -> tuple[int, int]:
        """(controlword, mode of operation) for this period's RPDO."""
        mode = (
            MODE_HOMING
            if self.homing in (HomingPhase.SELECT_MODE, HomingPhase.START, HomingPhase.RUNNING)
            else MODE_CSP
        )
        if self.reset is ResetPhase.ZERO:
            self.reset = ResetPhase.EDGE
            return CW_DISABLE_VOLTAGE, mode
        if self.reset is ResetPhase.EDGE:
            left_fault = self.reset_edges > 0 and self.state not in FAULT_STATES
            if left_fault or self.reset_edges >= RESET_EDGE_PERIODS:
                self.reset = ResetPhase.NONE
            else:
                self.reset_edges += 1
                return CW_FAULT_RESET, mode
        controlword = NEXT_CONTROLWORD[(self.request, self.state)]
        if controlword == CW_ENABLE_OPERATION and self.homing is HomingPhase.START:
            self.homing = HomingPhase.RUNNING
            controlword |= CW_HOMING_START
        elif controlword == CW_ENABLE_OPERATION and self.homing is HomingPhase.RUNNING:
            controlword |= CW_HOMING_START
        return controlword, mode
