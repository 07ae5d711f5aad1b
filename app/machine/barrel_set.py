"""A barrel being raised: its staves in order around the belly, and what the next board becomes.

Why the machine keeps this: on an oval barrel a stave's two bevels depend on where it sits,
and the last stave must be cut to exactly the width that closes the barrel. So each board
is placed after the staves cut before it (``app.geometry.barrel_section``): an ordinary
stave at its own width and the bevels of its place, or - once the gap left is no wider than
the board - the closing stave, cut to the gap's width with the bevels of the closing joints.
Once a single stave can close the gap, the operator may say so for the next board: cut the
closing stave now (a board narrower than the gap is then refused), or one more normal stave.

A board narrower than the gap that would leave a gap too narrow for any stave cannot be
placed without spoiling the barrel: the machine says so before cutting, and the operator
chooses (``BoardChoice``) to put in a wider board or to cut this one as an ordinary stave
anyway (the barrel then closes with the board after it, or is reported overrun).

Pure and immutable: the planner thread reads one ``BarrelSet`` value while the machine
thread replaces it when a stave is done.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from enum import Enum

from app.geometry.barrel_section import (
    CLOSED_GAP_MM,
    FULL_TURN_RAD,
    BarrelSection,
    PlacedBarrelTilt,
    PlacedStave,
    chord_stave,
    closing_stave,
    next_joint_t,
    staves_to_close,
)
from app.geometry.bevel import SideTilts


class Placement(Enum):
    """What the next board becomes."""

    ORDINARY = "ordinary"  # cut at its own width, the bevels of its place
    CLOSING = "closing"  # cut to the gap's width: the barrel closes
    TOO_NARROW = "too_narrow"  # would leave a gap no stave can fill: the operator chooses


class BoardChoice(Enum):
    """The operator's answer for the next board, once one stave can close the gap left (or
    when a board is too narrow to close the barrel)."""

    WIDER_BOARD = "wider_board"  # take it off; the next board is placed instead
    CUT_ORDINARY = "cut_ordinary"  # cut it as an ordinary stave; close with the next
    CLOSE_NOW = "close_now"  # the next board is the closing stave (a narrower one: E034)


@dataclass(frozen=True)
class NextStave:
    """The next board's place: its stave number, belly width after the cut and bevels."""

    number: int
    placement: Placement
    board_width_mm: float
    stave: PlacedStave
    section: BarrelSection
    barrel_number: int = 1

    @property
    def target_width_mm(self) -> float | None:
        """The width to cut to when it differs from the board's (the closing stave)."""
        return self.stave.width_mm if self.placement is Placement.CLOSING else None

    @property
    def tilts(self) -> SideTilts:
        """Side A at the stave's first joint, side B at its second."""
        return SideTilts(self.stave.bevel_start_deg, self.stave.bevel_end_deg)

    @property
    def tilt_rule(self) -> PlacedBarrelTilt:
        """The rule the cut composes with: the stave's own place on the barrel (for the
        closing stave, cut to the gap's width, that is the chord of the closing joints)."""
        return PlacedBarrelTilt(self.section, self.stave.start_t_rad)


@dataclass(frozen=True)
class BarrelSet:
    """One barrel: its belly section, the narrowest and widest stave the machine can cut for
    it, the staves done in order."""

    section: BarrelSection
    min_stave_width_mm: float
    staves: tuple[PlacedStave, ...] = ()
    number: int = 1
    # The widest board the machine takes: a gap wider than this is no closing stave yet.
    max_stave_width_mm: float = math.inf

    @property
    def end_t_rad(self) -> float:
        return self.staves[-1].end_t_rad if self.staves else 0.0

    @property
    def gap_mm(self) -> float:
        """The chord from the last joint back to the first (the whole barrel before stave 1)."""
        if not self.staves:
            return math.inf
        return self.section.chord_mm(self.end_t_rad, FULL_TURN_RAD)

    @property
    def closed(self) -> bool:
        return bool(self.staves) and (
            self.end_t_rad >= FULL_TURN_RAD or self.gap_mm < CLOSED_GAP_MM
        )

    @property
    def mean_width_mm(self) -> float | None:
        if not self.staves:
            return None
        return sum(s.width_mm for s in self.staves) / len(self.staves)

    def staves_left_estimate(self) -> int | None:
        """Staves still needed at the mean width so far (closing included); None before one."""
        mean = self.mean_width_mm
        if mean is None or self.closed:
            return None if mean is None else 0
        return staves_to_close(self.section, self.end_t_rad, mean)

    def place(self, board_width_mm: float, choice: BoardChoice | None = None) -> NextStave:
        """Where a board of this measured width goes (raises GeometryError for a bad width)."""
        number = len(self.staves) + 1
        start = self.end_t_rad
        closing = self._closing_stave(number)
        if closing is not None and board_width_mm >= closing.width_mm:
            return self._next(number, Placement.CLOSING, board_width_mm, closing)
        if closing is not None and choice is BoardChoice.CLOSE_NOW:
            return self._next(number, Placement.TOO_NARROW, board_width_mm, closing)
        end = next_joint_t(self.section, start, board_width_mm)
        stave = chord_stave(self.section, number, start, min(end, FULL_TURN_RAD))
        if closing is not None and choice is not BoardChoice.CUT_ORDINARY:
            left = self.section.chord_mm(end, FULL_TURN_RAD)
            if left < self.min_stave_width_mm:
                return self._next(number, Placement.TOO_NARROW, board_width_mm, stave)
        return self._next(number, Placement.ORDINARY, board_width_mm, stave)

    def _next(
        self, number: int, placement: Placement, board_mm: float, stave: PlacedStave
    ) -> NextStave:
        return NextStave(number, placement, board_mm, stave, self.section, self.number)

    def closing_width_mm(self) -> float | None:
        """The width of the stave that would close the gap now (None: no single stave can,
        or nothing is placed yet); what the operator is asked about before the next board."""
        if self.closed:
            return None
        closing = self._closing_stave(len(self.staves) + 1)
        return None if closing is None else closing.width_mm

    def _closing_stave(self, number: int) -> PlacedStave | None:
        """The stave that closes the gap now, if one board can be it: the gap is a single
        stave's chord and no wider than the widest board the machine takes."""
        if not self.staves:
            return None
        closing = closing_stave(self.section, number, self.end_t_rad)
        if closing is None or closing.width_mm > self.max_stave_width_mm:
            return None
        return closing

    def with_stave(self, next_stave: NextStave) -> BarrelSet:
        """This barrel with the stave just cut added."""
        return replace(self, staves=(*self.staves, next_stave.stave))

    def next_barrel(self) -> BarrelSet:
        """A new, empty barrel of the same section (the machine starts it when one closes)."""
        return replace(self, staves=(), number=self.number + 1)
