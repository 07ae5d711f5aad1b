"""The simulated machine seen through Modbus registers: what the emulator's server serves.

Why a view onto :class:`app.drivers.sim.world.SimWorld` and not a second model: the simulated
world already has CiA 402 drives (state machine on the controlword, CSP with finite
acceleration, homing on a home switch, fault codes, limit switches, STO), the pneumatic
devices, the spindle, the board and the E-stop chain. The Modbus backend must meet exactly
that machine, only through registers, so one world and two views (the sim backend's direct
one, this register one) keep the two backends honest against each other.

Time runs in lock-step with the master: a period of world time passes when a device's status
is read again (the machine reads every device once per period, so the second read of the
same device starts the next period). Tests therefore need no sleeps, and a technician's demo
runs at whatever period the master keeps.
"""

from __future__ import annotations

import threading

from app.config import MachineConfig
from app.drivers.contracts import OutputImage
from app.drivers.modbus.codec import decode, encode
from app.drivers.modbus.settings import (
    OUTPUT_NAMES,
    CouplerSettings,
    DataType,
    DriveSettings,
    Field,
    ModbusSettings,
    RegisterTable,
    WordOrder,
    parse_modbus_settings,
)
from app.drivers.sim.drive import SimDrive
from app.drivers.sim.world import SimWorld


class DriveRegisters:
    """One drive's register map over a :class:`SimDrive`."""

    def __init__(self, settings: DriveSettings, drive: SimDrive) -> None:
        self.settings = settings
        self.drive = drive
        m = settings.map
        self._order = m.word_order
        self.table = m.status_table

    @property
    def last_address(self) -> int:
        """The highest register address the map uses."""
        return (
            max(f.end for f in self.settings.map.read_fields() + self.settings.map.write_fields())
            - 1
        )

    def status_registers(self) -> dict[int, int]:
        """address -> register value of every status field, as the drive shows them now."""
        m = self.settings.map
        feedback = self.drive.feedback()
        s = self.settings
        values: list[tuple[Field | None, float]] = [
            (m.statusword, feedback.statusword),
            (m.position, feedback.position * s.counts_per_unit),
            (m.velocity, feedback.velocity * s.velocity_counts_per_unit_s),
            (m.fault_code, feedback.fault_code),
        ]
        inputs = (
            feedback.limit_negative << m.limit_negative_bit
            | feedback.limit_positive << m.limit_positive_bit
            | feedback.home_switch << m.home_switch_bit
        )
        values.append((m.inputs, inputs))
        registers: dict[int, int] = {}
        for field, value in values:
            if field is None:
                continue
            for i, word in enumerate(encode(value, field.data_type, self._order)):
                registers[field.address + i] = word
        return registers

    def covers_status(self, table: RegisterTable, address: int, count: int) -> bool:
        """Whether a read starts a drive's period: it includes the statusword."""
        start = self.settings.map.statusword.address
        return table is self.table and address <= start < address + count

    def write(self, address: int, values: list[int]) -> None:
        """Registers written by the master: mode first, then controlword, then target, as a
        drive applies one PDO (the mode decides what controlword bit 4 means)."""
        m = self.settings.map

        def get(field: Field | None) -> float | None:
            if field is None or field.address < address or field.end > address + len(values):
                return None
            offset = field.address - address
            return decode(
                values[offset : offset + field.data_type.registers], field.data_type, self._order
            )

        mode = get(m.mode)
        selected = None if mode is None else m.mode_of(int(mode))
        if selected is not None:
            self.drive.set_mode(selected)
        controlword = get(m.controlword)
        if controlword is not None:
            self.drive.write_controlword(int(controlword))
        target = get(m.target)
        if target is not None:
            self.drive.write_target(target / self.settings.counts_per_unit)


class CouplerBits:
    """The I/O coupler's discrete inputs and coils over the world's I/O devices."""

    def __init__(self, settings: CouplerSettings, world: SimWorld) -> None:
        self.settings = settings
        self.world = world
        self._outputs = dict.fromkeys(OUTPUT_NAMES, False)

    def input_bits(self) -> dict[int, bool]:
        """Input bit (relative to inputs_address) -> electrical level."""
        image = self.world.inputs()
        s = self.settings
        return {
            bit: bool(getattr(image, name)) != (name in s.inverted)
            for name, bit in s.input_bits.items()
        }

    def input_registers(self) -> dict[int, int]:
        """Input register address -> value: the handwheel's counter and the joystick's
        analog inputs as the coupler's counter and analog modules show them."""
        image = self.world.inputs()
        found: dict[int, int] = {}
        for name, address in self.settings.registers.items():
            value = getattr(image, name)
            if value is not None:
                kind = DataType.UINT16 if name == "handwheel_count" else DataType.INT16
                found[address] = encode(value, kind, WordOrder.BIG)[0]
        return found

    def write_coils(self, address: int, values: list[bool]) -> None:
        s = self.settings
        for name, bit in s.output_bits.items():
            index = s.outputs_address + bit - address
            if 0 <= index < len(values):
                self._outputs[name] = bool(values[index])
        self.world.write_outputs(OutputImage(**self._outputs))


class MachineEmulation:
    """The whole machine as a Modbus master would find it: drives and coupler by unit name,
    one world, one lock (the server thread and the test's thread both touch it)."""

    def __init__(
        self,
        config: MachineConfig,
        world: SimWorld | None = None,
        settings: ModbusSettings | None = None,
    ) -> None:
        self.config = config
        self.settings = (
            settings
            if settings is not None
            else parse_modbus_settings(config.backend_settings.get("modbus", {}), config)
        )
        self.world = world if world is not None else SimWorld.from_config(config)
        self.lock = threading.RLock()
        self.drives: dict[str, DriveRegisters] = {
            axis: DriveRegisters(s, self.world.drives[axis])
            for axis, s in self.settings.drives.items()
        }
        self.coupler = CouplerBits(self.settings.coupler, self.world)
        self._read_since_advance: set[str] = set()
        self.periods = 0

    def device_names(self) -> list[str]:
        return [*self.drives, "io"]

    def unit_of(self, name: str) -> int:
        if name == "io":
            return self.settings.coupler.device_id
        return self.settings.drives[name].device_id

    def follow_clock(self, time_s: float) -> None:
        """Let world time pass while the master is silent (its link lost, its process
        stopped): when the reads have fallen more than two periods behind ``time_s``, the
        world catches up, so that the drives' and the coupler's watchdogs act as they would
        on the machine, where time does not wait for the master."""
        world = self.world
        with self.lock:
            while world.time_s < time_s - 2 * world.period_s:
                world.advance(world.period_s)

    def on_status_read(self, name: str) -> None:
        """A device's status block is read: the second read of the same device since the
        last advance starts the next period."""
        if name in self._read_since_advance:
            self.world.advance(self.world.period_s)
            self.periods += 1
            self._read_since_advance.clear()
        self._read_since_advance.add(name)
