"""CiA 402 servo drives in cyclic synchronous position mode: the CANopen MotionBackend.

Once per period the machine loop calls ``read_axes`` (the TPDO1 answers to the previous
SYNC, received by the notifier thread) and then ``write_setpoints``: every drive's RPDO1
(controlword, target, mode) goes out first and then ONE SYNC, at which all drives take their
targets together, so X and Y have no skew (one period of skew between them is up to 0.4 mm
across the path at 0.2 m/s and 4 ms).

Safety rules kept here (see cia402.py for the controlword itself):
- an axis that is not OPERATION ENABLED, or is homing, gets its own measured position as
  target, so enabling it never makes it jump; a setpoint farther from the last target than
  ``JUMP_PERIODS`` periods at the axis' maximum velocity is refused with a DriverError and
  nothing is sent that period;
- a lost node (heartbeat, reboot, missing TPDOs, dead receive thread) latches the backend in
  ERROR, sends quick stop (controlword 0x02) and one SYNC to every drive, and clears the
  homed flag of the lost drives (they may have been power-cycled unseen);
- the backend never resets or enables a drive by itself;
- every drive watches the controller's heartbeat (0x1016, see ``device.py`` and
  ``master_heartbeat.py``): if the machine process dies or the controller's CAN connection
  is lost, an enabled drive faults by itself (EMCY 0x8130) after
  ``master_heartbeat_timeout_ms``, without waiting for SYNC loss. Deactivation switches a
  drive's consumer off only once its answers show the power stage off.
"""

from __future__ import annotations

import logging
import math
import struct
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from app.config import AxisConfig, MachineConfig
from app.drivers.canopen import objects as obj
from app.drivers.canopen.bus import CanopenBus
from app.drivers.canopen.device import CanopenDevice
from app.drivers.canopen.pdo import (
    DRIVE_RPDO1,
    DRIVE_TPDO1,
    answered_sync,
    disable_pdo,
    download_layout,
    drive_tpdo2,
    pack_drive_command,
    unpack_drive_feedback,
    unpack_drive_slow,
)
from app.drivers.canopen.settings import AxisNodeSettings, CanopenSettings
from app.drivers.cia402 import (
    FAULT_STATES,
    Cia402Master,
    Cia402State,
    DriveCommand,
    OperationMode,
    RequestRefusedError,
    decode_statusword,
)
from app.drivers.contracts import AxisFeedback, CommunicationError, DriverError, MotionBackend

log = logging.getLogger(__name__)

JUMP_PERIODS = 4.0  # a setpoint may move at most this many periods at max velocity
OPTIONAL_OBJECT_ABORTS = (0x06020000, 0x06090011)  # object / sub-index does not exist


@dataclass(frozen=True)
class _Sample:
    """One TPDO1: what the drive measured at SYNC number ``seq``."""

    statusword: int
    position_counts: int
    mode_display: int
    seq: int


class _Axis:
    """One drive: settings, controlword logic and the data its TPDOs brought."""

    def __init__(self, node: AxisNodeSettings, config: AxisConfig, period_s: float) -> None:
        self.node = node
        self.config = config
        self.label = f"{config.name} (node {node.node_id})"
        self.commander = Cia402Master(reports_mode=True)
        self.sample: _Sample | None = None
        self.previous: _Sample | None = None
        self.digital_inputs = 0
        self.error_code = 0
        self.bad_frame = ""
        self.target_counts = 0  # last target sent
        self.targets: dict[int, int] = {}  # SYNC number -> target taken at that SYNC
        self.max_step = config.max_velocity * period_s * JUMP_PERIODS + config.following_error_limit

    # receive thread, under the bus condition
    def on_tpdo1(self, data: bytes, seq: int) -> None:
        try:
            statusword, position, mode = unpack_drive_feedback(data)
        except struct.error:
            self.bad_frame = (
                f"TPDO1 has {len(data)} bytes, expected "
                f"{DRIVE_TPDO1.data_bytes}: the drive's PDO mapping differs"
            )
            return
        seq = answered_sync(self.sample.seq if self.sample else None, seq)
        if self.sample is not None and self.sample.seq != seq:
            self.previous = self.sample
        self.sample = _Sample(statusword, position, mode, seq)

    def on_tpdo2(self, data: bytes, seq: int) -> None:
        try:
            self.digital_inputs, self.error_code = unpack_drive_slow(data)
        except struct.error:
            self.bad_frame = f"TPDO2 has {len(data)} bytes, expected 6"

    @property
    def actual_counts(self) -> int:
        return self.sample.position_counts if self.sample else self.target_counts

    @property
    def follows_setpoints(self) -> bool:
        """The drive takes our targets (the master's rule)."""
        return self.commander.follows_setpoints


POWERED_STATES = (
    Cia402State.OPERATION_ENABLED,
    Cia402State.QUICK_STOP_ACTIVE,
    Cia402State.FAULT_REACTION_ACTIVE,
)


class CanopenMotion(CanopenDevice, MotionBackend):
    owner = "motion"
    profile = obj.PROFILE_DRIVE
    consumes_master_heartbeat = True

    def __init__(self, bus: CanopenBus, settings: CanopenSettings, config: MachineConfig) -> None:
        super().__init__(bus, settings)
        self._axes = {
            name: _Axis(settings.axes[name], axis, settings.period_s)
            for name, axis in config.axes.items()
        }
        self._by_node = {a.node.node_id: a for a in self._axes.values()}
        self._homed = {name: False for name in self._axes}

    @property
    def device_label(self) -> str:
        return "CANopen drives"

    @property
    def axis_names(self) -> tuple[str, ...]:
        return tuple(self._axes)

    def _nodes(self) -> dict[int, str]:
        return {a.node.node_id: a.label for a in self._axes.values()}

    # ---- start-up ----
    def _add_nodes(self) -> None:
        for axis in self._axes.values():
            node_id = axis.node.node_id
            self._bus.add_node(node_id, obj.build_drive_od(node_id), self.owner, axis.label)
            self._bus.subscribe(node_id, DRIVE_TPDO1.cob_id(node_id), axis.on_tpdo1)
            self._bus.subscribe(node_id, drive_tpdo2(1).cob_id(node_id), axis.on_tpdo2)
            axis.sample = axis.previous = None
            axis.bad_frame = ""

    def _configure_node(self, node_id: int) -> None:
        axis = self._by_node[node_id]
        counts = axis.node.counts_per_unit
        cfg = axis.config
        bus = self._bus

        def write(index: int, sub: int, data: bytes, what: str, optional: bool = False) -> None:
            try:
                bus.sdo_download(node_id, index, sub, data, what)
            except CommunicationError:
                raise
            except DriverError as exc:
                if not (optional and exc.code in OPTIONAL_OBJECT_ABORTS):
                    raise
                log.info("%s: optional object 0x%04X not present", axis.label, index)

        modes = self._supported_modes(node_id)
        if modes is not None and not modes & obj.SUPPORTED_CSP_BIT:
            raise DriverError(
                axis.label,
                f"does not support cyclic synchronous position mode "
                f"(0x6502 supported drive modes = 0x{modes:08X})",
            )
        if modes is not None and not cfg.absolute_encoder and not modes & obj.SUPPORTED_HOMING_BIT:
            raise DriverError(
                axis.label, "does not support homing mode, and the axis has an incremental encoder"
            )
        for number in range(2, 5):
            disable_pdo(lambda i, s, d: write(i, s, d, "RPDO communication"), True, number, node_id)
        for number in range(3, 5):
            disable_pdo(
                lambda i, s, d: write(i, s, d, "TPDO communication"), False, number, node_id
            )
        download_layout(lambda i, s, d: write(i, s, d, "RPDO1 mapping"), DRIVE_RPDO1, node_id)
        download_layout(lambda i, s, d: write(i, s, d, "TPDO1 mapping"), DRIVE_TPDO1, node_id)
        download_layout(
            lambda i, s, d: write(i, s, d, "TPDO2 mapping"),
            drive_tpdo2(self._settings.slow_feedback_every_n_sync),
            node_id,
        )
        period_us = round(self._settings.period_s * 1e6)
        write(
            obj.COMM_CYCLE_PERIOD,
            0,
            struct.pack("<I", period_us),
            "communication cycle period",
            optional=True,
        )
        value, index = _interpolation_period(self._settings.period_s)
        write(
            obj.INTERPOLATION_TIME_PERIOD,
            1,
            struct.pack("<B", value),
            "interpolation time period value",
            optional=True,
        )
        write(
            obj.INTERPOLATION_TIME_PERIOD,
            2,
            struct.pack("<b", index),
            "interpolation time index",
            optional=True,
        )
        write(
            obj.FOLLOWING_ERROR_WINDOW,
            0,
            struct.pack("<I", min(2**32 - 1, round(cfg.following_error_limit * counts))),
            "following error window",
        )
        write(obj.HOMING_METHOD, 0, struct.pack("<b", axis.node.homing_method), "homing method")
        speed = max(1, round(cfg.homing_velocity * counts))
        write(obj.HOMING_SPEEDS, 1, struct.pack("<I", speed), "homing speed (switch)")
        write(obj.HOMING_SPEEDS, 2, struct.pack("<I", max(1, speed // 10)), "homing speed (zero)")
        write(
            obj.HOMING_ACCELERATION,
            0,
            struct.pack("<I", max(1, round(cfg.jog_acceleration * counts))),
            "homing acceleration",
        )
        write(
            obj.HOME_OFFSET,
            0,
            struct.pack("<i", axis.node.to_counts(cfg.home_switch_position)),
            "home offset",
        )
        write(
            obj.MODES_OF_OPERATION,
            0,
            struct.pack("<b", OperationMode.CYCLIC_SYNC_POSITION),
            "modes of operation",
        )

    def _supported_modes(self, node_id: int) -> int | None:
        try:
            data = self._bus.sdo_upload(
                node_id, obj.SUPPORTED_DRIVE_MODES, 0, "supported drive modes"
            )
        except CommunicationError:
            raise
        except DriverError as exc:
            if exc.code in OPTIONAL_OBJECT_ABORTS:
                return None
            raise
        return int.from_bytes(data[:4], "little")

    def _latest_seq(self, node_id: int) -> int:
        sample = self._by_node[node_id].sample
        return sample.seq if sample else -1

    def _start_exchange(self) -> None:
        for name, axis in self._axes.items():
            if self._bus.take_booted(axis.node.node_id):
                self._homed[name] = False  # the drive rebooted: its position is gone
            axis.commander = Cia402Master(reports_mode=True, homed=self._homed[name])
            axis.targets.clear()
        self._sync_and_wait("no TPDO1 answer to SYNC at activation")
        for axis in self._axes.values():  # command = measured, power request DISABLED
            axis.target_counts = axis.actual_counts
            assert axis.sample is not None
            axis.commander.observe(axis.sample.statusword, axis.sample.mode_display)
            self._send_rpdo(axis, axis.commander.command(), axis.target_counts)
        self._sync_and_wait("no TPDO1 answer to SYNC at activation")  # taken at this SYNC
        self._sync_and_wait("no TPDO1 answer to SYNC at activation")  # and answered here

    def _sync_and_wait(self, what: str) -> None:
        seq = self._bus.sync(feedback=True)
        timeout_s = self._settings.startup_timeout_ms / 1000.0
        nodes = self._nodes()
        if not self._bus.wait(lambda: all(self._latest_seq(n) >= seq for n in nodes), timeout_s):
            late = [n for n in nodes if self._latest_seq(n) < seq]
            raise CommunicationError(nodes[late[0]], f"{what} within {timeout_s * 1000:.0f} ms")

    def _stop_exchange(self) -> None:
        # sent to every drive, lost or not: a CAN frame costs nothing if nobody hears it
        for axis in self._axes.values():
            axis.commander.disable()
            self._send_rpdo(axis, axis.commander.command(), axis.actual_counts)
        reachable = [a for a in self._axes.values() if not self._bus.lost_reason(a.node.node_id)]
        # the TPDO answering a SYNC is sampled before that SYNC's controlword is taken, so
        # the drives' confirmation is in the answers to the following SYNC
        for _ in range(3):
            seq = self._bus.sync(feedback=True)

            def answered(seq: int = seq) -> bool:
                return all(a.sample is not None and a.sample.seq >= seq for a in reachable)

            self._bus.wait(answered, max(0.05, 10 * self._settings.period_s))
            with self._bus.condition:
                if answered() and all(
                    a.sample is not None
                    and decode_statusword(a.sample.statusword) is not Cia402State.OPERATION_ENABLED
                    for a in reachable
                ):
                    return
        log.warning("%s: not every drive confirmed it is disabled", self.device_label)

    def _disarmable(self, node_id: int) -> bool:
        """A drive stops watching the controller only when its latest answer shows the power
        stage off: one that did not take the disable keeps its watchdog."""
        if not super()._disarmable(node_id):
            return False
        with self._bus.condition:
            sample = self._by_node[node_id].sample
            statusword = sample.statusword if sample is not None else None
        return statusword is not None and decode_statusword(statusword) not in POWERED_STATES

    def _on_lost(self) -> None:
        """Quick stop every drive (they decelerate and hold); the lost one too, in case it
        can still hear us. Nothing here enables or resets anything.

        A lost drive also loses its homed flag: it may have been power-cycled while we could
        not hear it (cable out, boot-up message missed), and an incremental encoder then
        counts from wherever it woke up. Re-homing after a link loss is the safe price."""
        for name, axis in self._axes.items():
            if self._bus.receive_failed or self._bus.lost_reason(axis.node.node_id):
                self._homed[name] = False
        for axis in self._axes.values():
            axis.commander.quick_stop()
            self._send_rpdo(axis, axis.commander.command(), axis.actual_counts)
        self._bus.sync()

    def _send_rpdo(self, axis: _Axis, command: DriveCommand, target_counts: int) -> None:
        self._bus.send(
            DRIVE_RPDO1.cob_id(axis.node.node_id),
            pack_drive_command(command.controlword, target_counts, int(command.mode)),
        )

    # ---- the period ----
    def read_axes(self) -> Mapping[str, AxisFeedback]:
        self._ensure_active()
        self._supervise_cycle()
        self._refresh()
        feedback: dict[str, AxisFeedback] = {}
        with self._bus.condition:
            for name, axis in self._axes.items():
                problem = axis.bad_frame or ("" if axis.sample else "no TPDO1 received")
                if problem:
                    self._bus.report_lost(axis.node.node_id, problem)
                    raise self._lose(axis.label, problem)
                feedback[name] = self._feedback(name, axis)
        return feedback

    def _feedback(self, name: str, axis: _Axis) -> AxisFeedback:
        sample, previous = axis.sample, axis.previous
        assert sample is not None
        commander = axis.commander
        commander.observe(sample.statusword, sample.mode_display)
        if commander.homed:
            self._homed[name] = True
        node = axis.node
        position = node.from_counts(sample.position_counts)
        velocity = 0.0
        if previous is not None and previous.seq < sample.seq:
            # per nominal period: the targets are planned on that grid, and a CSP drive
            # interpolates over 0x60C2, whatever the jitter of the SYNC itself
            dt_s = self._settings.period_s * (sample.seq - previous.seq)
            velocity = position - node.from_counts(previous.position_counts)
            velocity /= dt_s
        following_error = 0.0
        commanded = axis.targets.get(sample.seq - 1)
        if axis.follows_setpoints and commanded is not None:
            following_error = node.from_counts(commanded) - position
        faulted = commander.state in FAULT_STATES
        fault_code = (axis.error_code or self._bus.last_emcy_code(node.node_id)) if faulted else 0
        inputs = axis.digital_inputs
        negative = bool(inputs & obj.DI_NEGATIVE_LIMIT)
        positive = bool(inputs & obj.DI_POSITIVE_LIMIT)
        if node.invert:
            negative, positive = positive, negative
        return AxisFeedback(
            name=name,
            statusword=sample.statusword,
            position=position,
            velocity=velocity,
            following_error=following_error,
            fault_code=fault_code,
            homed=axis.config.absolute_encoder or self._homed[name],
            homing_active=commander.homing_active,
            home_switch=bool(inputs & obj.DI_HOME_SWITCH),
            limit_positive=positive,
            limit_negative=negative,
        )

    def write_setpoints(self, positions: Mapping[str, float]) -> None:
        self._ensure_active()
        try:
            self._bus.check()
        except CommunicationError as exc:
            raise self._lose(exc.device, str(exc)) from exc
        frames: list[tuple[_Axis, DriveCommand, int]] = []
        for name, axis in self._axes.items():
            command = axis.commander.command()
            if command.follows_setpoints and name in positions:
                target = self._checked_target(axis, positions[name])
            elif command.follows_setpoints:
                target = axis.target_counts
            else:
                target = axis.actual_counts  # not following: hold where it is
            frames.append((axis, command, target))
        try:
            for axis, command, target in frames:
                self._send_rpdo(axis, command, target)
            seq = self._bus.sync()
        except CommunicationError as exc:
            raise self._lose(exc.device, str(exc)) from exc
        for axis, _command, target in frames:
            axis.target_counts = target
            axis.targets[seq] = target
            axis.targets.pop(seq - 8, None)

    def _checked_target(self, axis: _Axis, position: float) -> int:
        if not math.isfinite(position):
            raise DriverError(axis.label, f"setpoint {position!r} is not a finite number")
        last = axis.node.from_counts(axis.target_counts)
        if abs(position - last) > axis.max_step:
            raise DriverError(
                axis.label,
                f"setpoint {position:.4f} {axis.config.unit} jumps {abs(position - last):.4f} "
                f"from the last target {last:.4f}; at most {axis.max_step:.4f} per period "
                "is allowed (nothing was sent)",
            )
        counts = axis.node.to_counts(position)
        if not -(2**31) <= counts < 2**31:
            raise DriverError(axis.label, f"setpoint {position} is beyond the 32-bit range")
        return counts

    # ---- power requests (the machine decides when) ----
    def _axis(self, name: str) -> _Axis:
        try:
            return self._axes[name]
        except KeyError:
            raise DriverError(
                self.device_label, f"unknown axis {name!r}: one of {', '.join(self._axes)}"
            ) from None

    def _request(self, name: str, what: str, request: Callable[[Cia402Master], None]) -> None:
        """One request of the master that needs an active backend; a refusal names it."""
        axis = self._axis(name)
        self._ensure_active()
        try:
            request(axis.commander)
        except RequestRefusedError as exc:
            raise DriverError(axis.label, f"{what} refused: {exc}") from exc

    def enable(self, axis: str) -> None:
        self._request(axis, "enable", Cia402Master.enable)

    def disable(self, axis: str) -> None:
        self._axis(axis).commander.disable()  # always accepted: the safe direction

    def quick_stop(self, axis: str) -> None:
        self._axis(axis).commander.quick_stop()  # always accepted: the safe direction

    def fault_reset(self, axis: str) -> None:
        self._request(axis, "fault reset", Cia402Master.fault_reset)
        self._bus.clear_emcy_code(self._axes[axis].node.node_id)

    def start_homing(self, axis: str) -> None:
        self._request(axis, "start homing", Cia402Master.start_homing)
        self._homed[axis] = False


def _interpolation_period(period_s: float) -> tuple[int, int]:
    """0x60C2 value and index (period = value * 10^index s) for a period in seconds."""
    for index in (-3, -4, -5, -6):
        value = period_s / 10.0**index
        if abs(value - round(value)) < 1e-6 and 1 <= round(value) <= 255:
            return round(value), index
    return max(1, min(255, round(period_s * 1000))), -3
