"""What every fitted side chain must satisfy, measured independently of the fitting code.

`distance_to_chain` finds the segment by x (a side is a function of x) and measures the plan
distance with the segment's own exact `distance_to`; the true curves are computed by each test
from its own formulas or from an independent library.
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Callable, Sequence
from itertools import pairwise

from app.geometry.segments import Point, Segment


def distance_to_chain(chain: Sequence[Segment], point: Point) -> float:
    starts = [segment.start[0] for segment in chain]
    index = bisect.bisect_right(starts, point[0]) - 1
    nearby = chain[max(0, index - 2) : index + 3]
    return min(segment.distance_to(point) for segment in nearby)


def worst_deviation_mm(
    chain: Sequence[Segment], true_point: Callable[[float], Point], samples: int = 10_000
) -> float:
    """Largest distance from `samples` points of the true curve (t in [0, 1]) to the chain."""
    return max(distance_to_chain(chain, true_point(i / (samples - 1))) for i in range(samples))


def worst_tangent_break_rad(chain: Sequence[Segment]) -> float:
    worst = 0.0
    for before, after in pairwise(chain):
        a = before.tangent_at(before.length_mm)
        b = after.tangent_at(0.0)
        worst = max(worst, abs(math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1])))
    return worst


def worst_gap_mm(chain: Sequence[Segment]) -> float:
    return max(
        (math.dist(before.end, after.start) for before, after in pairwise(chain)), default=0.0
    )
