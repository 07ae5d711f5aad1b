"""The catalogue of system parameters, as data.

Every parameter the System, Manual and production screens show is one row here: its unit, the
screen group it belongs to, the range a value must be in, the factory default, what it means and
the least role allowed to change it. The database stores only name -> value (plus the change
log); everything else comes from this table, so a screen can be generated from it and a value
is validated the same way wherever it is entered. Ranges are sanity bounds for the machine
class (a 3.5 m stave, a table a metre wide), not the axes' soft limits, which are parameters
themselves.

Some parameters only make sense together (the lead-in must be longer than the cutter's radius,
a soft limit's minimum below its maximum); :func:`check_parameter_set` checks those rules on the
whole set, with the proposed change applied, before anything is stored.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping
from dataclasses import dataclass

from app.data.users import Role
from app.geometry.errors import FieldError, format_value, not_a_number, out_of_range


@dataclass(frozen=True)
class ParameterSpec:
    """One system parameter: its unit, range, default, meaning and who may change it."""

    name: str
    unit: str
    group: str
    minimum: float
    maximum: float
    default: float
    description: str
    required_role: Role
    integer: bool = False

    @property
    def allowed(self) -> str:
        """The allowed range as the messages and the screens show it."""
        unit = f" {self.unit}" if self.unit else ""
        whole = " (whole number)" if self.integer else ""
        return (
            f"{format_value(float(self.minimum))} <= {self.name} <= "
            f"{format_value(float(self.maximum))}{unit}{whole}"
        )


CONFIGURATION_GROUPS: frozenset[str] = frozenset({"limits"})
"""Groups whose values the machine takes from its configuration (the axis travel it enforces,
``[axes.*]`` in the machine's TOML file), not from these parameters: the System screen shows
the configuration's values there, read-only. The stored parameters of these groups are kept
for older databases and backups only."""

UNUSED_PARAMETERS: frozenset[str] = frozenset({"solver_tolerance_mm"})
"""Parameters the machine does not read (the stave solver decides its root exactly): kept in
the catalogue for older databases and backups, not shown on the System screen."""

_T = Role.TECHNICIAN
_S = Role.SERVICE
_O = Role.OPERATOR

PARAMETERS: tuple[ParameterSpec, ...] = (
    # --- System screen: home position -------------------------------------------------------
    ParameterSpec("home_x_mm", "mm", "home", -500, 6000, 0, "Home position of X", _S),
    ParameterSpec("home_y_mm", "mm", "home", -1000, 1000, 0, "Home position of Y", _S),
    ParameterSpec("home_z_deg", "deg", "home", -60, 60, 0, "Home tilt of the router (Z)", _S),
    # --- System screen: tool and machine ----------------------------------------------------
    ParameterSpec("tool_radius_mm", "mm", "tool", 1, 150, 25, "Radius of the router cutter", _T),
    ParameterSpec(
        "max_depth_of_cut_mm",
        "mm",
        "tool",
        1,
        200,
        40,
        "Most material the router takes off one side in one pass (more: roughing passes first)",
        _T,
    ),
    ParameterSpec(
        "machine_height_mm",
        "mm",
        "tool",
        0,
        1000,
        250,
        "Height of the tilt pivot above the table (Hm)",
        _S,
    ),
    ParameterSpec(
        "solver_tolerance_mm",
        "mm",
        "tool",
        1e-9,
        0.01,
        1e-6,
        "Tolerance of the stave-side solver (root of the cubic in D)",
        _S,
    ),
    # --- System screen: start position P0 ---------------------------------------------------
    ParameterSpec(
        "start_x_mm", "mm", "start", -500, 6000, 300, "P0: machine X of the stave's left end", _S
    ),
    ParameterSpec(
        "start_y_mm", "mm", "start", -1000, 1000, 400, "P0: machine Y of the table centre line", _S
    ),
    # --- System screen: automatic motion ----------------------------------------------------
    ParameterSpec("xy_speed_mm_s", "mm/s", "motion", 1, 500, 100, "X-Y cutting feed", _T),
    ParameterSpec(
        "xy_rapid_speed_mm_s", "mm/s", "motion", 1, 2000, 300, "X-Y speed of non-cutting moves", _T
    ),
    ParameterSpec("xy_accel_mm_s2", "mm/s²", "motion", 1, 10000, 1000, "X-Y acceleration", _S),
    ParameterSpec("xy_jerk_mm_s3", "mm/s³", "motion", 10, 1e6, 20000, "X-Y jerk limit", _S),
    ParameterSpec("z_speed_deg_s", "deg/s", "motion", 0.1, 360, 30, "Tilt (Z) speed", _T),
    ParameterSpec("z_accel_deg_s2", "deg/s²", "motion", 1, 5000, 200, "Tilt (Z) acceleration", _S),
    ParameterSpec("z_jerk_deg_s3", "deg/s³", "motion", 10, 1e6, 2000, "Tilt (Z) jerk limit", _S),
    # --- tool path ---------------------------------------------------------------------------
    ParameterSpec(
        "lead_mm",
        "mm",
        "path",
        1,
        500,
        60,
        "Lead-in before x = 0 and lead-out after x = L (longer than the tool radius)",
        _T,
    ),
    ParameterSpec(
        "tilt_clearance_mm",
        "mm",
        "path",
        0,
        1000,
        100,
        "Distance beyond the board's right end where the tilt changes sides",
        _T,
    ),
    # --- soft limits of the axes -------------------------------------------------------------
    ParameterSpec("x_min_mm", "mm", "limits", -500, 6000, 0, "Soft limit: lowest X", _S),
    ParameterSpec("x_max_mm", "mm", "limits", -500, 6000, 4200, "Soft limit: highest X", _S),
    ParameterSpec("y_min_mm", "mm", "limits", -1000, 1000, 0, "Soft limit: lowest Y", _S),
    ParameterSpec("y_max_mm", "mm", "limits", -1000, 1000, 800, "Soft limit: highest Y", _S),
    ParameterSpec("z_min_deg", "deg", "limits", -60, 60, -30, "Soft limit: lowest tilt", _S),
    ParameterSpec("z_max_deg", "deg", "limits", -60, 60, 30, "Soft limit: highest tilt", _S),
    # --- Manual screen: jogging (does not change the automatic values) ----------------------
    ParameterSpec("jog_xy_speed_mm_s", "mm/s", "jog", 0.1, 500, 20, "X-Y jog speed", _O),
    ParameterSpec("jog_xy_accel_mm_s2", "mm/s²", "jog", 1, 5000, 200, "X-Y jog acceleration", _O),
    ParameterSpec("jog_z_speed_deg_s", "deg/s", "jog", 0.1, 90, 5, "Tilt (Z) jog speed", _O),
    ParameterSpec(
        "jog_z_accel_deg_s2", "deg/s²", "jog", 1, 1000, 50, "Tilt (Z) jog acceleration", _O
    ),
    # --- production shifts (piece counts per shift, production exports) ---------------------
    ParameterSpec(
        "shift_first_start_h",
        "h",
        "production",
        0,
        23.99,
        6,
        "Start of the first shift of the day, hours after midnight (6.5 = 06:30)",
        _T,
    ),
    ParameterSpec("shift_length_h", "h", "production", 1, 24, 8, "Length of one shift", _T),
    ParameterSpec(
        "shifts_per_day", "", "production", 1, 6, 3, "Number of shifts per day", _T, integer=True
    ),
)

PARAMETER_BY_NAME: Mapping[str, ParameterSpec] = {spec.name: spec for spec in PARAMETERS}

DEFAULT_PARAMETERS: Mapping[str, float] = {spec.name: float(spec.default) for spec in PARAMETERS}

# (lower, upper): the first must stay strictly below the second.
_ORDERED_PAIRS: tuple[tuple[str, str], ...] = (
    ("x_min_mm", "x_max_mm"),
    ("y_min_mm", "y_max_mm"),
    ("z_min_deg", "z_max_deg"),
)


def _unknown_message(name: object) -> str:
    close = difflib.get_close_matches(str(name), PARAMETER_BY_NAME, n=3)
    hint = f"; did you mean {', '.join(close)}?" if close else ""
    return f"parameter {str(name)!r} is unknown{hint}"


def parameter_spec(name: str) -> ParameterSpec:
    """Look a parameter up; an unknown name raises KeyError with the closest known names."""
    try:
        return PARAMETER_BY_NAME[name]
    except KeyError:
        raise KeyError(_unknown_message(name)) from None


def unknown_parameter(name: object, value: object) -> FieldError:
    """The error for a name that is not in the catalogue (with the closest known names)."""
    return FieldError(str(name), value, "a parameter of the catalogue", _unknown_message(name))


def check_parameter_value(spec: ParameterSpec, value: object) -> FieldError | None:
    """Check one value against its catalogue row; return the error or None."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return not_a_number(spec.name, value, spec.allowed)
    number = float(value)
    if not math.isfinite(number):
        return not_a_number(spec.name, value, spec.allowed)
    if spec.integer and not number.is_integer():
        return out_of_range(spec.name, value, spec.allowed, "must be a whole number")
    if not spec.minimum <= number <= spec.maximum:
        return out_of_range(spec.name, value, spec.allowed)
    return None


def check_parameter_set(values: Mapping[str, float]) -> list[FieldError]:
    """Rules between parameters, checked on a complete set (the stored one with changes applied)."""
    errors: list[FieldError] = []
    for lower, upper in _ORDERED_PAIRS:
        if values[lower] >= values[upper]:
            allowed = f"{upper} > {lower} = {format_value(values[lower])}"
            errors.append(out_of_range(upper, values[upper], allowed))
    if values["lead_mm"] <= values["tool_radius_mm"]:
        allowed = f"lead_mm > tool_radius_mm = {format_value(values['tool_radius_mm'])} mm"
        note = "the cutter must enter and leave the cut clear of the board"
        errors.append(out_of_range("lead_mm", values["lead_mm"], allowed, note))
    if values["shift_length_h"] * values["shifts_per_day"] > 24:
        most = 24 / values["shifts_per_day"]
        allowed = f"shift_length_h <= 24 h / shifts_per_day = {format_value(most)} h"
        note = "the shifts of one day must fit in 24 h"
        errors.append(out_of_range("shift_length_h", values["shift_length_h"], allowed, note))
    return errors
