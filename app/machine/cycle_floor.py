"""The shortest cycle a board can take on this machine: the yardstick of the cycle benchmark.

Why a floor and not a target number: the cut itself is already at the jerk-limited optimum,
so what a cycle wastes is whatever it adds beyond the strokes that cannot overlap. Those
are, in order: the centering device extends, the clamps close, the gauge measures (and,
when the centering device may only retract once the board is clamped, its retract before
the cutter may pass), the spindle runs up while the axes approach the lead-in (the longer
of the two), side A at the jerk-limited optimum, the repositioning between the sides at the
axis limits, side B likewise, and the part of the clamps' opening stroke that is left once
the cutter is clear of the board. Everything else (the waits for sensors, the settling, the
periods of the loop) is what the cycle adds.

The cut bound is the one the planner benchmark holds the planner to: length / feed plus the
time an S-curve ramp to the feed loses at the side's largest tangential acceleration and
jerk, with no corner slowing anything.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from app.config import CycleConfig, IOConfig
from app.machine.planner.chunk import path_box
from app.machine.planner.chunked import PlannedChunk
from app.machine.planner.keepout import TableKeepOut, routed_chunks
from app.machine.planner.limits import MotionLimits
from app.machine.planner.path import Path
from app.machine.planner.stave_plan import StavePlan
from app.machine.planner.trajectory import Phase

SAMPLE_PERIOD_S = 0.004
"""Resolution of the moment the cutter leaves the board (the machine's period)."""


def jerk_limited_cut_s(path: Path, limits: MotionLimits) -> float:
    """The shortest time to cut ``path`` from rest to rest at the feed: length / feed plus
    the jerk-limited ramps up and down (at the path's largest tangential acceleration and
    jerk the axis limits allow)."""
    feed = limits.feed_mm_s
    accel = 0.0
    jerk = 0.0
    for piece in path.pieces:
        box = path_box(piece.bounds(), limits.x, limits.y, math.inf, math.inf)
        accel = max(accel, box.acceleration)
        jerk = max(jerk, box.jerk)
    if feed < accel**2 / jerk:
        ramp_s = 2.0 * math.sqrt(feed / jerk)
    else:
        ramp_s = feed / accel + accel / jerk
    return path.length_mm / feed + ramp_s


def _moving_time_s(plan: StavePlan, phase: Phase) -> float:
    """The planned motion of one phase, dwells left out."""
    return sum(c.duration_s for c in plan.chunks if c.chunk.phase is phase and not c.chunk.dwell_s)


def approach_from_side_b_s(plan: StavePlan, limits: MotionLimits) -> float:
    """The fastest approach of the next board (of the same size): from where side B ends to
    side A's lead-in, around the board's keep-out."""
    ends = [c.chunk.end_xyz() for c in plan.chunks if c.chunk.phase is Phase.CUT_B]
    first = plan.toolpath.segments[0]
    target = (*first.start, first.z_start_deg)
    keep_out = TableKeepOut.around_toolpath(plan.toolpath)
    chunks = routed_chunks(keep_out, ends[-1], target, limits, Phase.APPROACH)
    return sum(PlannedChunk(c, 0.0).duration_s for c in chunks)


def clear_before_side_b_end_s(plan: StavePlan) -> float:
    """How long before the end of side B the cutter has left the board's keep-out for good
    (the clamps may open from then on)."""
    interval = plan.phase_interval(Phase.CUT_B)
    if interval is None:
        return 0.0
    keep_out = TableKeepOut.around_toolpath(plan.toolpath)
    start_s, end_s = interval
    last_inside_s = start_s
    steps = int((end_s - start_s) / SAMPLE_PERIOD_S)
    for k in range(steps + 1):
        t = start_s + k * SAMPLE_PERIOD_S
        sample = plan.sample(t)
        if keep_out.inside((sample.x, sample.y, sample.z)):
            last_inside_s = t
    return max(end_s - last_inside_s - SAMPLE_PERIOD_S, 0.0)


@dataclass(frozen=True)
class CycleFloor:
    """The floor of one board's cycle and what it is made of (seconds)."""

    parts_s: dict[str, float]

    @property
    def total_s(self) -> float:
        return sum(self.parts_s.values())


def cycle_floor(
    plan: StavePlan,
    limits: MotionLimits,
    io: IOConfig,
    cycle: CycleConfig,
    measure_s: float,
    approach_s: float | None = None,
) -> CycleFloor:
    """The floor of a cycle whose cut is ``plan``, approached in ``approach_s`` at best (by
    default from the end of the previous board's side B), on a machine with the I/O strokes
    ``io``, the overlaps ``cycle`` allows, and a gauge that reads in ``measure_s``."""
    if approach_s is None:
        approach_s = approach_from_side_b_s(plan, limits)
    if cycle.centering_retract_while_clamping:
        retract_after_clamped_s = max(io.centering_time_s - io.clamp_time_s, 0.0)
    else:
        retract_after_clamped_s = io.centering_time_s
    # From the clamps closed to the cutter at the lead-in with the spindle running.
    to_lead_in_s = max(
        measure_s + max(io.spindle_runup_s, approach_s),
        max(measure_s, retract_after_clamped_s) + approach_s,
    )
    unclamp_left_s = max(io.clamp_time_s - clear_before_side_b_end_s(plan), 0.0)
    return CycleFloor(
        {
            "centering": io.centering_time_s,
            "clamping": io.clamp_time_s,
            "to_lead_in": to_lead_in_s,
            "side_a": jerk_limited_cut_s(plan.cut_path("A"), limits),
            "repositioning": _moving_time_s(plan, Phase.REPOSITION),
            "side_b": jerk_limited_cut_s(plan.cut_path("B"), limits),
            "unclamping": unclamp_left_s,
        }
    )
