"""The tool path of one stave in machine coordinates, both sides, as exact lines and arcs.

Sign conventions (docs/MACHINE.md leaves some of them open; these are the ones the code uses):

* Profile frame (docs/MACHINE.md section 2): x along the stave from its left end, y across
  it, 0 on the centre line, +y towards side A, which is cut first.
* Machine frame: X = P0x + x, Y = P0y + y, the same orientation as the profile frame
  (P0 = the system parameter "start position"). The path's points are the positions the X
  and Y axes take, i.e. of the tilt pivot of the router holder.
* Z (tilt, deg): a positive tilt moves the cutter's lower end towards +Y: the tool axis meets
  the table at Y_pivot + Hm * tan(Z). Side A is cut at Z = +alpha_A, side B at Z = -alpha_B
  (equal on a round barrel; on an oval each side of a stave has its own bevel), so on both
  sides the cutter leans over the board and the top face comes out narrower. Below, alpha is
  the bevel of the side being cut.
* Compensation: the edge is offset *outward* (away from the board: +y on side A, -y on
  side B) along its normal by rc = r / cos(alpha), the radius in plan view of the tilted
  cutter at the table; lines stay lines, the arc keeps its centre with radius R + rc. Then the
  pivot shift: Y_pivot = Y_offset - Hm * tan(Z), i.e. -Hm*tan(alpha) on side A and
  +Hm*tan(alpha) on side B. Where the normal is along y this is section 3's
  y_cut = y_pivot + Hm*tan(alpha) - r/cos(alpha) on side A, mirrored on side B.
* Direction: both sides are cut clockwise around the board seen from above (+X to the right,
  +Y up): side A from the left end to the right end, side B back from right to left. The
  arcs are therefore "cw" on both sides.

Motion of one stave: home -> approach the side A lead-in start while tilting to +alpha (routed
around the board if the straight line would cross it) -> lead-in -> P1..P4 -> lead-out ->
travel out to the tilt position (tilt_clearance_mm beyond the board's right end plus the tool
radius) -> tilt +alpha -> -alpha while crossing to side B -> in to the side B lead-in start ->
lead-in -> P5..P8 -> lead-out -> home, tilting back to home_z.

Lead-in and lead-out run along the extension of the straight section (or of the arc's tangent
when lambda = 0) over `lead_mm`, which must exceed rc: then the cutter starts and ends clear
of the board (its extent along X is r at any tilt, rc in the plan-view model) and the corners
are cut completely. Non-cutting moves keep the pivot outside a keep-out box around the board
(see `keep_out_box`), so the tool never touches the board while travelling or tilting.

`build_original_toolpath` gives the original program's method (the whole profile shifted in
y only) for comparison: on the slanted sections it cuts too deep by rc*(1/cos(theta) - 1)
across the stave and moves the tangent points along X by rc*sin(theta).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, fields
from enum import Enum
from itertools import pairwise

from app.geometry.curved_profile import SideProfile
from app.geometry.errors import FieldError, GeometryError, format_value, not_a_number
from app.geometry.errors import out_of_range as _out_of_range
from app.geometry.polyline import PolylinePoint
from app.geometry.polyline import to_polyline as _to_polyline
from app.geometry.segments import ArcSegment, LineSegment, Point, Segment

__all__ = [
    "ArcSegment",
    "CompensationMethod",
    "KeepOutBox",
    "LineSegment",
    "Segment",
    "SideCut",
    "ToolPath",
    "ToolPathParams",
    "board_keep_out_box",
    "board_width_mm",
    "build_original_toolpath",
    "build_toolpath",
    "compensated_side",
    "keep_out_box",
    "validate_toolpath_params",
]

SIDE_SIGN = {"A": 1.0, "B": -1.0}
"""+1 for side A (outward is +y, tilt +alpha), -1 for side B."""


class CompensationMethod(Enum):
    """How the cutter radius is compensated."""

    NORMAL = "normal"
    """Offset along the edge's normal by r/cos(alpha) (this project)."""
    Y_SHIFT = "y_shift"
    """The original program: the whole edge shifted in y by r/cos(alpha)."""


@dataclass(frozen=True)
class ToolPathParams:
    """System parameters the tool path needs (mm, deg; machine coordinates).

    tilt_deg is the bevel alpha_A of side A (>= 0) and tilt_b_deg that of side B, alpha_B
    (None: the same as side A); side A is cut at Z = +alpha_A, side B at Z = -alpha_B, each
    with its own r/cos(alpha) offset and Hm*tan(alpha) pivot shift. start_x/y_mm is P0, the
    machine position of
    the profile origin; lead_mm the lead-in/lead-out length along the path (> r/cos(alpha));
    tilt_clearance_mm how far beyond (board's right end + tool radius) the tilt change
    happens, also the margin of the detours that take travel moves around the board.
    """

    tool_radius_mm: float
    machine_height_mm: float
    tilt_deg: float
    start_x_mm: float
    start_y_mm: float
    lead_mm: float
    home_x_mm: float
    home_y_mm: float
    home_z_deg: float
    tilt_clearance_mm: float
    tilt_b_deg: float | None = None
    board_width_mm: float | None = None
    """The raw board's width when the stave is cut narrower (to a target width); travel
    moves keep clear of the whole board. None: the board is as wide as the stave."""
    roughing_allowances_mm: tuple[float, ...] = ()
    """Roughing passes before the finishing one, on each side: how much material each leaves
    on the edge (mm, decreasing, > 0). Empty: one pass per side."""

    @property
    def passes(self) -> int:
        """Passes per side: the roughing ones and the finishing one."""
        return len(self.roughing_allowances_mm) + 1

    def side_tilt_deg(self, side: str) -> float:
        """The bevel of side "A" or "B" (>= 0; side B is cut at minus this)."""
        if side == "A" or self.tilt_b_deg is None:
            return self.tilt_deg
        return self.tilt_b_deg

    def side_effective_radius_mm(self, side: str) -> float:
        """r / cos(alpha) of one side: the cutter's radius in plan view at the table."""
        return self.tool_radius_mm / math.cos(math.radians(self.side_tilt_deg(side)))

    def side_pivot_shift_mm(self, side: str) -> float:
        """Hm * tan(alpha) of one side: how far the cutter meets the table from below the pivot."""
        return self.machine_height_mm * math.tan(math.radians(self.side_tilt_deg(side)))

    @property
    def max_tilt_deg(self) -> float:
        return max(self.side_tilt_deg("A"), self.side_tilt_deg("B"))

    @property
    def effective_radius_mm(self) -> float:
        """r / cos(alpha) at the larger bevel: the widest the cutter gets at the table."""
        return self.tool_radius_mm / math.cos(math.radians(self.max_tilt_deg))

    @classmethod
    def from_parameters(
        cls, params: Mapping[str, float], tilt_deg: float, tilt_b_deg: float | None = None
    ) -> ToolPathParams:
        """From the system parameters, whose names are this class's field names (the
        database's catalogue and the machine's configuration use the same names)."""
        values = {name: float(params[name]) for name in cls.system_parameter_names()}
        # The names are exactly the float fields: mypy cannot see that the dict fills no other.
        return cls(tilt_deg=tilt_deg, tilt_b_deg=tilt_b_deg, **values)  # type: ignore[arg-type]

    @classmethod
    def system_parameter_names(cls) -> tuple[str, ...]:
        """The fields that are system parameters (the bevels come from the recipe and board)."""
        board = ("tilt_deg", "tilt_b_deg", "board_width_mm", "roughing_allowances_mm")
        return tuple(f.name for f in fields(cls) if f.name not in board)

    @property
    def pivot_shift_mm(self) -> float:
        """Hm * tan(alpha) of side A (see side_pivot_shift_mm)."""
        return self.side_pivot_shift_mm("A")


def validate_toolpath_params(params: ToolPathParams) -> list[FieldError]:
    """Every violation in the parameters (geometric sanity; machine limits are elsewhere)."""
    errors: list[FieldError] = []
    values: dict[str, float] = {}
    for name in ToolPathParams.__dataclass_fields__:
        value = getattr(params, name)
        if name in ("tilt_b_deg", "board_width_mm") and value is None:
            continue
        if name == "roughing_allowances_mm":
            _check_allowances(value, errors)
            continue
        is_number = isinstance(value, int | float) and not isinstance(value, bool)
        if not (is_number and math.isfinite(value)):
            errors.append(not_a_number(name, value, "a finite number"))
        else:
            values[name] = float(value)

    def check(name: str, ok: bool, allowed: str, note: str = "") -> bool:
        if name in values and not ok:
            errors.append(_out_of_range(name, values[name], allowed, note))
            return False
        return name in values

    radius_ok = check(
        "tool_radius_mm", values.get("tool_radius_mm", 0.0) > 0.0, "tool radius > 0 mm"
    )
    check(
        "machine_height_mm",
        values.get("machine_height_mm", 0.0) >= 0.0,
        "machine height >= 0 mm",
    )
    tilt_ok = check("tilt_deg", 0.0 <= values.get("tilt_deg", 0.0) < 90.0, "0 <= tilt < 90 deg")
    tilt_ok = (
        check("tilt_b_deg", 0.0 <= values.get("tilt_b_deg", 0.0) < 90.0, "0 <= tilt < 90 deg")
        or params.tilt_b_deg is None
    ) and tilt_ok
    check("home_z_deg", -90.0 < values.get("home_z_deg", 0.0) < 90.0, "-90 < home tilt < 90 deg")
    check(
        "tilt_clearance_mm",
        values.get("tilt_clearance_mm", 0.0) >= 0.0,
        "tilt clearance >= 0 mm",
    )
    if radius_ok and tilt_ok:
        minimum = params.effective_radius_mm
        check(
            "lead_mm",
            values.get("lead_mm", 0.0) > minimum,
            f"lead > {minimum:.3f} mm",
            "longer than the cutter's radius at the table, tool_radius_mm / cos(tilt), at the "
            "larger bevel",
        )
    return errors


@dataclass(frozen=True)
class SideCut:
    """The compensated edge of one side in the profile frame, before the pivot shift.

    Cut order: lead_in_start -> edge[0].start (line) -> the edge's lines and arcs (tangent to
    each other) -> edge[-1].end -> lead_out_end (line).
    """

    side: str
    lead_in_start: Point
    edge: tuple[Segment, ...]
    lead_out_end: Point


def _moved(point: Point, dx: float, dy: float) -> Point:
    return (point[0] + dx, point[1] + dy)


def _left_normal(segment: Segment, s_mm: float, offset_mm: float) -> Point:
    tx, ty = segment.tangent_at(s_mm)
    return (-ty * offset_mm, tx * offset_mm)


def _concave_refusal(segment: ArcSegment, side: str, offset_mm: float) -> FieldError:
    x = min(segment.start[0], segment.end[0])
    allowed = f"concave radius >= {offset_mm:.3f} mm"
    message = (
        f"profile: side {side} is concave with a radius of {segment.radius_mm:.3f} mm near "
        f"x = {x:.3f} mm, tighter than the cutter's {offset_mm:.3f} mm "
        "(tool_radius_mm / cos(tilt_deg)): the cutter cannot follow it"
    )
    return FieldError("profile", segment.radius_mm, allowed, message)


def _offset_edge(edge: tuple[Segment, ...], offset_mm: float, side: str) -> tuple[Segment, ...]:
    """Every piece moved outward along its normal by offset_mm (the tool centre's path).

    The outward normal is the left-hand normal of the (clockwise) direction of travel; a
    line stays a line, a clockwise arc (convex edge) grows by offset_mm about its centre, a
    counter-clockwise one (concave edge) shrinks and must keep a radius above the offset.
    Consecutive pieces share their joint point exactly, computed once from the common normal.
    """
    joints = [_moved(edge[0].start, *_left_normal(edge[0], 0.0, offset_mm))]
    for piece in edge:
        joints.append(_moved(piece.end, *_left_normal(piece, piece.length_mm, offset_mm)))
    result: list[Segment] = []
    for piece, start, end in zip(edge, joints, joints[1:], strict=False):
        if isinstance(piece, LineSegment):
            result.append(LineSegment(start, end, 0.0, 0.0, False, side))
            continue
        if not piece.clockwise and piece.radius_mm <= offset_mm * (1.0 + 1e-9):
            raise GeometryError([_concave_refusal(piece, side, offset_mm)])
        result.append(ArcSegment(start, end, piece.center, piece.clockwise, 0.0, 0.0, False, side))
    return tuple(result)


def _shifted_edge(edge: tuple[Segment, ...], dy: float) -> tuple[Segment, ...]:
    """The original program's compensation: everything moved in y only."""
    result: list[Segment] = []
    for piece in edge:
        start, end = _moved(piece.start, 0.0, dy), _moved(piece.end, 0.0, dy)
        if isinstance(piece, LineSegment):
            result.append(LineSegment(start, end, 0.0, 0.0, False, piece.side))
        else:
            centre = _moved(piece.center, 0.0, dy)
            result.append(
                ArcSegment(start, end, centre, piece.clockwise, 0.0, 0.0, False, piece.side)
            )
    return tuple(result)


def compensated_side(
    profile: SideProfile,
    side: str,
    offset_mm: float,
    lead_mm: float,
    method: CompensationMethod = CompensationMethod.NORMAL,
) -> SideCut:
    """The tool centre's path in plan view for one side, profile frame, no pivot shift.

    Raises GeometryError when a concave part of the side is tighter than the cutter.
    """
    if side not in SIDE_SIGN:
        raise ValueError(f"side must be 'A' or 'B', got {side!r}")
    edge = profile.edge(side)
    if method is CompensationMethod.NORMAL:
        moved = _offset_edge(edge, offset_mm, side)
    else:
        moved = _shifted_edge(edge, SIDE_SIGN[side] * offset_mm)
    first_dir = edge[0].tangent_at(0.0)
    last_dir = edge[-1].tangent_at(edge[-1].length_mm)
    first, last = moved[0].start, moved[-1].end
    return SideCut(
        side=side,
        lead_in_start=_moved(first, -first_dir[0] * lead_mm, -first_dir[1] * lead_mm),
        edge=moved,
        lead_out_end=_moved(last, last_dir[0] * lead_mm, last_dir[1] * lead_mm),
    )


def _cut_segments(cut: SideCut, dx: float, dy: float, tilt_deg: float) -> list[Segment]:
    """The side's cutting moves, translated by (dx, dy) into machine coordinates."""
    start = _moved(cut.lead_in_start, dx, dy)
    first = _moved(cut.edge[0].start, dx, dy)
    segments: list[Segment] = [LineSegment(start, first, tilt_deg, tilt_deg, True, cut.side)]
    for piece in cut.edge:
        a = segments[-1].end  # the very point the previous move ended at: no gap
        b = _moved(piece.end, dx, dy)
        if isinstance(piece, LineSegment):
            segments.append(LineSegment(a, b, tilt_deg, tilt_deg, True, cut.side))
        else:
            centre = _moved(piece.center, dx, dy)
            segments.append(
                ArcSegment(a, b, centre, piece.clockwise, tilt_deg, tilt_deg, True, cut.side)
            )
    end = _moved(cut.lead_out_end, dx, dy)
    segments.append(LineSegment(segments[-1].end, end, tilt_deg, tilt_deg, True, cut.side))
    return segments


@dataclass(frozen=True)
class KeepOutBox:
    """Open rectangle (profile frame) the tilt pivot must stay out of when not cutting.

    With the pivot outside it the tool cannot touch the board: along X the cutter reaches r
    from the pivot at any tilt; across, at most r/cos(z) + Hm*tan|z| at the table.
    """

    x_min: float
    x_max: float
    y_min: float
    y_max: float

    def moved(self, dx: float, dy: float) -> KeepOutBox:
        """The same box translated (e.g. by P0 into machine coordinates)."""
        return KeepOutBox(self.x_min + dx, self.x_max + dx, self.y_min + dy, self.y_max + dy)

    def contains(self, point: Point) -> bool:
        return self.x_min < point[0] < self.x_max and self.y_min < point[1] < self.y_max

    def blocks(self, start: Point, end: Point) -> bool:
        """True if the straight move start -> end passes through the box's interior."""
        low, high = 0.0, 1.0
        for origin, delta, box_low, box_high in (
            (start[0], end[0] - start[0], self.x_min, self.x_max),
            (start[1], end[1] - start[1], self.y_min, self.y_max),
        ):
            if delta == 0.0:
                if not box_low < origin < box_high:
                    return False
                continue
            enter, leave = (box_low - origin) / delta, (box_high - origin) / delta
            low, high = max(low, min(enter, leave)), min(high, max(enter, leave))
            if low >= high:
                return False
        return True


def board_keep_out_box(
    length_mm: float,
    width_mm: float,
    tool_radius_mm: float,
    machine_height_mm: float,
    tilt_deg: float,
) -> KeepOutBox:
    """The box (profile frame) around a raw board of ``length_mm`` x ``width_mm`` that keeps
    a cutter tilted by up to ``|tilt_deg|`` off it while the pivot stays outside."""
    tilt_rad = math.radians(abs(tilt_deg))
    across = tool_radius_mm / math.cos(tilt_rad) + machine_height_mm * math.tan(tilt_rad)
    half_width = width_mm / 2.0
    return KeepOutBox(
        x_min=-tool_radius_mm,
        x_max=length_mm + tool_radius_mm,
        y_min=-half_width - across,
        y_max=half_width + across,
    )


def board_width_mm(profile: SideProfile, params: ToolPathParams) -> float:
    """The raw board's width: the measured one when the stave is cut narrower from it."""
    board_mm = params.board_width_mm
    return max(profile.width_mm, 0.0 if board_mm is None else board_mm)


def keep_out_box(profile: SideProfile, params: ToolPathParams) -> KeepOutBox:
    """The box around the raw board (L x W) that travel moves keep the pivot out of."""
    return board_keep_out_box(
        profile.length_mm,
        board_width_mm(profile, params),
        params.tool_radius_mm,
        params.machine_height_mm,
        max(abs(params.home_z_deg), params.max_tilt_deg),
    )


def _route(left: Point, other: Point, box: KeepOutBox, margin_mm: float) -> list[Point]:
    """Waypoints from `left` (a point left of the box) to `other` that avoid the box."""
    if not box.blocks(left, other):
        return [left, other]
    if other[1] >= box.y_max or other[1] <= box.y_min:
        return [left, (left[0], other[1]), other]
    # `other` is level with the board and beyond its right end: go round on `left`'s side.
    above = left[1] >= (box.y_min + box.y_max) / 2.0
    side_y = box.y_max + margin_mm if above else box.y_min - margin_mm
    return [left, (left[0], side_y), (other[0], side_y), other]


def _check_allowances(value: object, errors: list[FieldError]) -> None:
    allowed = "a decreasing list of finite numbers > 0 mm"
    numbers = list(value) if isinstance(value, tuple) else None
    ok = numbers is not None and all(
        isinstance(n, int | float) and not isinstance(n, bool) and math.isfinite(n) and n > 0
        for n in numbers
    )
    if ok and numbers is not None and all(a > b for a, b in pairwise(numbers)):
        return
    message = f"roughing_allowances_mm = {value!r} is not allowed: {allowed}"
    errors.append(FieldError("roughing_allowances_mm", value, allowed, message))


def _side_passes(
    profile: SideProfile,
    params: ToolPathParams,
    side: str,
    method: CompensationMethod,
    clear_y: float,
) -> list[Segment]:
    """All passes of one side, roughing first: each pass runs lead-in to lead-out, the cutter
    then travels back round the board (at ``clear_y``, outside the keep-out box, the tilt
    kept) to the next pass's lead-in. The travel moves carry the side, so a planner keeps
    them in the side's cut with the spindle running."""
    sign = SIDE_SIGN[side]
    tilt = sign * params.side_tilt_deg(side)
    dy = float(params.start_y_mm) - sign * params.side_pivot_shift_mm(side)
    radius = params.side_effective_radius_mm(side)
    segments: list[Segment] = []
    for allowance in (*params.roughing_allowances_mm, 0.0):
        cut = _cut_segments(
            compensated_side(profile, side, radius + allowance, params.lead_mm, method),
            float(params.start_x_mm),
            dy,
            tilt,
        )
        if segments:
            end, start = segments[-1].end, cut[0].start
            back = [end, (end[0], clear_y), (start[0], clear_y), start]
            segments += _travel(back, tilt, tilt, side)
        segments += cut
    return segments


def _travel(
    points: list[Point], z_from_deg: float, z_to_deg: float, side: str = ""
) -> list[Segment]:
    """Non-cutting moves through `points`, the tilt changing linearly with distance."""
    unique = [points[0]]
    for point in points[1:]:
        if point != unique[-1]:
            unique.append(point)
    if len(unique) == 1:
        if z_from_deg == z_to_deg:
            return []
        return [LineSegment(unique[0], unique[0], z_from_deg, z_to_deg, False, side)]
    lengths = [math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in pairwise(unique)]
    total = sum(lengths)
    segments: list[Segment] = []
    done = 0.0
    last = len(lengths) - 1
    for index, ((a, b), length) in enumerate(zip(pairwise(unique), lengths, strict=True)):
        if z_from_deg == z_to_deg:
            z_start = z_end = z_from_deg
        else:
            z_start = z_from_deg + (z_to_deg - z_from_deg) * done / total
            done += length
            z_end = (
                z_to_deg if index == last else z_from_deg + (z_to_deg - z_from_deg) * (done / total)
            )
        segments.append(LineSegment(a, b, z_start, z_end, False, side))
    return segments


@dataclass(frozen=True)
class ToolPath:
    """The complete motion of one stave, machine coordinates, in execution order."""

    segments: tuple[Segment, ...]
    params: ToolPathParams
    profile: SideProfile

    @property
    def length_mm(self) -> float:
        return sum(segment.length_mm for segment in self.segments)

    def side_segments(self, side: str) -> tuple[Segment, ...]:
        """The cutting segments of side "A" or "B" (lead-in and lead-out included)."""
        if side not in SIDE_SIGN:
            raise ValueError(f"side must be 'A' or 'B', got {side!r}")
        return tuple(s for s in self.segments if s.cutting and s.side == side)

    def cutting_length_mm(self, side: str | None = None) -> float:
        """Length cut at feed on one side ("A"/"B", leads included), or on both (None)."""
        sides = tuple(SIDE_SIGN) if side is None else (side,)
        return sum(s.length_mm for name in sides for s in self.side_segments(name))

    def to_json_list(self) -> list[dict[str, object]]:
        """The `stave solve --json` segment format (z_deg is the tilt at the segment's end)."""
        items: list[dict[str, object]] = []
        for segment in self.segments:
            item: dict[str, object] = {
                "type": "arc" if isinstance(segment, ArcSegment) else "line",
                "start": [segment.start[0], segment.start[1]],
                "end": [segment.end[0], segment.end[1]],
            }
            if isinstance(segment, ArcSegment):
                item["center"] = [segment.center[0], segment.center[1]]
                item["direction"] = "cw" if segment.clockwise else "ccw"
            item["z_deg"] = segment.z_end_deg
            if segment.z_start_deg != segment.z_end_deg:
                item["z_start_deg"] = segment.z_start_deg
            item["cutting"] = segment.cutting
            items.append(item)
        return items

    def to_polyline(
        self, max_chord_error_mm: float = 0.001, max_segment_mm: float | None = None
    ) -> list[PolylinePoint]:
        """Points (x_mm, y_mm, z_deg, cutting) whose chords stay within the bound of the path.

        `cutting` belongs to the move ending at the point; the first point is the start.
        """
        return _to_polyline(self.segments, max_chord_error_mm, max_segment_mm)


def _home_error(params: ToolPathParams, box: KeepOutBox) -> FieldError:
    x0, y0 = params.start_x_mm, params.start_y_mm
    allowed = (
        f"X <= {format_value(round(x0 + box.x_min, 3))} or "
        f"X >= {format_value(round(x0 + box.x_max, 3))} or "
        f"Y <= {format_value(round(y0 + box.y_min, 3))} or "
        f"Y >= {format_value(round(y0 + box.y_max, 3))} mm"
    )
    value = (params.home_x_mm, params.home_y_mm)
    message = (
        f"home_position_mm = ({format_value(value[0])}, {format_value(value[1])}) puts the "
        f"tool over the board: allowed {allowed}"
    )
    return FieldError("home_position_mm", value, allowed, message)


def _build(profile: SideProfile, params: ToolPathParams, method: CompensationMethod) -> ToolPath:
    errors = validate_toolpath_params(params)
    if errors:
        raise GeometryError(errors)
    x0, y0 = float(params.start_x_mm), float(params.start_y_mm)
    box = keep_out_box(profile, params)
    if box.contains((float(params.home_x_mm) - x0, float(params.home_y_mm) - y0)):
        raise GeometryError([_home_error(params, box)])
    # From here on everything is in machine coordinates, and the travel moves start and end
    # at the very points the cutting moves computed, so the path has no gaps, not even 1 ulp.
    box = box.moved(x0, y0)
    home = (float(params.home_x_mm), float(params.home_y_mm))
    alpha = params.side_tilt_deg("A")
    beta = params.side_tilt_deg("B")
    margin = params.tilt_clearance_mm
    cut_a = _side_passes(profile, params, "A", method, box.y_max + margin)
    cut_b = _side_passes(profile, params, "B", method, box.y_min - margin)
    start_a, end_a = cut_a[0].start, cut_a[-1].end
    start_b, end_b = cut_b[0].start, cut_b[-1].end

    tilt_x = max(x0 + profile.length_mm + params.tool_radius_mm + margin, end_a[0], start_b[0])
    segments: list[Segment] = []
    segments += _travel(
        list(reversed(_route(start_a, home, box, margin))), params.home_z_deg, alpha
    )
    segments += cut_a
    segments += _travel([end_a, (tilt_x, end_a[1])], alpha, alpha)
    segments += _travel([(tilt_x, end_a[1]), (tilt_x, start_b[1])], alpha, -beta)
    segments += _travel([(tilt_x, start_b[1]), start_b], -beta, -beta)
    segments += cut_b
    segments += _travel(_route(end_b, home, box, margin), -beta, params.home_z_deg)
    return ToolPath(segments=tuple(segments), params=params, profile=profile)


def build_toolpath(profile: SideProfile, params: ToolPathParams) -> ToolPath:
    """The tool path of both sides; raises GeometryError for invalid parameters.

    Also raised when the home position lies over the board (inside `keep_out_box`): no safe
    approach exists from there.
    """
    return _build(profile, params, CompensationMethod.NORMAL)


def build_original_toolpath(profile: SideProfile, params: ToolPathParams) -> ToolPath:
    """The same motion with the original program's y-only shift (for comparison only)."""
    return _build(profile, params, CompensationMethod.Y_SHIFT)
