"""Recipe import and export (JSON, CSV) and production exports (CSV).

Import is forgiving per row and strict per file: a file that cannot be read at all is refused
with one line (RecipeFileError), while within a readable file every row is judged on its own -
the valid rows are stored, each invalid one is reported with its row number, the field, the
value and what is allowed. A row whose name matches a stored recipe (letter case ignored)
updates it, but only if the row is valid: an invalid row never damages what is stored. The
accepted rows are written in batches, each its own short transaction, so that an import of
tens of thousands of recipes never keeps the machine's records waiting for the write lock.

Production exports are CSV with one line per board, times in the site's local time with their
UTC offset (or in the zone given), for a day, a shift or any range.
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from datetime import date, datetime, tzinfo
from pathlib import Path

from app.data.csv_cells import to_csv_text
from app.data.database import RECIPE_IMPORT_ROLE, Database
from app.data.errors import RecipeFormatError, StorageError
from app.data.files import atomic_write_text
from app.data.recipe import Recipe, recipe_from_mapping
from app.data.recipe_files import read_recipe_rows, write_recipe_file
from app.data.records import ProductionRecord
from app.data.shifts import ShiftPlan, day_window, shift_window
from app.data.users import User
from app.geometry.errors import FieldError
from app.geometry.limits import StaveLimits


class ImportInterrupted(StorageError):
    """An import stopped part way; the message says how much of it was committed."""


@dataclass(frozen=True)
class RejectedRow:
    """One row that was not imported, with every reason."""

    row: int
    name: str
    errors: tuple[FieldError, ...]

    def lines(self) -> list[str]:
        """One line per reason: ``row 4 (Barrique): length_mm = 500 is out of range: ...``."""
        label = f"row {self.row}" + (f" ({self.name})" if self.name else "")
        return [f"{label}: {error.message}" for error in self.errors]


@dataclass(frozen=True)
class ImportReport:
    """What an import did: names created, updated, unchanged, and the rejected rows."""

    path: Path
    created: tuple[str, ...]
    updated: tuple[str, ...]
    unchanged: tuple[str, ...]
    rejected: tuple[RejectedRow, ...]

    @property
    def accepted(self) -> int:
        """Rows that were valid (stored, or already stored exactly like that)."""
        return len(self.created) + len(self.updated) + len(self.unchanged)

    def summary(self) -> str:
        """One line for a status bar or the command line."""
        return (
            f"{self.path.name}: {self.accepted} accepted ({len(self.created)} new, "
            f"{len(self.updated)} updated, {len(self.unchanged)} unchanged), "
            f"{len(self.rejected)} rejected"
        )

    def lines(self) -> list[str]:
        """The summary and then every rejected row's reasons."""
        return [self.summary()] + [line for row in self.rejected for line in row.lines()]


def read_recipes(
    path: Path, limits: StaveLimits | None = None
) -> tuple[list[tuple[int, Recipe]], list[RejectedRow]]:
    """Read and validate a recipe file without a database: (row number, recipe) and rejects.

    This is also what ``stave simulate --recipe-file`` uses. Raises RecipeFileError if the file
    as a whole cannot be read. Duplicate names within the file are rejected after the first.
    """
    valid: list[tuple[int, Recipe]] = []
    rejected: list[RejectedRow] = []
    first_row_of: dict[str, int] = {}
    for row in read_recipe_rows(path):
        raw_name = row.values.get("name") if isinstance(row.values, Mapping) else None
        shown_name = raw_name.strip() if isinstance(raw_name, str) else ""
        errors: list[FieldError] = list(row.problems)
        recipe: Recipe | None = None
        try:
            recipe = recipe_from_mapping(row.values)
        except RecipeFormatError as exc:
            errors.extend(exc.errors)
        if recipe is not None:
            errors.extend(recipe.validate(limits))
            key = recipe.name.casefold()
            if key in first_row_of:
                allowed = "each name once per file"
                message = (
                    f"name = {recipe.name!r} was already on row {first_row_of[key]}: {allowed}"
                )
                errors.append(FieldError("name", recipe.name, allowed, message))
            elif not errors:
                first_row_of[key] = row.number
        if errors or recipe is None:
            rejected.append(RejectedRow(row.number, shown_name, tuple(errors)))
        else:
            valid.append((row.number, recipe))
    return valid, rejected


IMPORT_BATCH_SIZE = 200
"""Recipes per import transaction: each holds SQLite's write lock for a few tens of
milliseconds, so the machine's records slip in between the batches of even a huge file."""


def import_recipes(
    db: Database, path: Path, user: User, batch_size: int = IMPORT_BATCH_SIZE
) -> ImportReport:
    """Import a .json or .csv recipe file into ``db`` as ``user`` (needs RECIPE_IMPORT_ROLE).

    Valid rows are stored in batches of ``batch_size``, each its own transaction (new names
    created, existing names updated); invalid rows are reported and change nothing. If a
    batch cannot be stored (StorageError: the disk, or the lock held too long by another
    writer), the batches before it stay stored and the error names what was committed.
    """
    db.check_role(user, RECIPE_IMPORT_ROLE, "importing recipes")
    valid, rejected = read_recipes(path, db.limits)
    ids_by_name = db.recipe_ids_by_name()
    created: list[str] = []
    updated: list[str] = []
    unchanged: list[str] = []
    to_save: list[tuple[Recipe, list[str]]] = []
    for _, recipe in valid:
        existing_id = ids_by_name.get(recipe.name.strip().casefold())
        if existing_id is None:
            to_save.append((recipe, created))
            continue
        existing = db.get_recipe(existing_id)
        if replace(recipe, id=existing.id) == existing:
            unchanged.append(recipe.name)
        else:
            to_save.append((replace(recipe, id=existing.id), updated))
    stored = 0
    for first in range(0, len(to_save), max(1, batch_size)):
        batch = to_save[first : first + max(1, batch_size)]
        try:
            db.save_recipes([recipe for recipe, _ in batch], user)
        except StorageError as exc:
            raise ImportInterrupted(
                f"{path.name}: {stored} of {len(to_save)} recipes to store were committed "
                f"(in {first // max(1, batch_size)} transactions) before the import stopped: {exc}"
            ) from exc
        for recipe, outcome in batch:
            outcome.append(recipe.name)
        stored += len(batch)
    return ImportReport(path, tuple(created), tuple(updated), tuple(unchanged), tuple(rejected))


def export_recipes(db: Database, path: Path, recipes: Sequence[Recipe] | None = None) -> int:
    """Write all recipes (or ``recipes``) to a .json or .csv file; returns how many."""
    chosen = db.list_recipes() if recipes is None else list(recipes)
    write_recipe_file(path, chosen)
    return len(chosen)


PRODUCTION_COLUMNS: tuple[str, ...] = (
    "id",
    "time",
    "recipe_id",
    "recipe_name",
    "result",
    "width_mm",
    "d_mm",
    "r_mm",
    "tilt_deg",
    "cycle_time_s",
    "alarm_code",
    "barrel_number",
    "stave_number",
    "operator_name",
)


def _cell(value: object, digits: int) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:.{digits}f}" if math.isfinite(value) else ""
    return str(value)


def production_to_csv(records: Sequence[ProductionRecord], tz: tzinfo | None = None) -> str:
    """CSV text of production records (local times with offset unless ``tz`` is given)."""
    buffer = io.StringIO(newline="")
    writer = csv.writer(buffer, lineterminator="\r\n")
    writer.writerow(PRODUCTION_COLUMNS)
    for record in records:
        writer.writerow(
            [
                _cell(record.id, 0),
                record.time.astimezone(tz).isoformat(timespec="seconds"),
                _cell(record.recipe_id, 0),
                to_csv_text(record.recipe_name),
                record.result.value,
                _cell(record.width_mm, 2),
                _cell(record.d_mm, 4),
                _cell(record.r_mm, 2),
                _cell(record.tilt_deg, 3),
                _cell(record.cycle_time_s, 1),
                to_csv_text(record.alarm_code or ""),
                _cell(record.barrel_number, 0),
                _cell(record.stave_number, 0),
                to_csv_text(record.operator_name or ""),
            ]
        )
    return buffer.getvalue()


def export_production_csv(
    db: Database, path: Path, start: datetime, end: datetime, tz: tzinfo | None = None
) -> int:
    """Write the records with ``start <= time < end`` to a CSV file; returns how many."""
    if end <= start:
        raise ValueError(f"end = {end.isoformat()} is not after start = {start.isoformat()}")
    if path.suffix.lower() != ".csv":
        raise ValueError(f"{path}: production exports are CSV: use a .csv file name")
    records = db.list_production(start, end)
    atomic_write_text(path, production_to_csv(records, tz))
    return len(records)


def export_production_day(db: Database, path: Path, day: date, tz: tzinfo | None = None) -> int:
    """Write one calendar day's records (local midnight to midnight unless ``tz``)."""
    start, end = day_window(day, tz)
    return export_production_csv(db, path, start, end, tz)


def export_production_shift(
    db: Database,
    path: Path,
    day: date,
    shift_number: int,
    plan: ShiftPlan | None = None,
    tz: tzinfo | None = None,
) -> int:
    """Write one shift's records; the shift plan comes from the parameters unless given."""
    chosen = ShiftPlan.from_parameters(db.get_parameters()) if plan is None else plan
    start, end = shift_window(day, shift_number, chosen, tz)
    return export_production_csv(db, path, start, end, tz)
