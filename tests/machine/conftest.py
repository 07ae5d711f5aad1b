"""A real machine on the simulated backend and a real SQLite file, on a simulated clock."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

from app.config import MachineConfig, load_config
from app.data.users import Role
from app.machine import commands as cmd
from app.machine.runtime import MachineRuntime
from app.machine.states import MachineState

BARRIQUE = "Barrique 225 l Bordeaux"


class Rig:
    """The machine and the simulated world, with the operator's usual gestures."""

    def __init__(self, runtime: MachineRuntime, world: Any = None, faults: Any = None) -> None:
        """``world`` and ``faults``: the simulated machine behind a fieldbus backend (the
        Modbus emulator's world); by default the simulation backend's own."""
        self.runtime = runtime
        self.controller = runtime.controller
        self.world = world if world is not None else runtime.backend.extras["world"]
        self.faults = faults if faults is not None else runtime.backend.extras["faults"]

    @property
    def state(self) -> MachineState:
        return self.controller.state

    def send(self, command: cmd.Command, run_s: float = 0.02) -> None:
        self.controller.post(command)
        self.runtime.run_for(run_s)

    def run(self, seconds: float) -> None:
        self.runtime.run_for(seconds)

    def until(self, predicate, timeout_s: float = 120.0) -> None:  # type: ignore[no-untyped-def]
        assert self.runtime.run_until(predicate, timeout_s), (
            f"timed out in {self.state.value}: {self.controller.state_text()} "
            f"({self.controller.message})"
        )

    def home(self) -> None:
        self.send(cmd.Home())
        self.until(lambda c: c.state is MachineState.READY, 300.0)

    def select(self, name: str = BARRIQUE) -> None:
        recipe = self.controller.store.recipe_by_name(name)
        assert recipe is not None and recipe.id is not None
        self.send(cmd.SelectRecipe(recipe.id))

    def load(self, width_mm: float = 150.0) -> None:
        self.world.remove_board()
        self.run(0.05)
        self.world.load_board(width_mm)
        self.run(0.05)

    def set_parameters(self, values: dict[str, float]) -> None:
        """What the System screen does: store the parameters, then tell the machine."""
        db = self.controller.store.db  # type: ignore[attr-defined]
        db.set_parameters(values, next(u for u in db.list_users() if u.role is Role.SERVICE))
        self.send(cmd.ReloadParameters())

    def positions(self) -> tuple[float, float, float]:
        """Where the axes physically are (the simulation's truth, not the controller's
        possibly stale feedback: after a lost link the controller reads nothing)."""
        p = self.world.axis_positions()
        return (p["X"], p["Y"], p["Z"])

    def moving(self) -> bool:
        before = self.positions()
        self.run(0.1)
        return self.positions() != pytest.approx(before, abs=1e-4)


def homed_at_power_up(config: MachineConfig | None = None) -> MachineConfig:
    """The configuration with absolute encoders on every axis: homed from power-up (tests
    that need homed axes but not the homing itself)."""
    config = config or load_config()
    axes = {name: replace(axis, absolute_encoder=True) for name, axis in config.axes.items()}
    return replace(config, axes=axes)


def make_rig(tmp_path: Path, config: MachineConfig | None = None) -> Rig:
    runtime = MachineRuntime.create(config or load_config(), tmp_path / "stave.db")
    runtime.start()
    return Rig(runtime)


@pytest.fixture
def rig(tmp_path: Path) -> Iterator[Rig]:
    r = make_rig(tmp_path)
    yield r
    r.runtime.shutdown()


@pytest.fixture
def ready_rig(rig: Rig) -> Rig:
    """Homed, the barrique recipe selected, a 150 mm board on the table."""
    rig.home()
    rig.select()
    rig.load()
    return rig
