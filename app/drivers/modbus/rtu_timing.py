"""What period Modbus RTU can hold: frame sizes of one period's traffic, turned into time.

Why computed and checked at start-up: on a serial line every byte has a fixed cost and the
transactions of all devices are strictly one after another, so the shortest period is known
in advance. A configuration asking for less would overrun every period; it is refused with
the figure, instead of discovered as jitter on the machine.

Per transaction (Modbus over serial line V1.02): request frame, the device's answer delay
(never shorter than the t3.5 silence that ends the request frame), reply frame, and the
t3.5 silence before the next request. A character is start bit + 8 data bits + parity bit
(if any) + stop bits. RTU frame sizes: device id 1 + function 1 + data + CRC 2.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.config import ConfigError
from app.drivers.modbus.settings import CouplerSettings, DriveMap, ModbusSettings


@dataclass(frozen=True)
class Transaction:
    label: str
    request_bytes: int
    reply_bytes: int
    seconds: float


@dataclass(frozen=True)
class RtuCycleEstimate:
    character_s: float
    frame_gap_s: float
    turnaround_s: float
    transactions: tuple[Transaction, ...]

    @property
    def cycle_s(self) -> float:
        """One period's traffic: every drive read and written, the coupler read and written."""
        return sum(t.seconds for t in self.transactions)

    @property
    def xy_skew_s(self) -> float:
        """Time between X's new target and Y's (one drive write transaction): the skew
        between the two interpolating axes."""
        writes = [t.seconds for t in self.transactions if t.label.endswith("write")]
        return writes[0] if writes else 0.0

    @property
    def bytes_per_cycle(self) -> int:
        return sum(t.request_bytes + t.reply_bytes for t in self.transactions)


def drive_frames(drive_map: DriveMap) -> tuple[tuple[int, int], tuple[int, int]]:
    """((read request, read reply), (write request, write reply)) in bytes."""
    _, read_count = drive_map.read_block
    _, write_count = drive_map.write_block
    read = (8, 5 + 2 * read_count)  # fc 3/4: addr, count | byte count, data
    write = (9 + 2 * write_count, 8)  # fc 16: addr, count, byte count, data | addr, count
    return read, write


def coupler_frames(coupler: CouplerSettings) -> list[tuple[str, int, int]]:
    frames = [("io read", 8, 5 + (coupler.input_count + 7) // 8)]  # fc 2
    if coupler.output_count:
        frames.append(("io write", 9 + (coupler.output_count + 7) // 8, 8))  # fc 15
    return frames


def estimate_rtu_cycle(settings: ModbusSettings) -> RtuCycleEstimate | None:
    """The estimate for an RTU configuration; None for Modbus TCP."""
    link = settings.link
    if link.serial is None:
        return None
    character_s = link.serial.bits_per_character / link.serial.baudrate
    gap_s = link.rtu_frame_gap_s
    answer_s = max(link.rtu_turnaround_s, gap_s)

    def transaction(label: str, request: int, reply: int) -> Transaction:
        seconds = (request + reply) * character_s + answer_s + gap_s
        return Transaction(label, request, reply, seconds)

    reads: list[Transaction] = []
    writes: list[Transaction] = []
    for axis, drive in settings.drives.items():
        (read_req, read_rep), (write_req, write_rep) = drive_frames(drive.map)
        reads.append(transaction(f"{axis} read", read_req, read_rep))
        writes.append(transaction(f"{axis} write", write_req, write_rep))
    io = [transaction(label, req, rep) for label, req, rep in coupler_frames(settings.coupler)]
    # The order of one period: read_axes, read_inputs, write_setpoints, write_outputs.
    return RtuCycleEstimate(character_s, gap_s, answer_s, tuple(reads + io[:1] + writes + io[1:]))


def check_period(settings: ModbusSettings, period_s: float, source: str = "") -> None:
    """Refuse a period shorter than one period's RTU traffic."""
    estimate = estimate_rtu_cycle(settings)
    if estimate is None or period_s >= estimate.cycle_s:
        return
    serial = settings.link.serial
    assert serial is not None
    raise ConfigError(
        "backend.period_ms",
        round(period_s * 1000.0, 3),
        f"at least {estimate.cycle_s * 1000.0:.1f} ms: one period's Modbus RTU traffic "
        f"({len(estimate.transactions)} transactions, {estimate.bytes_per_cycle} bytes at "
        f"{serial.baudrate} baud, {estimate.frame_gap_s * 1000:.2f} ms frame gaps, "
        f"{estimate.turnaround_s * 1000:.2f} ms answer delay) takes that long "
        '(see the README, "Modbus RTU limits")',
        source,
    )
