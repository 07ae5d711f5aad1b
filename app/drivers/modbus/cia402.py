"""What one drive is told each period: controlword and mode of operation. Pure logic, no I/O.

Why a separate commander: on a fieldbus without SDO-style handshakes (Modbus), the master
walks the CiA 402 state machine itself, one controlword per period, deciding from the
statusword it read last. Keeping that walk free of I/O makes every row testable.

Rules, all from CiA 402 and the project's safety notes:

- ``enable`` walks SWITCH ON DISABLED -> (shutdown 0x06) READY TO SWITCH ON -> (switch on
  0x07) SWITCHED ON -> (enable operation 0x0F) OPERATION ENABLED. From QUICK STOP ACTIVE it
  first disables voltage (the drive returns through SWITCH ON DISABLED).
- A drive seen in FAULT (or FAULT REACTION ACTIVE) cancels every request: the commander then
  writes "disable voltage" and never resets or re-enables on its own.
- ``fault_reset`` writes 0x00 for one period and then 0x80 (the rising edge of bit 7) for
  one period, then "disable voltage": the drive ends in SWITCH ON DISABLED, not enabled.
- ``start_homing`` (once OPERATION ENABLED): mode = homing with bit 4 low for one period,
  then bit 4 high (the rising edge starts the drive's homing method) until the drive reports
  "homing attained" and "target reached" after having been seen in progress (or after
  "attained" was seen clear just before the start edge: a drive starting on its reference
  edge may finish within one period); then back to the position mode. "Homing error"
  (bit 13 in homing mode) or leaving OPERATION ENABLED ends the homing unsuccessfully.
- A successful homing stays "active" for one more period, in position mode with the target
  at the actual position: the drive moves its encoder frame to the machine frame at the
  reference and may finish within the same period, so the first period that shows the new
  frame must still be one in which the master commands the axis where it is (a command
  position from the old frame would be a jump of the whole offset).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from app.drivers.contracts import (
    CW_DISABLE_VOLTAGE,
    CW_ENABLE_OPERATION,
    CW_FAULT_RESET,
    CW_QUICK_STOP,
    CW_SHUTDOWN,
    CW_SWITCH_ON,
    SW_FOLLOWING_ERROR,
    SW_HOMING_ATTAINED,
    SW_TARGET_REACHED,
    Cia402State,
    decode_statusword,
)

CW_HOMING_START = 1 << 4  # controlword bit 4 in homing mode: homing operation start
SW_HOMING_ERROR = SW_FOLLOWING_ERROR  # statusword bit 13 in homing mode: homing error

S = Cia402State


class PowerRequest(enum.Enum):
    NONE = "none"  # nothing asked: disable voltage
    ENABLE = "enable"
    DISABLE = "disable"
    QUICK_STOP = "quick stop"


class HomingPhase(enum.Enum):
    IDLE = "idle"
    WAIT_ENABLED = "wait for operation enabled"
    ARM = "homing mode, bit 4 low"
    START = "bit 4 high"
    RUNNING = "running"
    FINISH = "one more period at the actual position, in position mode"


# Enable walk: state -> controlword that moves it one step towards OPERATION ENABLED.
ENABLE_WALK: dict[Cia402State, int] = {
    S.NOT_READY_TO_SWITCH_ON: CW_DISABLE_VOLTAGE,  # wait for the drive's self-test
    S.SWITCH_ON_DISABLED: CW_SHUTDOWN,  # transition 2
    S.READY_TO_SWITCH_ON: CW_SWITCH_ON,  # transition 3
    S.SWITCHED_ON: CW_ENABLE_OPERATION,  # transition 4
    S.OPERATION_ENABLED: CW_ENABLE_OPERATION,  # stay
    S.QUICK_STOP_ACTIVE: CW_DISABLE_VOLTAGE,  # transition 12, then walk again
}


@dataclass(frozen=True)
class Command:
    controlword: int
    mode: int
    track_actual: bool  # write the actual position as target (drive not following setpoints)


@dataclass(frozen=True)
class HomingOutcome:
    """What the last homing run ended with (``ok`` False: ``reason`` says why)."""

    ok: bool
    reason: str = ""


class Cia402Commander:
    def __init__(self, position_mode: int, homing_mode: int) -> None:
        self.position_mode = position_mode
        self.homing_mode = homing_mode
        self._request = PowerRequest.NONE
        self._reset_steps: list[int] = []
        self._homing = HomingPhase.IDLE
        self._seen_in_progress = False
        self._state = S.NOT_READY_TO_SWITCH_ON
        self._statusword = 0
        self.last_homing: HomingOutcome | None = None

    # -- requests (non-blocking; take effect with the next command) ----------------------
    def enable(self) -> None:
        self._request = PowerRequest.ENABLE

    def disable(self) -> None:
        self._request = PowerRequest.DISABLE
        self._abort_homing("disabled")

    def quick_stop(self) -> None:
        self._request = PowerRequest.QUICK_STOP
        self._abort_homing("quick stop")

    def fault_reset(self) -> None:
        self._request = PowerRequest.NONE
        self._abort_homing("fault reset")
        self._reset_steps = [CW_DISABLE_VOLTAGE, CW_FAULT_RESET]

    def start_homing(self) -> None:
        """Raises ValueError when the drive is neither enabled nor being enabled."""
        if self._state is not S.OPERATION_ENABLED and self._request is not PowerRequest.ENABLE:
            raise ValueError("homing needs the drive enabled (enable it first)")
        self._homing = HomingPhase.WAIT_ENABLED
        self._seen_in_progress = False
        self.last_homing = None

    @property
    def homing_active(self) -> bool:
        return self._homing is not HomingPhase.IDLE

    @property
    def state(self) -> Cia402State:
        return self._state

    # -- each period ------------------------------------------------------------------------
    def observe(self, statusword: int) -> HomingOutcome | None:
        """Take in the statusword read this period; returns the homing outcome when a homing
        run ends in this period."""
        self._statusword = statusword
        state = decode_statusword(statusword)
        self._state = state
        if state in (S.FAULT, S.FAULT_REACTION_ACTIVE):
            self._request = PowerRequest.NONE
            return self._abort_homing("drive fault")
        phase = self._homing
        if phase in (HomingPhase.START, HomingPhase.RUNNING):
            if state is not S.OPERATION_ENABLED:
                return self._abort_homing(f"drive left operation enabled ({state.value})")
            if phase is HomingPhase.START:
                self._homing = HomingPhase.RUNNING
            attained = statusword & SW_HOMING_ATTAINED
            reached = statusword & SW_TARGET_REACHED
            if statusword & SW_HOMING_ERROR:
                return self._abort_homing("the drive reports a homing error")
            if not attained and not reached:
                self._seen_in_progress = True
            elif attained and reached and self._seen_in_progress:
                self._homing = HomingPhase.FINISH
                self.last_homing = HomingOutcome(True)
                return self.last_homing
            elif reached and not attained and self._seen_in_progress:
                return self._abort_homing("homing stopped without finding the reference")
        elif phase is HomingPhase.ARM:
            if state is not S.OPERATION_ENABLED:
                return self._abort_homing(f"drive left operation enabled ({state.value})")
            # Homing mode, bit 4 still low: a clear "attained" bit now means an "attained"
            # after the start edge belongs to this run, even if the drive finishes within
            # one period (it started on the reference edge); a set one is an earlier run's
            # (or CSP's "drive follows"), and the run must be seen in progress first.
            self._seen_in_progress = not statusword & SW_HOMING_ATTAINED
        return None

    def command(self) -> Command:
        """The controlword and mode for this period (consumes one-period steps)."""
        if self._reset_steps:
            return Command(self._reset_steps.pop(0), self.position_mode, True)
        request = self._request
        state = self._state
        if request is PowerRequest.ENABLE:
            controlword = ENABLE_WALK.get(state, CW_DISABLE_VOLTAGE)
        elif request is PowerRequest.QUICK_STOP:
            controlword = CW_QUICK_STOP
        else:
            controlword = CW_DISABLE_VOLTAGE
        enabled = state is S.OPERATION_ENABLED
        phase = self._homing
        if phase is HomingPhase.WAIT_ENABLED and enabled:
            phase = self._homing = HomingPhase.ARM
            return Command(controlword, self.homing_mode, True)
        if phase is HomingPhase.ARM:
            self._homing = HomingPhase.START
            return Command(controlword | CW_HOMING_START, self.homing_mode, True)
        if phase in (HomingPhase.START, HomingPhase.RUNNING):
            return Command(controlword | CW_HOMING_START, self.homing_mode, True)
        if phase is HomingPhase.FINISH:
            self._homing = HomingPhase.IDLE
            return Command(controlword, self.position_mode, True)
        return Command(
            controlword, self.position_mode, not enabled or phase is not HomingPhase.IDLE
        )

    def _abort_homing(self, reason: str) -> HomingOutcome | None:
        if self._homing is HomingPhase.IDLE:
            return None
        self._homing = HomingPhase.IDLE
        self.last_homing = HomingOutcome(False, reason)
        return self.last_homing
