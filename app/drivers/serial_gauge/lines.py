"""Line framing and parsing of the gauge's answers. Pure: bytes in, readings out.

Why a buffer of our own: a serial read returns whatever has arrived, often half a line (and
pyserial's ``readline`` returns a partial line on timeout), so bytes are kept until the
terminator comes. A line that grows beyond ``max_line_bytes`` without a terminator is noise
on the wire (wrong baud rate, a babbling device): it is reported once as garbage and the
buffer skips to the next terminator, so the memory stays bounded.

Every reading that is not a width says why, in words a technician can act on.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from app.drivers.contracts import GaugeReading
from app.drivers.serial_gauge.settings import SerialGaugeSettings


@dataclass(frozen=True)
class Overflow:
    """More than ``max_line_bytes`` arrived without a terminator."""

    size: int
    head: bytes


class LineBuffer:
    def __init__(self, terminator: bytes, max_line_bytes: int) -> None:
        self.terminator = terminator
        self.max_line_bytes = max_line_bytes
        self._buffer = bytearray()
        self._skipping = False  # discard until the next terminator
        self._overflowed = False  # ... because the line ran away (already reported)

    def clear(self) -> None:
        self._buffer.clear()
        self._skipping = False
        self._overflowed = False

    def resync(self) -> None:
        """Forget everything and skip to the next terminator: the next complete line starts
        after now (a streaming gauge's line that began before a request is not its answer).
        A gauge babbling without terminators is still reported as an overflow (garbage, not
        silence) once the skipped part grows beyond a line."""
        self._buffer.clear()
        self._skipping = True
        self._overflowed = False

    def feed(self, data: bytes) -> list[bytes | Overflow]:
        """Complete lines (without the terminator) in the order they ended."""
        out: list[bytes | Overflow] = []
        self._buffer.extend(data)
        term = self.terminator
        while True:
            end = self._buffer.find(term)
            if end < 0:
                break
            line = bytes(self._buffer[:end])
            del self._buffer[: end + len(term)]
            if self._skipping:
                self._skipping = False
                self._overflowed = False
                continue
            out.append(line)
        if len(self._buffer) > self.max_line_bytes:
            # Keep a tail that could be the start of a split terminator.
            if not self._overflowed:
                out.append(Overflow(len(self._buffer), bytes(self._buffer[:32])))
            keep = len(term) - 1
            del self._buffer[: len(self._buffer) - keep]
            self._skipping = True
            self._overflowed = True
        return out


def _printable(raw: bytes | str) -> str:
    text = raw.decode("ascii", errors="backslashreplace") if isinstance(raw, bytes) else raw
    return repr(text if len(text) <= 40 else text[:37] + "...")


def parse_line(line: bytes | Overflow, settings: SerialGaugeSettings) -> GaugeReading | None:
    """The reading one line gives; None for an empty line (a stray CR or LF)."""
    if isinstance(line, Overflow):
        return GaugeReading(
            None,
            raw=line.head.decode("ascii", errors="backslashreplace"),
            error=f"garbage: {line.size} bytes without a line terminator "
            f"(baud rate or terminator wrong?), starting "
            f"{_printable(line.head)}",
        )
    text = line.decode(settings.encoding, errors="replace").strip()
    if not text:
        return None
    match = settings.pattern.search(text)
    if match is None:
        return GaugeReading(
            None, raw=text, error=f"garbage: {_printable(text)} does not match gauge.serial.pattern"
        )
    try:
        value = float(match.group("width"))
    except (TypeError, ValueError):
        return GaugeReading(
            None, raw=text, error=f"garbage: {_printable(match.group('width'))} is not a number"
        )
    width_mm = value * settings.unit_scale
    if not math.isfinite(width_mm):
        return GaugeReading(
            None, raw=text, error=f"garbage: {_printable(text)} is not a finite number"
        )
    if not settings.min_width_mm <= width_mm <= settings.max_width_mm:
        return GaugeReading(
            None,
            raw=text,
            error=f"out of range: {width_mm:g} mm is outside the gauge's "
            f"range {settings.min_width_mm:g} to "
            f"{settings.max_width_mm:g} mm",
        )
    return GaugeReading(width_mm, raw=text)
