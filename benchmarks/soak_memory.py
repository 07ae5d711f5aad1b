"""Memory of the machine process over many cycles: RSS per 1,000 cycles must stay flat.

The machine process runs for months, so anything it keeps per cycle (alarm history, finished
cycles, plans, previews, lateness samples, records waiting for the database) must be bounded.
This runs the machine process's own composition (``MachineRuntime`` with the threaded,
journalled store and the planner on a worker thread, logging to a rotating file, a snapshot
taken and pickled at the rate the process publishes it, each new plan preview pickled as it
goes to the screens) on the simulated machine with a simulated clock, as fast as it goes. After
every block of cycles it prints the resident set size, its growth per 1,000 cycles since the
block before, SQLite's own heap (its page caches, statements and schema; read from the
SQLite library through ``sqlite3_memory_used`` where that library is the one Python uses), and
the C heap's bytes in use and free (glibc's ``mallinfo2``: a leak shows there even while RSS
stays flat because the heap reuses free memory). At
the end it prints the growth per 1,000 cycles from the first block to the last (the first
block includes start-up allocations).

``--trim`` returns the C heap's free memory to the system (glibc ``malloc_trim``) before each
figure: RSS that then stays flat was free memory kept by the allocator, not a leak.
``--trace-frames N`` also starts tracemalloc (N frames per allocation) and, at the end, prints
the allocation sites that grew most between the first block and the last: where the memory
goes, not only how much (tracemalloc slows the run about threefold).

Run: ``.venv/bin/python benchmarks/soak_memory.py [--cycles 3000] [--every 1000] [--trim]
[--trace-frames 6]`` (0.3-1.2 s per cycle on the 2-core machine, depending on its load).
"""

from __future__ import annotations

import argparse
import concurrent.futures
import ctypes
import ctypes.util
import gc
import pickle
import sqlite3
import tempfile
import tracemalloc
from collections.abc import Callable
from pathlib import Path

from app.config import load_config
from app.logging_setup import setup_logging
from app.machine import commands as cmd
from app.machine.process_link import SNAPSHOT_PERIOD_S
from app.machine.runtime import MachineRuntime
from app.machine.states import MachineState

TOP_SITES = 12  # allocation sites printed with --trace-frames
PER_CYCLES = 1000  # growth is printed per this many cycles


def rss_kib() -> int:
    """Resident set size of this process (Linux /proc)."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    return 0


def sqlite_memory_reader() -> Callable[[], int] | None:
    """Bytes SQLite holds on its heap now, or None where that cannot be read: the library
    ctypes finds must be the one Python's sqlite3 module runs on (same version, and it has
    allocated something once a connection is open), else its figure would be another copy's."""
    name = ctypes.util.find_library("sqlite3")
    if name is None:
        return None
    try:
        library = ctypes.CDLL(name)
        library.sqlite3_libversion.restype = ctypes.c_char_p
        library.sqlite3_memory_used.restype = ctypes.c_int64
    except (OSError, AttributeError):
        return None
    if library.sqlite3_libversion().decode() != sqlite3.sqlite_version:
        return None
    used: Callable[[], int] = library.sqlite3_memory_used
    return used if used() > 0 else None


class _Mallinfo2(ctypes.Structure):
    _fields_ = [
        (name, ctypes.c_size_t)
        for name in (
            "arena", "ordblks", "smblks", "hblks", "hblkhd",
            "usmblks", "fsmblks", "uordblks", "fordblks", "keepcost",
        )
    ]  # fmt: skip


def c_heap_reader() -> Callable[[], tuple[int, int]] | None:
    """(bytes in use, bytes free) of the C heap (glibc >= 2.33 ``mallinfo2``, every arena), or
    None elsewhere. RSS alone hides a slow leak while the heap still has free memory to reuse:
    the bytes in use do not."""
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        mallinfo2 = libc.mallinfo2
    except (OSError, AttributeError):
        return None
    mallinfo2.restype = _Mallinfo2

    def read() -> tuple[int, int]:
        info = mallinfo2()
        return int(info.uordblks + info.hblkhd), int(info.fordblks)

    return read


def malloc_trim() -> bool:
    """Give the C heap's free pages back to the system (glibc only); False where unavailable."""
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        libc.malloc_trim(0)
    except (OSError, AttributeError):
        return False
    return True


def per_1000_kib(before: tuple[int, int], after: tuple[int, int]) -> float:
    """RSS growth per 1,000 cycles between two (cycles done, RSS KiB) figures."""
    return (after[1] - before[1]) * PER_CYCLES / (after[0] - before[0])


def print_grown_sites(first: tracemalloc.Snapshot, last: tracemalloc.Snapshot, cycles: int) -> None:
    """The allocation sites that grew most between two snapshots, per 1,000 cycles."""
    ignore = [tracemalloc.Filter(False, tracemalloc.__file__)]
    diff = last.filter_traces(ignore).compare_to(first.filter_traces(ignore), "traceback")
    total = sum(d.size_diff for d in diff)
    scale = PER_CYCLES / cycles / 1024
    print(f"traced growth {total / 1024:.1f} KiB = {total * scale:.1f} KiB per 1,000 cycles")
    for stat in diff[:TOP_SITES]:
        print(f"{stat.size_diff * scale:+8.1f} KiB/1,000 cycles {stat.count_diff:+6d} blocks")
        for line in stat.traceback.format():
            print(f"    {line}")


def soak(
    cycles: int, every: int, trace_frames: int = 0, trim: bool = False
) -> list[tuple[int, int]]:
    """(cycles done, RSS KiB) after each block."""
    if trace_frames:
        tracemalloc.start(trace_frames)
    snapshots: list[tracemalloc.Snapshot] = []
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=1, thread_name_prefix="planner")
    with tempfile.TemporaryDirectory() as tmp:
        setup_logging(tmp, "INFO", console=False, file_name="machine.log")
        runtime = MachineRuntime.create(
            load_config(), Path(tmp) / "soak.db", threaded_store=True, submit=pool.submit
        )
        sqlite_used = sqlite_memory_reader()
        c_heap = c_heap_reader()
        published = {"t": 0.0, "plan": 0, "bytes": 0}

        def publish(rt: MachineRuntime) -> None:
            # What machine_process_main does between periods: the queues pickle what they carry.
            if rt.time_s - published["t"] >= SNAPSHOT_PERIOD_S:
                published["t"] = rt.time_s
                snapshot = rt.controller.snapshot()
                published["bytes"] = len(pickle.dumps(snapshot))
                if snapshot.plan_id != published["plan"]:
                    preview = rt.controller.plan_preview(snapshot.plan_id)
                    published["bytes"] += len(pickle.dumps(preview))
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
                if trim:
                    malloc_trim()
                figures.append((done, rss_kib()))
                growth = (
                    f"  {per_1000_kib(figures[-2], figures[-1]):+8.1f} KiB per 1,000 cycles"
                    if len(figures) > 1
                    else " " * 29
                )
                sqlite_text = (
                    f"  SQLite {sqlite_used() / 1024:5.0f} KiB" if sqlite_used is not None else ""
                )
                heap_text = ""
                if c_heap is not None:
                    in_use, free = c_heap()
                    heap_text = f"  C heap in use {in_use / 1024:6.0f}, free {free / 1024:6.0f} KiB"
                print(
                    f"{done:6d} cycles  RSS {figures[-1][1] / 1024:7.1f} MiB{growth}"
                    f"{sqlite_text}{heap_text}",
                    flush=True,
                )
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
    parser.add_argument("--every", type=int, default=PER_CYCLES)
    parser.add_argument("--trace-frames", type=int, default=0)
    parser.add_argument("--trim", action="store_true", help="malloc_trim before each figure")
    args = parser.parse_args()
    figures = soak(args.cycles, args.every, args.trace_frames, args.trim)
    if len(figures) >= 2:
        growth = per_1000_kib(figures[0], figures[-1])
        print(
            f"growth from cycle {figures[0][0]} to {figures[-1][0]}: "
            f"{growth:+.1f} KiB per 1,000 cycles"
        )


if __name__ == "__main__":
    main()
