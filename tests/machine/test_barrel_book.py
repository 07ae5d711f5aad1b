"""The barrels' bookkeeping: a barrel started, its staves cut and the barrel closed are in the
database, the barrel being raised survives a restart, and the numbers count on."""

from __future__ import annotations

import itertools
import json
import math
from pathlib import Path

import pytest

from app.data.barrel_records import BarrelState
from app.data.database import Database
from app.data.recipe import BarrelType
from app.geometry.limits import DEFAULT_LIMITS
from app.machine import commands as cmd
from app.machine.barrel_book import BarrelBook, OpenBarrel
from app.machine.barrel_job import new_barrel
from app.machine.barrel_set import Placement
from app.machine.database_store import DatabaseStore
from tests.data.test_recipe import make_recipe

from .conftest import make_rig

OVAL = make_recipe(
    name="Oval 700 x 500",
    barrel_type=BarrelType.OVAL,
    barrel_diameter_mm=700.0,
    barrel_minor_diameter_mm=500.0,
)


@pytest.fixture
def store(tmp_path: Path):
    s = DatabaseStore(Database.open(tmp_path / "stave.db"))
    yield s
    s.close()


def test_a_barrel_from_start_to_closing_stave_is_recorded(store: DatabaseStore) -> None:
    clock = itertools.count(1.7e9, 60.0)
    book = BarrelBook(store, lambda: next(clock))
    barrel = new_barrel(OVAL, DEFAULT_LIMITS, book.next_number())
    assert barrel is not None and barrel.number == 1
    book.started(barrel, OVAL)
    assert store.db.get_barrel(1).state is BarrelState.OPEN  # type: ignore[union-attr]
    while not barrel.closed:
        placed = barrel.place(100.0 if len(barrel.staves) < 18 else 150.0)
        barrel = barrel.with_stave(placed)
        book.stave_cut(placed, barrel)
    stored = store.db.get_barrel(1)
    assert stored is not None and stored.state is BarrelState.CLOSED
    assert stored.barrel_type is BarrelType.OVAL
    assert (stored.belly_major_mm, stored.belly_minor_mm) == (700.0, 500.0)
    assert stored.finished_at is not None and stored.finished_at > stored.started_at
    staves = store.db.barrel_staves(1)
    assert len(staves) == 19 and [s.closing for s in staves] == [False] * 18 + [True]
    # docs/MACHINE.md section 7: the oval's first stave and its closing stave.
    assert staves[0].bevel_a_deg == pytest.approx(15.6644, abs=5e-5)
    assert staves[0].bevel_b_deg == pytest.approx(14.6323, abs=5e-5)
    closing = staves[-1]
    assert closing.width_mm == pytest.approx(88.3871, abs=5e-5) and closing.board_width_mm == 150
    assert closing.bevel_a_deg == pytest.approx(13.1755, abs=5e-5)
    assert closing.bevel_b_deg == pytest.approx(13.9145, abs=5e-5)
    assert store.open_barrel() is None  # closed: nothing to carry on with
    assert book.next_number() == 2


def test_the_open_barrel_survives_a_restart_and_a_new_one_abandons_it(
    store: DatabaseStore,
) -> None:
    book = BarrelBook(store, lambda: 1.7e9)
    barrel = new_barrel(OVAL, DEFAULT_LIMITS, book.next_number())
    assert barrel is not None
    book.started(barrel, OVAL)
    for _ in range(3):
        placed = barrel.place(100.0)
        assert placed.placement is Placement.ORDINARY
        barrel = barrel.with_stave(placed)
        book.stave_cut(placed, barrel)
    again = BarrelBook(store, lambda: 1.7e9 + 60)
    restored = again.restore()
    assert restored == OpenBarrel(barrel, OVAL.id, OVAL.name, 1.7e9)
    assert again.next_number() == 2
    fresh = new_barrel(OVAL, DEFAULT_LIMITS, again.next_number())
    assert fresh is not None
    again.started(fresh, OVAL)
    assert [b.state for b in store.db.list_barrels()] == [BarrelState.OPEN, BarrelState.ABANDONED]


def test_an_unreadable_saved_barrel_is_not_continued(store: DatabaseStore) -> None:
    store.save_open_barrel('{"number": 1}')
    assert BarrelBook(store, lambda: 1.7e9).restore() is None


def test_the_machine_carries_on_with_its_barrel_after_a_restart(tmp_path: Path) -> None:
    """The barrel started on the machine, the machine restarted: the same barrel with its
    recipe selected (the staves cut into it: the simulated barrel's test)."""
    rig = make_rig(tmp_path)
    try:
        rig.select("Hogshead 300 l")
        rig.send(cmd.StartBarrel())
        barrel = rig.controller.barrel
        assert barrel is not None and barrel.number == 1
    finally:
        rig.runtime.shutdown()
    again = make_rig(tmp_path)
    try:
        assert again.controller.barrel == barrel
        recipe = again.controller.recipe
        assert recipe is not None and recipe.name == "Hogshead 300 l"
    finally:
        again.runtime.shutdown()


def test_a_barrel_saved_before_the_widest_stave_was_kept_still_restores(
    store: DatabaseStore,
) -> None:
    barrel = new_barrel(OVAL, DEFAULT_LIMITS)
    assert barrel is not None and barrel.max_stave_width_mm == DEFAULT_LIMITS.max_width_mm
    saved = json.loads(OpenBarrel(barrel, OVAL.id, OVAL.name, 1.7e9).to_json())
    del saved["max_stave_width_mm"]
    store.save_open_barrel(json.dumps(saved))
    restored = BarrelBook(store, lambda: 1.7e9).restore()
    assert restored is not None and restored.barrel.max_stave_width_mm == math.inf
    assert OpenBarrel.from_json(restored.to_json()) == restored
