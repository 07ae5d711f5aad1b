"""The path executor: one X, Y, Z setpoint per period from a planned trajectory, with feed
override, controlled stop along the path, and immediate stop.

Where it runs: the machine loop (``app.machine.runtime``) calls :meth:`PathExecutor.step`
exactly once per period in the machine process, so no GUI work can delay it. ``step`` does
no I/O and no allocation beyond a few small objects; the three setpoints of one period come
from one evaluation of one trajectory, so there is no time skew between the axes.

The math of override and stop. A planned chunk is x(t) = c(s(t)) (``chunk.py``): the axes
are the exact path point at the path coordinate s. With ' = d/ds and dots = d/dt,

    v = c'(s) s_dot                                      (velocity)
    a = c'(s) s_ddot + c''(s) s_dot^2                    (acceleration)
    j = c'(s) s_dddot + 3 c''(s) s_dot s_ddot + c'''(s) s_dot^3   (jerk)

The classic time-scaling view writes s(t) = s_plan(tau(t)) with a time-scale rate
r = dtau/dt, so v = v_plan(tau) * r: velocity is continuous iff r is, and the acceleration
a = a_plan r^2 + v_plan r_dot shows why a step in r (or r_dot) is not allowed and why an
override above 100 % scales a planned acceleration at its limit by r^2 beyond the limit.
Rather than ramping r and proving the r^2, r^3 and r_dot terms stay within the limits at
every point of every profile, the executor re-plans s(t) itself: on an override change,
from the current state (s, s_dot, s_ddot), to the chunk's end, with the velocity limit
scaled by the override and the chunk's acceleration and jerk limits on s unchanged (ruckig,
time-optimal). The chunk's limits on s hold for every state inside them (``path_box``), so
the axes stay within their velocity, acceleration and jerk limits whatever the moment of
the change, and s_dot, s_ddot are continuous: no jump in velocity. A stop is the same with
the target "s_dot = 0": the shortest jerk-limited deceleration, along the path (the
setpoints are still c(s)), ending before the chunk's end. An override below 1 % holds
(decelerates to rest on the path) until it is raised again.

Time: ``elapsed_s`` counts periods. At 100 % the stream is exactly the plan sampled every
period (the executor follows the planned ruckig trajectories, carrying the remainder of a
period across the rest point between chunks).
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass

from ruckig import Trajectory as RuckigTrajectory

from app.machine.planner.chunk import (
    MIN_RUN_OVERRIDE_PCT,
    DofState,
    plan_to_end,
    plan_to_rest,
    rest_state,
    state_at,
)
from app.machine.planner.chunked import ChunkedTrajectory, PlannedChunk
from app.machine.planner.limits import MAX_OVERRIDE_PCT
from app.machine.planner.trajectory import Phase

REMAINING_CACHE_SIZE = 4
"""Override values whose remaining chunk durations the executor keeps (the newest): a feed
knob turned through many values in one long cut must not grow the cache by one entry each."""


class ExecutorState(enum.Enum):
    RUNNING = "running"
    HOLDING = "holding (override 0)"
    STOPPING = "stopping"
    STOPPED = "stopped"
    ABORTED = "aborted"
    DONE = "done"
    WAITING = "waiting at a lead-in"  # at rest before a cut until release()


@dataclass(frozen=True)
class ExecutorOutput:
    """The setpoints of one period (X, Y in mm, Z in deg) and their velocities."""

    x: float
    y: float
    z: float
    phase: Phase
    cutting: bool
    done: bool
    vx: float = 0.0
    vy: float = 0.0
    vz: float = 0.0


class PathExecutor:
    """Streams a :class:`ChunkedTrajectory` (a stave plan or a point-to-point move)."""

    def __init__(
        self,
        trajectory: ChunkedTrajectory,
        period_s: float,
        *,
        wait_before_cuts: bool = False,
        end_before: Phase | None = None,
    ) -> None:
        """``wait_before_cuts``: hold at rest at the start of every cut entered from rest
        (a dwell planned there is skipped: settling is the release's condition) until
        :meth:`release`. ``end_before``: done at the first chunk of that phase (the rest of
        the plan is not run)."""
        if (
            isinstance(period_s, bool)
            or not isinstance(period_s, int | float)
            or not math.isfinite(period_s)
            or not 0.0 < period_s <= 0.1
        ):
            raise ValueError(f"period_s = {period_s!r} is not allowed: a number in (0, 0.1] s")
        self._plan = trajectory
        self._period_s = float(period_s)
        self._count = _chunks_before(trajectory, end_before)
        self._gates = _cut_entries(trajectory, self._count) if wait_before_cuts else frozenset()
        cuts = [i for i, c in enumerate(trajectory.chunks[: self._count]) if c.chunk.cutting]
        self._last_cut = cuts[-1] if cuts else 0
        self._index = 0
        self._segment: RuckigTrajectory = trajectory.chunks[0].trajectory
        self._t_local = 0.0
        self._override_pct = 100.0
        self._state = ExecutorState.RUNNING
        self._elapsed_s = 0.0
        self._remaining_cache: dict[float, tuple[float, ...]] = {}
        self._skip_to_gate()
        self._last = self._output(self._current_dof_state())

    # -- properties ------------------------------------------------------------------------
    @property
    def period_s(self) -> float:
        return self._period_s

    @property
    def state(self) -> ExecutorState:
        return self._state

    @property
    def override_pct(self) -> float:
        return self._override_pct

    @property
    def elapsed_s(self) -> float:
        """Time since the first step (periods x period)."""
        return self._elapsed_s

    @property
    def done(self) -> bool:
        return self._state is ExecutorState.DONE

    @property
    def stopped(self) -> bool:
        """True once a controlled stop has come to rest, or after abort()."""
        return self._state in (ExecutorState.STOPPED, ExecutorState.ABORTED)

    @property
    def aborted(self) -> bool:
        return self._state is ExecutorState.ABORTED

    @property
    def phase(self) -> Phase:
        return self._chunk.chunk.phase

    @property
    def last_output(self) -> ExecutorOutput:
        return self._last

    @property
    def dwelling(self) -> bool:
        """True while the axes stand at rest on purpose (a dwell, a wait before a cut)."""
        if self._state is ExecutorState.WAITING:
            return True
        return self._state is ExecutorState.RUNNING and self._chunk.chunk.dwell_s > 0.0

    @property
    def in_last_cut(self) -> bool:
        """True from the first period of the plan's last cutting chunk on: no cut follows."""
        return self._index >= self._last_cut

    @property
    def waiting(self) -> bool:
        """True while held at rest before a cut, until :meth:`release`."""
        return self._state is ExecutorState.WAITING

    @property
    def progress(self) -> float:
        """0 .. 1: the planned (100 %) time of the path covered so far."""
        if self.done:
            return 1.0
        planned = self._chunk
        dofs = planned.chunk.dofs
        position = self._current_dof_state()[0][0]
        span = dofs[0].end - dofs[0].start
        if span == 0.0:  # a dwell: by time
            duration = float(self._segment.duration)
            fraction = 1.0 if duration <= 0.0 else min(self._t_local / duration, 1.0)
        else:
            fraction = min(max((position - dofs[0].start) / span, 0.0), 1.0)
        return (planned.t_start_s + fraction * planned.duration_s) / self._plan.duration_s

    @property
    def remaining_s(self) -> float:
        """Time to the end at the current override; to rest while stopping; 0 once done,
        stopped or aborted; inf while holding (override below 1 %)."""
        if self._state in (ExecutorState.DONE, ExecutorState.STOPPED, ExecutorState.ABORTED):
            return 0.0
        here = max(float(self._segment.duration) - self._t_local, 0.0)
        if self._state is ExecutorState.STOPPING:
            return here
        if self._state is ExecutorState.HOLDING:
            return math.inf
        return here + sum(self._future_durations()[self._index + 1 :])

    @property
    def distance_to_go_mm(self) -> float:
        """X-Y path length left in the current move (mm): to its end while running or
        holding, to the rest point while stopping; 0 on a tilt-only move, a dwell, or once
        done, stopped or aborted."""
        if self._state in (ExecutorState.DONE, ExecutorState.STOPPED, ExecutorState.ABORTED):
            return 0.0
        s_dof = self._chunk.chunk.s_dof
        if s_dof is None:
            return 0.0
        s_now = self._current_dof_state()[0][0]
        if self._state is ExecutorState.STOPPING:
            s_end = state_at(self._segment, float(self._segment.duration))[0][0]
        else:
            s_end = s_dof.end
        return abs(s_end - s_now)

    @property
    def phase_distance_to_go_mm(self) -> float:
        """X-Y path length left in the current phase (a side's cut with its lead-in and
        lead-out and every pass, the reposition, ...): this move's rest and the moves of the
        same phase after it (mm). While stopping, only the way to rest."""
        here = self.distance_to_go_mm
        if self._state is not ExecutorState.RUNNING and self._state is not ExecutorState.WAITING:
            return here
        phase = self._chunk.chunk.phase
        later = 0.0
        for planned in self._plan.chunks[self._index + 1 : self._count]:
            if planned.chunk.phase is not phase:
                break
            if planned.chunk.s_dof is not None:
                later += planned.chunk.s_dof.end - planned.chunk.s_dof.start
        return here + later

    @property
    def path_velocity_mm_s(self) -> float:
        """The X-Y speed along the path of the last setpoint (mm/s)."""
        return math.hypot(self._last.vx, self._last.vy)

    # -- commands --------------------------------------------------------------------------
    def set_override(self, percent: float) -> None:
        """Feed override, 0 .. 120 %. Takes effect at once, without a jump in velocity."""
        if (
            isinstance(percent, bool)
            or not isinstance(percent, int | float)
            or not math.isfinite(percent)
            or not 0.0 <= percent <= MAX_OVERRIDE_PCT
        ):
            raise ValueError(
                f"override percent = {percent!r} is not allowed: "
                f"a number from 0 to {MAX_OVERRIDE_PCT:g}"
            )
        percent = float(percent)
        if percent == self._override_pct:
            return
        self._override_pct = percent
        if self._state not in (ExecutorState.RUNNING, ExecutorState.HOLDING):
            return
        if self._state is ExecutorState.RUNNING and self._chunk.chunk.dwell_s > 0.0:
            return  # a dwell is time, not feed: the next chunk starts at the new override
        state = self._current_dof_state()
        if percent < MIN_RUN_OVERRIDE_PCT:
            if self._state is ExecutorState.RUNNING:
                self._replace_segment(plan_to_rest(self._chunk.chunk, state))
                self._state = ExecutorState.HOLDING
            return
        self._replace_segment(plan_to_end(self._chunk.chunk, state, percent))
        self._state = ExecutorState.RUNNING

    def request_stop(self) -> None:
        """Controlled stop along the path (IEC 60204-1 category 2): ``stopped`` once at rest."""
        if self._state is ExecutorState.WAITING:
            self._state = ExecutorState.STOPPED  # already at rest
            return
        if self._state not in (ExecutorState.RUNNING, ExecutorState.HOLDING):
            return
        self._replace_segment(plan_to_rest(self._chunk.chunk, self._current_dof_state()))
        self._state = ExecutorState.STOPPING
        if self._segment.duration <= 0.0:
            self._state = ExecutorState.STOPPED

    def abort(self) -> None:
        """Immediate stop: every later step returns the last setpoint. The controller
        quick-stops or disables the drives; nothing here resumes."""
        if self._state is not ExecutorState.DONE:
            self._state = ExecutorState.ABORTED

    def release(self) -> None:
        """Start the cut the executor waits before (no effect unless waiting)."""
        if self._state is not ExecutorState.WAITING:
            return
        self._state = ExecutorState.RUNNING
        self._segment = self._segment_for_new_chunk()
        self._t_local = 0.0

    # -- the period --------------------------------------------------------------------------
    def step(self) -> ExecutorOutput:
        """Advance one period and return its setpoints."""
        if self._state in (ExecutorState.DONE, ExecutorState.STOPPED, ExecutorState.ABORTED):
            return self._last
        self._elapsed_s += self._period_s
        if self._state is ExecutorState.WAITING:
            return self._last
        self._t_local += self._period_s
        if self._state is ExecutorState.RUNNING:
            while self._state is ExecutorState.RUNNING and self._t_local >= self._segment.duration:
                carry = self._t_local - self._segment.duration
                if self._index + 1 >= self._count:
                    self._state = ExecutorState.DONE
                    self._t_local = self._segment.duration
                    self._last = self._end_output()
                    return self._last
                self._index += 1
                self._segment = self._segment_for_new_chunk()
                self._t_local = carry
                if self._skip_to_gate():
                    break
        if self._state is not ExecutorState.RUNNING and self._t_local >= self._segment.duration:
            # holding or stopping: at rest now
            self._t_local = self._segment.duration
            if self._state is ExecutorState.STOPPING:
                self._state = ExecutorState.STOPPED
        self._last = self._output(self._current_dof_state())
        return self._last

    # -- internals -------------------------------------------------------------------------
    @property
    def _chunk(self) -> PlannedChunk:
        return self._plan.chunks[self._index]

    def _skip_to_gate(self) -> bool:
        """At a dwell before a gate, or at a gate: go to the gate and wait there (at rest,
        at the cut's first point). True if now waiting."""
        index = self._index
        while (
            index + 1 < self._count
            and index + 1 in self._gates
            and _is_dwell(self._plan.chunks[index])
        ):
            index += 1
        if index not in self._gates:
            return False
        self._index = index
        self._segment = self._chunk.trajectory
        self._t_local = 0.0
        self._state = ExecutorState.WAITING
        return True

    def _current_dof_state(self) -> DofState:
        return state_at(self._segment, self._t_local)

    def _replace_segment(self, segment: RuckigTrajectory) -> None:
        self._segment = segment
        self._t_local = 0.0

    def _segment_for_new_chunk(self) -> RuckigTrajectory:
        planned = self._chunk
        if self._override_pct == 100.0:
            return planned.trajectory
        chunk = planned.chunk
        if self._override_pct < MIN_RUN_OVERRIDE_PCT:  # held: wait at the chunk's start
            self._state = ExecutorState.HOLDING
            return plan_to_rest(chunk, rest_state(chunk))
        return plan_to_end(chunk, rest_state(chunk), self._override_pct, chunk.dwell_s)

    def _output(self, state: DofState) -> ExecutorOutput:
        chunk = self._chunk.chunk
        (x, y, z), (vx, vy, vz), cutting = chunk.state(state[0], state[1])
        waiting = self._state is ExecutorState.WAITING  # before the cut: not cutting yet
        return ExecutorOutput(x, y, z, chunk.phase, cutting and not waiting, False, vx, vy, vz)

    def _end_output(self) -> ExecutorOutput:
        chunk = self._chunk.chunk
        x, y, z = chunk.end_xyz()
        return ExecutorOutput(x, y, z, chunk.phase, False, True)

    def _future_durations(self) -> tuple[float, ...]:
        """Duration of every chunk run from rest at the current override (cached)."""
        key = self._override_pct
        cached = self._remaining_cache.get(key)
        if cached is None:
            if key == 100.0:
                cached = tuple(c.duration_s for c in self._plan.chunks)
            else:
                cached = tuple(
                    float(plan_to_end(c.chunk, rest_state(c.chunk), key, c.chunk.dwell_s).duration)
                    for c in self._plan.chunks
                )
            if len(self._remaining_cache) >= REMAINING_CACHE_SIZE:
                del self._remaining_cache[next(iter(self._remaining_cache))]  # the oldest
            self._remaining_cache[key] = cached[: self._count]
        return cached[: self._count]


def _is_dwell(planned: PlannedChunk) -> bool:
    return planned.chunk.dwell_s > 0.0


def _chunks_before(trajectory: ChunkedTrajectory, phase: Phase | None) -> int:
    """How many chunks come before the first of ``phase`` (all of them if none is)."""
    for index, planned in enumerate(trajectory.chunks):
        if index and planned.chunk.phase is phase:
            return index
    return len(trajectory.chunks)


def _cut_entries(trajectory: ChunkedTrajectory, count: int) -> frozenset[int]:
    """The chunks that begin cutting from rest after something else than a cut (travel, a
    dwell, or nothing): where the spindle must run and the axes be settled."""
    chunks = trajectory.chunks[:count]
    return frozenset(
        index
        for index, planned in enumerate(chunks)
        if planned.chunk.cutting and (index == 0 or not chunks[index - 1].chunk.cutting)
    )
