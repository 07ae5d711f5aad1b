"""One simulated servo drive, as a CiA 402 device would behave on the bus.

Why a model and not a shortcut: the machine layer must be tested against what a real drive
shows, so everything it learns comes through the same registers: the controlword it writes,
the statusword (exactly the patterns of :mod:`app.drivers.contracts`), the position, velocity
and following error it reads, and the CiA 301 emergency codes a fault sends. A fault is never a
flag the machine layer could not get from a real drive.

What is modelled:

- The power state machine (CiA 402 figure "state machine", transitions 0-16 in
  :data:`app.drivers.sim.cia402.TRANSITIONS`), evaluated on every controlword the master
  writes; fault reset is the rising edge of bit 7 and ends in SWITCH ON DISABLED. Quick stop
  option code 6 (brake on the quick-stop ramp and stay in QUICK STOP ACTIVE); disable
  operation, shutdown and disable voltage remove torque at once (the load coasts against
  friction).
- Cyclic synchronous position mode (0x6060 = 8): each SYNC brings a target; the drive
  interpolates linearly from the previous target over one interpolation period (0x60C2 = the
  machine's period) and feeds the target velocity forward. A PI position loop plus the
  feed-forward command an inner velocity loop (first order, ``velocity_time_constant_s``)
  whose acceleration is bounded by the current limit; the load sees Coulomb friction. The
  following error (position demand - actual, 0x60F4) is therefore physical: tiny at constant
  speed, larger while accelerating, unbounded when the demand outruns the current limit.
- A drive that is not OPERATION ENABLED (or is in FAULT) applies no torque and does not
  follow targets; its position demand tracks the actual position, so enabling never jumps.
- Monitoring: following error beyond ``following_error_limit`` for longer than
  ``following_error_time_s`` -> fault 0x8611 (statusword bit 13 is set while it is beyond);
  a limit switch reached while enabled -> fault 0xFF01 (positive) / 0xFF02 (negative); after
  a fault reset the axis may be enabled on the switch but a target that moves further into
  the switch faults again, while targets leading away are followed; no master for
  ``heartbeat_timeout_s`` while powered -> fault 0x8130; an injected power stage fault ->
  0x2310 (and the fault cannot be reset while the injection lasts).
- Fault reaction: brake on the quick-stop ramp (FAULT REACTION ACTIVE), then FAULT with torque
  off; a power stage fault removes torque at once.
- Safe torque off (E-stop, stop category 1): an enabled drive brakes on its quick-stop ramp
  (QUICK STOP ACTIVE), then torque is removed at standstill or after ``estop_stop_time_s``
  and the drive shows SWITCH ON DISABLED; while STO is active it refuses to leave that state.
- Homing mode (0x6060 = 6), started by the rising edge of controlword bit 4 in OPERATION
  ENABLED: a home-switch method with reversal at the limit switches. The drive searches the
  switch at ``homing_velocity`` in ``homing_direction``; found, it backs off until the switch
  releases and approaches again at a tenth of that speed; the switch's reference edge is
  latched as ``home_switch_position`` (the same frame as an absolute encoder), the drive
  stops, and statusword bits 10 (target reached) and 12 (homing attained) are set. Starting on
  the switch it first moves off it; starting beyond the switch it reverses at the limit
  switch and passes the switch before approaching; reaching the other limit switch as well
  faults with 0xFF03. Accelerations use the axis' ``jog_acceleration``.
- Encoders: an absolute axis reports the true position and is homed from power-up; an
  incremental one counts from 0 at power-up (its true position is arbitrary) and is unhomed
  until it has homed.

Mode-dependent statusword bits as in CiA 402: in CSP bit 12 = drive follows the command value,
bit 13 = following error; in homing mode bit 10 = target reached, bit 12 = homing attained.
Bit 9 (remote) is always set; bits 7 (warning) and 11 (internal limit) while a limit switch is
active; bit 4 (voltage enabled) in the powered states.
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from dataclasses import dataclass

from app.config import AxisConfig
from app.drivers.cia402 import (
    CW_FAULT_RESET,
    CW_HOMING_START,
    SW_DRIVE_FOLLOWS,
    SW_FOLLOWING_ERROR,
    SW_HOMING_ATTAINED,
    SW_INTERNAL_LIMIT,
    SW_REMOTE,
    SW_TARGET_REACHED,
    SW_VOLTAGE_ENABLED,
    SW_WARNING,
    Cia402State,
    OperationMode,
)
from app.drivers.contracts import AxisFeedback
from app.drivers.emcy import emcy_text
from app.drivers.sim.cia402 import (
    STATUSWORD_BASE,
    TRANSITIONS,
    VENDOR_EMCY_TEXT,
    EmcyCode,
    decode_controlword,
)
from app.drivers.sim.settings import SimSettings

S = Cia402State

CREEP_DIVISOR = 10.0  # slow approach of the home switch at homing_velocity / 10
VELOCITY_LIMIT_FACTOR = 1.5  # motor speed limit as a multiple of the axis' max_velocity
QUICK_STOP_SHARE = 0.6  # quick-stop deceleration as a share of the current limit


_POWERED = (S.READY_TO_SWITCH_ON, S.SWITCHED_ON, S.OPERATION_ENABLED, S.QUICK_STOP_ACTIVE)
# Module constants: faster than enum attribute lookups in the substep.
_OE = S.OPERATION_ENABLED
_QSA = S.QUICK_STOP_ACTIVE
_FRA = S.FAULT_REACTION_ACTIVE
_FAULT = S.FAULT
_CSP = OperationMode.CYCLIC_SYNC_POSITION


class HomingPhase(enum.Enum):
    LEAVE = "move off the switch"  # started on the switch
    SEARCH = "search the switch"
    REVERSE = "reversed at the limit switch, pass the switch"
    BACKOFF = "back off the switch"
    APPROACH = "approach the edge slowly"
    STOP = "stop"


@dataclass(frozen=True, slots=True)
class DriveParams:
    """Everything one drive needs, in axis units (mm or degrees) and seconds."""

    period_s: float  # interpolation time period (0x60C2)
    substeps_per_period: int
    position_gain_1_s: float
    integral_gain_1_s2: float
    velocity_time_constant_s: float
    acceleration_limit: float
    quick_stop_deceleration: float
    friction_acceleration: float
    velocity_limit: float
    following_error_window: float
    following_error_time_s: float
    heartbeat_timeout_s: float
    sto_delay_s: float
    limit_negative_at: float
    limit_positive_at: float
    home_switch_position: float  # reference edge of the cam
    home_cam_low: float
    home_cam_high: float
    homing_direction: int
    homing_velocity: float
    homing_acceleration: float
    absolute_encoder: bool

    @classmethod
    def from_config(
        cls, axis: AxisConfig, settings: SimSettings, period_s: float, substeps_per_period: int
    ) -> DriveParams:
        default_width = 5.0 if axis.unit == "deg" else 20.0
        width = settings.home_switch_width.get(axis.name, default_width)
        edge = axis.home_switch_position
        low, high = (edge - width, edge) if axis.homing_direction < 0 else (edge, edge + width)
        limit = settings.torque_limit_factor * axis.max_acceleration
        return cls(
            period_s=period_s,
            substeps_per_period=substeps_per_period,
            position_gain_1_s=settings.position_gain_1_s,
            integral_gain_1_s2=settings.position_gain_1_s / settings.integral_time_s,
            velocity_time_constant_s=settings.velocity_time_constant_s,
            acceleration_limit=limit,
            quick_stop_deceleration=QUICK_STOP_SHARE * limit,
            friction_acceleration=settings.friction_fraction * axis.max_acceleration,
            velocity_limit=VELOCITY_LIMIT_FACTOR * axis.max_velocity,
            following_error_window=axis.following_error_limit,
            following_error_time_s=settings.following_error_time_s,
            heartbeat_timeout_s=settings.heartbeat_timeout_s,
            sto_delay_s=settings.estop_stop_time_s,
            limit_negative_at=axis.min_position - axis.limit_switch_margin,
            limit_positive_at=axis.max_position + axis.limit_switch_margin,
            home_switch_position=edge,
            home_cam_low=low,
            home_cam_high=high,
            homing_direction=axis.homing_direction,
            homing_velocity=axis.homing_velocity,
            homing_acceleration=axis.jog_acceleration,
            absolute_encoder=axis.absolute_encoder,
        )


EmcySink = Callable[[str, int, str], None]


class SimDrive:
    """One axis: drive, motor, load and switches. The master (the sim backend) writes
    controlwords, modes and targets at SYNC; the world calls :meth:`step` every substep."""

    __slots__ = (
        "_cam_before",
        "_cw",
        "_demand",
        "_emcy",
        "_fault_code",
        "_fe_flag",
        "_fe_over_s",
        "_fra_ramp",
        "_hold_fault",
        "_homed",
        "_homing_active",
        "_homing_attained",
        "_homing_phase",
        "_integral",
        "_jammed",
        "_k",
        "_lim_neg",
        "_lim_pos",
        "_link_lost_s",
        "_link_ok",
        "_mode",
        "_offset",
        "_p",
        "_state",
        "_sto",
        "_sto_s",
        "_stuck_negative",
        "_stuck_positive",
        "_target",
        "_target_prev",
        "_unusual",
        "_v",
        "_vff",
        "_was_neg",
        "_was_pos",
        "name",
        "params",
    )

    def __init__(
        self, name: str, params: DriveParams, start_position: float, emcy: EmcySink
    ) -> None:
        self.name = name
        self.params = params
        self._emcy = emcy
        self._p = start_position  # true (physical) position
        self._v = 0.0
        self._offset = 0.0 if params.absolute_encoder else -start_position
        self._homed = params.absolute_encoder
        self._state = S.NOT_READY_TO_SWITCH_ON
        self._cw = 0
        self._mode = OperationMode.CYCLIC_SYNC_POSITION
        enc = start_position + self._offset
        self._demand = enc
        self._vff = 0.0
        self._integral = 0.0
        self._target = enc
        self._target_prev = enc
        self._k = params.substeps_per_period
        self._fe_over_s = 0.0
        self._fe_flag = False
        self._fault_code = 0
        self._fra_ramp = False
        self._homing_active = False
        self._homing_attained = False
        self._homing_phase = HomingPhase.SEARCH
        self._cam_before = False
        self._sto = False
        self._sto_s = 0.0
        self._link_ok = True
        self._link_lost_s = 0.0
        self._hold_fault = False
        self._jammed = False
        self._stuck_positive = False
        self._stuck_negative = False
        self._lim_pos = False
        self._lim_neg = False
        self._update_limits()
        self._unusual = True  # power-up pending: see _check_unusual
        self._was_pos = self._lim_pos  # switch states of the previous substep (edges)
        self._was_neg = self._lim_neg

    # -- what the bus sees ----------------------------------------------------------------
    @property
    def state(self) -> Cia402State:
        return self._state

    @property
    def mode(self) -> OperationMode:
        return self._mode

    @property
    def controlword(self) -> int:
        return self._cw

    @property
    def fault_code(self) -> int:
        return self._fault_code

    @property
    def homed(self) -> bool:
        return self._homed

    @property
    def homing_active(self) -> bool:
        return self._homing_active

    @property
    def position(self) -> float:
        """Actual position as the encoder reports it (0x6064)."""
        return self._p + self._offset

    @property
    def following_error(self) -> float:
        """Position demand - actual position (0x60F4); 0 without torque."""
        if self._torque_on():
            return self._demand - (self._p + self._offset)
        return 0.0

    @property
    def statusword(self) -> int:
        state = self._state
        word = STATUSWORD_BASE[state] | SW_REMOTE
        if state in _POWERED:
            word |= SW_VOLTAGE_ENABLED
        if self._lim_pos or self._lim_neg:
            word |= SW_WARNING | SW_INTERNAL_LIMIT
        if self._mode is OperationMode.HOMING:
            if not self._homing_active:
                word |= SW_TARGET_REACHED
            if self._homing_attained:
                word |= SW_HOMING_ATTAINED
        else:
            if state is S.OPERATION_ENABLED:
                word |= SW_DRIVE_FOLLOWS
            if self._fe_flag:
                word |= SW_FOLLOWING_ERROR
        return word

    def feedback(self) -> AxisFeedback:
        return AxisFeedback(
            name=self.name,
            statusword=self.statusword,
            position=self._p + self._offset,
            velocity=self._v,
            following_error=self.following_error,
            fault_code=self._fault_code,
            homed=self._homed,
            homing_active=self._homing_active,
            home_switch=self.home_switch,
            limit_positive=self._lim_pos,
            limit_negative=self._lim_neg,
        )

    # -- the physical truth, for tests and the technician's view ---------------------------
    @property
    def true_position(self) -> float:
        return self._p

    @property
    def true_velocity(self) -> float:
        return self._v

    @property
    def position_demand(self) -> float:
        return self._demand

    @property
    def home_switch(self) -> bool:
        return self.params.home_cam_low <= self._p <= self.params.home_cam_high

    @property
    def limit_positive(self) -> bool:
        return self._lim_pos

    @property
    def limit_negative(self) -> bool:
        return self._lim_neg

    # -- the master's writes (at SYNC) -----------------------------------------------------
    def write_controlword(self, controlword: int) -> None:
        """Evaluate one controlword: state transitions, fault reset edge, homing bit 4."""
        previous = self._cw
        self._cw = controlword
        state = self._state
        if controlword & CW_FAULT_RESET:
            if not previous & CW_FAULT_RESET and state is S.FAULT and not self._hold_fault:
                self._fault_code = 0  # transition 15
                self._fe_flag = False
                self._fe_over_s = 0.0
                self._enter(S.SWITCH_ON_DISABLED)
            return
        command = decode_controlword(controlword)
        nxt = TRANSITIONS.get((state, command))
        if nxt is not None:
            target_state = nxt[0]
            refused_by_sto = self._sto and (
                (target_state is S.READY_TO_SWITCH_ON and state is S.SWITCH_ON_DISABLED)
                or target_state is S.OPERATION_ENABLED
            )
            if not refused_by_sto:
                self._enter(target_state)
        if self._state is S.OPERATION_ENABLED and self._mode is OperationMode.HOMING:
            start = controlword & CW_HOMING_START
            if start and not previous & CW_HOMING_START:
                self._start_homing()
            elif not start and self._homing_active:
                self._homing_phase = HomingPhase.STOP  # bit 4 cleared: homing interrupted
                self._homing_active = False

    def set_mode(self, mode: OperationMode) -> None:
        """0x6060 modes of operation. Changing the mode ends a homing run and holds the
        axis where its demand is."""
        if mode is self._mode:
            return
        self._mode = mode
        self._homing_active = False
        self._vff = 0.0
        self._target = self._target_prev = self._demand
        self._k = self.params.substeps_per_period

    def write_target(self, target: float) -> None:
        """The CSP target position of this SYNC (0x607A), in the encoder frame."""
        if (
            self._state is not S.OPERATION_ENABLED
            or self._mode is not OperationMode.CYCLIC_SYNC_POSITION
        ):
            self._target = self._target_prev = target
            return
        previous = self._target
        if self._lim_pos and target > previous + 1e-9:
            self._fault(EmcyCode.POSITIVE_LIMIT_SWITCH, ramp=True)
            return
        if self._lim_neg and target < previous - 1e-9:
            self._fault(EmcyCode.NEGATIVE_LIMIT_SWITCH, ramp=True)
            return
        self._target_prev = previous
        self._target = target
        self._k = 0

    # -- conditions the world imposes -------------------------------------------------------
    def set_sto(self, active: bool) -> None:
        """Safe torque off requested by the safety relay (E-stop chain open)."""
        if active and not self._sto:
            self._sto_s = 0.0
        self._sto = active
        self._check_unusual()

    def set_link(self, ok: bool) -> None:
        if ok:
            self._link_lost_s = 0.0
        self._link_ok = ok
        self._check_unusual()

    def heartbeat_lost(self) -> None:
        """The drive's own watch of the controller (a CANopen heartbeat consumer, 0x1016)
        timed out: a powered drive faults with 0x8130, as on a lost link."""
        if self._state in _POWERED:
            self._fault(EmcyCode.HEARTBEAT, ramp=True)

    def inject_power_stage_fault(self, active: bool) -> None:
        self._hold_fault = active
        self._check_unusual()

    def set_jammed(self, jammed: bool) -> None:
        """A mechanical jam: the load does not move whatever the motor does."""
        self._jammed = jammed
        if jammed:
            self._v = 0.0

    def power_cycle(self) -> None:
        """Power off and on again: the drive's state is lost (an incremental encoder counts
        from 0 again and the axis is no longer homed); what the world imposes (safe torque
        off, a cut link, a jam, stuck switches, an injected fault) stays."""
        kept = (
            self._sto,
            self._link_ok,
            self._hold_fault,
            self._jammed,
            self._stuck_positive,
            self._stuck_negative,
        )
        self.__init__(self.name, self.params, self._p, self._emcy)  # type: ignore[misc]
        (
            self._sto,
            self._link_ok,
            self._hold_fault,
            self._jammed,
            self._stuck_positive,
            self._stuck_negative,
        ) = kept
        self._update_limits()
        self._was_pos, self._was_neg = self._lim_pos, self._lim_neg

    def move_by_hand(self, position: float) -> None:
        """The load pushed to ``position`` (encoder frame) while the drive applies no torque,
        as a setter does on a disabled axis; a powered drive holds its axis, so it refuses."""
        if self._torque_on():
            raise ValueError(f"{self.name}: move_by_hand needs a drive without torque")
        self._p = position - self._offset
        self._v = 0.0
        self._demand = self._target = self._target_prev = position
        self._update_limits()

    def stick_limit_switch(self, positive: bool, active: bool) -> None:
        """A limit switch that reads active wherever the axis is (hit by something)."""
        if positive:
            self._stuck_positive = active
        else:
            self._stuck_negative = active
        self._update_limits()

    # -- internals ------------------------------------------------------------------------
    def _check_unusual(self) -> None:
        """One flag for the rare conditions, so that a normal substep tests only it."""
        self._unusual = (
            self._sto
            or not self._link_ok
            or self._hold_fault
            or self._state is S.NOT_READY_TO_SWITCH_ON
        )

    def _torque_on(self) -> bool:
        state = self._state
        return (
            state is S.OPERATION_ENABLED
            or state is S.QUICK_STOP_ACTIVE
            or (state is S.FAULT_REACTION_ACTIVE and self._fra_ramp)
        )

    def _update_limits(self) -> None:
        p = self._p
        self._lim_pos = self._stuck_positive or p >= self.params.limit_positive_at
        self._lim_neg = self._stuck_negative or p <= self.params.limit_negative_at

    def _enter(self, state: Cia402State) -> None:
        old = self._state
        self._state = state
        if state is S.OPERATION_ENABLED:
            if old is not S.QUICK_STOP_ACTIVE:
                self._demand = self._p + self._offset
                self._integral = 0.0
            self._vff = 0.0
            self._target = self._target_prev = self._demand
            self._k = self.params.substeps_per_period
        else:
            self._homing_active = False
            if state is S.QUICK_STOP_ACTIVE:
                self._brake_from_actual()
            else:
                self._vff = 0.0
                self._integral = 0.0

    def _brake_from_actual(self) -> None:
        """A quick stop or fault reaction brakes the motion the load really has: the ramp
        starts from the actual position and velocity."""
        self._demand = self._p + self._offset
        self._vff = self._v
        self._integral = 0.0

    def _fault(self, code: int, *, ramp: bool) -> None:
        if self._state is S.FAULT_REACTION_ACTIVE or self._state is S.FAULT:
            return
        self._fra_ramp = ramp and self._torque_on()
        if self._fra_ramp:
            self._brake_from_actual()
        self._fault_code = int(code)
        self._homing_active = False
        self._state = S.FAULT_REACTION_ACTIVE  # transition 13
        if self._link_ok:  # an EMCY sent while the bus is down is lost
            self._emcy(self.name, int(code), emcy_text(int(code), VENDOR_EMCY_TEXT))

    def _start_homing(self) -> None:
        self._homing_active = True
        self._homing_attained = False
        self._homed = False
        self._demand = self._p + self._offset
        self._vff = 0.0
        self._cam_before = self.home_switch
        self._homing_phase = HomingPhase.LEAVE if self._cam_before else HomingPhase.SEARCH

    def _homing_velocity(self, dt: float) -> None:
        """One substep of the homing method: watch the switches, choose the demand velocity
        of this substep (the demand itself moves after the loop, see :meth:`step`).

        Only edges of the home switch seen while moving the right way count: an axis that
        overshoots through a short cam while braking must not mistake the far edge for the
        reference edge."""
        params = self.params
        direction = params.homing_direction
        phase = self._homing_phase
        cam = self.home_switch
        rising = cam and not self._cam_before
        falling = self._cam_before and not cam
        self._cam_before = cam
        moving = self._vff
        ahead_limit = self._lim_pos if direction > 0 else self._lim_neg
        behind_limit = self._lim_neg if direction > 0 else self._lim_pos
        speed = params.homing_velocity
        if phase is HomingPhase.SEARCH:
            if cam:
                phase = HomingPhase.BACKOFF
            elif ahead_limit:
                phase = HomingPhase.REVERSE
        elif phase is HomingPhase.APPROACH:
            if rising and moving * direction > 0:
                # Latch the reference edge: from here on the encoder reads the machine frame.
                shift = -self._offset
                self._offset = 0.0
                self._demand += shift
                self._target += shift
                self._target_prev += shift
                phase = HomingPhase.STOP
            elif ahead_limit and moving * direction > 0:
                self._fault(EmcyCode.HOMING_FAILED, ramp=True)
                return
        elif phase is not HomingPhase.STOP:  # LEAVE, REVERSE, BACKOFF: against the direction
            backing = moving * direction < 0
            if behind_limit and backing:
                self._fault(EmcyCode.HOMING_FAILED, ramp=True)
                return
            if falling and backing:  # left the cam at its reference edge
                phase = HomingPhase.APPROACH
        self._homing_phase = phase
        if phase is HomingPhase.SEARCH:
            wanted = direction * speed
        elif phase is HomingPhase.APPROACH:
            wanted = direction * speed / CREEP_DIVISOR
        elif phase is HomingPhase.STOP:
            wanted = 0.0
        else:
            wanted = -direction * speed
        step = params.homing_acceleration * dt
        delta = wanted - moving
        moving = moving + (step if delta > step else -step if delta < -step else delta)
        self._vff = moving
        if phase is HomingPhase.STOP and moving == 0.0:
            self._homing_active = False
            self._homing_attained = True
            self._homed = True
            self._target = self._target_prev = self._demand

    def _monitor_unusual(self, dt: float) -> None:
        """Power-up, lost master, injected power stage fault, safe torque off."""
        params = self.params
        if self._state is S.NOT_READY_TO_SWITCH_ON:
            self._state = S.SWITCH_ON_DISABLED  # transitions 0 and 1: self-test done
        if not self._link_ok:
            self._link_lost_s += dt
            if self._link_lost_s >= params.heartbeat_timeout_s and self._state in _POWERED:
                self._fault(EmcyCode.HEARTBEAT, ramp=True)
        state = self._state
        if self._hold_fault and state is not S.FAULT_REACTION_ACTIVE and state is not S.FAULT:
            self._fault(EmcyCode.CONTINUOUS_OVERCURRENT, ramp=False)
        state = self._state
        if self._sto:
            if state is S.READY_TO_SWITCH_ON or state is S.SWITCHED_ON:
                self._enter(S.SWITCH_ON_DISABLED)
            elif state is S.OPERATION_ENABLED:
                self._enter(S.QUICK_STOP_ACTIVE)
            elif state is S.QUICK_STOP_ACTIVE:
                self._sto_s += dt
                if self._vff == 0.0 or self._sto_s >= params.sto_delay_s:
                    self._enter(S.SWITCH_ON_DISABLED)
        self._check_unusual()

    def step(self, dt: float) -> None:
        """Advance drive, motor and load by one substep.

        Written for speed (this runs 3000 times per simulated second): locals instead of
        repeated attribute lookups, the rare conditions behind one flag."""
        params = self.params
        p = self._p
        lim_pos = self._lim_pos = self._stuck_positive or p >= params.limit_positive_at
        lim_neg = self._lim_neg = self._stuck_negative or p <= params.limit_negative_at
        if self._unusual:
            self._monitor_unusual(dt)
        state = self._state
        if state is _OE and not self._homing_active:
            if lim_pos and not self._was_pos:
                self._fault(EmcyCode.POSITIVE_LIMIT_SWITCH, ramp=True)
                state = self._state
            elif lim_neg and not self._was_neg:
                self._fault(EmcyCode.NEGATIVE_LIMIT_SWITCH, ramp=True)
                state = self._state
        self._was_pos = lim_pos
        self._was_neg = lim_neg

        # The demand velocity of this substep; the loop works on the demand at its start.
        csp = False
        if state is _OE:
            if self._mode is _CSP:
                csp = True
                vff = (
                    (self._target - self._target_prev) / params.period_s
                    if self._k < params.substeps_per_period
                    else 0.0
                )
                self._vff = vff
            elif self._homing_active:
                self._homing_velocity(dt)  # a homing fault brakes on the ramp, with torque
                vff = self._vff
            else:
                vff = self._vff = 0.0
        elif state is _QSA or (state is _FRA and self._fra_ramp):
            self._ramp_velocity(dt)
            vff = self._vff
        else:
            # No torque: the load coasts, the demand follows the actual position.
            if state is _FRA:
                self._state = _FAULT  # transition 14 (no ramp: torque removed at once)
            v = self._v
            if v != 0.0 and not self._jammed:
                friction = params.friction_acceleration
                new_v = v - friction * dt if v > 0.0 else v + friction * dt
                v = new_v if (new_v > 0.0) == (v > 0.0) else 0.0
                p += v * dt
                self._p = p
            else:
                v = 0.0
            self._v = v
            self._demand = p + self._offset
            self._integral = 0.0
            self._vff = 0.0
            self._fe_flag = False
            self._fe_over_s = 0.0
            return

        # Position loop (PI + feed-forward), velocity loop with current limit.
        v = self._v
        offset = self._offset
        error = self._demand - (p + offset)
        integral = self._integral + error * dt
        self._integral = integral
        v_cmd = vff + params.position_gain_1_s * error + params.integral_gain_1_s2 * integral
        v_limit = params.velocity_limit
        if v_cmd > v_limit:
            v_cmd = v_limit
        elif v_cmd < -v_limit:
            v_cmd = -v_limit
        a = (v_cmd - v) / params.velocity_time_constant_s
        a_limit = params.acceleration_limit
        if a > a_limit:
            a = a_limit
        elif a < -a_limit:
            a = -a_limit

        # The load, with Coulomb friction (it holds the load still below the friction force).
        if self._jammed:
            v = 0.0
        else:
            friction = params.friction_acceleration
            if v != 0.0:
                new_v = v + (a - friction if v > 0.0 else a + friction) * dt
                if (new_v > 0.0) != (v > 0.0) and -friction <= a <= friction:
                    new_v = 0.0
                v = new_v
            elif a > friction:
                v = (a - friction) * dt
            elif a < -friction:
                v = (a + friction) * dt
            p += v * dt
            self._p = p
        self._v = v

        # The demand at the end of the substep, the same instant as the new position.
        if csp:
            n = params.substeps_per_period
            k = self._k
            if k < n:
                k += 1
                self._k = k
                target_prev = self._target_prev
                demand = target_prev + (self._target - target_prev) * k / n
            else:
                demand = self._target
            self._demand = demand
        else:
            demand = self._demand + vff * dt
            self._demand = demand
            if self._state is _FRA and vff == 0.0:
                self._state = _FAULT  # transition 14: standstill reached, torque off
                self._fra_ramp = False
                return

        # Following error monitoring (enabled, position modes).
        if self._state is _OE:
            error = demand - (p + offset)
            window = params.following_error_window
            if error > window or error < -window:
                self._fe_flag = True
                self._fe_over_s += dt
                if self._fe_over_s > params.following_error_time_s:
                    self._fault(EmcyCode.FOLLOWING_ERROR, ramp=True)
            elif self._fe_flag:
                self._fe_flag = False
                self._fe_over_s = 0.0

    def _ramp_velocity(self, dt: float) -> None:
        """Quick-stop ramp: the demand velocity of this substep, down to standstill."""
        step = self.params.quick_stop_deceleration * dt
        moving = self._vff
        self._vff = moving - step if moving > step else moving + step if moving < -step else 0.0
