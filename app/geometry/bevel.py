"""The bevel of a board's two sides, and the rules that choose it from the measured width.

Why a pair and a rule: today both sides of a stave are bevelled alike, by a fixed angle or by
one computed from the barrel (`app.geometry.barrel`); barrels that are not round, and a
closing stave, need side A and side B bevelled differently. The cut is composed from
`SideTilts` so that a rule giving two angles needs no change in its callers.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

from app.geometry.limits import StaveLimits


@dataclass(frozen=True)
class SideTilts:
    """Bevel of each side in degrees (>= 0): side A is cut at Z = +a_deg, side B at -b_deg."""

    a_deg: float
    b_deg: float

    @classmethod
    def both(cls, tilt_deg: float) -> SideTilts:
        """Both sides bevelled alike."""
        return cls(tilt_deg, tilt_deg)

    @property
    def symmetric(self) -> bool:
        return self.a_deg == self.b_deg


class TiltRule(Protocol):
    """How a recipe chooses the bevel of a board once its width is measured."""

    def tilts_for_width(self, width_mm: float, limits: StaveLimits) -> SideTilts:
        """The bevels for a board ``width_mm`` wide; raises GeometryError (naming the field,
        the value and what is allowed) when no bevel within ``limits`` fits that width."""
        ...


@dataclass(frozen=True)
class FixedSideTilts:
    """Every board bevelled at the two given tilts, side A and side B (a stave planned with
    both bevels known, as ``stave solve --tilt A --tilt-b B`` does)."""

    tilts: SideTilts

    def tilts_for_width(self, width_mm: float, limits: StaveLimits) -> SideTilts:
        return self.tilts


@dataclass(frozen=True)
class FixedTilt:
    """Every board bevelled at ``tilt_deg`` on both sides, whatever its width (the tilt itself
    is checked against the limits with the stave, by `validate_stave`)."""

    tilt_deg: float

    def tilts_for_width(self, width_mm: float, limits: StaveLimits) -> SideTilts:
        return SideTilts.both(float(self.tilt_deg))
