"""The recipe selected on the machine survives a restart, and a recipe deleted or changed
behind the machine's back is never cut without someone choosing it."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from app.data.database import Database
from app.data.users import Role, User
from app.machine import commands as cmd
from app.machine.database_store import SELECTED_RECIPE_KEY
from app.machine.recipe_on_machine import (
    RememberedRecipeError,
    recipe_from_json,
    recipe_to_json,
)
from app.machine.refusals import Reason
from app.machine.states import MachineState
from tests.machine.conftest import BARRIQUE, Rig, homed_at_power_up, make_rig

OTHER = "Tonneau 1000 l"


def _restart(rig: Rig, tmp_path: Path) -> Rig:
    rig.runtime.shutdown()
    return make_rig(tmp_path)


def _technician(db: Database) -> User:
    return next(u for u in db.list_users() if u.role is Role.SERVICE)


def _selected(rig: Rig, name: str) -> Rig:
    rig.select(name)
    assert rig.controller.recipe is not None and rig.controller.recipe.name == name
    return rig


def test_the_selected_recipe_is_restored_after_a_restart(rig: Rig, tmp_path: Path) -> None:
    first = rig.controller.recipe
    assert first is not None and first.name != OTHER  # the first start: the first recipe
    rig = _restart(_selected(rig, OTHER), tmp_path)
    try:
        assert rig.controller.recipe is not None and rig.controller.recipe.name == OTHER
        assert rig.controller.message is None
        assert rig.controller.snapshot().recipe_name == OTHER  # what the screens show
    finally:
        rig.runtime.shutdown()


def test_a_recipe_deleted_while_the_machine_was_off_is_not_selected(
    rig: Rig, tmp_path: Path
) -> None:
    rig = _selected(rig, OTHER)
    rig.runtime.shutdown()
    with Database.open(tmp_path / "stave.db") as db:
        deleted = db.get_recipe_by_name(OTHER)
        assert deleted is not None and deleted.id is not None
        db.delete_recipe(deleted.id, _technician(db))
    rig = make_rig(tmp_path, homed_at_power_up())
    try:
        c = rig.controller
        assert c.recipe is None
        assert c.message is not None and c.message.reason is Reason.SELECTED_RECIPE_DELETED
        assert repr(OTHER) in str(c.message)
        rig.send(cmd.Start())
        assert rig.state is MachineState.READY
        assert c.message is not None and c.message.reason is Reason.SELECT_RECIPE_FIRST
    finally:
        rig.runtime.shutdown()


def test_a_recipe_changed_while_the_machine_was_off_keeps_its_version(
    rig: Rig, tmp_path: Path
) -> None:
    chosen = _selected(rig, OTHER).controller.recipe
    assert chosen is not None
    rig.runtime.shutdown()
    with Database.open(tmp_path / "stave.db") as db:
        db.save_recipe(replace(chosen, length_mm=chosen.length_mm - 50.0), _technician(db))
    rig = make_rig(tmp_path)
    try:
        c = rig.controller
        assert c.recipe == chosen  # the version it was chosen with, not the saved one
        assert c.message is not None and c.message.reason is Reason.SELECTED_RECIPE_CHANGED
        rig.select(OTHER)  # chosen again: now the new version
        assert c.recipe is not None and c.recipe.length_mm == chosen.length_mm - 50.0
    finally:
        rig.runtime.shutdown()


def test_a_recipe_deleted_while_selected_is_not_started(tmp_path: Path) -> None:
    ready_rig = make_rig(tmp_path, homed_at_power_up())
    ready_rig.select()
    ready_rig.load()
    c = ready_rig.controller
    assert c.recipe is not None and c.recipe.id is not None
    db = c.store.db  # type: ignore[attr-defined]
    db.delete_recipe(c.recipe.id, _technician(db))
    ready_rig.send(cmd.Start())
    assert ready_rig.state is MachineState.READY and c.cycle is None
    assert c.message is not None and c.message.reason is Reason.SELECTED_RECIPE_DELETED
    ready_rig.runtime.shutdown()


def test_saved_parameters_do_not_swap_the_recipe_version(rig: Rig) -> None:
    ready_rig = rig
    c = ready_rig.controller
    chosen = c.recipe
    assert chosen is not None
    db = c.store.db  # type: ignore[attr-defined]
    db.save_recipe(replace(chosen, length_mm=chosen.length_mm - 50.0), _technician(db))
    ready_rig.send(cmd.ReloadParameters())
    assert c.recipe == chosen
    ready_rig.select(BARRIQUE)
    assert c.recipe is not None and c.recipe.length_mm == chosen.length_mm - 50.0


def test_an_unreadable_selection_selects_nothing_and_says_so(rig: Rig, tmp_path: Path) -> None:
    rig.runtime.shutdown()
    with Database.open(tmp_path / "stave.db") as db:
        db.set_machine_state(SELECTED_RECIPE_KEY, '{"id": "x"}')
    rig = make_rig(tmp_path)
    try:
        assert rig.controller.recipe is None
        message = rig.controller.message
        assert message is not None and message.reason is Reason.SELECTED_RECIPE_UNREADABLE
    finally:
        rig.runtime.shutdown()


@pytest.mark.parametrize(
    ("text", "field"),
    [
        ("not json", "not JSON"),
        ("[]", "id = None"),
        ('{"id": true, "recipe": {}}', "id = True"),
        ('{"id": 0, "recipe": {}}', "id = 0"),
        ('{"id": 3, "recipe": {"name": "x"}}', "is missing"),
    ],
)
def test_a_stored_selection_that_cannot_be_read_names_what_is_wrong(text: str, field: str) -> None:
    with pytest.raises(RememberedRecipeError, match="selected recipe") as caught:
        recipe_from_json(text)
    assert field in str(caught.value)


def test_a_selection_reads_back_as_it_was_written(rig: Rig) -> None:
    recipe = rig.controller.recipe
    assert recipe is not None
    assert recipe_from_json(recipe_to_json(recipe)) == recipe
