"""The one CiA 402 master: what every drive is told each period, on every backend.

Why one module and no fieldbus import: this is where a drive could be enabled, reset or set
moving by accident, so the rule is written once, read in one place and tested row by row. The
simulation, Modbus and CANopen only carry its controlword, mode and target to the drive and
bring the statusword (and, where the bus has it, the mode display 0x6061) back. Pure logic:
one :meth:`Cia402Master.observe` of the latest statusword and one :meth:`Cia402Master.command`
per period, nothing waits, loops or talks to a bus.

The vocabulary (IEC 61800-7-201 / CiA 402): power states decoded from the statusword,
device control commands, statusword bits, modes of operation.

Decisions where a standard-conforming master could do either (written once, for all backends):

- **Enable from QUICK STOP ACTIVE** goes through "disable voltage" 0x00 (transition 12) and
  then the walk 2, 3, 4, not straight to 0x0F (transition 16). Transition 16 exists only for
  quick stop option codes 5 to 8, so it is not portable; and the walk through SWITCH ON
  DISABLED is the one path on which the target is reset to the actual position.
- **The master never re-enables a drive.** An enable request is fulfilled once the drive
  reports OPERATION ENABLED; if the drive then leaves it on its own (safe torque off, a quick
  stop by its own input, a fault), the request drops: to QUICK STOP when the drive is in
  QUICK STOP ACTIVE (its ramp and hold go on; "disable voltage" would let the load coast),
  to DISABLED otherwise. A drive that does not
  follow a step of the walk within ``step_limit_periods`` (safe torque off holds it in SWITCH
  ON DISABLED) drops the request too: nothing is left behind that would power the drive the
  moment the E-stop is released. Enabling again is a new request, made on an operator's
  command.
- **Enable on a faulted drive is refused** with :class:`RequestRefusedError`, never silently
  dropped: only a fault reset (transition 15), which only an operator's Reset asks for, leaves
  FAULT. Enable is refused as well while a fault reset is under way.
- **Fault reset**: controlword 0x00 for one period, then 0x80 (the rising edge of bit 7),
  held until the drive is seen out of FAULT or for ``reset_edge_periods`` at most (a drive
  whose statusword arrives a period late, as CANopen's TPDO sampled at SYNC, must still see
  the edge), then 0x00: the drive ends in SWITCH ON DISABLED with the request DISABLED, never
  enabled. Bit 7 appears nowhere else.
- **Disable and quick stop are always accepted** (the safe direction), in any state, and
  cancel a homing run. Quick stop from a state without torque sends "disable voltage".
- **Homing handshake**: refused unless the drive reports OPERATION ENABLED. Mode 6 with bit 4
  low until the drive shows homing mode (one period when it does not report 0x6061), then
  bit 4 high (the rising edge starts the drive's method), held until "homing attained" and
  "target reached" after the run was seen in progress, or after "attained" was seen clear
  just before the edge (a drive starting on its reference may finish within one period);
  "homing error" (bit 13), reaching the target without the reference after the run was seen,
  leaving OPERATION ENABLED, a fault, disable or quick stop end it unsuccessfully. Then mode 8
  with the target at the actual position until the drive shows the position mode (one period
  without 0x6061): the drive may have moved its encoder frame at the reference, and a command
  position from the old frame would be a jump of the whole offset.
- **Targets**: a drive that is not OPERATION ENABLED in the position mode, or is homing, is
  commanded to its own actual position (``DriveCommand.follows_setpoints`` is False), so that
  enabling it never makes it jump.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass


class Cia402State(enum.Enum):
    """CiA 402 power state machine, decoded from the statusword (same on every backend)."""

    NOT_READY_TO_SWITCH_ON = "not ready to switch on"
    SWITCH_ON_DISABLED = "switch on disabled"
    READY_TO_SWITCH_ON = "ready to switch on"
    SWITCHED_ON = "switched on"
    OPERATION_ENABLED = "operation enabled"
    QUICK_STOP_ACTIVE = "quick stop active"
    FAULT_REACTION_ACTIVE = "fault reaction active"
    FAULT = "fault"


S = Cia402State
FAULT_STATES = (S.FAULT, S.FAULT_REACTION_ACTIVE)

# (mask, value, state) from CiA 402 / IEC 61800-7-201, checked in order.
_STATUSWORD_TABLE: tuple[tuple[int, int, Cia402State], ...] = (
    (0x4F, 0x00, S.NOT_READY_TO_SWITCH_ON),
    (0x4F, 0x40, S.SWITCH_ON_DISABLED),
    (0x6F, 0x21, S.READY_TO_SWITCH_ON),
    (0x6F, 0x23, S.SWITCHED_ON),
    (0x6F, 0x27, S.OPERATION_ENABLED),
    (0x6F, 0x07, S.QUICK_STOP_ACTIVE),
    (0x4F, 0x0F, S.FAULT_REACTION_ACTIVE),
    (0x4F, 0x08, S.FAULT),
)

# Statusword bits beyond the power state.
SW_VOLTAGE_ENABLED = 1 << 4
SW_WARNING = 1 << 7
SW_REMOTE = 1 << 9
SW_TARGET_REACHED = 1 << 10  # in homing mode: homing stopped (target reached)
SW_INTERNAL_LIMIT = 1 << 11
SW_HOMING_ATTAINED = 1 << 12  # in homing mode: homing attained
SW_DRIVE_FOLLOWS = 1 << 12  # in CSP: the drive follows the command value
SW_FOLLOWING_ERROR = 1 << 13  # in position modes: following error
SW_HOMING_ERROR = 1 << 13  # in homing mode: homing error

# Controlwords (CiA 402 device control commands) and bits.
CW_DISABLE_VOLTAGE = 0x00
CW_QUICK_STOP = 0x02
CW_SHUTDOWN = 0x06
CW_SWITCH_ON = 0x07
CW_ENABLE_OPERATION = 0x0F
CW_FAULT_RESET = 0x80  # bit 7: fault reset on its rising edge
CW_HOMING_START = 1 << 4  # bit 4 in homing mode: homing operation start (rising edge)


class OperationMode(enum.IntEnum):
    """0x6060 modes of operation used here (0x6061 displays the one in effect)."""

    HOMING = 6
    CYCLIC_SYNC_POSITION = 8


def decode_statusword(statusword: int) -> Cia402State:
    """Return the power state a statusword encodes; unknown patterns are reported as
    NOT_READY_TO_SWITCH_ON, the only state in which a drive accepts no command."""
    for mask, value, state in _STATUSWORD_TABLE:
        if statusword & mask == value:
            return state
    return S.NOT_READY_TO_SWITCH_ON


class PowerRequest(enum.Enum):
    """What the machine asked this drive to be."""

    DISABLED = "disabled"
    ENABLED = "enabled"
    QUICK_STOP = "quick stop"


R = PowerRequest

# (request, reported state) -> controlword; CiA 402 transition numbers in the comments.
# Bit 7 (fault reset) appears in no row: only Cia402Master.fault_reset sets it.
NEXT_CONTROLWORD: dict[tuple[PowerRequest, Cia402State], int] = {
    (R.ENABLED, S.NOT_READY_TO_SWITCH_ON): CW_DISABLE_VOLTAGE,  # wait for 1 (self-test)
    (R.ENABLED, S.SWITCH_ON_DISABLED): CW_SHUTDOWN,  # 2
    (R.ENABLED, S.READY_TO_SWITCH_ON): CW_SWITCH_ON,  # 3
    (R.ENABLED, S.SWITCHED_ON): CW_ENABLE_OPERATION,  # 4
    (R.ENABLED, S.OPERATION_ENABLED): CW_ENABLE_OPERATION,  # stay
    (R.ENABLED, S.QUICK_STOP_ACTIVE): CW_DISABLE_VOLTAGE,  # 12, then 2, 3, 4 (not 16)
    (R.ENABLED, S.FAULT_REACTION_ACTIVE): CW_DISABLE_VOLTAGE,  # never bit 7
    (R.ENABLED, S.FAULT): CW_DISABLE_VOLTAGE,  # never bit 7
    (R.DISABLED, S.NOT_READY_TO_SWITCH_ON): CW_DISABLE_VOLTAGE,
    (R.DISABLED, S.SWITCH_ON_DISABLED): CW_DISABLE_VOLTAGE,  # stay
    (R.DISABLED, S.READY_TO_SWITCH_ON): CW_DISABLE_VOLTAGE,  # 7
    (R.DISABLED, S.SWITCHED_ON): CW_DISABLE_VOLTAGE,  # 10
    (R.DISABLED, S.OPERATION_ENABLED): CW_DISABLE_VOLTAGE,  # 9
    (R.DISABLED, S.QUICK_STOP_ACTIVE): CW_DISABLE_VOLTAGE,  # 12
    (R.DISABLED, S.FAULT_REACTION_ACTIVE): CW_DISABLE_VOLTAGE,
    (R.DISABLED, S.FAULT): CW_DISABLE_VOLTAGE,
    (R.QUICK_STOP, S.NOT_READY_TO_SWITCH_ON): CW_DISABLE_VOLTAGE,
    (R.QUICK_STOP, S.SWITCH_ON_DISABLED): CW_DISABLE_VOLTAGE,  # stay
    (R.QUICK_STOP, S.READY_TO_SWITCH_ON): CW_QUICK_STOP,  # 7
    (R.QUICK_STOP, S.SWITCHED_ON): CW_QUICK_STOP,  # 10
    (R.QUICK_STOP, S.OPERATION_ENABLED): CW_QUICK_STOP,  # 11
    (R.QUICK_STOP, S.QUICK_STOP_ACTIVE): CW_QUICK_STOP,  # stay, holding
    (R.QUICK_STOP, S.FAULT_REACTION_ACTIVE): CW_DISABLE_VOLTAGE,
    (R.QUICK_STOP, S.FAULT): CW_DISABLE_VOLTAGE,
}

# The enable walk's order: a state the drive falls back to from a higher one ends the walk.
_WALK_RANK: dict[Cia402State, int] = {
    S.NOT_READY_TO_SWITCH_ON: 0,
    S.SWITCH_ON_DISABLED: 1,
    S.QUICK_STOP_ACTIVE: 1,
    S.READY_TO_SWITCH_ON: 2,
    S.SWITCHED_ON: 3,
    S.OPERATION_ENABLED: 4,
}


class Refusal(enum.Enum):
    """Why the master refused a request."""

    ENABLE_IN_FAULT = "the drive is in FAULT: an operator's fault reset comes first"
    ENABLE_DURING_RESET = "a fault reset is in progress"
    HOMING_NOT_ENABLED = "homing needs OPERATION ENABLED (enable the drive first)"


class RequestRefusedError(Exception):
    """A request the drive's present state does not allow; ``refusal`` says which rule."""

    def __init__(self, refusal: Refusal, state: Cia402State) -> None:
        super().__init__(f"{refusal.value} (the drive is {state.value})")
        self.refusal = refusal
        self.state = state


class ResetPhase(enum.Enum):
    NONE = "none"
    ZERO = "controlword 0x00"  # bit 7 low for one period before the edge
    EDGE = "controlword 0x80"  # bit 7 high until the drive leaves FAULT


class HomingPhase(enum.Enum):
    IDLE = "idle"
    SELECT_MODE = "select homing mode"  # mode 6, bit 4 low, until the drive shows mode 6
    START = "start"  # the next command carries bit 4 (its rising edge starts homing)
    RUNNING = "running"  # bit 4 held until attained, error or an abort
    RETURN = "return to the position mode"  # mode 8, target = actual, until shown


@dataclass(frozen=True)
class DriveCommand:
    """What one drive gets this period. ``follows_setpoints`` False: send the drive's own
    actual position as target (it is not enabled in the position mode, or it homes)."""

    controlword: int
    mode: OperationMode
    follows_setpoints: bool


@dataclass(frozen=True)
class HomingOutcome:
    """How a homing run ended (``ok`` False: ``reason`` says why)."""

    ok: bool
    reason: str = ""


class Cia402Master:
    """The master's side of one drive.

    ``reports_mode``: the drive's mode display (0x6061) comes with every statusword (CANopen
    TPDO, the simulation); without it (a Modbus map without that register) a mode written is
    taken as in effect one period later. ``homed``: the axis' position is known at creation
    (absolute encoder, or homed before and not lost)."""

    def __init__(
        self,
        *,
        reports_mode: bool,
        homed: bool = False,
        step_limit_periods: int = 10,
        reset_edge_periods: int = 25,
    ) -> None:
        self.reports_mode = reports_mode
        self.homed = homed
        self.step_limit_periods = step_limit_periods
        self.reset_edge_periods = reset_edge_periods
        self.request = PowerRequest.DISABLED
        self.reset = ResetPhase.NONE
        self.homing = HomingPhase.IDLE
        self.statusword = 0
        self.mode_display: int | None = None
        self.last_homing: HomingOutcome | None = None
        self.dropped = ""  # why the last enable request was cancelled by the master
        self._reset_edges = 0
        self._reached = False  # the current enable request saw OPERATION ENABLED
        self._walk_state: Cia402State | None = None
        self._walk_periods = 0
        self._sent_mode = OperationMode.CYCLIC_SYNC_POSITION  # the last command's mode
        self._seen_running = False
        self._armed_clear = False

    @property
    def state(self) -> Cia402State:
        return decode_statusword(self.statusword)

    @property
    def homing_active(self) -> bool:
        return self.homing is not HomingPhase.IDLE

    @property
    def follows_setpoints(self) -> bool:
        """The drive takes the machine's targets: enabled, not homing, in the position mode."""
        return (
            self.state is S.OPERATION_ENABLED
            and self.homing is HomingPhase.IDLE
            and self._mode_shown(OperationMode.CYCLIC_SYNC_POSITION)
        )

    # -- requests (the machine decides when; nothing here asks for them) ------------------
    def enable(self) -> None:
        """Walk to OPERATION ENABLED; a request already under way goes on unchanged."""
        state = self.state
        if state in FAULT_STATES:
            raise RequestRefusedError(Refusal.ENABLE_IN_FAULT, state)
        if self.reset is not ResetPhase.NONE:
            raise RequestRefusedError(Refusal.ENABLE_DURING_RESET, state)
        if self.request is PowerRequest.ENABLED:
            return
        self.request = PowerRequest.ENABLED
        self.dropped = ""
        self._reached = state is S.OPERATION_ENABLED
        self._walk_state = state
        self._walk_periods = 0

    def disable(self) -> None:
        self.request = PowerRequest.DISABLED
        self._end_homing("disabled")

    def quick_stop(self) -> None:
        self.request = PowerRequest.QUICK_STOP
        self._end_homing("quick stop")

    def fault_reset(self) -> None:
        """Only ever on an operator's Reset: 0x00, then the edge of bit 7, ending disabled."""
        self.request = PowerRequest.DISABLED
        self._end_homing("fault reset")
        self.reset = ResetPhase.ZERO
        self._reset_edges = 0

    def start_homing(self) -> None:
        state = self.state
        if state is not S.OPERATION_ENABLED:
            raise RequestRefusedError(Refusal.HOMING_NOT_ENABLED, state)
        if self.homing in (HomingPhase.SELECT_MODE, HomingPhase.START, HomingPhase.RUNNING):
            return
        self.homing = HomingPhase.SELECT_MODE
        self._seen_running = False
        self._armed_clear = False
        self.homed = False
        self.last_homing = None

    # -- each period ------------------------------------------------------------------------
    def observe(self, statusword: int, mode_display: int | None = None) -> HomingOutcome | None:
        """Take in the latest statusword (and mode display); returns the homing outcome when
        a run ends with this observation."""
        self.statusword = statusword
        self.mode_display = mode_display
        state = self.state
        if state in FAULT_STATES:
            self.request = PowerRequest.DISABLED  # latched: only the machine enables again
            outcome = self._end_homing("drive fault")
            if outcome is None:
                self._follow_return()
            return outcome
        if self.request is PowerRequest.ENABLED:
            self._follow_walk(state)
        phase = self.homing
        if phase in (HomingPhase.SELECT_MODE, HomingPhase.START, HomingPhase.RUNNING) and (
            state is not S.OPERATION_ENABLED or self.request is not PowerRequest.ENABLED
        ):
            return self._end_homing(f"the drive left operation enabled ({state.value})")
        if phase is HomingPhase.SELECT_MODE and self._mode_shown(OperationMode.HOMING):
            # Bit 4 still low: a clear "attained" now means an "attained" after the edge
            # belongs to this run; a set one is an earlier run's (or CSP's bit 12).
            self._armed_clear = not statusword & SW_HOMING_ATTAINED
            self.homing = HomingPhase.START
        elif phase is HomingPhase.RUNNING:
            return self._follow_homing(statusword)
        else:
            self._follow_return()
        return None

    def command(self) -> DriveCommand:
        """The controlword and mode for this period (consumes one-period steps)."""
        phase = self.homing
        homing_mode = phase in (HomingPhase.SELECT_MODE, HomingPhase.START, HomingPhase.RUNNING)
        mode = OperationMode.HOMING if homing_mode else OperationMode.CYCLIC_SYNC_POSITION
        self._sent_mode = mode
        if self.reset is ResetPhase.ZERO:
            self.reset = ResetPhase.EDGE
            return DriveCommand(CW_DISABLE_VOLTAGE, mode, False)
        if self.reset is ResetPhase.EDGE:
            left_fault = self._reset_edges > 0 and self.state not in FAULT_STATES
            if not left_fault and self._reset_edges < self.reset_edge_periods:
                self._reset_edges += 1
                return DriveCommand(CW_FAULT_RESET, mode, False)
            self.reset = ResetPhase.NONE
        if self.request is PowerRequest.ENABLED:
            self._count_walk_step()
        controlword = NEXT_CONTROLWORD[(self.request, self.state)]
        if controlword == CW_ENABLE_OPERATION and phase is HomingPhase.START:
            self.homing = HomingPhase.RUNNING
            controlword |= CW_HOMING_START
        elif controlword == CW_ENABLE_OPERATION and phase is HomingPhase.RUNNING:
            controlword |= CW_HOMING_START
        return DriveCommand(controlword, mode, self.follows_setpoints)

    # -- internals --------------------------------------------------------------------------
    def _mode_shown(self, mode: OperationMode) -> bool:
        """Whether ``mode`` is in effect: displayed, or (no display) the last one sent."""
        if self.reports_mode:
            return self.mode_display == int(mode)
        return self._sent_mode is mode

    def _follow_return(self) -> None:
        if self.homing is HomingPhase.RETURN and self._mode_shown(
            OperationMode.CYCLIC_SYNC_POSITION
        ):
            self.homing = HomingPhase.IDLE

    def _follow_walk(self, state: Cia402State) -> None:
        """Drop the enable request when the drive leaves OPERATION ENABLED on its own, falls
        back during the walk, or does not follow a step in time."""
        if state is S.OPERATION_ENABLED:
            self._reached = True
            return
        if self._reached:
            self._drop(f"the drive left operation enabled on its own ({state.value})", state)
            return
        previous = self._walk_state
        if previous is not None and _WALK_RANK[state] < _WALK_RANK[previous]:
            self._drop(f"the drive fell back from {previous.value} to {state.value}")
        elif state is not previous:
            self._walk_state = state
            self._walk_periods = 0

    def _count_walk_step(self) -> None:
        """Once per command: a step the drive has not followed for ``step_limit_periods``
        commands is refused (safe torque off holds it); the self-test is waited for."""
        state = self.state
        if self._reached or state is S.NOT_READY_TO_SWITCH_ON or state is not self._walk_state:
            return
        self._walk_periods += 1
        if self._walk_periods > self.step_limit_periods:
            self._drop(
                f"the drive stayed in {state.value} for {self._walk_periods} periods "
                "(safe torque off?)"
            )

    def _drop(self, reason: str, state: Cia402State | None = None) -> None:
        """A drive that quick-stopped on its own (safe torque off, stop category 1) keeps
        its ramp and its hold: quick stop, not "disable voltage", which would let it coast."""
        quick = state is S.QUICK_STOP_ACTIVE
        self.request = PowerRequest.QUICK_STOP if quick else PowerRequest.DISABLED
        self.dropped = f"enable cancelled: {reason}; not re-enabled without a new request"

    def _follow_homing(self, statusword: int) -> HomingOutcome | None:
        attained = statusword & SW_HOMING_ATTAINED
        reached = statusword & SW_TARGET_REACHED
        if not self._mode_shown(OperationMode.HOMING):
            return None
        if statusword & SW_HOMING_ERROR:
            return self._end_homing("the drive reports a homing error")
        if not attained and not reached:
            self._seen_running = True
        elif attained and reached and (self._seen_running or self._armed_clear):
            self.homing = HomingPhase.RETURN
            self.homed = True
            self.last_homing = HomingOutcome(True)
            return self.last_homing
        elif reached and not attained and self._seen_running:
            return self._end_homing("homing stopped without finding the reference")
        return None

    def _end_homing(self, reason: str) -> HomingOutcome | None:
        if self.homing not in (HomingPhase.SELECT_MODE, HomingPhase.START, HomingPhase.RUNNING):
            return None
        self.homing = HomingPhase.RETURN
        self.last_homing = HomingOutcome(False, reason)
        return self.last_homing
