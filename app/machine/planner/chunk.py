"""One rest-to-rest piece of motion, reduced to one or two independent coordinates.

Why this reduction: the machine must follow the tool path exactly, so the X-Y setpoint is
never "planned" per axis; it is the exact point c(s) of the path at a path coordinate s,
and only s(t) is planned. Z (the tilt) is constant while cutting; on a non-cutting move it
is a second coordinate with its own limits, free to change anywhere along that move (the
tool path declares the move as clear of the board), synchronised to arrive with X-Y.

So a chunk has the coordinates ("DOFs")
    s   arc length along an X-Y path (mm), when X-Y moves
    z   the tilt (deg), when it changes
and the axis positions are (x, y) = c(s) and z (constant or the z DOF).

From axis limits to limits on s (the "path box"). With ' = d/ds and dots = d/dt:
    x_i'   = c_i'(s) s_dot
    x_i''  = c_i'(s) s_ddot + c_i''(s) s_dot^2
    x_i''' = c_i'(s) s_dddot + 3 c_i''(s) s_dot s_ddot + c_i'''(s) s_dot^3
With m1, m2, m3 the largest |c_i'|, |c_i''|, |c_i'''| over the path, every state with
|s_dot| <= V, |s_ddot| <= A, |s_dddot| <= J keeps every axis inside its limits if
    m1 V <= v_i,    m1 A + m2 V^2 <= a_i,    m1 J + 3 m2 V A + m3 V^3 <= j_i.
:func:`path_box` picks V (the feed, or the axis velocity limits), leaves at least half of
a_i and of j_i for the tangential terms (V <= sqrt(a_i / (2 m2)), V^3 <= j_i / (3 m3),
A <= j_i / (6 m2 V)), then takes the largest A and J the inequalities allow. On lines
m2 = m3 = 0 and the box is exact; on the stave's arcs (radius of metres) the curvature terms
are a fraction of a percent. Because the box holds for *any* state inside it, the executor
may re-plan s(t) from any state (override change, stop) and stay within the axis limits.

Curvature steps. Where two pieces join with a change of curvature (line to arc; the arcs of a
curve fitted with biarcs) c'' jumps by dk * n, and the normal acceleration steps by
v^2 * dk * |n_i| at once. The drives receive one position per setpoint period, so the step
is spread over one period: a jerk of v^2 * dk * |n_i| / T. The box keeps that below half of
each axis's jerk limit (V^2 <= j_i T / (2 step_i)) and takes it off the jerk left for the
tangential terms. On the stave's line-arc-line (radii of metres) neither binds; on a fitted
curve with quick shoulders it is what keeps every axis inside its jerk limit.

Why ruckig: given a box (V, A, J) and a rest-to-rest target, the time-optimal jerk-limited
s(t) is exactly what ruckig computes (1 or 2 DOFs, "Time" synchronisation), in microseconds,
including from a moving state whose velocity is above a newly lowered V (its brake profile
stays within A and J). We do not re-implement that.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from ruckig import ControlInterface, InputParameter, Synchronization
from ruckig import Trajectory as RuckigTrajectory

from app.machine.planner.limits import MAX_OVERRIDE_PCT, AxisLimits
from app.machine.planner.otg import calculate
from app.machine.planner.path import DerivativeBounds, Path, Point
from app.machine.planner.trajectory import Phase, PlannerError

CURVATURE_STEP_WINDOW_S = 0.004
"""The setpoint period over which a curvature step reaches the drives (the machine's 4 ms)."""

MIN_RUN_OVERRIDE_PCT = 1.0
"""Below this feed override the executor holds (decelerates to rest on the path) instead of
creeping: ruckig cannot plan velocity limits that are a vanishing fraction of the others."""


@dataclass(frozen=True)
class PathBox:
    """Limits on the path coordinate that keep every axis within its limits (module doc)."""

    velocity_cap: float  # the highest |s_dot| at any override
    nominal_velocity: float  # |s_dot| at 100 % override
    acceleration: float
    jerk: float


def path_box(
    bounds: DerivativeBounds,
    x: AxisLimits,
    y: AxisLimits,
    nominal_velocity: float,
    max_velocity: float,
) -> PathBox:
    """The box for a path with these derivative bounds (see the module docstring).

    ``nominal_velocity`` is the wanted speed at 100 % (the feed, or inf for "as fast as the
    axes allow"); ``max_velocity`` the highest speed any override may ask for."""
    axes = (x, y)
    caps = [max_velocity]
    for i, limits in enumerate(axes):
        m1, m2, m3 = bounds.first[i], bounds.second[i], bounds.third[i]
        if m1 > 0.0:
            caps.append(limits.velocity / m1)
        if m2 > 0.0:
            caps.append(math.sqrt(limits.acceleration / (2.0 * m2)))
        if m3 > 0.0:
            caps.append((limits.jerk / (3.0 * m3)) ** (1.0 / 3.0))
        if bounds.step[i] > 0.0:
            caps.append(math.sqrt(limits.jerk * CURVATURE_STEP_WINDOW_S / (2.0 * bounds.step[i])))
    velocity = min(caps)
    if not math.isfinite(velocity) or velocity <= 0.0:
        raise PlannerError(f"no path velocity fits the limits (got {velocity!r} mm/s)")
    accelerations = []
    for i, limits in enumerate(axes):
        m1, m2 = bounds.first[i], bounds.second[i]
        if m1 > 0.0:
            accelerations.append((limits.acceleration - m2 * velocity**2) / m1)
        if m2 > 0.0:
            accelerations.append(limits.jerk / (6.0 * m2 * velocity))
    acceleration = min(accelerations)
    jerks = []
    for i, limits in enumerate(axes):
        m1, m2, m3 = bounds.first[i], bounds.second[i], bounds.third[i]
        step_jerk = velocity**2 * bounds.step[i] / CURVATURE_STEP_WINDOW_S
        if m1 > 0.0:
            left = limits.jerk - step_jerk - 3.0 * m2 * velocity * acceleration
            jerks.append((left - m3 * velocity**3) / m1)
    jerk = min(jerks)
    if not (acceleration > 0.0 and jerk > 0.0):
        raise PlannerError("the path's curvature leaves no acceleration or jerk for the feed")
    return PathBox(velocity, min(nominal_velocity, velocity), acceleration, jerk)


@dataclass(frozen=True)
class Dof:
    """One planned coordinate, rest to rest from ``start`` to ``end``."""

    start: float
    end: float
    nominal_velocity: float
    velocity_cap: float
    acceleration: float
    jerk: float

    def velocity_at(self, override_pct: float) -> float:
        """The velocity limit at this feed override, never above the cap."""
        return min(self.nominal_velocity * override_pct / 100.0, self.velocity_cap)


@dataclass(frozen=True)
class Chunk:
    """A rest-to-rest motion: an X-Y path (or a fixed X-Y point) and a tilt move or a fixed
    tilt. ``cutting`` and ``side`` come from the tool path pieces."""

    phase: Phase
    path: Path | None
    xy: Point  # the X-Y position when path is None
    z_start: float
    z_end: float
    s_dof: Dof | None
    z_dof: Dof | None
    dwell_s: float = 0.0  # > 0: a dwell at rest (nothing moves), e.g. settling before a cut

    @property
    def dofs(self) -> tuple[Dof, ...]:
        return tuple(d for d in (self.s_dof, self.z_dof) if d is not None)

    @property
    def cutting(self) -> bool:
        return self.path is not None and any(p.cutting for p in self.path.pieces)

    def start_xyz(self) -> tuple[float, float, float]:
        x, y = self.path.start if self.path is not None else self.xy
        return (x, y, self.z_start)

    def end_xyz(self) -> tuple[float, float, float]:
        x, y = self.path.end if self.path is not None else self.xy
        return (x, y, self.z_end)

    def _split(self, values: Sequence[float]) -> tuple[float, float]:
        """(s, z) from the DOF values."""
        index = 0
        s = 0.0
        z = self.z_start
        if self.s_dof is not None:
            s = values[index]
            index += 1
        if self.z_dof is not None:
            z = values[index]
        return s, z

    def state(
        self,
        positions: Sequence[float],
        velocities: Sequence[float],
    ) -> tuple[tuple[float, float, float], tuple[float, float, float], bool]:
        """Axis positions, axis velocities and the cutting flag for a DOF state."""
        s, z = self._split(positions)
        s_dot, z_dot = self._split(velocities)
        if self.z_dof is None:
            z_dot = 0.0
        if self.path is None:
            return (self.xy[0], self.xy[1], z), (0.0, 0.0, z_dot), False
        index, local = self.path.locate(s)
        piece = self.path.pieces[index]
        tangent = piece.derivatives(local)[0]
        x, y = piece.point(local)
        return (x, y, z), (tangent[0] * s_dot, tangent[1] * s_dot, z_dot), piece.cutting


def make_chunk(
    phase: Phase,
    path: Path | None,
    xy: Point,
    z_start: float,
    z_end: float,
    x: AxisLimits,
    y: AxisLimits,
    z: AxisLimits,
    feed_mm_s: float | None,
) -> Chunk:
    """A chunk with its DOF limits. ``feed_mm_s`` None: X-Y as fast as the axes allow."""
    s_dof = None
    if path is not None:
        if feed_mm_s is None:
            nominal = max_velocity = math.inf
        else:
            nominal = feed_mm_s
            max_velocity = feed_mm_s * MAX_OVERRIDE_PCT / 100.0
        box = path_box(path.bounds(), x, y, nominal, max_velocity)
        s_dof = Dof(
            0.0, path.length_mm, box.nominal_velocity, box.velocity_cap, box.acceleration, box.jerk
        )
    z_dof = None
    if z_end != z_start:
        z_dof = Dof(z_start, z_end, z.velocity, z.velocity, z.acceleration, z.jerk)
    if s_dof is None and z_dof is None:
        raise PlannerError("a chunk must move X-Y or Z")
    return Chunk(phase, path, xy, z_start, z_end, s_dof, z_dof)


def make_dwell(
    phase: Phase, xyz: tuple[float, float, float], z: AxisLimits, dwell_s: float
) -> Chunk:
    """A chunk that holds ``xyz`` for ``dwell_s`` seconds (its one DOF, Z, stays put)."""
    if not (math.isfinite(dwell_s) and dwell_s > 0.0):
        raise PlannerError(f"dwell_s = {dwell_s!r} is not allowed: a finite number > 0")
    z_dof = Dof(xyz[2], xyz[2], z.velocity, z.velocity, z.acceleration, z.jerk)
    return Chunk(phase, None, xyz[:2], xyz[2], xyz[2], None, z_dof, dwell_s)


# -- ruckig ---------------------------------------------------------------------------------

DofState = tuple[tuple[float, ...], tuple[float, ...], tuple[float, ...]]
"""(positions, velocities, accelerations) of a chunk's DOFs."""


def rest_state(chunk: Chunk) -> DofState:
    n = len(chunk.dofs)
    return (tuple(d.start for d in chunk.dofs), (0.0,) * n, (0.0,) * n)


_NEGLIGIBLE = 1e-9
"""Velocities and accelerations below this fraction of their limit are rounding residue of a
trajectory that has come to rest; they are set to 0 (ruckig can fail on such residue next to
its target)."""


def _input(chunk: Chunk, state: DofState) -> InputParameter:
    dofs = chunk.dofs
    inp = InputParameter(len(dofs))
    inp.current_position = list(state[0])
    inp.current_velocity = [
        0.0 if abs(v) < _NEGLIGIBLE * d.velocity_cap else v
        for v, d in zip(state[1], dofs, strict=True)
    ]
    inp.current_acceleration = [
        0.0 if abs(a) < _NEGLIGIBLE * d.acceleration else a
        for a, d in zip(state[2], dofs, strict=True)
    ]
    inp.max_acceleration = [d.acceleration for d in dofs]
    inp.max_jerk = [d.jerk for d in dofs]
    return inp


def plan_to_end(
    chunk: Chunk, state: DofState, override_pct: float, minimum_duration_s: float = 0.0
) -> RuckigTrajectory:
    """Time-optimal jerk-limited s(t) (and z(t)) from ``state`` to the chunk's end at rest,
    with the DOF velocity limits at ``override_pct`` (>= MIN_RUN_OVERRIDE_PCT), lasting at
    least ``minimum_duration_s`` (a dwell)."""
    if override_pct < MIN_RUN_OVERRIDE_PCT:
        raise PlannerError(
            f"override_pct = {override_pct}: planning to the end needs >= {MIN_RUN_OVERRIDE_PCT} %"
        )
    inp = _input(chunk, state)
    dofs = chunk.dofs
    inp.control_interface = ControlInterface.Position
    inp.synchronization = Synchronization.Time
    inp.max_velocity = [d.velocity_at(override_pct) for d in dofs]
    inp.target_position = [d.end for d in dofs]
    inp.target_velocity = [0.0] * len(dofs)
    inp.target_acceleration = [0.0] * len(dofs)
    if minimum_duration_s > 0.0:
        inp.minimum_duration = minimum_duration_s
    try:
        return calculate(inp, f"{chunk.phase.value} move")
    except PlannerError:
        if len(dofs) == 1:
            raise
        # Time synchronisation can fail numerically when one DOF is (almost) at its target;
        # each DOF then simply runs its own time-optimal profile.
        inp.synchronization = Synchronization.No
        return calculate(inp, f"{chunk.phase.value} move")


def plan_to_rest(chunk: Chunk, state: DofState) -> RuckigTrajectory:
    """The shortest jerk-limited deceleration of every DOF to rest (a controlled stop).

    It never runs past the chunk's end: the trajectory being followed reaches the end at
    rest, so the end lies at least one minimal stopping distance ahead."""
    inp = _input(chunk, state)
    dofs = chunk.dofs
    inp.control_interface = ControlInterface.Velocity
    inp.synchronization = Synchronization.No
    inp.max_velocity = [d.velocity_cap for d in dofs]
    inp.target_velocity = [0.0] * len(dofs)
    inp.target_acceleration = [0.0] * len(dofs)
    return calculate(inp, f"stop during {chunk.phase.value}")


def state_at(trajectory: RuckigTrajectory, t_s: float) -> DofState:
    """The DOF state at ``t_s``, clamped to the trajectory (ruckig extrapolates outside)."""
    t_s = min(max(t_s, 0.0), trajectory.duration)
    position, velocity, acceleration = trajectory.at_time(t_s)
    return (tuple(position), tuple(velocity), tuple(acceleration))
