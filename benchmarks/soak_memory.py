"""Memory of the machine process over many cycles: RSS per block of cycles must stay flat.

The machine process runs for months, so anything it keeps per cycle (alarm history, finished
cycles, plans, previews, lateness samples, records waiting for the database) must be bounded.
This runs the machine process's own composition (``MachineRuntime`` with the threaded,
journalled store and the planner on a worker thread, a snapshot and the plan preview taken
as the process publishes them) on the simulated machine with a simulated clock, as fast as it
goes, and prints the resident set size after every block of cycles, and the growth per cycle
between the second block and the last (the first block includes start-up allocations).

Run: ``.venv/bin/python benchmarks/soak_memory.py [--cycles 3000] [--every 1000]``
(about 0.3 s per cycle on the 2-core machine).
"""

from __future__ import annotations

import argparse
import concurrent.futures
import gc
import tempfile
from pathlib import Path

from app.config import load_config
from app.machine import commands as cmd
from app.machine.runtime import MachineRuntime
from app.machine.states import MachineState

PUBLISH_EVERY_S = 0.02  # the machine process publishes a snapshot at 50 Hz


def rss_kib() -> int:
    """Resident set size of this process (Linux /proc)."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    return 0


def soak(cycles: int, every: int) -> list[tuple[int, int]]:
    """(cycles done, RSS KiB) after each block."""
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
                print(f"{done:6d} cycles  RSS {figures[-1][1] / 1024:8.1f} MiB", flush=True)
        runtime.shutdown()
    pool.shutdown()
    return figures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cycles", type=int, default=3000)
    parser.add_argument("--every", type=int, default=1000)
    args = parser.parse_args()
    figures = soak(args.cycles, args.every)
    if len(figures) >= 3:
        (n0, r0), (n1, r1) = figures[1], figures[-1]
        print(f"growth after warm-up: {(r1 - r0) / (n1 - n0):.3f} KiB per cycle")


if __name__ == "__main__":
    main()
