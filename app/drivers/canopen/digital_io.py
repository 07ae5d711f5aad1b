"""The machine's digital I/O on one CiA 401 node: the CANopen DigitalIO.

Where the I/O comes from: one generic I/O node (CiA 401) on the same bus as the drives, with
up to 16 inputs (0x6000, "read input 8-bit") and 16 outputs (0x6200, "write output 8-bit").
Which terminal bit carries which machine function is configuration
(``[backend.canopen.io.inputs]`` / ``[backend.canopen.io.outputs]``).

Analog inputs (0x6401, ``[backend.canopen.io.analog]``: the handwheel's counter, the
joystick) come in TPDO2 on every SYNC beside them, when any is wired.

Inputs come in TPDO1 on every SYNC (the SYNC the motion backend sends after its setpoints),
so they are as fresh as the axis feedback and a missing answer is noticed the same way.
Outputs go out in RPDO1 with transmission type 255 (applied on receipt), when they change
and every ``REFRESH_PERIODS`` periods otherwise, so a lost frame cannot leave an output
wrong for long. The outputs are switched off at activation and at deactivation.
"""

from __future__ import annotations

import logging
import struct

from app.drivers.canopen import objects as obj
from app.drivers.canopen.bus import CanopenBus
from app.drivers.canopen.device import CanopenDevice
from app.drivers.canopen.pdo import (
    answered_sync,
    disable_pdo,
    download_layout,
    io_rpdo1,
    io_tpdo1,
    io_tpdo2,
    pack_bits,
    unpack_bits,
)
from app.drivers.canopen.settings import CanopenSettings
from app.drivers.contracts import CommunicationError, DigitalIO, InputImage, OutputImage

log = logging.getLogger(__name__)

REFRESH_PERIODS = 50  # resend unchanged outputs this often (0.2 s at 4 ms)


class CanopenIO(CanopenDevice, DigitalIO):
    owner = "io"
    profile = obj.PROFILE_IO

    def __init__(self, bus: CanopenBus, settings: CanopenSettings) -> None:
        super().__init__(bus, settings)
        self._io = settings.io
        self._label = f"I/O (node {self._io.node_id})"
        self._tpdo = io_tpdo1(self._io.input_bytes)
        self._analog_subs = tuple(sorted(self._io.analog.values()))
        self._analog_tpdo = io_tpdo2(self._analog_subs) if self._analog_subs else None
        self._analog: dict[int, int] = {}  # 0x6401 sub-index -> last value
        self._rpdo = io_rpdo1(self._io.output_bytes)
        self._raw_inputs = 0
        self._input_seq = -1
        self._bad_frame = ""
        self._sent_outputs: int | None = None
        self._periods_since_send = 0

    @property
    def device_label(self) -> str:
        return self._label

    def _nodes(self) -> dict[int, str]:
        return {self._io.node_id: self._label}

    def _add_nodes(self) -> None:
        node_id = self._io.node_id
        self._bus.add_node(node_id, obj.build_io_od(node_id), self.owner, self._label)
        self._bus.subscribe(node_id, self._tpdo.cob_id(node_id), self._on_tpdo)
        if self._analog_tpdo is not None:
            self._bus.subscribe(node_id, self._analog_tpdo.cob_id(node_id), self._on_analog)
        self._analog = {}
        self._input_seq = -1
        self._bad_frame = ""

    def _on_tpdo(self, data: bytes, seq: int) -> None:
        try:
            self._raw_inputs = unpack_bits(data, self._io.input_bytes)
        except struct.error:
            self._bad_frame = (
                f"TPDO1 has {len(data)} bytes, expected "
                f"{self._io.input_bytes}: the node's PDO mapping differs"
            )
            return
        self._input_seq = answered_sync(self._input_seq if self._input_seq >= 0 else None, seq)

    def _on_analog(self, data: bytes, seq: int) -> None:
        layout = f"<{len(self._analog_subs)}h"
        try:
            values = struct.unpack(layout, data)
        except struct.error:
            self._bad_frame = (
                f"TPDO2 has {len(data)} bytes, expected {2 * len(self._analog_subs)}: "
                "the node's PDO mapping differs"
            )
            return
        self._analog = dict(zip(self._analog_subs, values, strict=True))

    def _configure_node(self, node_id: int) -> None:
        def write(index: int, sub: int, data: bytes) -> None:
            self._bus.sdo_download(node_id, index, sub, data, "PDO configuration")

        for number in range(2, 5):
            disable_pdo(write, True, number, node_id)
            disable_pdo(write, False, number, node_id)
        download_layout(write, self._tpdo, node_id)
        if self._analog_tpdo is not None:
            download_layout(write, self._analog_tpdo, node_id)
        download_layout(write, self._rpdo, node_id)
        for sub in range(1, self._io.output_bytes + 1):
            self._bus.sdo_download(
                node_id, obj.WRITE_OUTPUT_8BIT, sub, b"\x00", "write output 8-bit (all off)"
            )

    def _latest_seq(self, node_id: int) -> int:
        return self._input_seq

    def _start_exchange(self) -> None:
        seq = self._bus.sync(feedback=True)
        timeout_s = self._settings.startup_timeout_ms / 1000.0
        if not self._bus.wait(lambda: self._input_seq >= seq, timeout_s):
            raise CommunicationError(
                self._label,
                f"no TPDO1 answer to SYNC at activation within {timeout_s * 1000:.0f} ms",
            )
        self._send_outputs(0)

    def _stop_exchange(self) -> None:
        if not self._bus.lost_reason(self._io.node_id):
            self._send_outputs(0)

    def _send_outputs(self, value: int) -> None:
        self._bus.send(self._rpdo.cob_id(self._io.node_id), pack_bits(value, self._io.output_bytes))
        self._sent_outputs = value
        self._periods_since_send = 0

    def read_inputs(self) -> InputImage:
        self._ensure_active()
        self._supervise_cycle()
        self._refresh()
        with self._bus.condition:
            if self._bad_frame:
                raise self._lose(self._label, self._bad_frame)
            raw = self._raw_inputs
            analog = self._analog
        values: dict[str, bool | int | None] = {
            name: bool(raw >> bit & 1) != (name in self._io.inverted_inputs)
            for name, bit in self._io.inputs.items()
        }
        for name, sub in self._io.analog.items():
            value = analog.get(sub)
            # 0x6401 is INTEGER16; a counter module's count is its 16 bits unsigned.
            if value is not None and name == "handwheel_count":
                value &= 0xFFFF
            values[name] = value
        return InputImage(**values)  # type: ignore[arg-type]

    def write_outputs(self, outputs: OutputImage) -> None:
        self._ensure_active()
        value = 0
        for name, bit in self._io.outputs.items():
            if getattr(outputs, name):
                value |= 1 << bit
        self._periods_since_send += 1
        if value == self._sent_outputs and self._periods_since_send < REFRESH_PERIODS:
            return
        try:
            self._send_outputs(value)
        except CommunicationError as exc:
            raise self._lose(exc.device, str(exc)) from exc
