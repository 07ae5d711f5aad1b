"""Time in each state as the Values folder of OPC 40550-1 counts it, in milliseconds.

Why two counters per time: the specification's Relative* values count since the server
started, its Absolute* values over the machine's life. The absolute ones are kept in the
database (``machine_state``, key ``opcua_state_times``) and written every ``SAVE_EVERY_S``
and when the server stops, so a restart continues them; at most that much is lost in a
power cut. AbsoluteMachineOffTime is the time between the last save and the next start
(the specification: "the shutdown time and the starting time have to be stored on the
machine"), plus any time the server ran without the machine process.

Each time is counted while its condition holds, one table of conditions over the unit
flags and the unit state; the Woodworking NodeSet's descriptions name them.
"""

from __future__ import annotations

import json
import logging
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from app.data.database import Database
from app.plant.state_map import UnitFlags, WwUnitState, unit_state

log = logging.getLogger(__name__)

STORE_KEY = "opcua_state_times"
SAVE_EVERY_S = 10.0

Condition = Callable[[UnitFlags, WwUnitState], bool]

# Time name (without Absolute/Relative) -> while it counts.
CONDITIONS: dict[str, Condition] = {
    "MachineOnTime": lambda f, _s: f.machine_on,
    "PowerPresentTime": lambda f, _s: f.power_present,
    "StandbyTime": lambda _f, s: s is WwUnitState.STANDBY,
    "ReadyTime": lambda _f, s: s is WwUnitState.READY,
    "WorkingTime": lambda _f, s: s is WwUnitState.WORKING,
    "ErrorTime": lambda _f, s: s is WwUnitState.ERROR,
    "ProductionTime": lambda f, _s: f.recipe_in_run and f.workpiece_present,
    "ProductionWithoutWorkpieceTime": lambda f, _s: f.recipe_in_run and not f.workpiece_present,
    "ProductionWaitWorkpieceTime": lambda f, _s: f.recipe_in_run and f.wait_load,
}
MACHINE_OFF = "MachineOffTime"  # absolute only: the NodeSet has no RelativeMachineOffTime

VALUE_NAMES: tuple[str, ...] = (
    *(f"Relative{name}" for name in CONDITIONS),
    *(f"Absolute{name}" for name in CONDITIONS),
    f"Absolute{MACHINE_OFF}",
)


@dataclass
class StateTimes:
    """The counters; ``add`` is called with the flags that held over the elapsed time."""

    absolute_ms: dict[str, float] = field(default_factory=dict)
    relative_ms: dict[str, float] = field(default_factory=dict)

    def add(self, flags: UnitFlags, elapsed_ms: float) -> None:
        if elapsed_ms <= 0.0:
            return
        state = unit_state(flags)
        for name, holds in CONDITIONS.items():
            if holds(flags, state):
                self.relative_ms[name] = self.relative_ms.get(name, 0.0) + elapsed_ms
                self.absolute_ms[name] = self.absolute_ms.get(name, 0.0) + elapsed_ms
        if not flags.machine_on:
            self.absolute_ms[MACHINE_OFF] = self.absolute_ms.get(MACHINE_OFF, 0.0) + elapsed_ms

    def values(self) -> dict[str, int]:
        """Browse name in the Values folder -> whole milliseconds."""
        found = {f"Relative{n}": int(self.relative_ms.get(n, 0.0)) for n in CONDITIONS}
        found.update(
            {f"Absolute{n}": int(self.absolute_ms.get(n, 0.0)) for n in (*CONDITIONS, MACHINE_OFF)}
        )
        return found

    def to_json(self, saved_at: float) -> str:
        return json.dumps({"saved_at": saved_at, "absolute_ms": self.absolute_ms})

    @classmethod
    def from_json(cls, text: str | None, started_at: float) -> StateTimes:
        """The absolute times saved, the time since ``saved_at`` counted as machine off.
        Anything unreadable starts from zero, with a warning: counters are not worth a
        server that does not start."""
        if not text:
            return cls()
        try:
            data = json.loads(text)
            saved_at = float(data["saved_at"])
            absolute = {
                str(k): float(v)
                for k, v in data["absolute_ms"].items()
                if k in CONDITIONS or k == MACHINE_OFF
            }
        except (ValueError, TypeError, KeyError, AttributeError) as exc:
            log.warning("OPC UA: saved state times not readable (%s); counting from zero", exc)
            return cls()
        times = cls({k: v for k, v in absolute.items() if v >= 0.0})
        off_ms = max(0.0, started_at - saved_at) * 1000.0
        times.absolute_ms[MACHINE_OFF] = times.absolute_ms.get(MACHINE_OFF, 0.0) + off_ms
        return times


def load_state_times(db_path: Path, started_at: float) -> StateTimes:
    with Database.open(db_path, load_samples=False) as db:
        return StateTimes.from_json(db.machine_state(STORE_KEY), started_at)


def save_state_times(times: StateTimes, db_path: Path, saved_at: float) -> None:
    with Database.open(db_path, load_samples=False) as db:
        db.set_machine_state(STORE_KEY, times.to_json(saved_at))
