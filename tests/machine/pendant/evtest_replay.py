"""Replaying an ``evtest`` capture: the device's axis ranges from its header, then the events
with their times, fed period by period into the real event mapping, as the device would
deliver them to the machine's non-blocking read."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from app.drivers.contracts import PendantReading
from app.drivers.evdev_pendant.device import event_code
from app.drivers.evdev_pendant.mapping import AxisRange, EventMapping
from app.pendant_settings import EvdevSettings

EVENT = re.compile(r"^Event: time ([0-9.]+), type (\d+) \(\w+\), code (\d+) \(\w+\), value (-?\d+)")
SYN = re.compile(r"^Event: time ([0-9.]+), -+ SYN_REPORT -+")
CODE = re.compile(r"^\s+Event code (\d+) \((\w+)\)")
LIMIT = re.compile(r"^\s+(Min|Max)\s+(-?\d+)")

DATA = Path(__file__).resolve().parent / "data"


@dataclass(frozen=True)
class Capture:
    name: str
    ranges: dict[int, AxisRange]
    events: list[tuple[float, int, int, int]]  # time since the first event, type, code, value


def read_capture(path: Path) -> Capture:
    name = ""
    ranges: dict[int, AxisRange] = {}
    limits: dict[int, dict[str, int]] = {}
    code = -1
    events: list[tuple[float, int, int, int]] = []
    start: float | None = None
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("Input device name:"):
            name = line.split(":", 1)[1].strip().strip('"')
        elif match := CODE.match(line):
            code = int(match.group(1))
        elif (match := LIMIT.match(line)) and code >= 0:
            limits.setdefault(code, {})[match.group(1)] = int(match.group(2))
        elif match := EVENT.match(line):
            t = float(match.group(1))
            start = t if start is None else start
            events.append((t - start, *(int(match.group(i)) for i in (2, 3, 4))))
        elif match := SYN.match(line):
            t = float(match.group(1))
            start = t if start is None else start
            events.append((t - start, 0, 0, 0))
    for axis, found in limits.items():
        ranges[axis] = AxisRange(found["Min"], found["Max"])
    return Capture(name, ranges, events)


class ReplayedPendant:
    """The capture as a pendant the machine polls: each read delivers the events whose time
    has come (``period_s`` per read), through the product's own mapping."""

    def __init__(self, capture: Capture, settings: EvdevSettings, period_s: float) -> None:
        codes = {role: event_code(name) for role, name in settings.code_names().items()}
        self.mapping = EventMapping(codes, capture.ranges)
        self._events = list(capture.events)
        self._period_s = period_s
        self._time_s = 0.0
        self.connected = True

    @property
    def finished(self) -> bool:
        return not self._events

    def read(self) -> PendantReading:
        self._time_s += self._period_s
        while self._events and self._events[0][0] <= self._time_s:
            _, kind, code, value = self._events.pop(0)
            self.mapping.feed(kind, code, value)
        return self.mapping.reading()

    def close(self) -> None:
        self.connected = False
