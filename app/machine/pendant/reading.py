"""What a USB pendant or gamepad gives the machine each period, whatever its driver."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

from app.machine.pendant.handwheel import WheelSelection


@dataclass(frozen=True)
class PendantReading:
    """One period of a USB pendant: its enable button, its wheel's selection and the
    increments turned since the last read (multiplier applied), its sticks' speed fractions
    (-1..1, deadband and curve applied)."""

    enable: bool = False
    selection: WheelSelection = field(default_factory=lambda: WheelSelection("", 1))
    increments: int = 0
    sticks: dict[str, float] = field(default_factory=dict)

    @property
    def moving(self) -> bool:
        return bool(self.increments and self.selection.axis) or any(self.sticks.values())


class PendantDevice(Protocol):
    """A USB pendant the machine polls once per period; it never blocks, and a device that
    is unplugged reads as at rest (``connected`` False) until it is back."""

    @property
    def connected(self) -> bool: ...

    def read(self) -> PendantReading: ...

    def close(self) -> None: ...
