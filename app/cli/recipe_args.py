"""The options that name the recipe a command works on, the same in every ``stave`` tool."""

from __future__ import annotations

import argparse
from pathlib import Path


def add_recipe_source(parser: argparse.ArgumentParser) -> None:
    """``--recipe NAME`` (in the database) or ``--recipe-file FILE``, exactly one of them."""
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument("--recipe", metavar="NAME", help="recipe name in the database")
    source.add_argument(
        "--recipe-file",
        type=Path,
        metavar="FILE",
        help="recipe file, JSON or CSV as `stave db` exports them (the first recipe is used)",
    )
