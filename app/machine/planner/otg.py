"""One call into ruckig that never fails on a numerical boundary case.

Why: ruckig's closed-form profiles switch type where a limit is *just* reached; exactly on
such a boundary its root finding can fail and it raises, e.g. a 7.0710678118654 mm move
at a = 1000*sqrt(2), j = 20000*sqrt(2) (the diagonal from a homed (-5, -5) to (0, 0) on
this machine's limits). Lowering the acceleration and jerk limits by a few parts per
billion moves the input off the boundary and keeps it inside the real limits, so we retry
with slightly lower limits before reporting a failure.
"""

from __future__ import annotations

from ruckig import InputParameter, Result, Ruckig, RuckigError
from ruckig import Trajectory as RuckigTrajectory

from app.machine.planner.trajectory import PlannerError

_SHRINK = (0.0, 1e-9, 1e-7, 1e-5, 1e-3)
"""Relative reductions of the acceleration and jerk limits tried in turn."""


def calculate(inp: InputParameter, what: str) -> RuckigTrajectory:
    """ruckig's trajectory for ``inp``; raises PlannerError naming ``what`` if even the
    slightly lowered limits cannot be planned."""
    accelerations = list(inp.max_acceleration)
    jerks = list(inp.max_jerk)
    failure = ""
    for shrink in _SHRINK:
        inp.max_acceleration = [a * (1.0 - shrink) for a in accelerations]
        inp.max_jerk = [j * (1.0 - 2.0 * shrink) for j in jerks]
        trajectory = RuckigTrajectory(inp.degrees_of_freedom)
        try:
            result = Ruckig(inp.degrees_of_freedom).calculate(inp, trajectory)
        except RuckigError as exc:
            failure = str(exc).strip().splitlines()[0] if str(exc).strip() else repr(exc)
            continue
        if result in (Result.Working, Result.Finished):
            return trajectory
        failure = str(result)
    raise PlannerError(f"{what}: the trajectory generator refused it ({failure})")
