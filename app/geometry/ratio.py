"""Exact ratios, entered the way coopers give them.

Coopers state the length ratio (lambda = L1 : L) and the width ratio (k = W1 : W) as
fractions, "1/4", "3/4". Keeping the numerator and denominator as entered (not reduced) lets
the recipe screen show back exactly what was typed; the geometry only ever uses `.value`.
Decimals are accepted too and turned into the nearest fraction with a denominator of at most
10000, so that "0.75" and "3/4" give the same stave.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from fractions import Fraction

MAX_DENOMINATOR = 10_000
"""Largest denominator a decimal is converted to (finer than any cooper's ratio)."""

_FRACTION_RE = re.compile(r"^\s*(\d+)\s*/\s*(\d+)\s*$")
_DECIMAL_RE = re.compile(r"^\s*(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?\s*$")

_EXPECTED = "a fraction like '3/4' or a decimal like '0.75' (not negative)"

MAX_TEXT_CHARS = 40
"""Longest ratio text read: a cooper's ratio is a few characters; an enormous one would
make the exact arithmetic take minutes (``1e99999999`` is ten characters, hence also:)"""
MAX_EXPONENT = 30
"""Largest decimal exponent magnitude read (``1e-31`` and ``1e31`` are refused, not computed)."""
MAX_PART = 10**12
"""Largest numerator or denominator typed as a fraction."""


@dataclass(frozen=True)
class Ratio:
    """A non-negative fraction numerator/denominator, kept as entered (not reduced)."""

    numerator: int
    denominator: int

    def __post_init__(self) -> None:
        for name in ("numerator", "denominator"):
            part = getattr(self, name)
            if isinstance(part, bool) or not isinstance(part, int):
                raise ValueError(f"ratio {name} must be an integer, got {part!r}")
        if self.denominator <= 0:
            raise ValueError(
                f"ratio denominator must be a positive integer, got {self.denominator}"
            )
        if self.numerator < 0:
            raise ValueError(f"ratio numerator must not be negative, got {self.numerator}")

    @property
    def value(self) -> float:
        """The ratio as a float (int / int is correctly rounded in Python)."""
        return self.numerator / self.denominator

    @property
    def fraction(self) -> Fraction:
        """The exact value, reduced."""
        return Fraction(self.numerator, self.denominator)

    def __str__(self) -> str:
        return f"{self.numerator}/{self.denominator}"

    @classmethod
    def parse(cls, text: str) -> Ratio:
        """Read "3/4" (kept as entered) or "0.75" (nearest fraction, denominator <= 10000).

        Raises ValueError naming the text and what is accepted.
        """
        if not isinstance(text, str):
            raise ValueError(f"invalid ratio {text!r}: expected {_EXPECTED}")
        if len(text) > MAX_TEXT_CHARS:
            raise ValueError(
                f"invalid ratio {text[:20]!r}... ({len(text)} characters): at most "
                f"{MAX_TEXT_CHARS} characters"
            )
        match = _FRACTION_RE.match(text)
        if match is not None:
            numerator, denominator = int(match.group(1)), int(match.group(2))
            if denominator == 0:
                raise ValueError(f"invalid ratio {text!r}: the denominator must not be 0")
            if numerator > MAX_PART or denominator > MAX_PART:
                raise ValueError(
                    f"invalid ratio {text!r}: numerator and denominator at most {MAX_PART:.0e}"
                )
            return cls(numerator, denominator)
        decimal = _DECIMAL_RE.match(text)
        if decimal is None:
            raise ValueError(f"invalid ratio {text!r}: expected {_EXPECTED}")
        if decimal.group(3) is not None and abs(int(decimal.group(3)[1:])) > MAX_EXPONENT:
            raise ValueError(
                f"invalid ratio {text!r}: the exponent must be within -{MAX_EXPONENT}.."
                f"{MAX_EXPONENT}"
            )
        approx = Fraction(text.strip()).limit_denominator(MAX_DENOMINATOR)
        return cls(approx.numerator, approx.denominator)

    @classmethod
    def from_float(cls, value: float, max_denominator: int = MAX_DENOMINATOR) -> Ratio:
        """The nearest fraction to `value` with a denominator of at most `max_denominator`."""
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise ValueError(f"invalid ratio {value!r}: expected a number")
        if not math.isfinite(value):
            raise ValueError(f"invalid ratio {value!r}: expected a finite number")
        if value < 0:
            raise ValueError(f"invalid ratio {value!r}: must not be negative")
        if max_denominator < 1:
            raise ValueError(f"max_denominator must be >= 1, got {max_denominator}")
        approx = Fraction(value).limit_denominator(max_denominator)
        return cls(approx.numerator, approx.denominator)
