"""The machine's digital I/O on a Modbus remote I/O coupler: :class:`DigitalIO`.

One "read discrete inputs" (function 2) and one "write multiple coils" (function 15) per
period. The outputs are written every period, changed or not: a coupler's Modbus watchdog
(set it in the coupler, e.g. 100 ms) switches its outputs off when the master falls silent,
and only a steady stream of writes keeps it fed.

Inputs listed in ``inverted`` are wired as normally-closed contacts and read inverted, so
that :class:`InputImage` always says "healthy" for True.

Registers listed in ``[backend.modbus.io.registers]`` (the handwheel's counter, the joystick's
analog inputs) are read in the same exchange, one "read input registers" (function 4).
"""

from __future__ import annotations

from dataclasses import asdict

from app.drivers.contracts import (
    DeviceEvent,
    DigitalIO,
    InputImage,
    LifecycleState,
    OutputImage,
)
from app.drivers.modbus.bus import DeviceAddress, ModbusBus, TransientError
from app.drivers.modbus.codec import decode
from app.drivers.modbus.device import BusDevice
from app.drivers.modbus.link import ModbusLink
from app.drivers.modbus.settings import CouplerSettings, DataType, RegisterTable, WordOrder

USER = "io"


class ModbusIO(BusDevice, DigitalIO):
    def __init__(self, settings: CouplerSettings, bus: ModbusBus) -> None:
        super().__init__(bus, USER, "io")
        self.settings = settings
        self.address = DeviceAddress("io", settings.endpoint, settings.device_id)
        self._inputs: InputImage | None = None

    def _first_exchange(self) -> None:
        self._read(tolerate=False)  # _read keeps the image

    def _on_activate(self) -> None:
        """Start cyclic exchange with every output off."""
        self._write(OutputImage(), tolerate=False)

    def _on_deactivate(self) -> None:
        """Every output off. With the link lost the base is in ERROR and nothing is written
        (the coupler's watchdog switches its outputs off then)."""
        self._write(OutputImage(), tolerate=False)

    def _pending_events(self) -> list[DeviceEvent]:
        return self._bus.events()

    # -- cyclic exchange ------------------------------------------------------------------
    def _read(self, *, tolerate: bool) -> InputImage:
        s = self.settings
        count = s.input_count

        first, span = s.register_span

        def read(link: ModbusLink) -> tuple[list[bool], list[int]]:
            bits = link.read_discrete_inputs(s.device_id, s.inputs_address, count)
            if not span:
                return bits, []
            words = link.read_registers(RegisterTable.INPUT, s.device_id, first, span)
            return bits, words

        try:
            bits, words = self._exchange(self.address, read, tolerate=tolerate)
        except TransientError:
            assert self._inputs is not None  # configure read the inputs once
            return self._inputs
        values: dict[str, bool | int] = {
            name: bits[bit] != (name in s.inverted) for name, bit in s.input_bits.items()
        }
        for name, address in s.registers.items():
            word = words[address - first]
            # The counter is unsigned 16-bit; an analog input is signed (+-10 V: +-27648).
            kind = DataType.UINT16 if name == "handwheel_count" else DataType.INT16
            values[name] = int(decode([word], kind, WordOrder.BIG))
        self._inputs = InputImage(**values)  # type: ignore[arg-type]
        return self._inputs

    def _write(self, outputs: OutputImage, *, tolerate: bool) -> None:
        s = self.settings
        count = s.output_count
        if count == 0:
            return
        wanted = asdict(outputs)
        bits = [False] * count
        for name, bit in s.output_bits.items():
            bits[bit] = bool(wanted[name])

        def write(link: ModbusLink) -> None:
            link.write_coils(s.device_id, s.outputs_address, bits)

        try:
            self._exchange(self.address, write, tolerate=tolerate)
        except TransientError:
            return  # written again next period

    def read_inputs(self) -> InputImage:
        self._check(LifecycleState.INACTIVE, LifecycleState.ACTIVE)
        return self._read(tolerate=True)

    def write_outputs(self, outputs: OutputImage) -> None:
        self._check(LifecycleState.ACTIVE)
        self._write(outputs, tolerate=True)
