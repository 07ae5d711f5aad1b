"""The bevel of a stave from the barrel it belongs to (round barrels, radial joints).

The barrel's cross-section at the belly is a circle of diameter Db and the staves' joints are
radial planes (they all meet on the barrel's axis; that is what makes them close). A stave
whose face on the table is W wide at the belly is a chord of that circle, subtending the
central angle 2*asin(W / Db). Each of its two joints lies in the radial plane through one end
of the chord, which is turned by half that angle from the radius through the middle of the
stave - and that radius is the normal of the stave's face. So each side is bevelled by

    alpha = asin(W / Db)

(a barrel of n equal staves has W = Db*sin(180/n), giving alpha = 180/n). The heads need no
other angle: with k = W1/W matched to the head diameter, W1/Dhead = W/Db. This is the inverse
of `app.geometry.limits.barrel_diameter_mm(W, alpha) = W / sin(alpha)`.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

from app.geometry.bevel import SideTilts
from app.geometry.errors import (
    FieldError,
    GeometryError,
    format_value,
    not_a_number,
    out_of_range,
    worded,
)
from app.geometry.limits import StaveLimits
from app.geometry.rule_texts import RuleText


def barrel_tilt_deg(width_mm: object, diameter_mm: float | None, limits: StaveLimits) -> float:
    """The bevel (deg) of each side of a board ``width_mm`` wide in a barrel of belly diameter
    ``diameter_mm``: asin(W / Db).

    Raises GeometryError (field ``barrel_diameter_mm``, ``width_mm`` or ``tilt_deg``) if the
    diameter is not positive, the width is not a positive finite number below the diameter, or
    the computed tilt falls outside the machine's tilt limits.
    """
    if diameter_mm is None or not math.isfinite(diameter_mm) or diameter_mm <= 0:
        allowed = "a positive barrel diameter (recipe in tilt mode 'barrel')"
        message = f"barrel_diameter_mm = {format_value(diameter_mm)} cannot give a tilt: {allowed}"
        raise GeometryError([FieldError("barrel_diameter_mm", diameter_mm, allowed, message)])
    allowed_width = f"0 < width < barrel_diameter_mm = {format_value(diameter_mm)} mm"
    if isinstance(width_mm, bool) or not isinstance(width_mm, numbers.Real):
        raise GeometryError([not_a_number("width_mm", width_mm, allowed_width)])
    width = float(width_mm)
    if not math.isfinite(width):
        raise GeometryError([not_a_number("width_mm", width_mm, allowed_width)])
    if not 0.0 < width < diameter_mm:
        error = out_of_range("width_mm", width_mm, allowed_width)
        rule = RuleText.BOARD_WIDER_THAN_BARREL
        raise GeometryError([worded(error, rule, width_mm, diameter_mm)])
    tilt = math.degrees(math.asin(width / diameter_mm))
    if not limits.min_tilt_deg <= tilt <= limits.max_tilt_deg:
        low, high = format_value(limits.min_tilt_deg), format_value(limits.max_tilt_deg)
        allowed = f"{low} <= tilt <= {high} deg"
        note = (
            f"computed as asin(width_mm / barrel_diameter_mm) = asin({format_value(width)} / "
            f"{format_value(diameter_mm)})"
        )
        error = out_of_range("tilt_deg", round(tilt, 3), allowed, note)
        rule = RuleText.BARREL_TILT
        shown = (width, round(tilt, 3), limits.min_tilt_deg, limits.max_tilt_deg)
        raise GeometryError([worded(error, rule, *shown)])
    return tilt


def barrel_width_errors(
    diameter_mm: float, width_ratio: float, limits: StaveLimits
) -> list[FieldError]:
    """Why no board of a recipe can be bevelled for this barrel (empty: some board can).

    Boards range from ``min_head_width / k`` (narrower ones give a head under the minimum) to
    the maximum width; the computed tilt asin(W / Db) must stay within the tilt limits.
    """
    width_low = max(
        limits.min_head_width_mm / width_ratio,
        diameter_mm * math.sin(math.radians(limits.min_tilt_deg)),
    )
    width_high = min(limits.max_width_mm, diameter_mm * math.sin(math.radians(limits.max_tilt_deg)))
    if width_low <= width_high:
        return []
    allowed = (
        f"a belly diameter for which some board of "
        f"{format_value(round(limits.min_head_width_mm / width_ratio, 1))}.."
        f"{format_value(limits.max_width_mm)} mm gets a tilt of "
        f"{format_value(limits.min_tilt_deg)}..{format_value(limits.max_tilt_deg)} deg"
    )
    message = (
        f"barrel_diameter_mm = {format_value(diameter_mm)} fits no board of this recipe: "
        f"allowed {allowed}"
    )
    error = FieldError("barrel_diameter_mm", diameter_mm, allowed, message)
    rule = RuleText.BARREL_FITS_NO_BOARD
    widths = (round(limits.min_head_width_mm / width_ratio, 1), limits.max_width_mm)
    tilts = (limits.min_tilt_deg, limits.max_tilt_deg)
    return [worded(error, rule, diameter_mm, *widths, *tilts)]


@dataclass(frozen=True)
class RoundBarrelTilt:
    """Each board bevelled for the round barrel of belly diameter ``diameter_mm`` (None: the
    recipe has none, and every width is refused naming the field)."""

    diameter_mm: float | None

    def tilts_for_width(self, width_mm: float, limits: StaveLimits) -> SideTilts:
        return SideTilts.both(barrel_tilt_deg(width_mm, self.diameter_mm, limits))
