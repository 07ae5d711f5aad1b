"""Pure geometry of the stave jointer: profile solver, limits, tool path (no Qt, no I/O).

Modules: `ratio` (exact fractions as coopers give them), `errors` (typed field errors), `limits`
(machine limits and validation), `bevel` / `barrel` (the bevel of each side, fixed or from the
barrel), `barrel_section` (staves placed around a round or oval barrel, their two bevels, the
closing stave), `profile` (the cubic and the side profile), `segments` / `polyline` (exact lines and
arcs, chord splitting), `toolpath` (machine coordinates of both sides), `travel` (the tool path
against the axis travel), `stave_cut` (all of these composed: recipe and measured width to a checked
tool path), `outline` (what a plan view draws), `compare` (edge error of a path, for the benchmark),
`profile_kinds` / `curved_profile` / `biarc` / `nurbs` / `drawn_profile` (side profiles of any
shape: curve families and drawings, fitted as tangent lines and arcs). Its command line, `stave
solve`, lives in `app.cli.solve`.
"""

from app.geometry.bevel import FixedTilt, SideTilts, TiltRule
from app.geometry.errors import FieldError, GeometryError
from app.geometry.limits import StaveLimits, validate_recipe_fields, validate_stave
from app.geometry.profile import StaveProfile, solve_cubic_d, solve_profile
from app.geometry.ratio import Ratio
from app.geometry.segments import ArcSegment, LineSegment, Segment
from app.geometry.stave_cut import CutStage, StaveCut, StaveCutRefused, StaveSpec, cut_stave
from app.geometry.toolpath import (
    ToolPath,
    ToolPathParams,
    build_original_toolpath,
    build_toolpath,
)
from app.geometry.travel import check_toolpath_travel

__all__ = [
    "ArcSegment",
    "CutStage",
    "FieldError",
    "FixedTilt",
    "GeometryError",
    "LineSegment",
    "Ratio",
    "Segment",
    "SideTilts",
    "StaveCut",
    "StaveCutRefused",
    "StaveLimits",
    "StaveProfile",
    "StaveSpec",
    "TiltRule",
    "ToolPath",
    "ToolPathParams",
    "build_original_toolpath",
    "build_toolpath",
    "check_toolpath_travel",
    "cut_stave",
    "solve_cubic_d",
    "solve_profile",
    "validate_recipe_fields",
    "validate_stave",
]
