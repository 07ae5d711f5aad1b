"""CAN bus load of the cyclic traffic, computed from the frames actually mapped.

Why compute it: a SYNC period and a bitrate that look harmless in a configuration file can
fill the bus, and then the lowest-priority frames (TPDOs of the highest node ids, heartbeats)
arrive late or never, which shows up as following errors or a lost heartbeat in the middle
of a cut. The configuration reader refuses a load above :data:`MAX_BUS_LOAD`.

A classical CAN frame with an 11-bit identifier and ``n`` data bytes has 47 + 8n bits
(SOF, identifier, RTR, IDE, r0, DLC, data, CRC, delimiters, ACK, EOF, interframe space);
bit stuffing adds at most one bit per four of the 34 + 8n stuffed bits. The load is given
as a range: no stuffing and worst-case stuffing.
"""

from __future__ import annotations

from dataclasses import dataclass

MAX_BUS_LOAD = 0.60  # refuse configurations whose worst-case cyclic load exceeds this


def frame_bits(data_bytes: int, *, worst_case: bool) -> int:
    """Bits on the wire for one standard-identifier data frame."""
    if not 0 <= data_bytes <= 8:
        raise ValueError(f"a CAN frame carries 0 to 8 data bytes, not {data_bytes}")
    stuffed = 34 + 8 * data_bytes
    return 47 + 8 * data_bytes + ((stuffed - 1) // 4 if worst_case else 0)


@dataclass(frozen=True)
class CyclicFrame:
    """A frame sent ``per_period`` times per SYNC period (fractions for slower frames)."""

    name: str
    data_bytes: int
    per_period: float


@dataclass(frozen=True)
class BusLoad:
    bits_per_period_min: float
    bits_per_period_max: float
    period_s: float
    bitrate: int

    @property
    def minimum(self) -> float:
        return self.bits_per_period_min / (self.period_s * self.bitrate)

    @property
    def maximum(self) -> float:
        return self.bits_per_period_max / (self.period_s * self.bitrate)

    def describe(self) -> str:
        return (
            f"{100 * self.minimum:.1f}-{100 * self.maximum:.1f} % at "
            f"{1000 * self.period_s:g} ms and {self.bitrate // 1000} kbit/s"
        )


def bus_load(frames: list[CyclicFrame], period_s: float, bitrate: int) -> BusLoad:
    low = sum(f.per_period * frame_bits(f.data_bytes, worst_case=False) for f in frames)
    high = sum(f.per_period * frame_bits(f.data_bytes, worst_case=True) for f in frames)
    return BusLoad(low, high, period_s, bitrate)
