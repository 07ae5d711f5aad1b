"""The keep-out model of the table: where the cutter may go on its own.

Why it exists: every move the machine makes by itself that is not the cut (the approach to the
first lead-in, a retract, repositioning, the return, the clearing move before homing, a move
to a position) must never take the cutter through the clamped board. The cut itself enters
the board only along the tool path; everything else keeps the tilt pivot outside the board's
keep-out box, or is refused with the reason.

The model. The board is the raw L x W rectangle at P0 (its outline from the measured width and
the recipe, or the largest board the table takes when nothing is known). The box around it is
the one the tool path's own travel moves respect (``app.geometry.toolpath.board_keep_out_box``):
along X the cutter reaches ``r`` from the pivot, across at most ``r/cos(z) + Hm*tan|z|`` at the
table, for the largest tilt of the move. The clamps press on the board's top face and the
centering device is retracted (the cycle waits for its sensor) before the cutter moves, so both
lie inside that outline. ``clearance_mm`` (the system parameter ``tilt_clearance_mm``) is how far
outside the box a detour runs.

A move is planned around the box with the fewest corners that stay within the axis travel:
straight if the line is clear, otherwise through the box's corners widened by the clearance
(a shortest path in the visibility graph of start, end and those four corners).
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from itertools import pairwise

from app.geometry.limits import StaveLimits
from app.geometry.segments import Point
from app.geometry.toolpath import KeepOutBox, ToolPath, board_keep_out_box, board_width_mm
from app.machine.planner.chunk import Chunk
from app.machine.planner.limits import MotionLimits
from app.machine.planner.point_to_point import point_to_point_chunk
from app.machine.planner.trajectory import Phase, PlannerError
from app.table_outlines import TableOutline

XYZ = tuple[float, float, float]


class KeepOutRefused(PlannerError):
    """A move the machine would make on its own cannot stay clear of the board."""


@dataclass(frozen=True)
class TableKeepOut:
    """The board on the table, in machine coordinates, and how to travel around it."""

    length_mm: float
    width_mm: float
    origin_x_mm: float
    origin_y_mm: float
    tool_radius_mm: float
    machine_height_mm: float
    clearance_mm: float
    x_travel_mm: tuple[float, float] = (-math.inf, math.inf)
    y_travel_mm: tuple[float, float] = (-math.inf, math.inf)
    devices: tuple[TableOutline, ...] = ()  # clamps, centering device: those in the way now
    board_on_table: bool = True  # False: only ``devices`` (the table is empty)

    @classmethod
    def for_board(
        cls,
        length_mm: float,
        width_mm: float,
        params: Mapping[str, float],
        limits: StaveLimits | None = None,
        devices: Sequence[TableOutline] = (),
    ) -> TableKeepOut:
        """From the system parameters (P0, tool radius, machine height, clearance)."""
        x_travel = (-math.inf, math.inf)
        y_travel = (-math.inf, math.inf)
        if limits is not None:
            x_travel = _travel(limits.x_min_mm, limits.x_max_mm)
            y_travel = _travel(limits.y_min_mm, limits.y_max_mm)
        return cls(
            length_mm=float(length_mm),
            width_mm=float(width_mm),
            origin_x_mm=float(params["start_x_mm"]),
            origin_y_mm=float(params["start_y_mm"]),
            tool_radius_mm=float(params["tool_radius_mm"]),
            machine_height_mm=float(params["machine_height_mm"]),
            clearance_mm=float(params["tilt_clearance_mm"]),
            x_travel_mm=x_travel,
            y_travel_mm=y_travel,
            devices=tuple(devices),
        )

    @classmethod
    def largest_board(
        cls,
        params: Mapping[str, float],
        limits: StaveLimits,
        length_mm: float | None = None,
        devices: Sequence[TableOutline] = (),
    ) -> TableKeepOut:
        """Nothing measured: the widest board the table takes (of the recipe's length, or
        the longest the table takes)."""
        length = limits.max_length_mm if length_mm is None else length_mm
        return cls.for_board(length, limits.max_width_mm, params, limits, devices)

    @classmethod
    def devices_only(
        cls, devices: Sequence[TableOutline], params: Mapping[str, float], limits: StaveLimits
    ) -> TableKeepOut:
        """An empty table with devices in the way (the centering device out)."""
        keep_out = cls.for_board(0.0, 0.0, params, limits, devices)
        return replace(keep_out, board_on_table=False)

    @classmethod
    def around_toolpath(
        cls, toolpath: ToolPath, devices: Sequence[TableOutline] = ()
    ) -> TableKeepOut:
        """The board a tool path was made for."""
        p = toolpath.params
        return cls(
            length_mm=toolpath.profile.length_mm,
            width_mm=board_width_mm(toolpath.profile, p),
            origin_x_mm=p.start_x_mm,
            origin_y_mm=p.start_y_mm,
            tool_radius_mm=p.tool_radius_mm,
            machine_height_mm=p.machine_height_mm,
            clearance_mm=p.tilt_clearance_mm,
            devices=tuple(devices),
        )

    def box(self, tilt_deg: float) -> KeepOutBox:
        """The board's open box (machine coordinates) the pivot stays out of at tilts up to
        ``|tilt_deg|``."""
        return board_keep_out_box(
            self.length_mm,
            self.width_mm,
            self.tool_radius_mm,
            self.machine_height_mm,
            tilt_deg,
        ).moved(self.origin_x_mm, self.origin_y_mm)

    def boxes(self, tilt_deg: float) -> list[tuple[str, KeepOutBox]]:
        """Every obstacle's box at tilts up to ``|tilt_deg|``, named for the messages: the
        board's (if one is on the table) and each device's, grown by the same reach."""
        named = [("the board", self.box(tilt_deg))] if self.board_on_table else []
        for device in self.devices:
            grown = board_keep_out_box(
                device.x_max_mm - device.x_min_mm,
                device.y_max_mm - device.y_min_mm,
                self.tool_radius_mm,
                self.machine_height_mm,
                tilt_deg,
            ).moved(device.x_min_mm, (device.y_min_mm + device.y_max_mm) / 2.0)
            named.append((device.name, grown))
        return named

    def extent(self, tilt_deg: float) -> KeepOutBox:
        """The smallest box around every obstacle (where a move is clear of all of them)."""
        boxes = [box for _, box in self.boxes(tilt_deg)] or [self.box(tilt_deg)]
        return KeepOutBox(
            min(b.x_min for b in boxes),
            max(b.x_max for b in boxes),
            min(b.y_min for b in boxes),
            max(b.y_max for b in boxes),
        )

    def inside(self, xyz: Sequence[float]) -> bool:
        """True if the cutter at pivot (x, y) and tilt z may touch the board or a device."""
        return self._holding(xyz[2], (xyz[0], xyz[1])) is not None

    def _holding(self, tilt_deg: float, point: Point) -> tuple[str, KeepOutBox] | None:
        return next(((n, b) for n, b in self.boxes(tilt_deg) if b.contains(point)), None)

    def route(self, start: Sequence[float], end: Sequence[float]) -> list[XYZ]:
        """Waypoints from ``start`` to ``end`` (x, y, z) that keep the pivot out of every
        box; the tilt changes linearly with the distance travelled. Raises KeepOutRefused."""
        a = (float(start[0]), float(start[1]), float(start[2]))
        b = (float(end[0]), float(end[1]), float(end[2]))
        tilt = max(abs(a[2]), abs(b[2]))
        for name, point in (("start", a), ("target", b)):
            if (held := self._holding(tilt, point[:2])) is not None:
                what, box = held
                raise KeepOutRefused(
                    f"the {name} X {point[0]:.1f} Y {point[1]:.1f} mm is over {what} "
                    f"(keep-out X {box.x_min:.1f}..{box.x_max:.1f}, "
                    f"Y {box.y_min:.1f}..{box.y_max:.1f} mm)"
                )
        boxes = [box for _, box in self.boxes(tilt)]
        if not _blocked(boxes, a[:2], b[:2]):
            return [a, b]
        corners = [
            c
            for box in boxes
            for c in self._corners(box)
            if self._within_travel(c) and not any(o.contains(c) for o in boxes)
        ]
        xy_path = _shortest_clear_path(a[:2], b[:2], corners, boxes)
        if xy_path is None:
            raise KeepOutRefused(
                f"no way from X {a[0]:.1f} Y {a[1]:.1f} to X {b[0]:.1f} Y {b[1]:.1f} mm "
                f"around {self.obstacle_names(tilt)} within the axis travel"
            )
        return _with_tilt(xy_path, a[2], b[2])

    def obstacle_names(self, tilt_deg: float) -> str:
        names = list(dict.fromkeys(name for name, _ in self.boxes(tilt_deg)))
        return " and ".join(names) if names else "the board"

    def _corners(self, box: KeepOutBox) -> list[Point]:
        m = self.clearance_mm
        return [
            (box.x_min - m, box.y_min - m),
            (box.x_min - m, box.y_max + m),
            (box.x_max + m, box.y_max + m),
            (box.x_max + m, box.y_min - m),
        ]

    def _within_travel(self, point: Point) -> bool:
        return (
            self.x_travel_mm[0] <= point[0] <= self.x_travel_mm[1]
            and self.y_travel_mm[0] <= point[1] <= self.y_travel_mm[1]
        )

    def crossing(self, points: Sequence[Sequence[float]]) -> int | None:
        """Index of the first leg of a polyline (x, y, z points) that enters the box sized
        for its tilts, or None if every leg stays clear."""
        for index, (a, b) in enumerate(pairwise(points)):
            boxes = [box for _, box in self.boxes(max(abs(a[2]), abs(b[2])))]
            if _blocked(boxes, (a[0], a[1]), (b[0], b[1])):
                return index
        return None


def _blocked(boxes: Sequence[KeepOutBox], start: Point, end: Point) -> bool:
    return any(box.blocks(start, end) for box in boxes)


def _travel(low: float | None, high: float | None) -> tuple[float, float]:
    return (-math.inf if low is None else low, math.inf if high is None else high)


def _shortest_clear_path(
    start: Point, end: Point, corners: Sequence[Point], boxes: Sequence[KeepOutBox]
) -> list[Point] | None:
    nodes = [start, end, *corners]
    best = {0: 0.0}
    previous: dict[int, int] = {}
    queue = [(0.0, 0)]
    while queue:
        dist, index = heapq.heappop(queue)
        if index == 1:
            path = [1]
            while path[-1] in previous:
                path.append(previous[path[-1]])
            return [nodes[i] for i in reversed(path)]
        if dist > best.get(index, math.inf):
            continue
        for other in range(len(nodes)):
            if other == index or _blocked(boxes, nodes[index], nodes[other]):
                continue
            candidate = dist + math.dist(nodes[index], nodes[other])
            if candidate < best.get(other, math.inf):
                best[other] = candidate
                previous[other] = index
                heapq.heappush(queue, (candidate, other))
    return None


def _with_tilt(points: Sequence[Point], z_start: float, z_end: float) -> list[XYZ]:
    lengths = [math.dist(a, b) for a, b in pairwise(points)]
    total = sum(lengths)
    result = [(points[0][0], points[0][1], z_start)]
    done = 0.0
    for point, length in zip(points[1:], lengths, strict=True):
        done += length
        fraction = 1.0 if total == 0.0 else done / total
        result.append((point[0], point[1], z_start + (z_end - z_start) * fraction))
    result[-1] = (points[-1][0], points[-1][1], z_end)
    return result


def routed_chunks(
    keep_out: TableKeepOut,
    start: Sequence[float],
    end: Sequence[float],
    limits: MotionLimits,
    phase: Phase,
) -> list[Chunk]:
    """The rest-to-rest moves of :meth:`TableKeepOut.route` (none if already there)."""
    chunks = []
    for a, b in pairwise(keep_out.route(start, end)):
        chunk = point_to_point_chunk(a, b, limits, phase)
        if chunk is not None:
            chunks.append(chunk)
    return chunks
