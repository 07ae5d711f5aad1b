"""Geometry benchmark: solve and tool-path times, and the original method's error next to ours.

Run:  .venv/bin/python benchmarks/geometry_bench.py [--quick]

Prints
* the time of one profile solve (validation + certified cubic root + points), of the cubic
  alone, of a tool path and of its polyline at 0.001 mm chord error;
* for a few staves, the edge error of the original program's y-only shift of r/cos(alpha)
  against the normal offset (overcut normal to the edge, the across-the-stave figure of
  docs/MACHINE.md section 3, rc*(1/cos(theta) - 1), and how far along X the tangent points move),
  with ours beside it;
* the worst of both over random staves covering the whole valid range.

Machine parameters: tool radius 40 mm, machine height 250 mm, tilt 3.5 deg, P0 (100, 400),
lead 60 mm, tilt clearance 50 mm, home (0, 0, 0).
"""

from __future__ import annotations

import argparse
import math
import random
import statistics
import time
from collections.abc import Callable

from app.cli.solve import PROCESS_DEFAULTS
from app.geometry.compare import edge_deviation, slope_overcut_formula_mm, tangent_point_shift_mm
from app.geometry.profile import solve_cubic_d, solve_profile
from app.geometry.ratio import Ratio
from app.geometry.toolpath import ToolPathParams, build_original_toolpath, build_toolpath

# The typical jointer of `stave solve` (80 mm cutter, pivot 250 mm above the table), 3.5 deg.
PARAMS = ToolPathParams.from_parameters(PROCESS_DEFAULTS, tilt_deg=3.5)

STAVES = [  # (L, W, lambda, k)
    (1000.0, 150.0, "1/4", "3/4"),  # the worked example of docs/MACHINE.md section 2
    (900.0, 120.0, "1/3", "2/3"),
    (1200.0, 200.0, "1/4", "3/5"),
    (950.0, 280.0, "1/5", "3/14"),  # widest board, narrowest head: steepest slope
    (3500.0, 280.0, "1/4", "1/2"),
    (2000.0, 180.0, "0", "3/4"),  # one arc, no straight sections
]


def per_call_us(function: Callable[[], object], repeats: int) -> tuple[float, float]:
    """Median and best time of one call in microseconds, over `repeats` batches."""
    batch = 200
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(batch):
            function()
        times.append((time.perf_counter() - start) / batch * 1e6)
    return statistics.median(times), min(times)


def random_stave(rng: random.Random) -> tuple[float, float, float, float]:
    length = rng.uniform(900.0, 3500.0)
    lam = rng.randrange(0, 5000) / 10_000
    k = rng.uniform(60.0 / 280.0, 0.999)
    width = rng.uniform(60.0 / k, 280.0)
    return length, width, lam, k


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats and samples")
    args = parser.parse_args()
    repeats = 5 if args.quick else 20
    sweep = 200 if args.quick else 1000

    profile = solve_profile(1000.0, 150.0, 0.25, 0.75)
    path = build_toolpath(profile, PARAMS)
    print("timing (median / best of batches, one call):")
    for name, function in (
        ("solve_profile (validate + cubic + points)", lambda: solve_profile(1000, 150, 0.25, 0.75)),
        ("solve_cubic_d (certified root)", lambda: solve_cubic_d(250.0, 250.0, 18.75)),
        ("build_toolpath (both sides, travel)", lambda: build_toolpath(profile, PARAMS)),
        ("to_polyline(0.001 mm)", lambda: path.to_polyline(0.001)),
    ):
        median, best = per_call_us(function, repeats)
        print(f"  {name:44s} {median:9.1f} us  {best:9.1f} us")
    points = path.to_polyline(0.001)
    print(f"  polyline of the worked example at 0.001 mm: {len(points)} points")
    print(f"  polyline at 0.001 mm, chords <= 1 mm: {len(path.to_polyline(0.001, 1.0))} points")

    rc = PARAMS.effective_radius_mm
    print()
    print(f"edge error, tool radius 40 mm, tilt 3.5 deg (rc = r/cos(alpha) = {rc:.4f} mm):")
    print(
        "     L      W  lambda     k  slope deg | y-only: overcut  across(spec)  tangent X"
        " | ours: max error"
    )
    for length, width, lam_text, k_text in STAVES:
        lam, k = Ratio.parse(lam_text), Ratio.parse(k_text)
        profile = solve_profile(length, width, lam.value, k.value)
        ours = build_toolpath(profile, PARAMS)
        original = build_original_toolpath(profile, PARAMS)
        old = max(edge_deviation(original, side).max_abs_mm for side in "AB")
        new = max(edge_deviation(ours, side).max_abs_mm for side in "AB")
        print(
            f"  {length:6.0f} {width:5.0f} {lam_text:>6} {k_text:>5} "
            f"{math.degrees(profile.slope_rad):9.3f}  | {old:12.4f} mm "
            f"{slope_overcut_formula_mm(profile, rc):9.4f} mm "
            f"{tangent_point_shift_mm(original, ours):8.3f} mm | {new:9.1e} mm"
        )

    rng = random.Random(20240501)
    worst_old = worst_new = worst_shift = 0.0
    solve_times = []
    for _ in range(sweep):
        length, width, lam_value, k_value = random_stave(rng)
        start = time.perf_counter()
        profile = solve_profile(length, width, lam_value, k_value)
        solve_times.append((time.perf_counter() - start) * 1e6)
        ours = build_toolpath(profile, PARAMS)
        original = build_original_toolpath(profile, PARAMS)
        worst_old = max(worst_old, edge_deviation(original, "A", 60).max_abs_mm)
        worst_new = max(worst_new, edge_deviation(ours, "A", 60).max_abs_mm)
        worst_shift = max(worst_shift, tangent_point_shift_mm(original, ours))
    print()
    print(f"over {sweep} random staves in the valid range (side A, 60 samples per piece):")
    solve_times.sort()
    p99 = solve_times[int(0.99 * (len(solve_times) - 1))]
    print(
        f"  solve_profile median {statistics.median(solve_times):.1f} us, p99 {p99:.1f} us, "
        f"max {solve_times[-1]:.1f} us (max includes scheduler hiccups of a shared machine)"
    )
    print(
        f"  y-only shift: worst edge error {worst_old:.4f} mm, "
        f"tangent points moved up to {worst_shift:.3f} mm along X"
    )
    print(f"  normal offset (ours): worst edge error {worst_new:.1e} mm")


if __name__ == "__main__":
    main()
