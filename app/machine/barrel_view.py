"""What the main screen draws of the barrel being raised, computed on the machine's side.

Why here and not in the screen: the joint points come from the barrel's geometry (the ellipse
and the placed chords), and the screens compute no geometry; they draw the points this view
hands them in the belly section's own millimetres (x along the long axis). The view also says
whether to ask the operator about the closing stave: once a single stave can close the gap,
the next board may be cut as the closing stave or as one more normal stave.

Cached by value: the snapshot is built many times a second while the barrel changes once a
board, and finding whether one stave closes the gap scans the section.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

from app.geometry.barrel_section import FULL_TURN_RAD
from app.machine.barrel_set import BarrelSet, BoardChoice, NextStave, Placement

Point = tuple[float, float]


@dataclass(frozen=True)
class BarrelView:
    """The barrel for the screens: the section's semi-axes, the joints placed so far, the
    stave being cut now and the numbers the operator reads."""

    number: int
    a_mm: float
    b_mm: float
    joints_xy: tuple[Point, ...]  # stave n runs from joint n-1 to joint n
    staves_done: int
    closed: bool
    gap_mm: float | None  # the chord back to the first joint; None before the first stave
    perimeter_left_mm: float  # along the belly from the last joint round to the first
    staves_left: int | None  # at the mean width so far, the closing stave counted
    mean_width_mm: float | None
    current_xy: tuple[Point, Point] | None = None  # the stave being cut, once planned
    current_number: int = 1
    current_closing: bool = False
    closing_width_mm: float | None = None  # one stave this wide closes the gap: ask
    choice: BoardChoice | None = None  # the operator's answer for the next board

    @property
    def ask_closing(self) -> bool:
        """Whether the operator is asked: cut the closing stave now, or one more normal one."""
        return self.closing_width_mm is not None and self.current_xy is None


@functools.lru_cache(maxsize=8)
def barrel_view(
    barrel: BarrelSet, current: NextStave | None, choice: BoardChoice | None
) -> BarrelView:
    section = barrel.section
    joints = [section.point(0.0)] + [section.point(s.end_t_rad) for s in barrel.staves]
    being_cut = current if current is not None and current.barrel_number == barrel.number else None
    if being_cut is not None and being_cut.number != len(barrel.staves) + 1:
        being_cut = None  # already counted: the barrel has it
    current_xy = (
        None
        if being_cut is None
        else (section.point(being_cut.stave.start_t_rad), section.point(being_cut.stave.end_t_rad))
    )
    return BarrelView(
        number=barrel.number,
        a_mm=section.a_mm,
        b_mm=section.b_mm,
        joints_xy=tuple(joints),
        staves_done=len(barrel.staves),
        closed=barrel.closed,
        gap_mm=None if not barrel.staves else barrel.gap_mm,
        perimeter_left_mm=0.0
        if barrel.closed
        else section.arc_length_mm(barrel.end_t_rad, FULL_TURN_RAD),
        staves_left=barrel.staves_left_estimate(),
        mean_width_mm=barrel.mean_width_mm,
        current_xy=current_xy,
        current_number=len(barrel.staves) + 1,
        current_closing=being_cut is not None and being_cut.placement is Placement.CLOSING,
        closing_width_mm=barrel.closing_width_mm(),
        choice=choice,
    )
