"""A trajectory made of rest-to-rest chunks, each planned time-optimally at 100 % override.

Why keep the chunks (and not only a sampled table): the executor re-plans the current chunk
from its live state when the override changes or a stop is requested, so it needs the exact
path and the DOF limits, not a table of setpoints. Sampling is exact at any time.
"""

from __future__ import annotations

import bisect
from collections.abc import Sequence

import numpy as np
from ruckig import Trajectory as RuckigTrajectory

from app.machine.planner.chunk import Chunk, plan_to_end, rest_state, state_at
from app.machine.planner.path import FloatArray
from app.machine.planner.trajectory import Phase, PlannerError, TrajectorySample


class PlannedChunk:
    """A chunk, its start time in the trajectory and its ruckig s(t) at 100 %."""

    def __init__(self, chunk: Chunk, t_start_s: float) -> None:
        self.chunk = chunk
        self.t_start_s = t_start_s
        self.trajectory: RuckigTrajectory = plan_to_end(
            chunk, rest_state(chunk), 100.0, chunk.dwell_s
        )

    @property
    def duration_s(self) -> float:
        return float(self.trajectory.duration)

    @property
    def t_end_s(self) -> float:
        return self.t_start_s + self.duration_s

    def __reduce__(self) -> tuple[type[PlannedChunk], tuple[Chunk, float]]:
        # ruckig's Trajectory does not pickle; planning is deterministic, so re-plan.
        return (PlannedChunk, (self.chunk, self.t_start_s))

    def sample(self, t_s: float) -> TrajectorySample:
        local = t_s - self.t_start_s
        if t_s >= self.t_end_s:  # exactly at the end, not within rounding of it
            dofs = self.chunk.dofs
            positions: tuple[float, ...] = tuple(d.end for d in dofs)
            velocities: tuple[float, ...] = (0.0,) * len(dofs)
        else:
            positions, velocities, _ = state_at(self.trajectory, local)
        xyz, vxyz, cutting = self.chunk.state(positions, velocities)
        return TrajectorySample(t_s, *xyz, *vxyz, self.chunk.phase, cutting)


class ChunkedTrajectory:
    """Chunks run one after the other; implements :class:`Trajectory`."""

    def __init__(self, chunks: Sequence[Chunk]) -> None:
        if not chunks:
            raise PlannerError("a trajectory needs at least one move")
        planned = []
        t = 0.0
        for chunk in chunks:
            item = PlannedChunk(chunk, t)
            planned.append(item)
            t = item.t_end_s
        self._chunks = tuple(planned)
        self._starts = [c.t_start_s for c in self._chunks]

    @property
    def chunks(self) -> tuple[PlannedChunk, ...]:
        return self._chunks

    @property
    def duration_s(self) -> float:
        return self._chunks[-1].t_end_s

    @property
    def start_xyz(self) -> tuple[float, float, float]:
        return self._chunks[0].chunk.start_xyz()

    @property
    def end_xyz(self) -> tuple[float, float, float]:
        return self._chunks[-1].chunk.end_xyz()

    def chunk_at(self, t_s: float) -> PlannedChunk:
        index = max(bisect.bisect_right(self._starts, t_s) - 1, 0)
        return self._chunks[index]

    def sample(self, t_s: float) -> TrajectorySample:
        t_s = min(max(t_s, 0.0), self.duration_s)
        return self.chunk_at(t_s).sample(t_s)

    def phase_interval(self, phase: Phase) -> tuple[float, float] | None:
        spans = [(c.t_start_s, c.t_end_s) for c in self._chunks if c.chunk.phase is phase]
        if not spans:
            return None
        return (spans[0][0], spans[-1][1])

    def setpoints(self, period_s: float) -> FloatArray:
        """The setpoint stream at k * period_s, k = 0 .. until the end is reached (rows
        t, x, y, z): what the executor sends at 100 % override."""
        if not period_s > 0.0:
            raise PlannerError(f"period_s = {period_s!r}: allowed > 0")
        count = int(np.ceil(self.duration_s / period_s)) + 1
        rows = np.empty((count, 4))
        for k in range(count):
            s = self.sample(k * period_s)
            rows[k] = (k * period_s, s.x, s.y, s.z)
        return rows
