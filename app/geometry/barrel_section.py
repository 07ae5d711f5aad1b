"""Staves placed around a round or oval barrel: joint points, the two bevels, the closing stave.

Model (docs/MACHINE.md section 7): the belly cross-section seen from the head is the ellipse
E(t) = (a*cos t, b*sin t), a >= b (a circle when a = b = D/2). A stave's outer face is a chord
of it whose length is the stave's belly width. Staves follow one another counter-clockwise
(increasing t) from the end of the major axis, t_0 = 0, with |E(t_i+1) - E(t_i)| = W_i.

Why joints along the surface's normal: neighbouring staves then meet face to face, so the
bevel of a side is the angle between the surface's inward normal at the joint point and the
inward normal of the stave's face. On a circle that is asin(W/D) on both sides; on an ellipse
the two sides of one stave differ, which is why the cut needs two tilts.

Why a scan and bisection rather than a closed form: the distance from a point of an ellipse to
a point moving along it has no closed-form inverse, and on elongated ovals it is not even
monotonic over a half turn. Stepping t by at most a quarter of the width along the curve finds
the first crossing without skipping one; bisection then pins it to the last bit of a double,
far below the 1e-9 mm the joints are compared to.

The head cross-section is the belly's scaled by the width ratio k, so the same bevels serve the
whole length of the stave; nothing here depends on k.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from app.geometry.bevel import SideTilts
from app.geometry.errors import FieldError, GeometryError, format_value, not_a_number, out_of_range
from app.geometry.limits import DEFAULT_LIMITS, StaveLimits
from app.geometry.limits import _finite as finite_number

FULL_TURN_RAD = 2.0 * math.pi
CLOSED_GAP_MM = 1e-6
"""A closing chord shorter than this is no gap: the staves placed already close the barrel."""

_SAME_JOINT_RAD = 1e-6
"""Joints this close in t are one (a chord's end at its longest is only found to ~1e-8 rad)."""

MAX_AXIS_RATIO = 2.0
"""The longest oval accepted, a : b (barrel ovals are about 1.1 to 1.5)."""

_SAME_POINT_MM = 1e-9
"""A chord this much short of the width at its longest is that width, lost to rounding."""

Point = tuple[float, float]


@dataclass(frozen=True)
class BarrelSection:
    """The belly cross-section: semi-axes in mm, a >= b; a circle when they are equal."""

    a_mm: float
    b_mm: float

    @classmethod
    def circle(cls, diameter_mm: float) -> BarrelSection:
        return cls(diameter_mm / 2.0, diameter_mm / 2.0)

    @property
    def is_round(self) -> bool:
        return self.a_mm == self.b_mm

    def point(self, t_rad: float) -> Point:
        return (self.a_mm * math.cos(t_rad), self.b_mm * math.sin(t_rad))

    def inward_normal(self, t_rad: float) -> Point:
        """Unit normal at E(t) pointing into the barrel (the gradient of the ellipse, negated)."""
        nx, ny = -self.b_mm * math.cos(t_rad), -self.a_mm * math.sin(t_rad)
        length = math.hypot(nx, ny)
        return (nx / length, ny / length)

    def chord_mm(self, t0_rad: float, t1_rad: float) -> float:
        (x0, y0), (x1, y1) = self.point(t0_rad), self.point(t1_rad)
        return math.hypot(x1 - x0, y1 - y0)

    def arc_length_mm(self, t0_rad: float, t1_rad: float, steps: int = 720) -> float:
        """Length along the section from t0 to t1 (Simpson's rule on |E'(t)|, smooth and
        periodic: 720 steps a turn are exact to far below a micrometre on barrel ovals)."""
        if t1_rad <= t0_rad:
            return 0.0
        count = max(2, 2 * math.ceil(steps * (t1_rad - t0_rad) / FULL_TURN_RAD / 2))
        h = (t1_rad - t0_rad) / count

        def speed(t: float) -> float:
            return math.hypot(self.a_mm * math.sin(t), self.b_mm * math.cos(t))

        total = speed(t0_rad) + speed(t1_rad)
        total += sum((4 if k % 2 else 2) * speed(t0_rad + k * h) for k in range(1, count))
        return total * h / 3.0

    @property
    def perimeter_mm(self) -> float:
        """Ramanujan's second approximation (exact for a circle; 1e-10 relative on barrel ovals)."""
        a, b = self.a_mm, self.b_mm
        h = ((a - b) / (a + b)) ** 2
        return math.pi * (a + b) * (1.0 + 3.0 * h / (10.0 + math.sqrt(4.0 - 3.0 * h)))


@dataclass(frozen=True)
class PlacedStave:
    """One stave around the barrel: its joints (ellipse parameter t) and the bevel at each.

    Side A of the cut is the first joint (it meets the previous stave), side B the second.
    """

    number: int
    width_mm: float
    start_t_rad: float
    end_t_rad: float
    bevel_start_deg: float
    bevel_end_deg: float

    @property
    def start_angle_deg(self) -> float:
        return math.degrees(self.start_t_rad)

    @property
    def end_angle_deg(self) -> float:
        return math.degrees(self.end_t_rad)


def _angle_between_deg(u: Point, v: Point) -> float:
    cross = u[0] * v[1] - u[1] * v[0]
    dot = u[0] * v[0] + u[1] * v[1]
    return math.degrees(math.atan2(abs(cross), dot))


def face_normal(section: BarrelSection, t0_rad: float, t1_rad: float) -> Point:
    """Inward unit normal of the chord from E(t0) to E(t1) (counter-clockwise: turn left)."""
    (x0, y0), (x1, y1) = section.point(t0_rad), section.point(t1_rad)
    dx, dy = x1 - x0, y1 - y0
    length = math.hypot(dx, dy)
    return (-dy / length, dx / length)


def chord_stave(section: BarrelSection, number: int, t0_rad: float, t1_rad: float) -> PlacedStave:
    """The stave whose face is the chord from t0 to t1, with the bevels of both its joints."""
    normal = face_normal(section, t0_rad, t1_rad)
    return PlacedStave(
        number=number,
        width_mm=section.chord_mm(t0_rad, t1_rad),
        start_t_rad=t0_rad,
        end_t_rad=t1_rad,
        bevel_start_deg=_angle_between_deg(section.inward_normal(t0_rad), normal),
        bevel_end_deg=_angle_between_deg(section.inward_normal(t1_rad), normal),
    )


def next_joint_t(section: BarrelSection, start_t_rad: float, width_mm: float) -> float:
    """The first t > start_t with |E(t) - E(start_t)| = width_mm.

    The joint is on the distance's first rise from the start point: a width beyond that
    rise's maximum reaches no joint without passing over the section, and raises
    GeometryError on ``width_mm``.
    """

    def distance(t: float) -> float:
        return section.chord_mm(start_t_rad, t)

    # |dE/dt| <= a: a step of W/(4a) moves at most W/4 along the curve.
    step = width_mm / (4.0 * section.a_mm)
    before, low = start_t_rad, start_t_rad
    high = start_t_rad + step
    while distance(high) < width_mm:
        if distance(high) < distance(low):  # past the first maximum, which lies in (before, high)
            peak = _argmax(distance, before, high)
            if distance(peak) < width_mm - _SAME_POINT_MM:
                break
            return _bisect_rising(distance, width_mm, before, peak)
        before, low = low, high
        high += step
    else:
        return _bisect_rising(distance, width_mm, low, high)
    allowed = "a width no longer than the longest chord from the joint across the section"
    raise GeometryError([out_of_range("width_mm", width_mm, allowed)])


def _argmax(function: Callable[[float], float], low: float, high: float) -> float:
    """Golden-section search for the maximum of a function unimodal on [low, high]."""
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(200):
        if high - low <= 1e-15 * max(1.0, abs(high)):
            break
        left = high - ratio * (high - low)
        right = low + ratio * (high - low)
        if function(left) < function(right):
            low = left
        else:
            high = right
    return 0.5 * (low + high)


def _bisect_rising(
    function: Callable[[float], float], target: float, low: float, high: float
) -> float:
    """The crossing of ``target`` by a function rising through it on [low, high], to one ulp."""
    if function(high) < target:  # the peak of a tangent crossing, found to rounding
        return high
    for _ in range(200):
        middle = 0.5 * (low + high)
        if middle in (low, high):
            break
        if function(middle) < target:
            low = middle
        else:
            high = middle
    return high


def place_stave(
    section: BarrelSection, number: int, start_t_rad: float, width_mm: float
) -> PlacedStave:
    """The stave of belly width ``width_mm`` whose first joint is at ``start_t_rad``."""
    return chord_stave(section, number, start_t_rad, next_joint_t(section, start_t_rad, width_mm))


def closing_stave(section: BarrelSection, number: int, end_t_rad: float) -> PlacedStave | None:
    """The stave from the last joint back to the first (t = 0 + one turn), if one can close it.

    None when there is no gap, or when the gap is no single stave: a chord that long from the
    last joint would first meet the section before the first joint (half the barrel left
    open has a chord that reaches across it), so more staves are needed before closing.
    """
    width = section.chord_mm(end_t_rad, FULL_TURN_RAD)
    if width < CLOSED_GAP_MM:
        return None
    if next_joint_t(section, end_t_rad, width) < FULL_TURN_RAD - _SAME_JOINT_RAD:
        return None
    return chord_stave(section, number, end_t_rad, FULL_TURN_RAD)


@dataclass(frozen=True)
class BarrelPlan:
    """Boards placed in order; ``overrun_number`` is the first stave that no longer fits."""

    section: BarrelSection
    staves: tuple[PlacedStave, ...]
    closing: PlacedStave | None
    overrun_number: int | None

    @property
    def end_t_rad(self) -> float:
        return self.staves[-1].end_t_rad if self.staves else 0.0


def plan_barrel(section: BarrelSection, widths_mm: Sequence[float]) -> BarrelPlan:
    """Place boards of these widths one after another; the closing stave fills the gap left.

    A board whose second joint would pass the first stave's first joint overruns the
    perimeter: placing stops there, and there is no closing stave.
    """
    staves: list[PlacedStave] = []
    t = 0.0
    for number, width in enumerate(widths_mm, start=1):
        end_t = next_joint_t(section, t, width)
        if end_t > FULL_TURN_RAD:
            if section.chord_mm(FULL_TURN_RAD, end_t) >= CLOSED_GAP_MM:
                return BarrelPlan(section, tuple(staves), None, number)
            end_t = FULL_TURN_RAD  # closes on the first joint, past it by rounding only
        staves.append(chord_stave(section, number, t, end_t))
        t = end_t
    return BarrelPlan(section, tuple(staves), closing_stave(section, len(staves) + 1, t), None)


def staves_to_close(section: BarrelSection, end_t_rad: float, width_mm: float) -> int:
    """How many more staves of this width close the barrel from ``end_t_rad`` (closing included).

    The estimate the operator sees while a barrel is being raised: boards of the mean width so
    far are placed until the next would overrun; the narrower closing stave counts as one.
    """
    count = 0
    t = end_t_rad
    # At t = 0 nothing is placed yet: the whole turn is left, not a closed barrel.
    while t == 0.0 or section.chord_mm(t, FULL_TURN_RAD) >= CLOSED_GAP_MM:
        count += 1
        t = next_joint_t(section, t, width_mm)
        if t > FULL_TURN_RAD:
            break
    return count


def validate_section(
    diameter_mm: object | None = None,
    a_mm: object | None = None,
    b_mm: object | None = None,
    limits: StaveLimits | None = None,
) -> list[FieldError]:
    """Check a round section (diameter) or an oval one (semi-axes a >= b); every violation.

    Why the semi-axes are checked as diameters: the machine's belly-diameter range applies to
    the oval's major and minor axes, 2a and 2b, as it does to a circle's diameter.
    """
    limits = DEFAULT_LIMITS if limits is None else limits
    low = 0.0 if limits.min_barrel_diameter_mm is None else limits.min_barrel_diameter_mm
    high = math.inf if limits.max_barrel_diameter_mm is None else limits.max_barrel_diameter_mm
    errors: list[FieldError] = []
    if diameter_mm is not None:
        _check_size("barrel_diameter_mm", diameter_mm, low, high, "diameter", errors)
        return errors
    a = _check_size(
        "barrel_a_mm", a_mm, low / 2.0, high / 2.0, "a", errors, " (2a is the major axis)"
    )
    b = _check_size(
        "barrel_b_mm", b_mm, low / 2.0, high / 2.0, "b", errors, " (2b is the minor axis)"
    )
    if a is not None and b is not None and b > a:
        allowed = f"b <= a = {format_value(a)} mm (a is the semi-major axis)"
        errors.append(out_of_range("barrel_b_mm", b_mm, allowed))
    elif a is not None and b is not None and a > MAX_AXIS_RATIO * b:
        # Ends that sharp (radius b^2/a) curl a stave's chord round them: no cooper's barrel.
        allowed = (
            f"a / {format_value(MAX_AXIS_RATIO)} = {format_value(a / MAX_AXIS_RATIO)} <= b <= a mm"
        )
        errors.append(
            out_of_range("barrel_b_mm", b_mm, allowed, "an oval at most twice as long as wide")
        )
    return errors


def _check_size(
    field: str,
    value: object,
    low: float,
    high: float,
    name: str,
    errors: list[FieldError],
    note: str = "",
) -> float | None:
    allowed = f"{format_value(low)} <= {name} <= {format_value(high)} mm{note}"
    number = finite_number(field, value, allowed, errors)
    if number is not None and not low <= number <= high:
        errors.append(out_of_range(field, value, allowed))
        return None
    return number


def validate_widths(
    widths_mm: Sequence[object], limits: StaveLimits | None = None
) -> list[FieldError]:
    """Each board's belly width: a finite number in 0 < W <= the machine's widest board."""
    limits = DEFAULT_LIMITS if limits is None else limits
    allowed = f"0 < width <= {format_value(limits.max_width_mm)} mm"
    errors: list[FieldError] = []
    for width in widths_mm:
        if (
            isinstance(width, bool)
            or not isinstance(width, int | float)
            or not math.isfinite(width)
        ):
            errors.append(not_a_number("width_mm", width, allowed))
        elif not 0.0 < width <= limits.max_width_mm:
            errors.append(out_of_range("width_mm", width, allowed))
    return errors


@dataclass(frozen=True)
class PlacedBarrelTilt:
    """The two bevels of the board placed next around a barrel, its first joint at ``start_t_rad``.

    Why a rule of its own: on an oval the bevels depend on where the stave sits, not only on
    its width, so a barrel being raised hands the cut the position of the next stave. Side A
    is the stave's first joint (it meets the stave before), side B its second.
    """

    section: BarrelSection
    start_t_rad: float = 0.0

    def tilts_for_width(self, width_mm: float, limits: StaveLimits) -> SideTilts:
        errors = validate_widths([width_mm], limits)
        if errors:
            raise GeometryError(errors)
        stave = place_stave(self.section, 1, self.start_t_rad, float(width_mm))
        low, high = limits.min_tilt_deg, limits.max_tilt_deg
        allowed = f"{format_value(low)} <= tilt <= {format_value(high)} deg"
        for field, bevel in (
            ("tilt_a_deg", stave.bevel_start_deg),
            ("tilt_b_deg", stave.bevel_end_deg),
        ):
            if not low <= bevel <= high:
                note = (
                    f"the bevel of a {format_value(width_mm)} mm stave at "
                    f"t = {stave.start_angle_deg:.3f} deg of this barrel"
                )
                errors.append(out_of_range(field, round(bevel, 3), allowed, note))
        if errors:
            raise GeometryError(errors)
        return SideTilts(stave.bevel_start_deg, stave.bevel_end_deg)
