"""The ``[keep_out]`` table of the machine configuration: where the clamps and the centering
device stand on the table, so that the cutter's own moves and the jogs keep clear of them.

Why outlines of their own: a clamp closed on the empty end of the table beyond a short board,
or the centering device's pushers still out while the operator jogs or sends the axes to a
position, stand where the board's outline does not reach. Each is a rectangle in machine X/Y
(mm, the coordinates of P0: the table does not move), the ground the device covers in any of
its positions; the keep-out model (:mod:`app.machine.planner.keepout`) grows it by the
cutter's reach like the board. The clamps count while a board is on the table or they are
closed, the centering device while its retracted sensor is off.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol

MAX_OUTLINES = 16  # per device kind: more is a typing error, not a table
OUTLINE_REACH_MM = 20_000.0  # no table is larger (see app.config.AXIS_REACH)


class Section(Protocol):
    """What these settings read of a table (``app.config.Section``, which imports this
    module: a protocol keeps the imports one way)."""

    def error(self, name: str, value: object, allowed: str) -> Exception: ...

    def number(self, name: str, default: float, minimum: float, maximum: float) -> float: ...

    def table_list(self, name: str, maximum: int) -> list[Any]: ...

    def finish(self) -> None: ...


@dataclass(frozen=True)
class TableOutline:
    """A device's ground on the table, machine coordinates (mm)."""

    name: str  # for messages: "clamp 1", "the centering device"
    x_min_mm: float
    x_max_mm: float
    y_min_mm: float
    y_max_mm: float


@dataclass(frozen=True)
class TableDevices:
    """Both kinds of outline; none configured means the devices lie inside the board's."""

    clamps: tuple[TableOutline, ...] = ()
    centering: tuple[TableOutline, ...] = ()

    def in_the_way(
        self, *, board_on_table: bool, clamps_closed: bool, centering_retracted: bool
    ) -> tuple[TableOutline, ...]:
        """The outlines that count with these sensors."""
        clamps = self.clamps if board_on_table or clamps_closed else ()
        centering = () if centering_retracted else self.centering
        return clamps + centering


def _read_outline(section: Section, name: str) -> TableOutline:
    reach = OUTLINE_REACH_MM
    x_min = section.number("x_min_mm", 0.0, -reach, reach)
    x_max = section.number("x_max_mm", 0.0, -reach, reach)
    y_min = section.number("y_min_mm", 0.0, -reach, reach)
    y_max = section.number("y_max_mm", 0.0, -reach, reach)
    if x_max <= x_min:
        raise section.error("x_max_mm", x_max, f"greater than x_min_mm ({x_min:g})")
    if y_max <= y_min:
        raise section.error("y_max_mm", y_max, f"greater than y_min_mm ({y_min:g})")
    section.finish()
    return TableOutline(name, x_min, x_max, y_min, y_max)


def read_table_devices(section: Section) -> TableDevices:
    """Read ``[keep_out]``: ``clamps`` and ``centering_device``, each a list of
    ``{ x_min_mm, x_max_mm, y_min_mm, y_max_mm }``."""
    clamps = section.table_list("clamps", MAX_OUTLINES)
    centering = section.table_list("centering_device", MAX_OUTLINES)
    devices = TableDevices(
        clamps=tuple(_read_outline(c, f"clamp {i + 1}") for i, c in enumerate(clamps)),
        centering=tuple(_read_outline(c, "the centering device") for c in centering),
    )
    section.finish()
    return devices
