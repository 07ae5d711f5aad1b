"""How much faster than real time the simulated machine runs (the target is >= 50x).

One simulated minute of the three axes in cyclic synchronous position mode at the configured
4 ms period: every period the setpoints of X, Y and Z are written (cosine sweeps that keep
all three axes moving and accelerating), the world is advanced by one period, the feedback and
the inputs are read, as the machine loop does. Prints the wall time and the speed-up.

Run: ``.venv/bin/python benchmarks/sim_speed.py [--minutes N]``
"""

from __future__ import annotations

import argparse
import math
import time
import tomllib

from app.config import default_config_path, parse_config
from app.drivers.sim.backend import create_backend


def simulate(minutes: float) -> tuple[float, float]:
    """Returns (simulated seconds, wall seconds)."""
    data = tomllib.loads(default_config_path().read_text(encoding="utf-8"))
    data["backend"]["sim"] = {"start_position": {"X": 1000.0, "Y": 200.0, "Z": 0.0}}
    config = parse_config(data)
    backend = create_backend(config)
    motion, io = backend.motion, backend.io
    motion.activate()
    io.activate()
    period_s = config.period_s
    for axis in motion.axis_names:
        motion.enable(axis)
    for _ in range(10):
        motion.advance(period_s)
    start = {name: fb.position for name, fb in motion.read_axes().items()}
    amplitude = {"X": 300.0, "Y": 150.0, "Z": 6.0}
    periods = round(minutes * 60.0 / period_s)
    wall_start = time.perf_counter()
    for i in range(periods):
        t = i * period_s
        motion.write_setpoints(
            {
                name: start[name] + amplitude[name] * (1.0 - math.cos(2.0 * math.pi * 0.2 * t))
                for name in ("X", "Y", "Z")
            }
        )
        motion.advance(period_s)
        feedback = motion.read_axes()
        io.read_inputs()
        if any(fb.faulted for fb in feedback.values()):
            raise RuntimeError(f"a drive faulted at t = {t:.3f} s: {feedback}")
    wall_s = time.perf_counter() - wall_start
    return periods * period_s, wall_s


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=1.0)
    args = parser.parse_args()
    simulated_s, wall_s = simulate(args.minutes)
    print(
        f"simulated {simulated_s:.1f} s of 3 axes at a 4 ms period in {wall_s:.3f} s wall: "
        f"{simulated_s / wall_s:.0f}x real time (required: >= 50x)"
    )


if __name__ == "__main__":
    main()
