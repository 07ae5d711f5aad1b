"""The PDO mapping the backend downloads, and the packing of the cyclic frames.

Why fixed layouts packed with ``struct`` (and not canopen's ``PdoMap`` variables): the
layouts are ours, chosen once for every drive, and the machine loop packs three RPDOs every
4 ms; one ``struct.pack`` per drive is fast and obviously right, and the same layout object
both downloads the mapping (CiA 301 procedure, by SDO) and decodes the frames, so the two
cannot disagree.

Cyclic traffic per SYNC period (see :func:`cyclic_frames` and the README's bus load):

    RPDO1 to each drive   controlword 0x6040 (16) + target position 0x607A (32)
                          + modes of operation 0x6060 (8)           7 bytes, taken at SYNC
    TPDO1 from each drive statusword 0x6041 (16) + position actual 0x6064 (32)
                          + modes of operation display 0x6061 (8)   7 bytes, every SYNC
    TPDO2 from each drive digital inputs 0x60FD (32) + error code 0x603F (16)
                                                                    6 bytes, every n-th SYNC
    TPDO1 from the I/O    read input 8-bit 0x6000:01.. (8 each)     1-2 bytes, every SYNC
    RPDO1 to the I/O      write output 8-bit 0x6200:01.. (8 each)   1-2 bytes, on change
"""

from __future__ import annotations

import struct
from collections.abc import Callable
from dataclasses import dataclass

from app.drivers.canopen import objects as obj
from app.drivers.canopen.busload import CyclicFrame

PDO_NOT_VALID = 1 << 31  # COB-ID bit 31: PDO does not exist / is not valid
RTR_NOT_ALLOWED = 1 << 30  # COB-ID bit 30 of a TPDO: no remote transmission request
TRANSMISSION_SYNC = 1  # TPDO: sent on every SYNC; RPDO: actuated at the next SYNC
TRANSMISSION_EVENT = 255  # RPDO: actuated at once on receipt (manufacturer/profile event)

INT32_RANGE = (-(2**31), 2**31 - 1)

SdoDownload = Callable[[int, int, bytes], None]


@dataclass(frozen=True)
class PdoEntry:
    index: int
    subindex: int
    bits: int

    @property
    def map_value(self) -> int:
        """The 32-bit mapping entry: index, sub-index, length in bits."""
        return self.index << 16 | self.subindex << 8 | self.bits


@dataclass(frozen=True)
class PdoLayout:
    """One PDO of the pre-defined connection set (number 1..4) and what it carries."""

    receive: bool  # True: RPDO, master to node; False: TPDO, node to master
    number: int
    transmission_type: int
    entries: tuple[PdoEntry, ...]

    def cob_id(self, node_id: int) -> int:
        base = 0x200 if self.receive else 0x180
        return base + 0x100 * (self.number - 1) + node_id

    @property
    def comm_index(self) -> int:
        return (obj.RPDO_COMM if self.receive else obj.TPDO_COMM) + self.number - 1

    @property
    def map_index(self) -> int:
        return (obj.RPDO_MAPPING if self.receive else obj.TPDO_MAPPING) + self.number - 1

    @property
    def data_bytes(self) -> int:
        return sum(e.bits for e in self.entries) // 8


DRIVE_RPDO1 = PdoLayout(
    True,
    1,
    TRANSMISSION_SYNC,
    (
        PdoEntry(obj.CONTROLWORD, 0, 16),
        PdoEntry(obj.TARGET_POSITION, 0, 32),
        PdoEntry(obj.MODES_OF_OPERATION, 0, 8),
    ),
)
DRIVE_TPDO1 = PdoLayout(
    False,
    1,
    TRANSMISSION_SYNC,
    (
        PdoEntry(obj.STATUSWORD, 0, 16),
        PdoEntry(obj.POSITION_ACTUAL, 0, 32),
        PdoEntry(obj.MODES_DISPLAY, 0, 8),
    ),
)


def drive_tpdo2(every_n_sync: int) -> PdoLayout:
    return PdoLayout(
        False,
        2,
        every_n_sync,
        (
            PdoEntry(obj.DIGITAL_INPUTS, 0, 32),
            PdoEntry(obj.ERROR_CODE, 0, 16),
        ),
    )


def io_tpdo1(input_bytes: int) -> PdoLayout:
    return PdoLayout(
        False,
        1,
        TRANSMISSION_SYNC,
        tuple(PdoEntry(obj.READ_INPUT_8BIT, sub, 8) for sub in range(1, input_bytes + 1)),
    )


def io_tpdo2(analog_subs: tuple[int, ...]) -> PdoLayout:
    """The I/O node's analog inputs (0x6401, the handwheel's counter, the joystick) on every
    SYNC, in the order of their sub-indices."""
    return PdoLayout(
        False,
        2,
        TRANSMISSION_SYNC,
        tuple(PdoEntry(obj.READ_ANALOG_INPUT_16BIT, sub, 16) for sub in analog_subs),
    )


def io_rpdo1(output_bytes: int) -> PdoLayout:
    return PdoLayout(
        True,
        1,
        TRANSMISSION_EVENT,
        tuple(PdoEntry(obj.WRITE_OUTPUT_8BIT, sub, 8) for sub in range(1, output_bytes + 1)),
    )


_DRIVE_COMMAND = struct.Struct("<Hib")  # controlword, target position, mode
_DRIVE_FEEDBACK = struct.Struct("<Hib")  # statusword, position actual, mode display
_DRIVE_SLOW = struct.Struct("<IH")  # digital inputs, error code


def pack_drive_command(controlword: int, target_counts: int, mode: int) -> bytes:
    """RPDO1 payload; raises ValueError when the target does not fit in INTEGER32."""
    if not INT32_RANGE[0] <= target_counts <= INT32_RANGE[1]:
        raise ValueError(f"target {target_counts} counts does not fit in INTEGER32")
    return _DRIVE_COMMAND.pack(controlword, target_counts, mode)


def unpack_drive_feedback(data: bytes) -> tuple[int, int, int]:
    """(statusword, position actual, mode display); struct.error on a wrong length."""
    statusword, position, mode = _DRIVE_FEEDBACK.unpack(data)
    return int(statusword), int(position), int(mode)


def unpack_drive_slow(data: bytes) -> tuple[int, int]:
    """(digital inputs, error code); struct.error on a wrong length."""
    inputs, code = _DRIVE_SLOW.unpack(data)
    return int(inputs), int(code)


def answered_sync(previous: int | None, current: int) -> int:
    """The number of the SYNC a cyclic TPDO (transmission type 1) answers.

    A node answers every SYNC once, in order, so an answer belongs to the oldest SYNC it has
    not answered yet: ``previous + 1``. That is the SYNC sent last (``current``) when the
    answer is on time, and the one before when the answer comes after the next SYNC went out
    (a starved receive thread, a late drive). Stamping by arrival alone would then pair the
    position with the wrong target, a false following error of one period of travel. The
    result is kept within [current - 1, current], so a SYNC a node never answered shifts the
    pairing by at most one period instead of for ever."""
    if previous is None:
        return current
    return min(current, max(previous + 1, current - 1))


def pack_bits(value: int, nbytes: int) -> bytes:
    return value.to_bytes(nbytes, "little")


def unpack_bits(data: bytes, nbytes: int) -> int:
    if len(data) != nbytes:
        raise struct.error(f"{len(data)} bytes, expected {nbytes}")
    return int.from_bytes(data, "little")


def download_layout(download: SdoDownload, layout: PdoLayout, node_id: int) -> None:
    """Write one PDO's mapping by the CiA 301 procedure: invalidate the PDO, set the
    transmission type, clear the mapping, write the entries, set their number, validate."""
    cob_id = layout.cob_id(node_id)
    download(layout.comm_index, 1, struct.pack("<I", cob_id | PDO_NOT_VALID))
    download(layout.comm_index, 2, struct.pack("<B", layout.transmission_type))
    download(layout.map_index, 0, struct.pack("<B", 0))
    for sub, entry in enumerate(layout.entries, start=1):
        download(layout.map_index, sub, struct.pack("<I", entry.map_value))
    download(layout.map_index, 0, struct.pack("<B", len(layout.entries)))
    valid = cob_id if layout.receive else cob_id | RTR_NOT_ALLOWED
    download(layout.comm_index, 1, struct.pack("<I", valid))


def disable_pdo(download: SdoDownload, receive: bool, number: int, node_id: int) -> None:
    """Invalidate a PDO the backend does not use, so that it takes no bus time."""
    layout = PdoLayout(receive, number, 0, ())
    download(layout.comm_index, 1, struct.pack("<I", layout.cob_id(node_id) | PDO_NOT_VALID))


def cyclic_frames(
    drives: int,
    slow_every_n_sync: int,
    io_input_bytes: int,
    heartbeat_nodes: int,
    heartbeat_ms: int,
    period_s: float,
) -> list[CyclicFrame]:
    """Every frame of the cyclic traffic, per SYNC period (the bus load's input)."""
    heartbeat_per_period = period_s * 1000.0 / heartbeat_ms
    frames = [CyclicFrame("SYNC", 0, 1.0)]
    frames += [
        CyclicFrame("RPDO1 drive", DRIVE_RPDO1.data_bytes, float(drives)),
        CyclicFrame("TPDO1 drive", DRIVE_TPDO1.data_bytes, float(drives)),
        CyclicFrame(
            "TPDO2 drive", drive_tpdo2(slow_every_n_sync).data_bytes, drives / slow_every_n_sync
        ),
    ]
    if io_input_bytes:
        frames.append(CyclicFrame("TPDO1 I/O", io_input_bytes, 1.0))
    frames.append(CyclicFrame("heartbeat", 1, heartbeat_nodes * heartbeat_per_period))
    return frames
