"""Counts of production records by result, for the plant connection's counters.

Why here: the database is the one record of every board; the OPC UA counters of good,
aborted and total runs are those records counted, so a plant system and a production
export always agree.
"""

from __future__ import annotations

from app.data.database import Database
from app.data.records import PieceResult


def run_counts(db: Database) -> dict[str, int]:
    """Result value ("ok", "rejected", "aborted") -> how many records, every result present."""
    counts = {result.value: 0 for result in PieceResult}
    for row in db._conn.execute("SELECT result, count(*) FROM production GROUP BY result"):
        counts[str(row[0])] = int(row[1])
    return counts
