"""The recipe selected on the machine, remembered across a restart.

Why the whole version and not only its id: the machine cuts the version the operator chose.
A recipe saved again on the Recipes screen, or deleted there, must never change what the
machine cuts without someone choosing it; so the version in use is remembered as it was
chosen, and on a restart it is compared with the stored one. A deleted recipe is not
restored (nothing is selected, and the operator is told); a recipe changed while the machine
was off keeps the version it was chosen with until it is chosen again.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, replace

from app.data.errors import DataError
from app.data.recipe import Recipe, recipe_from_mapping, recipe_to_mapping
from app.machine.refusals import Reason, Refusal, refusal
from app.machine.store import MachineStore


class RememberedRecipeError(ValueError):
    """A stored selection that cannot be read back (named field, value, what is allowed)."""


def recipe_to_json(recipe: Recipe) -> str:
    return json.dumps({"id": recipe.id, "recipe": recipe_to_mapping(recipe)}, sort_keys=True)


def recipe_from_json(text: str) -> Recipe:
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise RememberedRecipeError(f"selected recipe: not JSON ({exc})") from exc
    recipe_id = data.get("id") if isinstance(data, dict) else None
    if isinstance(recipe_id, bool) or not isinstance(recipe_id, int) or recipe_id <= 0:
        raise RememberedRecipeError(
            f"selected recipe: id = {recipe_id!r} is not allowed: a recipe id (an integer above 0)"
        )
    try:
        recipe = recipe_from_mapping(data.get("recipe"))
    except (DataError, ValueError) as exc:
        raise RememberedRecipeError(f"selected recipe: {exc}") from exc
    return replace(recipe, id=recipe_id)


@dataclass(frozen=True)
class Restored:
    """What a restart puts on the machine, and what the operator is told about it."""

    recipe: Recipe | None
    message: Refusal | None = None


def same_version(a: Recipe, b: Recipe) -> bool:
    return replace(a, id=None) == replace(b, id=None)


def restore(store: MachineStore) -> Restored:
    """The recipe on the machine at start-up: the one remembered, as it was chosen."""
    try:
        remembered = store.selected_recipe()
    except RememberedRecipeError:
        return Restored(None, Refusal(Reason.SELECTED_RECIPE_UNREADABLE))
    if remembered is None:  # never chose one (a new machine): the first recipe
        first = store.first_recipe_id()
        return Restored(store.recipe(first) if first is not None else None)
    assert remembered.id is not None
    stored = store.recipe(remembered.id)
    if stored is None:
        return Restored(None, refusal(Reason.SELECTED_RECIPE_DELETED, repr(remembered.name)))
    if not same_version(stored, remembered):
        return Restored(remembered, refusal(Reason.SELECTED_RECIPE_CHANGED, repr(remembered.name)))
    return Restored(stored)
