"""Pure geometry of the stave jointer: profile solver, limits, tool path (no Qt, no I/O).

Modules: `ratio` (exact fractions as coopers give them), `errors` (typed field errors),
`limits` (machine limits and validation), `profile` (the cubic and the side profile),
`segments` / `polyline` (exact lines and arcs, chord splitting), `toolpath` (machine
coordinates of both sides), `compare` (edge error of a path, for the benchmark). Its command
line, `stave solve`, lives in `app.cli.solve`.
"""

from app.geometry.errors import FieldError, GeometryError
from app.geometry.limits import (
    StaveLimits,
    check_toolpath_travel,
    validate_recipe_fields,
    validate_stave,
)
from app.geometry.profile import StaveProfile, solve_cubic_d, solve_profile
from app.geometry.ratio import Ratio
from app.geometry.segments import ArcSegment, LineSegment, Segment
from app.geometry.toolpath import (
    ToolPath,
    ToolPathParams,
    build_original_toolpath,
    build_toolpath,
)

__all__ = [
    "ArcSegment",
    "FieldError",
    "GeometryError",
    "LineSegment",
    "Ratio",
    "Segment",
    "StaveLimits",
    "StaveProfile",
    "ToolPath",
    "ToolPathParams",
    "build_original_toolpath",
    "build_toolpath",
    "check_toolpath_travel",
    "solve_cubic_d",
    "solve_profile",
    "validate_recipe_fields",
    "validate_stave",
]
