"""The servo axes on Modbus: :class:`MotionBackend` over the bus and the register map.

Each period costs two transactions per drive, the least Modbus allows: one block read of the
status fields (statusword, position, velocity, error code, digital inputs) in ``read_axes``,
one block write of the command fields (controlword, mode, target) in ``write_setpoints``.
Power-state requests (``enable``, ``fault_reset``, ...) only change what the next write
carries; the drive's answer shows in the next ``read_axes``.

Why the target follows the actual position while a drive is not enabled (and while it homes):
a CSP drive takes the target the moment it is enabled, so a stale target would make the axis
jump. This is also what "on activation the command position is set to the measured one"
means on a bus where the target is a register.

Why a failed read returns the previous period's feedback: see :mod:`app.drivers.modbus.bus`
(a tolerated failure skips one exchange; the count of failures in a row decides the loss).
"""

from __future__ import annotations

from collections.abc import Mapping

from app.config import AxisConfig
from app.drivers.cia402 import FAULT_STATES, Cia402Master, RequestRefusedError
from app.drivers.contracts import (
    AxisFeedback,
    DeviceEvent,
    DeviceEventKind,
    DriverError,
    LifecycleState,
    MotionBackend,
)
from app.drivers.emcy import emcy_text
from app.drivers.modbus.bus import DeviceAddress, ModbusBus, TransientError
from app.drivers.modbus.codec import EncodeError, encode, field_value, put_field
from app.drivers.modbus.device import BusDevice
from app.drivers.modbus.link import ModbusLink
from app.drivers.modbus.settings import DriveSettings, WordOrder

GENERIC_FAULT_CODE = 0x1000  # CiA 301 "generic error": a fault whose code is not mapped
USER = "motion"


class _Axis:
    """One drive: where it is, how its registers scale, what it was last told."""

    def __init__(self, settings: DriveSettings, config: AxisConfig) -> None:
        self.settings = settings
        self.config = config
        self.address = DeviceAddress(settings.axis, settings.endpoint, settings.device_id)
        self.commander = Cia402Master(reports_mode=False, homed=config.absolute_encoder)
        self.feedback: AxisFeedback | None = None
        self.actual_counts = 0.0
        self.target_counts = 0.0
        self.fault_code = 0

    def decode(self, block: list[int]) -> AxisFeedback:
        m = self.settings.map
        start, _ = m.read_block
        order = m.word_order
        statusword = int(field_value(block, start, m.statusword, order))
        counts = field_value(block, start, m.position, order)
        self.actual_counts = counts
        velocity = (
            field_value(block, start, m.velocity, order) / self.settings.velocity_counts_per_unit_s
            if m.velocity
            else 0.0
        )
        inputs = int(field_value(block, start, m.inputs, order)) if m.inputs else 0
        state_faulted = self.commander.state in FAULT_STATES
        if m.fault_code is not None:
            fault_code = int(field_value(block, start, m.fault_code, order))
        else:
            fault_code = GENERIC_FAULT_CODE if state_faulted else 0
        self.fault_code = fault_code
        position = counts / self.settings.counts_per_unit
        following = 0.0
        if self.commander.follows_setpoints:
            following = (self.target_counts - counts) / self.settings.counts_per_unit
        return AxisFeedback(
            name=self.settings.axis,
            statusword=statusword,
            position=position,
            velocity=velocity,
            following_error=following,
            fault_code=fault_code,
            homed=self.commander.homed,
            homing_active=self.commander.homing_active,
            home_switch=bool(m.inputs and inputs >> m.home_switch_bit & 1),
            limit_positive=bool(m.inputs and inputs >> m.limit_positive_bit & 1),
            limit_negative=bool(m.inputs and inputs >> m.limit_negative_bit & 1),
        )


class ModbusMotion(BusDevice, MotionBackend):
    def __init__(
        self, drives: Mapping[str, DriveSettings], axes: Mapping[str, AxisConfig], bus: ModbusBus
    ) -> None:
        super().__init__(bus, USER, "modbus")
        self._drives = dict(drives)
        self._axes: dict[str, _Axis] = {}
        self._events: list[DeviceEvent] = []
        self._axis_configs = dict(axes)

    # -- lifecycle --------------------------------------------------------------------------
    @property
    def axis_names(self) -> tuple[str, ...]:
        return tuple(self._drives)

    def _first_exchange(self) -> None:
        """Read every drive once: a drive that does not answer, or refuses the mapped
        block, fails configure with its unit id and link named."""
        self._axes = {name: _Axis(s, self._axis_configs[name]) for name, s in self._drives.items()}
        for axis in self._axes.values():
            self._read_axis(axis, tolerate=False)

    def _on_activate(self) -> None:
        """Start cyclic exchange: targets are set to the measured positions. Nothing is
        written yet; the first ``write_setpoints`` writes "disable voltage" unless an enable
        was requested: a drive this backend did not enable is never left enabled."""
        for axis in self._axes.values():
            self._read_axis(axis, tolerate=False)
            axis.target_counts = axis.actual_counts

    def _on_deactivate(self) -> None:
        """Disable every drive (one write each). With the link lost the base is in ERROR and
        nothing is written (nothing can be: the drives' own Modbus watchdog and the
        hard-wired stop chain act then)."""
        for axis in self._axes.values():
            axis.commander.disable()
        self._write_all({}, tolerate=False)

    def _pending_events(self) -> list[DeviceEvent]:
        events, self._events = self._events, []
        return events + self._bus.events()

    def _axis(self, name: str) -> _Axis:
        try:
            return self._axes[name]
        except KeyError:
            raise DriverError(
                name, "no such axis (known: " + ", ".join(self._drives) + ")"
            ) from None

    # -- cyclic exchange -----------------------------------------------------------------------
    def _read_axis(self, axis: _Axis, *, tolerate: bool) -> AxisFeedback:
        m = axis.settings.map
        start, count = m.read_block

        def read(link: ModbusLink) -> list[int]:
            return link.read_registers(m.status_table, axis.address.device_id, start, count)

        try:
            block = self._exchange(axis.address, read, tolerate=tolerate)
        except TransientError:
            assert axis.feedback is not None  # configure read every axis once
            return axis.feedback
        previous = axis.commander.state
        outcome = axis.commander.observe(int(block[m.statusword.address - start]))
        feedback = axis.decode(block)
        if outcome is not None and not outcome.ok:
            self._events.append(
                DeviceEvent(
                    DeviceEventKind.EMERGENCY,
                    axis.settings.axis,
                    axis.fault_code,
                    f"homing failed: {outcome.reason}",
                )
            )
        if feedback.faulted and previous not in FAULT_STATES:
            self._events.append(
                DeviceEvent(
                    DeviceEventKind.EMERGENCY,
                    axis.settings.axis,
                    feedback.fault_code,
                    fault_text(feedback.fault_code),
                )
            )
        axis.feedback = feedback
        return feedback

    def read_axes(self) -> Mapping[str, AxisFeedback]:
        self._check(LifecycleState.INACTIVE, LifecycleState.ACTIVE)
        return {name: self._read_axis(axis, tolerate=True) for name, axis in self._axes.items()}

    def write_setpoints(self, positions: Mapping[str, float]) -> None:
        self._check(LifecycleState.ACTIVE)
        for name, position in positions.items():
            target = self._axis(name).settings.map.target
            try:  # a bad setpoint is the caller's bug even while the drive ignores it
                encode(
                    position * self._drives[name].counts_per_unit, target.data_type, WordOrder.BIG
                )
            except (EncodeError, TypeError) as exc:
                raise DriverError(name, f"setpoint {position!r}: {exc}") from None
        self._write_all(positions, tolerate=True)

    def _write_all(self, positions: Mapping[str, float], *, tolerate: bool) -> None:
        """One write per drive, X first then Y: the skew between the two interpolating axes
        is one write transaction (see the README, "Modbus RTU limits")."""
        for name, axis in self._axes.items():
            m = axis.settings.map
            command = axis.commander.command()
            if not command.follows_setpoints:
                axis.target_counts = axis.actual_counts
            elif name in positions:
                axis.target_counts = positions[name] * axis.settings.counts_per_unit
            start, count = m.write_block
            block = [0] * count
            try:
                put_field(block, start, m.controlword, command.controlword, m.word_order)
                if m.mode is not None:
                    put_field(block, start, m.mode, m.mode_value(command.mode), m.word_order)
                put_field(block, start, m.target, axis.target_counts, m.word_order)
            except EncodeError as exc:
                raise DriverError(name, f"target {positions.get(name)!r}: {exc}") from None

            def write(
                link: ModbusLink,
                block: list[int] = block,
                unit: int = axis.address.device_id,
                start: int = start,
            ) -> None:
                link.write_registers(unit, start, block)

            try:
                self._exchange(axis.address, write, tolerate=tolerate)
            except TransientError:
                continue  # sent again next period

    # -- power-state requests -------------------------------------------------------------------
    def enable(self, axis: str) -> None:
        self._check(LifecycleState.ACTIVE)
        try:
            self._axis(axis).commander.enable()
        except RequestRefusedError as exc:
            raise DriverError(axis, f"enable refused: {exc}") from None

    def disable(self, axis: str) -> None:
        self._axis(axis).commander.disable()  # always accepted: the safe direction

    def quick_stop(self, axis: str) -> None:
        self._axis(axis).commander.quick_stop()  # always accepted: the safe direction

    def fault_reset(self, axis: str) -> None:
        self._check(LifecycleState.ACTIVE)
        self._axis(axis).commander.fault_reset()

    def start_homing(self, axis: str) -> None:
        self._check(LifecycleState.ACTIVE)
        target = self._axis(axis)
        if target.settings.map.mode is None:
            raise DriverError(
                axis,
                "homing needs the modes-of-operation register "
                "(backend.modbus.drive_map.mode is -1)",
            )
        try:
            target.commander.start_homing()
        except RequestRefusedError as exc:
            raise DriverError(axis, f"start homing refused: {exc}") from None


def fault_text(fault_code: int) -> str:
    """The event text of a drive fault: its error code (0x603F) and what the code means; a
    map without the error code register reports 0."""
    if not fault_code:
        return "drive fault"
    return f"drive fault {fault_code:#06x}: {emcy_text(fault_code)}"
