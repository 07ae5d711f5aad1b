"""Where the seconds of an automatic cycle go, against the floor of the machine.

    .venv/bin/python benchmarks/cycle_bench.py                # every case (about 2 min)
    .venv/bin/python benchmarks/cycle_bench.py --json out.json
    .venv/bin/python benchmarks/cycle_bench.py --config my-machine.toml

For every sample recipe (at a 150 mm board, or the nearest width the recipe cuts) and for
staves of sizes no recipe has (the fixed-tilt "Cask 2500 l" at lengths 900 to 3500 mm), two
boards go through the simulated machine exactly as in ``stave simulate``; the second one is
reported (the steady state: its approach starts where the previous board left the axes).
Printed per case: the cycle time split by step (``step_times_s`` of the cycle), the floor
(``app.machine.cycle_floor``: the cut at the jerk-limited optimum plus the strokes that
cannot overlap, with the configuration's I/O times and the simulated gauge's reading time),
the ratio cycle / floor, and staves per hour against the original machine's 90 s per stave.
Nothing here is asserted.
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from dataclasses import replace
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from app.config import MachineConfig, load_config  # noqa: E402
from app.data.recipe import Recipe  # noqa: E402
from app.drivers.sim.settings import parse_gauge_settings  # noqa: E402
from app.geometry.width_range import cuttable_widths  # noqa: E402
from app.machine import commands as cmd  # noqa: E402
from app.machine.cycle_floor import cycle_floor  # noqa: E402
from app.machine.process_params import motion_limits, stave_limits  # noqa: E402
from app.machine.runtime import MachineRuntime  # noqa: E402
from app.machine.states import MachineState, TimedStep  # noqa: E402

ORIGINAL_MACHINE_S = 90.0
BOARD_WIDTH_MM = 150.0
HIDDEN_BASE = "Cask 2500 l"
HIDDEN_LENGTHS_MM = (900.0, 1300.0, 1800.0, 2400.0, 3000.0, 3500.0)
CYCLE_TIMEOUT_S = 600.0


def _width_for(recipe: Recipe, runtime: MachineRuntime) -> float:
    c = runtime.controller
    widths = cuttable_widths(recipe.stave, c.params, stave_limits(c.config))
    if widths is None:
        raise SystemExit(f"recipe {recipe.name!r} cuts no board on this machine")
    return min(max(BOARD_WIDTH_MM, widths.min_mm), widths.max_mm)


def _one_board(runtime: MachineRuntime, width_mm: float) -> None:
    c = runtime.controller
    world = runtime.backend.extras["world"]
    world.remove_board()
    runtime.run_for(0.1)
    world.load_board(width_mm)
    runtime.run_for(0.1)
    done_before = c.pieces_total
    c.post(cmd.Start())
    runtime.run_for(2 * runtime.period_s)
    finished = runtime.run_until(
        lambda m: m.pieces_total > done_before or m.state is not MachineState.AUTOMATIC,
        CYCLE_TIMEOUT_S,
    )
    if not finished or c.pieces_total == done_before:
        raise SystemExit(f"the cycle did not finish: {c.state.value}: {c.message}")
    runtime.run_until(lambda m: m.state is MachineState.READY, 1.0)


def measure_case(runtime: MachineRuntime, recipe: Recipe, measure_s: float) -> dict[str, Any]:
    """Two boards of ``recipe``; the figures of the second."""
    c = runtime.controller
    assert recipe.id is not None
    c.post(cmd.SelectRecipe(recipe.id))
    runtime.run_for(2 * runtime.period_s)
    width_mm = _width_for(recipe, runtime)
    for _ in range(2):
        _one_board(runtime, width_mm)
    piece, cycle = c.finished_cycles[-1]
    assert cycle.planned is not None
    plan = cycle.planned.plan
    limits = motion_limits(c.config, c.params)
    floor = cycle_floor(plan, limits, c.config.io, c.config.cycle, measure_s)
    return {
        "case": recipe.name,
        "length_mm": recipe.length_mm,
        "width_mm": width_mm,
        "cycle_s": piece.cycle_time_s,
        "step_times_s": dict(piece.step_times_s),
        "floor_s": floor.total_s,
        "floor_parts_s": floor.parts_s,
        "ratio": piece.cycle_time_s / floor.total_s,
        "staves_per_hour": 3600.0 / piece.cycle_time_s,
    }


def run_cases(config: MachineConfig) -> list[dict[str, Any]]:
    measure_s = parse_gauge_settings(config.gauge_settings.get("sim", {})).measurement_time_s
    with tempfile.TemporaryDirectory() as tmp:
        runtime = MachineRuntime.create(config.with_backend("sim", "sim"), Path(tmp) / "b.db")
        try:
            runtime.start()
            c = runtime.controller
            c.post(cmd.Home())
            runtime.run_until(lambda m: m.state is MachineState.READY, 300.0)
            recipes = list(c.store.recipes())
            base = c.store.recipe_by_name(HIDDEN_BASE)
            if base is None:
                raise SystemExit(f"the sample recipe {HIDDEN_BASE!r} is missing")
            for length in HIDDEN_LENGTHS_MM:
                variant = replace(base, id=None, name=f"stave {length:.0f} mm", length_mm=length)
                recipes.append(c.store.save_recipe(variant))
            return [measure_case(runtime, recipe, measure_s) for recipe in recipes]
        finally:
            runtime.shutdown()


_COLUMNS = [s.value for s in TimedStep if s is not TimedStep.RETRACTING]


def print_table(rows: list[dict[str, Any]]) -> None:
    head = " ".join(f"{name[:7]:>7}" for name in _COLUMNS)
    tail = f"{'cycle':>6} {'floor':>6} {'ratio':>6} {'/h':>5}"
    print(f"{'case':24} {'L mm':>5} {'W mm':>5} {head} {tail}")
    for r in rows:
        steps = " ".join(f"{r['step_times_s'].get(name, 0.0):7.2f}" for name in _COLUMNS)
        print(
            f"{r['case'][:24]:24} {r['length_mm']:5.0f} {r['width_mm']:5.1f} {steps} "
            f"{r['cycle_s']:6.2f} {r['floor_s']:6.2f} {r['ratio']:6.3f} "
            f"{r['staves_per_hour']:5.1f}"
        )
    worst = max(r["ratio"] for r in rows)
    print(
        f"worst cycle / floor {worst:.3f}; the original machine: {ORIGINAL_MACHINE_S:.0f} s "
        f"per stave = {3600.0 / ORIGINAL_MACHINE_S:.0f} staves per hour"
    )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else "")
    parser.add_argument("--config", type=Path, help="machine configuration (TOML)")
    parser.add_argument("--json", type=Path, metavar="FILE", help="also write the rows as JSON")
    args = parser.parse_args(argv)
    rows = run_cases(load_config(args.config))
    print_table(rows)
    if args.json is not None:
        args.json.write_text(json.dumps(rows, indent=2), encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
