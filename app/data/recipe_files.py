"""Reading and writing recipe files (JSON and CSV) in the row format of ``recipe.ROW_KEYS``.

Problems with the file as a whole (it cannot be read, it is not JSON, a CSV column is unknown
or missing) raise RecipeFileError with one clear line; problems with one row are left to the
caller (import reports them row by row and goes on with the others).

JSON: ``{"format": "stave-jointer-recipes", "version": 1, "recipes": [ {row}, ... ]}``, or just
a list of rows, or a single row object. Rows are numbered from 1 in file order.

CSV: a header line with the keys, one recipe per line; UTF-8 (a BOM, as spreadsheet programs
write it, is fine); the delimiter may be "," or ";" or a tab. In a ";" or tab-separated file a
decimal comma is accepted in numbers ("27,5"), since that is what a spreadsheet in a
comma-decimal locale writes. Rows are numbered as a spreadsheet shows them: the header is
row 1, so the first recipe is row 2.
"""

from __future__ import annotations

import csv
import io
import json
import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from app.data.csv_cells import from_csv_text, to_csv_text
from app.data.errors import DataError, RecipeFormatError
from app.data.files import atomic_write_text
from app.data.recipe import (
    IGNORED_KEYS,
    LEGACY_KEYS,
    REQUIRED_KEYS,
    ROW_KEYS,
    Recipe,
    recipe_from_mapping,
)
from app.data.recipe import recipe_to_mapping as _to_mapping
from app.geometry.errors import FieldError

JSON_FORMAT_NAME = "stave-jointer-recipes"
JSON_FORMAT_VERSION = 1
SUFFIXES = (".json", ".csv")
MAX_FILE_BYTES = 64 * 1024 * 1024
"""Largest recipe file read (a 24,000-recipe file is about 2 MB)."""

_DECIMAL_COMMA = re.compile(r"^\s*[-+]?\d+,\d+\s*$")
_TEXT_KEYS = frozenset({"name", "note", "barrel_type", "tilt_mode", "profile_kind", "profile"})


class RecipeFileError(DataError, ValueError):
    """A recipe file cannot be read or written at all (message names the file and the reason)."""


@dataclass(frozen=True)
class RecipeRow:
    """One row of a recipe file: its number as the user sees it, and its raw values."""

    number: int
    values: Mapping[str, object]
    problems: tuple[FieldError, ...] = ()  # found while reading the row (e.g. too many cells)


def _suffix(path: Path) -> str:
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise RecipeFileError(
            f"{path}: file type {path.suffix or '(none)'!r} is not supported: "
            f"allowed {', '.join(SUFFIXES)}"
        )
    return suffix


def read_recipe_rows(path: Path) -> list[RecipeRow]:
    """The rows of a .json or .csv recipe file (raw values, not yet checked)."""
    suffix = _suffix(path)
    try:
        size = path.stat().st_size
        if size > MAX_FILE_BYTES:
            raise RecipeFileError(
                f"{path}: {size} bytes is too large: a recipe file is at most {MAX_FILE_BYTES}"
            )
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise RecipeFileError(f"{path}: file not found") from None
    except UnicodeDecodeError as exc:
        reason = f"{exc.reason} at byte {exc.start}"
        raise RecipeFileError(f"{path}: not UTF-8 text ({reason})") from None
    except OSError as exc:
        raise RecipeFileError(f"{path}: cannot be read ({exc.strerror})") from None
    if suffix == ".json":
        return _json_rows(path, text)
    return _csv_rows(path, text)


def _json_rows(path: Path, text: str) -> list[RecipeRow]:
    try:
        document = json.loads(text)
    except json.JSONDecodeError as exc:
        raise RecipeFileError(
            f"{path}: not valid JSON ({exc.msg} at line {exc.lineno}, column {exc.colno})"
        ) from None
    except RecursionError:
        raise RecipeFileError(f"{path}: JSON nested too deeply (a recipe file is flat)") from None
    except ValueError as exc:  # e.g. an integer of more than 4300 digits
        raise RecipeFileError(f"{path}: not usable JSON ({exc})") from None
    if isinstance(document, dict) and "recipes" in document:
        declared = document.get("format", JSON_FORMAT_NAME)
        if declared != JSON_FORMAT_NAME:
            raise RecipeFileError(
                f"{path}: format {declared!r} is not supported: expected {JSON_FORMAT_NAME!r}"
            )
        version = document.get("version", JSON_FORMAT_VERSION)
        if version != JSON_FORMAT_VERSION:
            raise RecipeFileError(
                f"{path}: version {version!r} is not supported: expected {JSON_FORMAT_VERSION}"
            )
        items = document["recipes"]
        if not isinstance(items, list):
            raise RecipeFileError(f"{path}: 'recipes' must be a list of recipe objects")
    elif isinstance(document, dict):
        items = [document]
    elif isinstance(document, list):
        items = document
    else:
        raise RecipeFileError(
            f"{path}: expected a recipe object, a list of them or "
            f'{{"format": "{JSON_FORMAT_NAME}", "recipes": [...]}}'
        )
    # A non-object item stays a row: recipe_from_mapping rejects it with its row number.
    return [RecipeRow(number, item) for number, item in enumerate(items, start=1)]


def _sniff_delimiter(header_line: str) -> str:
    counts = {delimiter: header_line.count(delimiter) for delimiter in (",", ";", "\t")}
    best = max(counts, key=lambda delimiter: counts[delimiter])
    return best if counts[best] > 0 else ","


def _csv_rows(path: Path, text: str) -> list[RecipeRow]:
    header_line = text.split("\n", 1)[0]
    delimiter = _sniff_delimiter(header_line)
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delimiter)
    try:
        header = next(reader)
    except StopIteration:
        raise RecipeFileError(f"{path}: the file is empty (expected a header line)") from None
    except csv.Error as exc:
        raise RecipeFileError(f"{path}: not valid CSV on line 1 ({exc})") from None
    keys = [cell.strip().lower() for cell in header]
    allowed = set(ROW_KEYS) | IGNORED_KEYS | set(LEGACY_KEYS)
    for key in keys:
        if key not in allowed:
            raise RecipeFileError(
                f"{path}: column {key!r} is unknown: allowed columns {', '.join(ROW_KEYS)}"
            )
        if keys.count(key) > 1:
            raise RecipeFileError(f"{path}: column {key!r} appears more than once")
    missing = [key for key in REQUIRED_KEYS if key not in keys]
    if missing:
        raise RecipeFileError(f"{path}: column(s) {', '.join(missing)} missing from the header")

    rows: list[RecipeRow] = []
    try:
        for cells in reader:
            if not any(cell.strip() for cell in cells):
                continue  # blank line
            values: dict[str, object] = {}
            for key, cell in zip(keys, cells, strict=False):
                if key in _TEXT_KEYS:
                    values[key] = from_csv_text(cell)
                    continue
                comma = delimiter != "," and _DECIMAL_COMMA.match(cell)
                values[key] = cell.replace(",", ".") if comma else cell
            problems: tuple[FieldError, ...] = ()
            if len(cells) > len(keys):
                extra = delimiter.join(cells[len(keys) :])
                cells_allowed = f"at most {len(keys)} cells, as many as the header has"
                message = (
                    f"row has {len(cells)} cells ({extra!r} beyond the header): {cells_allowed}"
                )
                problems = (FieldError("row", extra, cells_allowed, message),)
            rows.append(RecipeRow(reader.line_num, values, problems))
    except csv.Error as exc:
        raise RecipeFileError(f"{path}: not valid CSV on line {reader.line_num} ({exc})") from None
    return rows


def load_recipe_file(path: Path) -> list[Recipe]:
    """All recipes of a file, or RecipeFileError naming the first bad row (for trusted files).

    Rows are read, not validated against the limits (that is ``Recipe.validate``).
    """
    recipes: list[Recipe] = []
    for row in read_recipe_rows(path):
        if row.problems:
            raise RecipeFileError(f"{path}: row {row.number}: {row.problems[0].message}")
        try:
            recipes.append(recipe_from_mapping(row.values))
        except RecipeFormatError as exc:
            raise RecipeFileError(f"{path}: row {row.number}: {exc}") from None
    return recipes


def _csv_cell(value: object) -> str:
    if value is None:
        return ""
    if isinstance(value, dict):  # the side profile's data: one JSON text cell
        return json.dumps(value, ensure_ascii=False, sort_keys=True)
    if isinstance(value, float):
        if math.isfinite(value) and value.is_integer() and abs(value) < 1e15:
            return str(int(value))
        return repr(value)
    return str(value)


def recipes_to_json(recipes: Sequence[Recipe]) -> str:
    """The JSON document for ``recipes`` (the export format)."""
    document = {
        "format": JSON_FORMAT_NAME,
        "version": JSON_FORMAT_VERSION,
        "recipes": [_to_mapping(recipe) for recipe in recipes],
    }
    return json.dumps(document, indent=2, ensure_ascii=False) + "\n"


def recipes_to_csv(recipes: Sequence[Recipe]) -> str:
    """The CSV text for ``recipes`` (comma-separated, header line first)."""
    buffer = io.StringIO(newline="")
    writer = csv.writer(buffer, lineterminator="\r\n")
    writer.writerow(ROW_KEYS)
    for recipe in recipes:
        mapping = _to_mapping(recipe)
        writer.writerow(
            [
                to_csv_text(_csv_cell(mapping[key]))
                if key in _TEXT_KEYS
                else _csv_cell(mapping[key])
                for key in ROW_KEYS
            ]
        )
    return buffer.getvalue()


def write_recipe_file(path: Path, recipes: Sequence[Recipe]) -> None:
    """Write ``recipes`` as .json or .csv (by the suffix), replacing the file atomically."""
    suffix = _suffix(path)
    text = recipes_to_json(recipes) if suffix == ".json" else recipes_to_csv(recipes)
    try:
        atomic_write_text(path, text)
    except OSError as exc:
        raise RecipeFileError(f"{path}: cannot be written ({exc.strerror})") from None
