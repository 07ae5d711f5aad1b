"""Recipe to tool path, composed once: measured width -> bevel -> validation -> profile ->
tool path -> travel check.

Why one function: the automatic cycle, the plan preview, the recipe screen's preview and
`stave solve` must agree on whether a board can be cut and how. Each of them used to chain the
steps itself, and a copy that skipped the travel check showed staves the machine then refused.
Pure computation (no devices, no time): motion planning is the machine's, on top of this.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, replace
from enum import Enum

from app.geometry.bevel import SideTilts, TiltRule
from app.geometry.curved_profile import ProfileSpec, SideProfile
from app.geometry.errors import (
    FieldError,
    GeometryError,
    format_value,
    not_a_number,
    out_of_range,
    worded,
)
from app.geometry.limits import StaveLimits, validate_stave
from app.geometry.rule_texts import RuleText
from app.geometry.toolpath import ToolPath, ToolPathParams, build_toolpath
from app.geometry.travel import check_toolpath_travel

LINE_ARC_LINE = ProfileSpec()
"""The side as it always was: two straight sections and an arc."""


MAX_DEPTH_PARAMETER = "max_depth_of_cut_mm"
"""The system parameter: the most material the router takes off one side in one pass."""


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
    target_width_mm: float | None = None
    """Cut the stave to this belly width, centred on a board at least that wide (None: the
    board's own width). The closing stave of a barrel and staves made to stock use it."""


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
    """A board that can be cut: its width, bevels, solved profile and checked tool path.

    ``width_mm`` is the stave's belly width after the cut, ``board_width_mm`` the board's
    measured one (wider when the stave is cut to a target width)."""

    width_mm: float
    tilts: SideTilts
    profile: SideProfile
    toolpath: ToolPath
    board_width_mm: float | None = None

    @property
    def passes(self) -> int:
        """Passes per side (roughing and finishing) the depth of cut needed."""
        return self.toolpath.params.passes

    @property
    def depth_per_side_mm(self) -> float:
        """The most material taken off one side: at the heads, (board - head width) / 2."""
        board = self.width_mm if self.board_width_mm is None else self.board_width_mm
        return (board - self.profile.W1) / 2.0


def toolpath_params(
    params: Mapping[str, float], tilts: SideTilts, board_width_mm: float | None = None
) -> ToolPathParams:
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
    return replace(
        ToolPathParams.from_parameters(params, tilts.a_deg, b_deg), board_width_mm=board_width_mm
    )


def cut_stave(
    stave: StaveSpec, width_mm: float, params: Mapping[str, float], limits: StaveLimits
) -> StaveCut:
    """Compose the cut of one board ``width_mm`` wide; raises StaveCutRefused (every reason,
    one line each, naming the field, the value and what is allowed), never anything else."""
    board_mm = width_mm
    if stave.target_width_mm is not None:
        target_errors = _target_errors(width_mm, stave.target_width_mm, limits)
        if target_errors:
            raise StaveCutRefused(CutStage.STAVE, target_errors)
        width_mm = stave.target_width_mm
    try:
        tilts = stave.tilt.tilts_for_width(width_mm, limits)
    except GeometryError as exc:
        raise StaveCutRefused(CutStage.TILT, exc.errors) from exc
    errors: list[FieldError] = []
    length_ratio = stave.length_ratio if stave.profile.uses_length_ratio() else 0.0
    sides = (("", tilts.a_deg),) if tilts.symmetric else (("A", tilts.a_deg), ("B", tilts.b_deg))
    for side, tilt_deg in sides:
        errors.extend(
            error
            for error in (
                side_tilt_error(found, side)
                for found in validate_stave(
                    stave.length_mm,
                    width_mm,
                    length_ratio,
                    stave.width_ratio,
                    limits,
                    thickness_mm=stave.thickness_mm,
                    tilt_deg=tilt_deg,
                )
            )
            if error not in errors
        )
    if errors:
        raise StaveCutRefused(CutStage.STAVE, errors, tilts)
    try:
        profile = stave.profile.solve(
            stave.length_mm, width_mm, stave.width_ratio, stave.length_ratio, limits
        )
        board = None if board_mm == width_mm else float(board_mm)
        allowances = roughing_allowances_mm(
            (float(board_mm) - profile.W1) / 2.0, params.get(MAX_DEPTH_PARAMETER)
        )
        path_params = replace(
            toolpath_params(params, tilts, board), roughing_allowances_mm=allowances
        )
        toolpath = build_toolpath(profile, path_params)
    except GeometryError as exc:
        raise StaveCutRefused(CutStage.TOOLPATH, exc.errors, tilts) from exc
    travel = check_toolpath_travel(toolpath, limits)
    if travel:
        raise StaveCutRefused(CutStage.TRAVEL, travel, tilts)
    return StaveCut(float(width_mm), tilts, profile, toolpath, float(board_mm))


SIDE_TILT_FIELDS = {"A": "tilt_a_deg", "B": "tilt_b_deg"}
"""The field of each side's bevel when the two sides differ."""


def side_tilt_error(error: FieldError, side: str) -> FieldError:
    """``error`` about the tilt said of one side ("tilt of side B") when the sides differ: a
    refusal naming only ``tilt_deg`` does not say which of the two bevels is wrong."""
    if not side or error.field != "tilt_deg":
        return error
    words = f"tilt of side {side}"
    message = error.message.replace("tilt_deg", words, 1)
    return replace(error, field=SIDE_TILT_FIELDS[side], message=message)


def roughing_allowances_mm(depth_mm: float, max_depth_mm: float | None) -> tuple[float, ...]:
    """What each roughing pass leaves on the edge when ``depth_mm`` is more than the router
    takes in one pass: n = ceil(depth / max) equal passes, the finishing one last.

    Why equal passes: each then takes at most the maximum, and the finishing pass takes as
    little as the others, so the finished edge is not left by a heavy cut."""
    if max_depth_mm is None or not max_depth_mm > 0 or depth_mm <= max_depth_mm:
        return ()
    passes = math.ceil(depth_mm / max_depth_mm - 1e-9)
    return tuple(depth_mm * (passes - number) / passes for number in range(1, passes))


def _target_errors(board_mm: object, target_mm: float, limits: StaveLimits) -> list[FieldError]:
    """A board narrower than the stave it should become cannot be cut to it."""
    allowed = (
        f"target_width_mm = {format_value(target_mm)} <= width <= "
        f"{format_value(limits.max_width_mm)} mm"
    )
    if isinstance(board_mm, bool) or not isinstance(board_mm, int | float):
        return [not_a_number("width_mm", board_mm, allowed)]
    if not board_mm >= target_mm:  # NaN too
        note = "the board is too narrow for the stave it should become"
        error = out_of_range("width_mm", board_mm, allowed, note)
        return [worded(error, RuleText.BOARD_BELOW_TARGET, board_mm, target_mm)]
    if board_mm > limits.max_width_mm:
        error = out_of_range("width_mm", board_mm, allowed)
        return [worded(error, RuleText.BOARD_WIDTH, board_mm, limits.max_width_mm)]
    return []
