"""The simulated width gauge: measures the board on the simulated table, with noise, and fails
the ways a real gauge fails.

Why it reads the world's board: the width the gauge reports and the board the machine cuts
must be the same board, so with the simulated machine the true width is that of
``SimWorld.board``; the gauge adds gaussian noise (``noise_mm``, seeded) and answers like the
serial gauge, ``W=150.12`` (0.01 mm resolution), ``measurement_time_s`` after ``request()``.
``poll()`` returns that reading once, and None before and after. An empty table reads
``W=0.00``.

Failure modes (injected through ``extras["faults"]`` or :meth:`SimGauge.inject`), evaluated
when the reading falls due:

- ``gauge_none``: no reply ever; ``poll()`` keeps returning None (the machine layer times out).
- ``gauge_garbage``: ``GaugeReading(width_mm=None, raw="#?!x", error="unparseable reply ...")``.
- ``gauge_out_of_range``: ``out_of_range_mm`` (999.0), a width the machine layer must reject.
- ``comms_loss`` with target ``gauge``: unplugged; ``request()`` and ``poll()`` raise
  CommunicationError.

Without a simulated world (the sim gauge beside a real machine backend) the gauge has its
own seeded widths (``width_*`` options, or :meth:`SimGauge.queue_widths`), each request
measuring a new board, and since it has no clock it counts time in polls: each ``poll()``
stands for one machine period. It never reads the wall clock.
"""

from __future__ import annotations

import random
from collections import deque
from collections.abc import Iterable

from app.config import MachineConfig
from app.drivers.contracts import (
    CommunicationError,
    DeviceEvent,
    DeviceEventKind,
    GaugeReading,
    LifecycleState,
    MachineBackend,
    WidthGauge,
)
from app.drivers.lifecycle import ManagedLifecycle
from app.drivers.sim.faults import fault_targets
from app.drivers.sim.settings import GaugeSettings, parse_gauge_settings
from app.drivers.sim.world import GaugeLine, GaugeMode, SimWorld

L = LifecycleState
GARBAGE_REPLY = "#?!x"
GAUGE_FAULT_KINDS: dict[str, GaugeMode] = {
    "gauge_none": GaugeMode.NO_REPLY,
    "gauge_garbage": GaugeMode.GARBAGE,
    "gauge_out_of_range": GaugeMode.OUT_OF_RANGE,
}


class SimGauge(ManagedLifecycle, WidthGauge):
    """A WidthGauge on the simulated world (or on its own widths without one)."""

    def __init__(self, settings: GaugeSettings, world: SimWorld | None, period_s: float) -> None:
        super().__init__("sim gauge")
        self.settings = settings
        self._world = world
        self._line = world.gauge_line if world is not None else GaugeLine()
        self._period_s = period_s
        self._noise_rng = random.Random(f"{settings.seed}/noise")
        self._width_rng = random.Random(f"{settings.seed}/widths")
        self._queue: deque[float] = deque()
        self._own_time_s = 0.0
        self._due_at_s: float | None = None
        self._own_width_mm = 0.0
        self._plugged_seen = True
        self._injected: list[tuple[str, str]] = []

    # -- lifecycle hooks ------------------------------------------------------------------------
    def _require_plugged(self, what: str) -> None:
        if not self._line.plugged:
            raise CommunicationError("sim gauge", f"{what} failed: no reply (unplugged)")

    def _on_configure(self) -> None:
        self._require_plugged("configure")

    def _on_activate(self) -> None:
        self._require_plugged("activate")
        self._due_at_s = None

    def _on_deactivate(self) -> None:
        self._require_plugged("deactivate")
        self._due_at_s = None

    def _on_shutdown(self) -> None:
        self._due_at_s = None

    def _pending_events(self) -> list[DeviceEvent]:
        plugged = self._line.plugged
        if plugged == self._plugged_seen:
            return []
        self._plugged_seen = plugged
        kind = (
            DeviceEventKind.COMMUNICATION_RESTORED
            if plugged
            else DeviceEventKind.COMMUNICATION_LOST
        )
        return [DeviceEvent(kind, "sim gauge", text="plugged in" if plugged else "unplugged")]

    # -- measuring ---------------------------------------------------------------------------
    def _now(self) -> float:
        return self._world.time_s if self._world is not None else self._own_time_s

    def _require_active(self, what: str) -> None:
        self._require(what, L.ACTIVE)
        if not self._line.plugged:
            raise CommunicationError("sim gauge", f"{what}: no reply (unplugged)")

    def request(self) -> None:
        """Start a measurement; the reading is due ``measurement_time_s`` later."""
        self._require_active("request")
        self._due_at_s = self._now() + self.settings.measurement_time_s
        if self._world is None:
            self._own_width_mm = (
                self._queue.popleft() if self._queue else self.settings.widths.draw(self._width_rng)
            )

    def poll(self) -> GaugeReading | None:
        """The reading once it is due (once), else None; never blocks."""
        if self._world is None and self._state is L.ACTIVE:
            self._own_time_s += self._period_s  # no clock: one poll per machine period
        self._require_active("poll")
        if self._due_at_s is None or self._now() < self._due_at_s - 1e-9:
            return None
        self._due_at_s = None
        mode = self._line.mode
        if mode is GaugeMode.NO_REPLY:
            return None
        if mode is GaugeMode.GARBAGE:
            return GaugeReading(
                None, GARBAGE_REPLY, f"unparseable reply {GARBAGE_REPLY!r} (expected W=<mm>)"
            )
        if mode is GaugeMode.OUT_OF_RANGE:
            value = self.settings.out_of_range_mm
        else:
            value = self._true_width_mm()
            if value > 0.0:
                value += self._noise_rng.gauss(0.0, self.settings.noise_mm)
        raw = f"W={value:.2f}"
        return GaugeReading(float(raw[2:]), raw)

    def _true_width_mm(self) -> float:
        if self._world is None:
            return self._own_width_mm
        board = self._world.board
        return board.true_width_mm if board is not None else 0.0

    def queue_widths(self, widths: Iterable[float]) -> None:
        """True widths of the next boards: with a world, of the next boards put on the
        table; without one, of the next requests."""
        values = list(widths)
        if self._world is not None:
            self._world.queue_board_widths(values)
            return
        for value in values:
            if isinstance(value, bool) or not isinstance(value, int | float) or not value > 0:
                raise ValueError(f"width = {value!r} is not allowed: a finite number of mm > 0")
        self._queue.extend(float(v) for v in values)

    # -- fault injection of the gauge alone -------------------------------------------------
    def inject(self, kind: str, target: str = "") -> None:
        """Gauge faults only: gauge_none, gauge_garbage, gauge_out_of_range, and
        comms_loss with target "gauge" (unplugged)."""
        if kind in GAUGE_FAULT_KINDS and target == "":
            self._line.mode = GAUGE_FAULT_KINDS[kind]
        elif kind == "comms_loss" and target == "gauge":
            self._set_plugged(False)
        else:
            fault_targets(kind)  # an unknown kind names the allowed ones
            raise ValueError(
                f"fault {kind!r} (target {target!r}) is not allowed on the gauge: "
                "one of gauge_none, gauge_garbage, gauge_out_of_range, "
                "comms_loss with target 'gauge'"
            )
        self._injected.append((kind, target))

    def clear_injections(self) -> None:
        if self._injected:
            self._line.mode = GaugeMode.NORMAL
            self._set_plugged(True)
        self._injected.clear()

    def _set_plugged(self, plugged: bool) -> None:
        if self._world is not None:
            self._world.set_link("gauge", plugged)
        else:
            self._line.plugged = plugged


def create_gauge(config: MachineConfig, backend: MachineBackend) -> SimGauge:
    """The simulated gauge, configured (INACTIVE); it measures the simulated board when
    ``backend.extras["world"]`` is a SimWorld. ``[gauge.sim]`` is checked here."""
    settings = parse_gauge_settings(config.gauge_settings.get("sim", {}))
    world = backend.extras.get("world")
    gauge = SimGauge(settings, world if isinstance(world, SimWorld) else None, config.period_s)
    gauge.configure()
    return gauge
