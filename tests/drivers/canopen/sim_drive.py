"""The old CiA 402 drive model of the CANopen tests (its own power state machine, position
equal to the target at every SYNC), kept only for the tests not yet moved onto the simulated
world's drives (:mod:`tests.drivers.canopen.world_nodes`)."""

from __future__ import annotations

from dataclasses import dataclass, field

from canopen.sdo import SdoAbortedError

from app.drivers.canopen import objects as obj
from app.drivers.cia402 import CW_HOMING_START, Cia402State, OperationMode
from tests.drivers.canopen.sim_nodes import SimIoNode, SimNetwork, SimNode

S = Cia402State
MODE_CSP = int(OperationMode.CYCLIC_SYNC_POSITION)
MODE_HOMING = int(OperationMode.HOMING)
SUPPORTED_HOMING_METHODS = frozenset({17, 18, 19, 20, 21, 22, 33, 34, 35, 37})
ABORT_VALUE_RANGE = 0x06090030
EMCY_HEARTBEAT = 0x8130  # CiA 301: life guard or heartbeat error
POWERED = (Cia402State.OPERATION_ENABLED, Cia402State.QUICK_STOP_ACTIVE)


# ---- CiA 402 drive ---------------------------------------------------------------------------


def _command(controlword: int) -> str:
    """Device control command of a controlword (bit 7 clear), CiA 402 table."""
    if controlword & 0x82 == 0x00:
        return "disable voltage"
    if controlword & 0x86 == 0x02:
        return "quick stop"
    if controlword & 0x87 == 0x06:
        return "shutdown"
    if controlword & 0x8F == 0x07:
        return "switch on"
    if controlword & 0x8F == 0x0F:
        return "enable operation"
    return "none"


# (state, command) -> next state; CiA 402 transition numbers in the comments.
DRIVE_TRANSITIONS: dict[tuple[Cia402State, str], Cia402State] = {
    (S.SWITCH_ON_DISABLED, "shutdown"): S.READY_TO_SWITCH_ON,  # 2
    (S.READY_TO_SWITCH_ON, "switch on"): S.SWITCHED_ON,  # 3
    (S.READY_TO_SWITCH_ON, "enable operation"): S.OPERATION_ENABLED,  # 3 + 4
    (S.SWITCHED_ON, "enable operation"): S.OPERATION_ENABLED,  # 4
    (S.OPERATION_ENABLED, "switch on"): S.SWITCHED_ON,  # 5
    (S.SWITCHED_ON, "shutdown"): S.READY_TO_SWITCH_ON,  # 6
    (S.READY_TO_SWITCH_ON, "disable voltage"): S.SWITCH_ON_DISABLED,  # 7
    (S.READY_TO_SWITCH_ON, "quick stop"): S.SWITCH_ON_DISABLED,  # 7
    (S.OPERATION_ENABLED, "shutdown"): S.READY_TO_SWITCH_ON,  # 8
    (S.OPERATION_ENABLED, "disable voltage"): S.SWITCH_ON_DISABLED,  # 9
    (S.SWITCHED_ON, "disable voltage"): S.SWITCH_ON_DISABLED,  # 10
    (S.SWITCHED_ON, "quick stop"): S.SWITCH_ON_DISABLED,  # 10
    (S.OPERATION_ENABLED, "quick stop"): S.QUICK_STOP_ACTIVE,  # 11
    (S.QUICK_STOP_ACTIVE, "disable voltage"): S.SWITCH_ON_DISABLED,  # 12
    (S.QUICK_STOP_ACTIVE, "enable operation"): S.OPERATION_ENABLED,  # 16
}

STATE_BITS: dict[Cia402State, int] = {
    S.NOT_READY_TO_SWITCH_ON: 0x00,
    S.SWITCH_ON_DISABLED: 0x40,
    S.READY_TO_SWITCH_ON: 0x31,  # + voltage enabled (bit 4)
    S.SWITCHED_ON: 0x33,
    S.OPERATION_ENABLED: 0x37,
    S.QUICK_STOP_ACTIVE: 0x17,
    S.FAULT_REACTION_ACTIVE: 0x0F,
    S.FAULT: 0x08,
}


@dataclass
class DriveRecord:
    """What a test may check afterwards: the controlword and target taken at each SYNC."""

    controlwords: list[tuple[int, int]] = field(default_factory=list)  # (sync, controlword)
    targets: list[tuple[int, int]] = field(default_factory=list)  # (sync, target) when moving
    emcy_sent: list[int] = field(default_factory=list)


class SimDrive(SimNode):
    """A CiA 402 servo drive: power state machine, CSP and homing, faults and EMCY."""

    def __init__(
        self,
        network: SimNetwork,
        node_id: int,
        position_counts: int = 0,
        max_counts_per_sync: int = 10**9,
        homing_syncs: int = 5,
        homing_overshoot_counts: int = 0,
        *,
        heartbeat_consumer: bool = True,
    ) -> None:
        """``heartbeat_consumer=False``: a drive without object 0x1016."""
        self.initial_position = position_counts
        self.homing_overshoot_counts = homing_overshoot_counts  # stops past the switch edge
        self.max_counts_per_sync = max_counts_per_sync
        self.homing_syncs = homing_syncs
        self.record = DriveRecord()
        od = obj.build_drive_od(node_id)
        if not heartbeat_consumer:
            del od[obj.CONSUMER_HEARTBEAT_TIME]
        super().__init__(network, node_id, od)

    def reset_application(self) -> None:
        with self.lock:
            self.state = S.SWITCH_ON_DISABLED  # transitions 0 and 1 are immediate here
            self.position = self.initial_position
            self.target = self.initial_position
            self.controlword = 0
            self.mode = MODE_CSP
            self.mode_display = MODE_CSP
            self.error_code = 0
            self.fault_cause_active = False
            self.digital_inputs = 0
            self.homing_left = -1  # SYNCs until homing completes; -1 not running
            self.homing_attained = False
            self.homing_error = False
            self.inject_homing_error = False
            self.following_error = False

    # ---- test controls ----
    def inject_fault(self, code: int, *, persistent: bool = False) -> None:
        """A fault: FAULT REACTION ACTIVE now, FAULT at the next SYNC, EMCY at once."""
        with self.lock:
            self.state = S.FAULT_REACTION_ACTIVE
            self.error_code = code
            self.fault_cause_active = persistent
            self.homing_left = -1
            self._emcy(code)
            self.changed.notify_all()

    def on_heartbeat_event(self) -> None:
        """The controller is silent: with the power stage on, fault (0x8130, EMCY). The fault
        reaction ends on the drive's own clock: no SYNC will come to finish it."""
        if self.state in POWERED:
            self.inject_fault(EMCY_HEARTBEAT)
            self.state = S.FAULT  # 14

    def clear_fault_cause(self) -> None:
        with self.lock:
            self.fault_cause_active = False

    def _emcy(self, code: int) -> None:
        register = {0x2: 0x02, 0x3: 0x04, 0x4: 0x08, 0x8: 0x10}.get(code >> 12, 0x80) | 0x01
        self.record.emcy_sent.append(code)
        self.node.emcy.send(code, register)

    @property
    def statusword(self) -> int:
        word = STATE_BITS[self.state] | 0x0200  # remote
        if self.mode_display == MODE_CSP and self.state is S.OPERATION_ENABLED:
            word |= 1 << 12  # drive follows the command value
            if self.following_error:
                word |= 1 << 13
        if self.mode_display == MODE_HOMING:
            if self.homing_left < 0:
                word |= 1 << 10  # target reached: homing done, interrupted or not started
            if self.homing_attained:
                word |= 1 << 12
            if self.homing_error:
                word |= 1 << 13
        return word

    # ---- object hooks ----
    def on_read(self, index: int, subindex: int) -> int | None:
        return {
            obj.STATUSWORD: self.statusword,
            obj.POSITION_ACTUAL: self.position,
            obj.MODES_DISPLAY: self.mode_display,
            obj.ERROR_CODE: self.error_code,
            obj.DIGITAL_INPUTS: self.digital_inputs,
            obj.ERROR_REGISTER: 0x01 if self.error_code else 0,
            obj.CONTROLWORD: self.controlword,
            obj.TARGET_POSITION: self.target,
            obj.MODES_OF_OPERATION: self.mode,
        }.get(index)

    def on_write(self, index: int, subindex: int, value: object) -> None:
        assert isinstance(value, int)
        if index == obj.HOMING_METHOD and value not in SUPPORTED_HOMING_METHODS:
            raise SdoAbortedError(ABORT_VALUE_RANGE)
        if index == obj.CONTROLWORD:
            self._controlword(value)
        elif index == obj.TARGET_POSITION:
            self.target = value
        elif index == obj.MODES_OF_OPERATION:
            self.mode = value
            self.mode_display = value

    def _controlword(self, controlword: int) -> None:
        rising_reset = controlword & 0x80 and not self.controlword & 0x80
        self.controlword = controlword
        if self.nmt_state == "OPERATIONAL":
            self.record.controlwords.append((self.sync_count, controlword))
        if self.state is S.FAULT:
            if rising_reset and not self.fault_cause_active:
                self.state = S.SWITCH_ON_DISABLED  # 15
                self.error_code = 0
                self.node.emcy.reset()
            return
        if controlword & 0x80 or self.state is S.FAULT_REACTION_ACTIVE:
            return
        command = _command(controlword)
        new_state = DRIVE_TRANSITIONS.get((self.state, command))
        if new_state is None:
            return
        if new_state is S.OPERATION_ENABLED and self.state is not S.OPERATION_ENABLED:
            self.target = self.position  # CSP: a freshly enabled drive holds where it is
        self.state = new_state
        if self.mode_display == MODE_HOMING and controlword & CW_HOMING_START:
            self._maybe_start_homing()

    def _maybe_start_homing(self) -> None:
        if self.state is S.OPERATION_ENABLED and self.homing_left < 0 and not self.homing_attained:
            self.homing_left = self.homing_syncs
            self.homing_error = False

    def on_sync(self) -> None:
        if self.state is S.FAULT_REACTION_ACTIVE:
            self.state = S.FAULT  # 14
            return
        if self.state is not S.OPERATION_ENABLED:
            return
        if self.mode_display == MODE_CSP:
            self.homing_attained = False
            self.record.targets.append((self.sync_count, self.target))
            step = max(
                -self.max_counts_per_sync,
                min(self.max_counts_per_sync, self.target - self.position),
            )
            self.position += step
            window = self.read(obj.FOLLOWING_ERROR_WINDOW)
            if abs(self.target - self.position) > window:
                self.following_error = True
                self.inject_fault(0x8611)
        elif self.mode_display == MODE_HOMING:
            if not self.controlword & CW_HOMING_START:
                self.homing_left = -1
                self.homing_attained = False
            elif self.homing_left < 0 and not self.homing_attained:
                self._maybe_start_homing()
            elif self.homing_left > 0:
                self.homing_left -= 1
                if self.homing_left == 0:
                    self.homing_left = -1
                    if self.inject_homing_error:
                        self.homing_error = True
                    else:
                        self.position = self.read(obj.HOME_OFFSET) + self.homing_overshoot_counts
                        self.target = self.position
                        self.homing_attained = True


class SimStationIo(SimIoNode):
    """The I/O node wired to a simulated station: centering device, clamps and spindle answer
    their outputs with their sensors after a travel time counted in SYNCs (machine periods),
    and a board is put on the table by the test (``part_present``)."""

    def __init__(
        self,
        network: SimNetwork,
        node_id: int,
        inputs: dict[str, int],
        outputs: dict[str, int],
        travel_syncs: int = 10,
    ) -> None:
        self.input_bits = inputs
        self.output_bits = outputs
        self.travel_syncs = travel_syncs
        self.part_present = False
        self._moving: dict[str, int] = {}  # output name -> SYNCs since it changed
        self._last: dict[str, bool] = {}
        super().__init__(network, node_id)
        self.inputs = self._sensor_bits(centering=False, clamps=False, spindle=False)

    def _on(self, name: str) -> bool:
        return bool(self.outputs >> self.output_bits[name] & 1)

    def _sensor_bits(self, *, centering: bool | None, clamps: bool | None, spindle: bool) -> int:
        values = {
            "part_present": self.part_present,
            "guard_closed": True,
            "estop_ok": True,
            "centering_extended": centering is True,
            "centering_retracted": centering is False,
            "clamps_closed": clamps is True,
            "clamps_open": clamps is False,
            "spindle_running": spindle,
        }
        return sum(1 << self.input_bits[n] for n, on in values.items() if on)

    def on_sync(self) -> None:
        state: dict[str, bool | None] = {}
        for name in ("centering_extend", "clamps_close", "spindle_on"):
            on = self._on(name)
            if self._last.get(name) != on:
                self._last[name] = on
                self._moving[name] = 0
            self._moving[name] = self._moving.get(name, 0) + 1
            arrived = self._moving[name] >= self.travel_syncs
            state[name] = on if arrived else None  # None: travelling, both sensors off
        self.inputs = self._sensor_bits(
            centering=state["centering_extend"],
            clamps=state["clamps_close"],
            spindle=state["spindle_on"] is True,
        )
