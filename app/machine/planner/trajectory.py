"""What every planned motion offers its users: a duration and a sample at any time.

Why a protocol: the executor, the benchmark, the plan preview and the tests read a stave
plan and a point-to-point move the same way, and none of them needs to know how it was
planned. Samples are clamped to the ends, so a consumer that runs a little past the end
(or asks before the start) gets the end state at rest, never an extrapolation.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from typing import Protocol, runtime_checkable


class PlannerError(ValueError):
    """A motion cannot be planned (bad input, or the trajectory generator refused it)."""


class Phase(enum.Enum):
    """Which part of the stave cycle a piece of trajectory belongs to."""

    APPROACH = "approach"  # from the start position to the lead-in of side A
    CUT_A = "cut side A"  # lead-in, P1 -> P4, lead-out
    REPOSITION = "reposition"  # around the right end, tilt +alpha -> -alpha
    CUT_B = "cut side B"  # lead-in, P5 -> P8, lead-out
    RETURN = "return"  # to the home position
    POINT_TO_POINT = "point to point"  # a single move outside the cycle
    RETRACT = "retract"  # spindle off: back along the cut and around the board (resume, abandon)


@dataclass(frozen=True)
class TrajectorySample:
    """Setpoints and their velocities at one instant (X, Y in mm; Z in deg)."""

    t_s: float
    x: float
    y: float
    z: float
    vx: float
    vy: float
    vz: float
    phase: Phase
    cutting: bool

    @property
    def xyz(self) -> tuple[float, float, float]:
        return (self.x, self.y, self.z)


@runtime_checkable
class Trajectory(Protocol):
    """A planned motion, starting at t = 0 and ending at ``duration_s``, at rest at both ends."""

    @property
    def duration_s(self) -> float: ...

    def sample(self, t_s: float) -> TrajectorySample:
        """The state at ``t_s``, clamped to [0, duration_s]."""
        ...

    def phase_interval(self, phase: Phase) -> tuple[float, float] | None:
        """(start, end) of that phase in this trajectory, or None if it has none."""
        ...
