"""The barrels' bookkeeping: each barrel set and its staves into the database, and the barrel
being raised kept across a restart.

Why apart from ``barrel_set``: placing staves is geometry and stays pure; what was started,
cut, closed or given up is a record, written through the store's journal like the production
records (nothing the machine made is lost while the database is busy). The open barrel is
saved after every change, so a restart - planned or a power loss - carries on with the same
barrel, its staves and the gap left, instead of starting a new one on a half-raised barrel.
"""

from __future__ import annotations

import json
import logging
import math
from collections.abc import Callable
from dataclasses import asdict, dataclass
from datetime import UTC, datetime
from typing import Any

from app.data.barrel_records import BarrelRecord, BarrelState, BarrelStaveRecord
from app.data.recipe import BarrelType, Recipe
from app.geometry.barrel_section import BarrelSection, PlacedStave
from app.machine.barrel_set import BarrelSet, NextStave, Placement
from app.machine.store import MachineStore

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class OpenBarrel:
    """The barrel being raised and what its record needs: the recipe and the start."""

    barrel: BarrelSet
    recipe_id: int | None
    recipe_name: str
    started_s: float

    def to_json(self) -> str:
        b = self.barrel
        return json.dumps(
            {
                "number": b.number,
                "recipe_id": self.recipe_id,
                "recipe_name": self.recipe_name,
                "started_s": self.started_s,
                "a_mm": b.section.a_mm,
                "b_mm": b.section.b_mm,
                "min_stave_width_mm": b.min_stave_width_mm,
                "max_stave_width_mm": (
                    None if math.isinf(b.max_stave_width_mm) else b.max_stave_width_mm
                ),
                "staves": [asdict(s) for s in b.staves],
            },
            sort_keys=True,
            allow_nan=False,
        )

    @classmethod
    def from_json(cls, text: str) -> OpenBarrel:
        """Inverse of :meth:`to_json`; ValueError (KeyError, TypeError) for a damaged text."""
        data: dict[str, Any] = json.loads(text)
        section = BarrelSection(float(data["a_mm"]), float(data["b_mm"]))
        staves = tuple(PlacedStave(**s) for s in data["staves"])
        widest = data.get("max_stave_width_mm")  # absent in barrels kept before it existed
        barrel = BarrelSet(
            section,
            float(data["min_stave_width_mm"]),
            staves,
            int(data["number"]),
            max_stave_width_mm=math.inf if widest is None else float(widest),
        )
        recipe_id = data["recipe_id"]
        return cls(
            barrel,
            None if recipe_id is None else int(recipe_id),
            str(data["recipe_name"]),
            float(data["started_s"]),
        )


def _utc(epoch_s: float) -> datetime:
    return datetime.fromtimestamp(epoch_s, UTC)


class BarrelBook:
    """Writes a barrel's life to the store; one open barrel at a time."""

    def __init__(self, store: MachineStore, wall_clock: Callable[[], float]) -> None:
        self._store = store
        self._wall_clock = wall_clock
        self.open: OpenBarrel | None = None

    def next_number(self) -> int:
        """The number of the next barrel: one more than any stored or open."""
        current = 0 if self.open is None else self.open.barrel.number
        return max(current, self._store.last_barrel_number()) + 1

    def started(self, barrel: BarrelSet, recipe: Recipe) -> None:
        """A new barrel set: the one still open (not closed) is given up first."""
        self._finish(BarrelState.ABANDONED)
        self.open = OpenBarrel(barrel, recipe.id, recipe.name, self._wall_clock())
        self._store.record_barrel(self._record(self.open, BarrelState.OPEN))
        self._save()

    def dropped(self) -> None:
        """No barrel any more (another recipe): the open one is given up."""
        self._finish(BarrelState.ABANDONED)
        self._save()

    def stave_cut(self, placed: NextStave, barrel: BarrelSet) -> None:
        """A stave cut for the open barrel; ``barrel`` is the barrel with it."""
        if self.open is None:
            return
        stave = placed.stave
        self._store.record_barrel_stave(
            BarrelStaveRecord(
                barrel_number=placed.barrel_number,
                number=placed.number,
                time=_utc(self._wall_clock()),
                board_width_mm=max(placed.board_width_mm, stave.width_mm),
                width_mm=stave.width_mm,
                start_angle_deg=stave.start_angle_deg,
                end_angle_deg=stave.end_angle_deg,
                bevel_a_deg=stave.bevel_start_deg,
                bevel_b_deg=stave.bevel_end_deg,
                closing=placed.placement is Placement.CLOSING,
            )
        )
        self.open = OpenBarrel(
            barrel, self.open.recipe_id, self.open.recipe_name, self.open.started_s
        )
        if barrel.closed:
            self._finish(BarrelState.CLOSED)
        self._save()

    def restore(self) -> OpenBarrel | None:
        """The barrel open when the machine last stopped (None: none, or unreadable)."""
        text = self._store.open_barrel()
        if text is None:
            return None
        try:
            self.open = OpenBarrel.from_json(text)
        except (ValueError, KeyError, TypeError) as exc:
            log.error("the barrel saved before the restart is unreadable, not continued: %s", exc)
            return None
        return self.open

    def _finish(self, state: BarrelState) -> None:
        if self.open is not None:
            self._store.record_barrel(self._record(self.open, state))
            self.open = None

    def _record(self, open_barrel: OpenBarrel, state: BarrelState) -> BarrelRecord:
        section = open_barrel.barrel.section
        return BarrelRecord(
            number=open_barrel.barrel.number,
            recipe_id=open_barrel.recipe_id,
            recipe_name=open_barrel.recipe_name,
            barrel_type=BarrelType.ROUND if section.is_round else BarrelType.OVAL,
            belly_major_mm=2.0 * section.a_mm,
            belly_minor_mm=2.0 * section.b_mm,
            started_at=_utc(open_barrel.started_s),
            state=state,
            finished_at=None if state is BarrelState.OPEN else _utc(self._wall_clock()),
        )

    def _save(self) -> None:
        self._store.save_open_barrel(None if self.open is None else self.open.to_json())
