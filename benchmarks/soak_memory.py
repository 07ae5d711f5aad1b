"""Memory of the machine process over many cycles: RSS per block of cycles must stay flat.

The machine process runs for months, so anything it keeps per cycle (alarm history, finished
cycles, plans, previews, lateness samples, records waiting for the database) must be bounded.
This runs the machine process's own composition (``MachineRuntime`` with the threaded,
journalled store and the planner on a worker thread, a snapshot and the plan preview taken
as the process publishes them) on the simulated machine with a simulated clock, as fast as it
goes, and prints the resident set size after every block of cycles with the growth per
cycle since the block before, and at the end the growth per cycle between the first block and
the last (the first block includes start-up allocations).

``--trace-frames N`` also starts tracemalloc (N frames per allocation) and, at the end, prints
the allocation sites that grew most between the first block and the last: where the memory
goes, not only how much (tracemalloc slows the run about threefold).

Run: ``.venv/bin/python benchmarks/soak_memory.py [--cycles 3000] [--every 1000]
[--trace-frames 6]`` (about 0.3 s per cycle on the 2-core machine).
"""

from __future__ import annotations

import argparse
import concurrent.futures
import gc
import tempfile
import tracemalloc
from pathlib import Path

from app.config import load_config
from app.machine import commands as cmd
from app.machine.runtime import MachineRuntime
from app.machine.states import MachineState

PUBLISH_EVERY_S = 0.02  # the machine process publishes a snapshot at 50 Hz
TOP_SITES = 12  # allocation sites printed with --trace-frames


def rss_kib() -> int:
    """Resident set size of this process (Linux /proc)."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    return 0


def per_cycle_kib(before: tuple[int, int], after: tuple[int, int]) -> float:
    """RSS growth per cycle between two (cycles done, RSS KiB) figures."""
    return (after[1] - before[1]) / (after[0] - before[0])


def print_grown_sites(first: tracemalloc.Snapshot, last: tracemalloc.Snapshot, cycles: int) -> None:
    """The allocation sites that grew most between two snapshots, per cycle."""
    ignore = [tracemalloc.Filter(False, tracemalloc.__file__)]
    diff = last.filter_traces(ignore).compare_to(first.filter_traces(ignore), "traceback")
    total = sum(d.size_diff for d in diff)
    print(f"traced growth {total / 1024:.1f} KiB = {total / 1024 / cycles:.3f} KiB per cycle")
    for stat in diff[:TOP_SITES]:
        print(f"{stat.size_diff / 1024 / cycles:+8.3f} KiB/cycle {stat.count_diff:+6d} blocks")
        for line in stat.traceback.format():
            print(f"    {line}")


def soak(cycles: int, every: int, trace_frames: int = 0) -> list[tuple[int, int]]:
    """(cycles done, RSS KiB) after each block."""
    if trace_frames:
        tracemalloc.start(trace_frames)
    snapshots: list[tracemalloc.Snapshot] = []
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=1, thread_name_prefix="planner")
    with tempfile.TemporaryDirectory() as tmp:
        runtime = MachineRuntime.create(
            load_config(), Path(tmp) / "soak.db", threaded_store=True, submit=pool.submit
        )
        published = {"t": 0.0, "plan": 0}

        def publish(rt: MachineRuntime) -> None:
            if rt.time_s - published["t"] >= PUBLISH_EVERY_S:
                published["t"] = rt.time_s
                snapshot = rt.controller.snapshot()
                if snapshot.plan_id != published["plan"]:
                    rt.controller.plan_preview(snapshot.plan_id)
                    published["plan"] = snapshot.plan_id

        runtime.on_tick.append(publish)
        runtime.start()
        c = runtime.controller
        world = runtime.backend.extras["world"]
        c.post(cmd.Home())
        runtime.run_until(lambda m: m.state is MachineState.READY, 300.0)
        recipe_id = c.store.first_recipe_id()
        assert recipe_id is not None
        c.post(cmd.SelectRecipe(recipe_id))
        runtime.run_for(0.1)
        figures: list[tuple[int, int]] = []
        for done in range(1, cycles + 1):
            world.remove_board()
            runtime.run_for(0.1)
            world.load_board(150.0)
            runtime.run_for(0.1)
            c.post(cmd.Start())
            runtime.run_for(0.05)
            if not runtime.run_until(
                lambda m: m.state is MachineState.READY and m.cycle is None, 300.0
            ):
                raise RuntimeError(f"cycle {done} did not end: {c.state_text()}")
            if done % every == 0:
                gc.collect()
                figures.append((done, rss_kib()))
                growth = (
                    f"  {per_cycle_kib(figures[-2], figures[-1]):+8.3f} KiB per cycle"
                    if len(figures) > 1
                    else ""
                )
                print(f"{done:6d} cycles  RSS {figures[-1][1] / 1024:8.1f} MiB{growth}", flush=True)
                if trace_frames:
                    snapshots.append(tracemalloc.take_snapshot())
        runtime.shutdown()
    pool.shutdown()
    if len(snapshots) > 1:
        print_grown_sites(snapshots[0], snapshots[-1], figures[-1][0] - figures[0][0])
    return figures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cycles", type=int, default=3000)
    parser.add_argument("--every", type=int, default=1000)
    parser.add_argument("--trace-frames", type=int, default=0)
    args = parser.parse_args()
    figures = soak(args.cycles, args.every, args.trace_frames)
    if len(figures) >= 2:
        growth = per_cycle_kib(figures[0], figures[-1])
        print(f"growth after the first block: {growth:.3f} KiB per cycle")


if __name__ == "__main__":
    main()
