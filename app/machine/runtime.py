"""The machine loop: one period after another, on a simulated clock or in real time.

Why one loop for both: the behaviour a test sees on the simulated clock must be the behaviour
of the panel. Each period the simulated devices (if any) are advanced by exactly one period,
then the controller reads, decides and writes. In real time the loop first waits for the
period's deadline; that wait is the only difference.
"""

from __future__ import annotations

import gc
import logging
import time
from array import array
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from app.config import MachineConfig
from app.drivers.contracts import MachineBackend, PendantDevice, TimeDriven, WidthGauge
from app.drivers.evdev_pendant import create_pendant
from app.drivers.registry import create_backend, create_gauge
from app.machine.controller import MachineController
from app.machine.cycle import PlanSubmitter, run_now
from app.machine.store import MachineStore

log = logging.getLogger(__name__)


@dataclass
class LatenessStats:
    """How late each period started, in seconds (real-time loop only).

    Bounded: at most ``limit`` samples (the older half is dropped when full; 200,000 periods are
    13 minutes at 4 ms). Kept as an array of doubles, 8 bytes a sample (1.6 MB at the bound),
    not a list of float objects (32 bytes a sample), because the machine process runs for months.
    """

    samples: array[float] = field(default_factory=lambda: array("d"))
    overruns: int = 0
    limit: int = 200_000

    def add(self, lateness_s: float) -> None:
        if len(self.samples) >= self.limit:
            del self.samples[: self.limit // 2]
        self.samples.append(lateness_s)

    def percentile_ms(self, q: float) -> float:
        if not self.samples:
            return 0.0
        ordered = sorted(self.samples)
        index = min(len(ordered) - 1, round(q / 100.0 * (len(ordered) - 1)))
        return ordered[index] * 1000.0

    def summary(self) -> dict[str, float]:
        return {
            "periods": float(len(self.samples)),
            "p50_ms": self.percentile_ms(50),
            "p99_ms": self.percentile_ms(99),
            "max_ms": max(self.samples, default=0.0) * 1000.0,
            "overruns": float(self.overruns),
        }


class MachineRuntime:
    def __init__(
        self,
        config: MachineConfig,
        store: MachineStore,
        backend: MachineBackend | None = None,
        gauge: WidthGauge | None = None,
        *,
        submit: PlanSubmitter = run_now,
        wall_clock: Callable[[], float] = time.time,
        pendant: PendantDevice | None = None,
    ) -> None:
        self.config = config
        self.backend = backend if backend is not None else create_backend(config)
        self.gauge = gauge if gauge is not None else create_gauge(config, self.backend)
        self.controller = MachineController(
            config,
            self.backend,
            self.gauge,
            store,
            submit=submit,
            wall_clock=wall_clock,
            pendant=pendant if pendant is not None else create_pendant(config),
        )
        self.period_s = config.period_s
        self.time_s = 0.0
        self.periods = 0
        self._time_driven = [
            d for d in (*self.backend.devices(), self.gauge) if isinstance(d, TimeDriven)
        ]
        self.lateness = LatenessStats()
        self.on_tick: list[Callable[[MachineRuntime], None]] = []

    @classmethod
    def create(
        cls,
        config: MachineConfig,
        db_path: Path,
        *,
        threaded_store: bool = False,
        submit: PlanSubmitter = run_now,
        pendant: PendantDevice | None = None,
    ) -> MachineRuntime:
        """A runtime on the configured backends, with the database at ``db_path`` (and the
        configured USB pendant unless ``pendant`` is given)."""
        from app.machine.database_store import open_store

        store = open_store(db_path, config, threaded=threaded_store)
        return cls(config, store, submit=submit, pendant=pendant)

    def start(self) -> None:
        self.controller.power_up()

    def tick(self) -> None:
        """One period: the world moves for one period, then the controller acts on it."""
        for device in self._time_driven:
            device.advance(self.period_s)
        self.time_s = (self.periods + 1) * self.period_s
        self.periods += 1
        self.controller.tick(self.time_s)
        for hook in self.on_tick:
            hook(self)

    def run_for(self, seconds: float) -> None:
        """Simulated clock: as many periods as fit in ``seconds``, as fast as possible."""
        for _ in range(max(1, round(seconds / self.period_s))):
            self.tick()

    def run_until(self, done: Callable[[MachineController], bool], timeout_s: float) -> bool:
        """Simulated clock: tick until ``done`` or ``timeout_s`` of machine time passed."""
        end_s = self.time_s + timeout_s
        while self.time_s < end_s:
            self.tick()
            if done(self.controller):
                return True
        return False

    def run_realtime(
        self, keep_running: Callable[[], bool], between: Callable[[], None] = lambda: None
    ) -> None:
        """Real time: wait for each period's deadline, then tick; ``between`` runs after the
        tick (command intake, snapshot publishing) and must not block."""
        gc.collect()
        gc.freeze()  # long-lived objects out of the collector's way: shorter pauses
        period = self.period_s
        deadline = time.monotonic()
        while keep_running():
            deadline += period
            delay = deadline - time.monotonic()
            if delay > 0:
                time.sleep(delay)
            lateness = time.monotonic() - deadline
            self.lateness.add(max(0.0, lateness))
            if lateness > 5 * period:
                self.lateness.overruns += 1
                deadline = time.monotonic()  # resynchronise instead of catching up in a burst
            self.tick()
            between()

    def shutdown(self) -> None:
        self.controller.shutdown()
