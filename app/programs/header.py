"""What every program says about itself, and the number format both dialects write.

Why comments matter here: a program file outlives the session that wrote it; whoever loads
it on another control must see which recipe, which board width (or "parametric"), when, by
which version of the product, and at which tilt each side is cut.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from datetime import datetime

COORDINATE_DECIMALS = 4
"""0.1 um: far below the 0.001 mm the programs are checked to, and what rs274 prints."""


@dataclass(frozen=True)
class ProgramInfo:
    """The facts a program's comments and its spindle and feed words are written from."""

    recipe_name: str
    width_mm: float | None  # None: the parametric program (the width is its parameter)
    written_at: datetime
    product_version: str
    feed_mm_min: float
    spindle_rpm: float
    spindle_runup_s: float
    chord_error_mm: float | None = None

    def describe_width(self) -> str:
        if self.width_mm is None:
            return "width: parameter of the program"
        return f"width {format_number(self.width_mm)} mm"

    def describe_arcs(self) -> str:
        if self.chord_error_mm is None:
            return "arcs as circular moves with centres I, J relative to their start"
        return (
            "arcs as straight chords, chord error at most "
            f"{format_number(self.chord_error_mm)} mm (fewest chords)"
        )

    def stamp(self) -> str:
        return (
            f"written {self.written_at.strftime('%Y-%m-%d %H:%M %Z').strip()} "
            f"by stave jointer {self.product_version}"
        )


def format_number(value: float, decimals: int = COORDINATE_DECIMALS) -> str:
    """Fixed decimals, never "-0.0000" (some controls read the sign of a zero)."""
    if not math.isfinite(value):
        raise ValueError(f"a program cannot hold the number {value}")
    text = f"{value:.{decimals}f}"
    if float(text) == 0.0:
        text = f"{0.0:.{decimals}f}"
    return text


def plain_text(text: str, forbidden: str) -> str:
    """Text safe inside a comment: no line breaks, the dialect's delimiters replaced."""
    cleaned = " ".join(text.split())
    for char in forbidden:
        cleaned = cleaned.replace(char, "_")
    return cleaned
