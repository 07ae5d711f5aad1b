"""What the machine needs from the database, as a narrow protocol.

Why a protocol here and not direct database calls: the machine layer must run the same on
the panel (where writes go through a writer thread so that an fsync never delays a setpoint)
and in tests and ``stave simulate`` (where they are written at once). Both adapters wrap the
one data layer API, ``app.data.database.Database``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

from app.data.barrel_records import BarrelRecord, BarrelStaveRecord
from app.data.recipe import Recipe
from app.machine.alarms import AlarmTransition
from app.machine.interrupted import InterruptedBoard

RECORD_DELAY_ALARM_S = 60.0
"""A record not stored after this long raises W103 (the database is busy or unavailable)."""


@dataclass(frozen=True)
class PieceRecord:
    """One board through the machine, as the machine layer reports it."""

    time: float  # epoch seconds at the end of the cycle
    recipe_id: int | None
    recipe_name: str
    width_mm: float | None
    d_mm: float | None
    r_mm: float | None
    tilt_deg: float | None
    cycle_time_s: float
    result: str  # "ok", "rejected" or "aborted"
    alarm_code: str | None = None
    resumed: bool = False  # an interrupted cut, resumed and completed
    step_times_s: dict[str, float] = field(default_factory=dict)  # timed step -> seconds
    barrel_number: int | None = None  # the barrel the board was cut for (None: single staves)
    stave_number: int | None = None  # its place in that barrel
    operator_name: str = ""  # the operator of the shift (else the panel's user); "": nobody


class MachineStore(Protocol):
    def recipe(self, recipe_id: int) -> Recipe | None: ...

    def first_recipe_id(self) -> int | None: ...

    def recipe_by_name(self, name: str) -> Recipe | None: ...

    def recipes(self) -> list[Recipe]: ...

    def save_recipe(self, recipe: Recipe) -> Recipe:
        """Store (insert or update by name) a recipe, validated; returns it with its id."""
        ...

    def parameters(self) -> dict[str, float]: ...

    def piece_counts(self, shift_start: float) -> tuple[int, int]: ...

    def record_piece(self, piece: PieceRecord) -> None: ...

    def record_alarm(self, transition: AlarmTransition) -> None: ...

    def unstored_age_s(self) -> float:
        """How long the oldest record not yet in the database has waited (0: none waits)."""
        ...

    def interrupted_board(self) -> InterruptedBoard | None:
        """The board whose cut began and did not end, if any (survives a restart)."""
        ...

    def save_interrupted_board(self, board: InterruptedBoard | None) -> None:
        """Remember (or with None forget) the interrupted board."""
        ...

    def record_barrel(self, barrel: BarrelRecord) -> None:
        """A barrel set started, closed or abandoned (stored in order with the pieces)."""
        ...

    def record_barrel_stave(self, stave: BarrelStaveRecord) -> None:
        """A stave cut for a barrel, after the piece record of its board."""
        ...

    def last_barrel_number(self) -> int:
        """The highest barrel number stored or waiting to be (0: none)."""
        ...

    def open_barrel(self) -> str | None:
        """The barrel being raised when the machine stopped, as saved (survives a restart)."""
        ...

    def save_open_barrel(self, text: str | None) -> None:
        """Remember (or with None forget) the barrel being raised."""
        ...

    def selected_recipe(self) -> Recipe | None:
        """The recipe version last selected on the machine, as it was selected (survives a
        restart); RememberedRecipeError when the stored selection cannot be read."""
        ...

    def save_selected_recipe(self, recipe: Recipe | None) -> None:
        """Remember (or with None forget) the recipe version selected on the machine."""
        ...

    def close(self) -> None: ...
