"""A recipe's program or drawing for another controller: the one place that turns a recipe,
a width (or none: parametric) and the machine's parameters into the exported file.

Why here and not in the writers: the tool path must be the one the machine cuts, from the
same composition (tilt for the width, validation, profile, tool path, travel check), and a
width the machine would refuse must be refused here with the same reasons. The writers in
`app.programs` only translate. Shared by `stave gcode` and the Recipes screen.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from datetime import UTC, datetime
from enum import Enum

from app import __version__
from app.data.recipe import Recipe
from app.geometry.barrel import RoundBarrelTilt
from app.geometry.bevel import FixedTilt
from app.geometry.errors import FieldError, GeometryError
from app.geometry.limits import StaveLimits
from app.geometry.profile_kinds import ProfileKind
from app.geometry.stave_cut import cut_stave, toolpath_params
from app.geometry.toolpath import ToolPath
from app.machine.preview import nominal_width_mm
from app.programs import dxf, linuxcnc, sinumerik
from app.programs.header import ProgramInfo
from app.programs.moves import stave_moves
from app.programs.parametric import ParametricStave, write_parametric_program

DEFAULT_SPINDLE_RPM = 18000.0
"""Written as the S word; the jointer itself only switches its router's contactor."""
WIDTH_STEP_MM = 0.001
"""The parametric program's width range is exact to this (rounded inwards)."""
_SEARCH_GRID_MM = 5.0
PARAMETRIC_KINDS = (ProfileKind.LINE_ARC_LINE, ProfileKind.SINGLE_ARC)
"""The kinds the parametric program computes itself: line-arc-line, and the single arc as
line-arc-line with no straight sections (length ratio 0)."""


class Dialect(Enum):
    LINUXCNC = "linuxcnc"
    SINUMERIK = "sinumerik"


class ExportFormat(Enum):
    """What the Recipes screen offers to write: a program for one width, the parametric
    program, or the drawing."""

    LINUXCNC = "linuxcnc"
    LINUXCNC_PARAMETRIC = "linuxcnc_parametric"
    SINUMERIK = "sinumerik"
    DXF = "dxf"

    @property
    def suffix(self) -> str:
        return {"sinumerik": ".mpf", "dxf": ".dxf"}.get(self.value, ".ngc")

    @property
    def parametric(self) -> bool:
        return self is ExportFormat.LINUXCNC_PARAMETRIC


@dataclass(frozen=True)
class ExportOptions:
    dialect: Dialect = Dialect.LINUXCNC
    chord_error_mm: float | None = None
    spindle_rpm: float = DEFAULT_SPINDLE_RPM
    spindle_runup_s: float = 2.0


def stave_toolpath(
    recipe: Recipe, width_mm: float, params: Mapping[str, float], limits: StaveLimits
) -> ToolPath:
    """The tool path the machine cuts for this board (the machine's own composition,
    ``cut_stave``); StaveCutRefused with every reason if the machine would refuse it."""
    return cut_stave(recipe.stave, width_mm, params, limits).toolpath


def _accepts(accepts: Callable[[float], bool], width_mm: float) -> bool:
    try:
        return accepts(width_mm)
    except (GeometryError, ValueError, ArithmeticError):
        return False


def accepted_width_range(
    accepts: Callable[[float], bool], seed_mm: float, max_width_mm: float
) -> tuple[float, float] | None:
    """The widths around ``seed_mm`` that ``accepts`` takes, to WIDTH_STEP_MM, rounded inwards.

    Why a search and not a formula: the bounds come from several rules (head width, barrel
    diameter, tilt limits, axis travel, home position) and the machine's own function is the
    only complete statement of them; the accepted widths form one interval (every rule bounds
    the width from one side). None if no width from 1 mm to ``max_width_mm`` is accepted."""
    if not _accepts(accepts, seed_mm):
        grid = [_SEARCH_GRID_MM * n for n in range(1, int(max_width_mm / _SEARCH_GRID_MM) + 1)]
        inside = [w for w in grid if _accepts(accepts, w)]
        if not inside:
            return None
        seed_mm = inside[len(inside) // 2]

    def edge(outside: float) -> float:
        inner, outer = seed_mm, outside
        if _accepts(accepts, outer):
            return outer
        while abs(outer - inner) > WIDTH_STEP_MM / 10.0:
            middle = 0.5 * (inner + outer)
            if _accepts(accepts, middle):
                inner = middle
            else:
                outer = middle
        return inner

    def on_step(width_mm: float, inward: float) -> float:
        nearest = round(round(width_mm / WIDTH_STEP_MM) * WIDTH_STEP_MM, 3)
        return nearest if _accepts(accepts, nearest) else round(nearest + inward, 3)

    return (
        on_step(edge(WIDTH_STEP_MM), WIDTH_STEP_MM),
        on_step(edge(max_width_mm), -WIDTH_STEP_MM),
    )


def parametric_stave(
    recipe: Recipe, params: Mapping[str, float], limits: StaveLimits
) -> ParametricStave:
    """The recipe as the parametric program's constants; GeometryError if no width fits."""

    if recipe.profile.kind not in PARAMETRIC_KINDS:
        kinds = " or ".join(kind.value for kind in PARAMETRIC_KINDS)
        allowed = f"{kinds} (the program solves its cubic itself)"
        message = (
            f"profile_kind = {recipe.profile.kind.value!r} has no parametric program: "
            f"allowed {allowed}; export a program for one width instead"
        )
        raise GeometryError(
            [FieldError("profile_kind", recipe.profile.kind.value, allowed, message)]
        )

    def accepts(width_mm: float) -> bool:
        stave_toolpath(recipe, width_mm, params, limits)
        return True

    seed = nominal_width_mm(recipe, limits, None)
    found = accepted_width_range(accepts, seed, limits.max_width_mm)
    if found is None:
        allowed = f"some width up to {limits.max_width_mm:g} mm that the machine can cut"
        message = f"recipe {recipe.name!r} accepts no board width: allowed {allowed}"
        raise GeometryError([FieldError("width_mm", None, allowed, message)])
    low, high = found
    default = seed if low <= seed <= high else round(0.5 * (low + high))
    default = min(max(default, low), high)
    cut = cut_stave(recipe.stave, default, params, limits)
    rule = recipe.tilt_rule
    if isinstance(rule, RoundBarrelTilt):
        barrel_mm = rule.diameter_mm
    elif isinstance(rule, FixedTilt):
        barrel_mm = None
    else:
        allowed = "a fixed tilt or a round barrel's tilt"
        message = (
            f"recipe {recipe.name!r}: its tilt rule has no parametric program: allowed {allowed}"
        )
        raise GeometryError([FieldError("barrel_type", recipe.barrel_type.value, allowed, message)])
    return ParametricStave(
        length_mm=recipe.length_mm,
        length_ratio=recipe.length_ratio.value if recipe.profile.spec.uses_length_ratio() else 0.0,
        width_ratio=recipe.width_ratio.value,
        tilt_a_deg=cut.tilts.a_deg,
        tilt_b_deg=cut.tilts.b_deg,
        barrel_diameter_mm=barrel_mm,
        width_min_mm=low,
        width_max_mm=high,
        default_width_mm=default,
        machine=toolpath_params(params, cut.tilts),
    )


def program_info(
    recipe: Recipe,
    width_mm: float | None,
    params: Mapping[str, float],
    options: ExportOptions,
    written_at: datetime | None = None,
) -> ProgramInfo:
    return ProgramInfo(
        recipe_name=recipe.name,
        width_mm=width_mm,
        written_at=written_at or datetime.now(UTC),
        product_version=__version__,
        feed_mm_min=float(params["xy_speed_mm_s"]) * 60.0,
        spindle_rpm=options.spindle_rpm,
        spindle_runup_s=options.spindle_runup_s,
        chord_error_mm=options.chord_error_mm,
    )


def export_program(
    recipe: Recipe,
    width_mm: float | None,
    params: Mapping[str, float],
    limits: StaveLimits,
    options: ExportOptions,
    written_at: datetime | None = None,
) -> str:
    """The program text: fixed for ``width_mm``, parametric (LinuxCNC only) for None.

    Raises GeometryError for a board the machine refuses, ValueError for options outside
    their range (a chord error, the parametric program in another dialect)."""
    info = program_info(recipe, width_mm, params, options, written_at)
    if width_mm is None:
        if options.dialect is not Dialect.LINUXCNC:
            raise ValueError(
                f"dialect = {options.dialect.value!r} has no parametric program: "
                "allowed 'linuxcnc' with parametric"
            )
        if options.chord_error_mm is not None:
            raise ValueError("chords are not allowed with parametric: its arcs are G2 moves")
        return write_parametric_program(parametric_stave(recipe, params, limits), info)
    moves = stave_moves(stave_toolpath(recipe, width_mm, params, limits), options.chord_error_mm)
    if options.dialect is Dialect.SINUMERIK:
        return sinumerik.write_program(moves, info)
    return linuxcnc.write_program(moves, info)


def export_drawing(
    recipe: Recipe,
    width_mm: float,
    params: Mapping[str, float],
    limits: StaveLimits,
    written_at: datetime | None = None,
) -> str:
    """The DXF drawing (text) of the stave for ``width_mm``."""
    toolpath = stave_toolpath(recipe, width_mm, params, limits)
    info = program_info(recipe, width_mm, params, ExportOptions(), written_at)
    return dxf.drawing_text(toolpath, info)


def export_text(
    recipe: Recipe,
    export_format: ExportFormat,
    width_mm: float,
    params: Mapping[str, float],
    limits: StaveLimits,
) -> str:
    """The file's content for one of the screen's formats (the width is ignored by the
    parametric program); GeometryError for a board the machine refuses."""
    if export_format is ExportFormat.DXF:
        return export_drawing(recipe, width_mm, params, limits)
    dialect = Dialect.SINUMERIK if export_format is ExportFormat.SINUMERIK else Dialect.LINUXCNC
    width = None if export_format.parametric else width_mm
    return export_program(recipe, width, params, limits, ExportOptions(dialect=dialect))


def export_file_name(recipe: Recipe, export_format: ExportFormat, width_mm: float) -> str:
    """A file name that says what the file holds and that every file system takes."""
    stem = "".join(ch if ch.isascii() and ch.isalnum() else "-" for ch in recipe.name)
    stem = "-".join(part for part in stem.split("-") if part) or "stave"
    board = "parametric" if export_format.parametric else f"{width_mm:g}mm"
    return f"{stem}-{board}{export_format.suffix}"
