"""The cooper's card: a barrel's staves in the order they are raised, as CSV.

Why a card: on an oval barrel every stave has its own place and its own two bevels, so the
cooper must set them up in exactly the order they were cut; the card says which stave goes
where (the ellipse parameter of both joints), its width, the bevel of each side and which
neighbour each side meets, and marks the closing stave. Side A of stave n meets side B of
stave n - 1; stave 1's side A meets the last stave once the barrel is closed.

One row per stave, the barrel's number and recipe on every row (so a sheet of several cards
pasted together still says which barrel each line belongs to); text cells are escaped
against spreadsheet formulas (``app.data.csv_cells``).
"""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from app.data.barrel_records import BarrelRecord, BarrelState, BarrelStaveRecord
from app.data.csv_cells import to_csv_text
from app.data.database import Database
from app.data.errors import NotFoundError
from app.data.files import atomic_write_text

CARD_COLUMNS = (
    "barrel",
    "recipe",
    "stave",
    "width_mm",
    "board_width_mm",
    "bevel_a_deg",
    "bevel_b_deg",
    "start_angle_deg",
    "end_angle_deg",
    "side_a_meets_stave",
    "side_b_meets_stave",
    "closing",
)


@dataclass(frozen=True)
class CardStave:
    """What the card says of one stave (``board_width_mm`` None: planned, not cut yet)."""

    number: int
    width_mm: float
    start_angle_deg: float
    end_angle_deg: float
    bevel_a_deg: float
    bevel_b_deg: float
    closing: bool
    board_width_mm: float | None = None

    @classmethod
    def of(cls, record: BarrelStaveRecord) -> CardStave:
        return cls(
            record.number,
            record.width_mm,
            record.start_angle_deg,
            record.end_angle_deg,
            record.bevel_a_deg,
            record.bevel_b_deg,
            record.closing,
            record.board_width_mm,
        )


def barrel_card_csv(
    staves: Sequence[CardStave], *, closed: bool, barrel_number: int | None, recipe_name: str
) -> str:
    """The card's CSV text; ``closed``: the last stave meets the first."""
    buffer = io.StringIO(newline="")
    writer = csv.writer(buffer, lineterminator="\r\n")
    writer.writerow(CARD_COLUMNS)
    last = len(staves)
    for index, stave in enumerate(staves):
        before = staves[index - 1].number if index > 0 else (staves[-1].number if closed else None)
        after = (
            staves[index + 1].number if index + 1 < last else (staves[0].number if closed else None)
        )
        writer.writerow(
            [
                "" if barrel_number is None else str(barrel_number),
                to_csv_text(recipe_name),
                str(stave.number),
                f"{stave.width_mm:.3f}",
                "" if stave.board_width_mm is None else f"{stave.board_width_mm:.2f}",
                f"{stave.bevel_a_deg:.4f}",
                f"{stave.bevel_b_deg:.4f}",
                f"{stave.start_angle_deg:.6f}",
                f"{stave.end_angle_deg:.6f}",
                "" if before is None else str(before),
                "" if after is None else str(after),
                "yes" if stave.closing else "",
            ]
        )
    return buffer.getvalue()


def stored_card_csv(barrel: BarrelRecord, staves: Sequence[BarrelStaveRecord]) -> str:
    return barrel_card_csv(
        [CardStave.of(s) for s in staves],
        closed=barrel.state is BarrelState.CLOSED,
        barrel_number=barrel.number,
        recipe_name=barrel.recipe_name,
    )


def export_barrel_card(db: Database, path: Path, number: int | None = None) -> BarrelRecord:
    """Write the card of barrel ``number`` (None: the newest) to a .csv file; returns the
    barrel (NotFoundError: no such barrel; ValueError: not a .csv name)."""
    if path.suffix.lower() != ".csv":
        raise ValueError(f"{path}: the cooper's card is CSV: use a .csv file name")
    if number is None:
        newest = db.list_barrels(limit=1)
        if not newest:
            raise NotFoundError("barrel: none stored yet (start a barrel on the machine)")
        barrel = newest[0]
    else:
        found = db.get_barrel(number)
        if found is None:
            last = db.last_barrel_number()
            allowed = f"1..{last}" if last else "none stored yet"
            raise NotFoundError(f"barrel = {number} is not stored: allowed {allowed}")
        barrel = found
    atomic_write_text(path, stored_card_csv(barrel, db.barrel_staves(barrel.number)))
    return barrel
