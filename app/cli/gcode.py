"""``stave gcode``: the program of one stave (or of every board of a recipe) for another control.

    stave gcode (--recipe NAME | --recipe-file FILE) (--width MM | --parametric)
                [--dialect linuxcnc|sinumerik] [--chords MM] [--dxf] [--spindle-rpm RPM]
                [--config FILE] [--db FILE] [-o FILE]

The program is written to stdout unless ``-o FILE``; ``--dxf`` writes the drawing instead of a
program. The moves are the tool path the machine itself cuts, computed by the same function
from the recipe, the width and the parameters: the database's (``--db``, or the default
database with ``--recipe``) or, for a recipe file without a database, the configuration's
factory values. Invalid input exits with code 2 and one line naming the field and what is
allowed.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Mapping
from pathlib import Path

from app.cli.console import EXIT_INVALID_INPUT, EXIT_OK, CliInputError, emit
from app.cli.recipe_args import add_recipe_source
from app.config import ConfigError, MachineConfig, load_config
from app.data.errors import DataError
from app.data.recipe import Recipe
from app.geometry.errors import GeometryError
from app.geometry.limits import StaveLimits
from app.machine.process_params import config_parameters, stave_limits
from app.machine.program_export import (
    DEFAULT_SPINDLE_RPM,
    Dialect,
    ExportOptions,
    export_drawing,
    export_program,
)
from app.programs.moves import check_chord_error


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_recipe_source(parser)
    board = parser.add_mutually_exclusive_group(required=True)
    board.add_argument("--width", metavar="MM", help="the board's measured width")
    board.add_argument(
        "--parametric",
        action="store_true",
        help="one program for every board: the width is the parameter #<width> (LinuxCNC)",
    )
    parser.add_argument(
        "--dialect",
        default=Dialect.LINUXCNC.value,
        metavar="|".join(d.value for d in Dialect),
        help="the control's dialect (default linuxcnc)",
    )
    parser.add_argument(
        "--chords",
        metavar="MM",
        help="arcs as the fewest straight chords with at most this chord error",
    )
    parser.add_argument("--dxf", action="store_true", help="write the DXF drawing instead")
    parser.add_argument(
        "--spindle-rpm",
        metavar="RPM",
        help=f"the S word (default {DEFAULT_SPINDLE_RPM:g})",
    )
    parser.add_argument("--config", type=Path, metavar="FILE", help="machine configuration")
    parser.add_argument("--db", type=Path, metavar="FILE", help="database (recipes, parameters)")
    parser.add_argument("-o", "--output", type=Path, metavar="FILE", help="write to FILE")


def _number(option: str, text: str, allowed: str, ok: bool | None = None) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or ok is False:
        raise CliInputError(f"{option} = {text!r} is not allowed: {allowed}")
    return value


def _database_path(args: argparse.Namespace, config: MachineConfig) -> Path:
    from app.data.paths import default_database_path

    if args.db is not None:
        return Path(args.db)
    return Path(config.database_path) if config.database_path else default_database_path()


def _recipe_and_parameters(
    args: argparse.Namespace, config: MachineConfig, limits: StaveLimits
) -> tuple[Recipe, Mapping[str, float]]:
    from app.data.database import Database

    if args.recipe_file is not None:
        from app.data.recipe_files import load_recipe_file

        try:
            recipes = load_recipe_file(args.recipe_file)
        except (DataError, OSError, ValueError) as exc:
            raise CliInputError(f"--recipe-file: {exc}") from exc
        if not recipes:
            raise CliInputError(f"--recipe-file {args.recipe_file}: no recipe in the file")
        recipe = recipes[0]
        errors = recipe.validate(limits)
        if errors:
            raise CliInputError(f"--recipe-file: {errors[0].message}")
        if args.db is None:
            return recipe, config_parameters(config)
    path = _database_path(args, config)
    if not path.is_file():
        raise CliInputError(f"--db {path}: no database there (file not found)")
    try:
        with Database.open(path, limits=limits, load_samples=False) as db:
            params = db.get_parameters()
            if args.recipe_file is not None:
                return recipe, params
            found = db.get_recipe_by_name(args.recipe)
            names = [r.name for r in db.list_recipes()]
    except DataError as exc:
        raise CliInputError(f"--db: {exc}") from exc
    if found is None:
        raise CliInputError(
            f"--recipe {args.recipe!r} is not in the database: allowed "
            + (", ".join(repr(n) for n in names) or "(no recipes)")
        )
    return found, params


def _options(args: argparse.Namespace, config: MachineConfig) -> ExportOptions:
    dialects = [d.value for d in Dialect]
    if args.dialect not in dialects:
        allowed = ", ".join(dialects)
        raise CliInputError(f"--dialect {args.dialect!r} is not allowed: one of {allowed}")
    chords = None
    if args.chords is not None:
        chords = _number("--chords", args.chords, "a chord error in mm")
        try:
            check_chord_error(chords)
        except ValueError as exc:
            raise CliInputError(f"--{exc}") from exc
    rpm = DEFAULT_SPINDLE_RPM
    if args.spindle_rpm is not None:
        rpm = _number("--spindle-rpm", args.spindle_rpm, "1 to 100000 rpm")
        _number("--spindle-rpm", args.spindle_rpm, "1 to 100000 rpm", 1.0 <= rpm <= 100_000.0)
    if args.parametric and args.dialect != Dialect.LINUXCNC.value:
        raise CliInputError(
            f"--dialect {args.dialect} is not allowed with --parametric: allowed linuxcnc"
        )
    if args.parametric and (chords is not None or args.dxf):
        raise CliInputError(
            "--parametric is not allowed with --chords or --dxf: the parametric program's arcs "
            "are G2 moves and a drawing needs a width"
        )
    return ExportOptions(
        dialect=Dialect(args.dialect),
        chord_error_mm=chords,
        spindle_rpm=rpm,
        spindle_runup_s=config.io.spindle_runup_s,
    )


def generate(args: argparse.Namespace) -> str:
    """The program or drawing text; CliInputError or GeometryError for invalid input."""
    try:
        config = load_config(args.config)
    except ConfigError as exc:
        raise CliInputError(f"--config: {exc}") from exc
    except OSError as exc:
        raise CliInputError(f"--config {args.config}: {exc}") from exc
    limits = stave_limits(config)
    options = _options(args, config)
    width = None if args.parametric else _number("--width", args.width, "a width in mm")
    recipe, params = _recipe_and_parameters(args, config, limits)
    if args.dxf:
        assert width is not None
        return export_drawing(recipe, width, params, limits)
    return export_program(recipe, width, params, limits, options)


def run(args: argparse.Namespace) -> int:
    try:
        text = generate(args)
    except GeometryError as exc:
        print("stave gcode: " + "; ".join(e.message for e in exc.errors), file=sys.stderr)
        return EXIT_INVALID_INPUT
    except (CliInputError, ValueError) as exc:
        print(f"stave gcode: {exc}", file=sys.stderr)
        return EXIT_INVALID_INPUT
    if args.output is None:
        emit(text.removesuffix("\n"))
        return EXIT_OK
    try:
        args.output.write_text(text, encoding="utf-8")
    except OSError as exc:
        print(f"stave gcode: -o {args.output}: cannot write ({exc.strerror})", file=sys.stderr)
        return EXIT_INVALID_INPUT
    return EXIT_OK
