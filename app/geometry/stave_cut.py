"""Recipe to tool path, composed once: measured width -> bevel -> validation -> profile ->
tool path -> travel check.

Why one function: the automatic cycle, the plan preview, the recipe screen's preview and
`stave solve` must agree on whether a board can be cut and how. Each of them used to chain the
steps itself, and a copy that skipped the travel check showed staves the machine then refused.
Pure computation (no devices, no time): motion planning is the machine's, on top of this.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from enum import Enum

from app.geometry.bevel import SideTilts, TiltRule
from app.geometry.curved_profile import ProfileSpec, SideProfile
from app.geometry.errors import FieldError, GeometryError, format_value
from app.geometry.limits import StaveLimits, validate_stave
from app.geometry.toolpath import ToolPath, ToolPathParams, build_toolpath
from app.geometry.travel import check_toolpath_travel

LINE_ARC_LINE = ProfileSpec()
"""The side as it always was: two straight sections and an arc."""


@dataclass(frozen=True)
class StaveSpec:
    """What the geometry needs of a recipe: the stave's dimensions, its two ratios as decimals
    the rule that chooses the bevel from the measured width (``thickness_mm`` None: not
    known, the bevels are then not checked against it) and the side's shape (line-arc-line
    unless the recipe chose another kind; only line-arc-line uses ``length_ratio``)."""

    length_mm: float
    thickness_mm: float | None
    length_ratio: float
    width_ratio: float
    tilt: TiltRule
    profile: ProfileSpec = LINE_ARC_LINE


class CutStage(Enum):
    """Where composing the cut stopped; the machine raises a different alarm for TRAVEL (the
    stave is valid but this machine cannot reach it) than for the others (the board or the
    recipe is wrong)."""

    TILT = "tilt"
    STAVE = "stave"
    TOOLPATH = "toolpath"
    TRAVEL = "travel"


class StaveCutRefused(GeometryError):
    """The board cannot be cut; ``stage`` says where that was found, ``errors`` why, and
    ``tilts`` the bevels if they were found before the refusal (None at stage TILT)."""

    def __init__(
        self, stage: CutStage, errors: Iterable[FieldError], tilts: SideTilts | None = None
    ) -> None:
        super().__init__(errors)
        self.stage = stage
        self.tilts = tilts

    def __reduce__(self) -> tuple[object, ...]:
        return (StaveCutRefused, (self.stage, self.errors, self.tilts))


@dataclass(frozen=True)
class StaveCut:
    """A board that can be cut: its width, bevels, solved profile and checked tool path."""

    width_mm: float
    tilts: SideTilts
    profile: SideProfile
    toolpath: ToolPath


def toolpath_params(params: Mapping[str, float], tilts: SideTilts) -> ToolPathParams:
    """The tool path's parameters from the system parameters and the bevels.

    Raises GeometryError for a missing or non-numeric parameter. Side A is cut at +a_deg,
    side B at -b_deg."""
    errors: list[FieldError] = []
    for name in ToolPathParams.system_parameter_names():
        value = params.get(name)
        if isinstance(value, bool) or not isinstance(value, int | float):
            message = f"{name} = {format_value(value)} is not a number: allowed a number"
            errors.append(FieldError(name, value, "a number", message))
    if errors:
        raise GeometryError(errors)
    b_deg = None if tilts.symmetric else tilts.b_deg
    return ToolPathParams.from_parameters(params, tilts.a_deg, b_deg)


def cut_stave(
    stave: StaveSpec, width_mm: float, params: Mapping[str, float], limits: StaveLimits
) -> StaveCut:
    """Compose the cut of one board ``width_mm`` wide; raises StaveCutRefused (every reason,
    one line each, naming the field, the value and what is allowed), never anything else."""
    try:
        tilts = stave.tilt.tilts_for_width(width_mm, limits)
    except GeometryError as exc:
        raise StaveCutRefused(CutStage.TILT, exc.errors) from exc
    errors: list[FieldError] = []
    length_ratio = stave.length_ratio if stave.profile.uses_length_ratio() else 0.0
    for tilt_deg in dict.fromkeys((tilts.a_deg, tilts.b_deg)):
        errors.extend(
            error
            for error in validate_stave(
                stave.length_mm,
                width_mm,
                length_ratio,
                stave.width_ratio,
                limits,
                thickness_mm=stave.thickness_mm,
                tilt_deg=tilt_deg,
            )
            if error not in errors
        )
    if errors:
        raise StaveCutRefused(CutStage.STAVE, errors, tilts)
    try:
        profile = stave.profile.solve(
            stave.length_mm, width_mm, stave.width_ratio, stave.length_ratio, limits
        )
        toolpath = build_toolpath(profile, toolpath_params(params, tilts))
    except GeometryError as exc:
        raise StaveCutRefused(CutStage.TOOLPATH, exc.errors, tilts) from exc
    travel = check_toolpath_travel(toolpath, limits)
    if travel:
        raise StaveCutRefused(CutStage.TRAVEL, travel, tilts)
    return StaveCut(float(width_mm), tilts, profile, toolpath)
