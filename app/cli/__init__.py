"""The ``stave`` command-line tools: one subcommand per job, one module each in this package.

Why the entry points live here and not beside the code they drive: the geometry, machine,
drivers and data packages do no console I/O and parse no arguments, so each stays a library
that the machine process, the screens and these tools share. Why a table of module names: each
tool is imported only when run, so ``stave solve`` on an office PC never loads Qt or a
fieldbus stack.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

from app import __version__
from app.cli.console import OneLineParser

# subcommand -> (module with add_arguments(parser) and run(args) -> int, one-line help)
SUBCOMMANDS: dict[str, tuple[str, str]] = {
    "solve": ("app.cli.solve", "compute a stave's profile and tool path"),
    "barrel": (
        "app.cli.barrel",
        "place staves around a round or oval barrel",
    ),
    "simulate": ("app.cli.simulate", "run automatic cycles on the simulated machine"),
    "probe": ("app.cli.probe", "connect to the configured hardware and show its state"),
    "db": ("app.cli.db", "recipes import/export, production export, backup and restore"),
    "gcode": ("app.cli.gcode", "a stave's program for LinuxCNC or SINUMERIK, or its DXF drawing"),
    "opcua": ("app.cli.opcua", "plant connection: OPC UA users, trusted clients, endpoints"),
}


def _module(module_name: str):  # type: ignore[no-untyped-def]
    return importlib.import_module(module_name)


def main(argv: Sequence[str] | None = None) -> int:
    args_list = list(sys.argv[1:] if argv is None else argv)
    parser = argparse.ArgumentParser(prog="stave", description=__doc__.splitlines()[0])
    parser.add_argument("--version", action="version", version=f"stave {__version__}")
    # Each tool's usage errors are one line, exit 2, like every other bad input.
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=OneLineParser)
    chosen = args_list[0] if args_list else ""
    for name, (module_name, help_text) in SUBCOMMANDS.items():
        sub_parser = sub.add_parser(name, help=help_text, description=help_text)
        sub_parser.set_defaults(_module=module_name)
        if name == chosen:  # only the chosen tool's module is imported
            _module(module_name).add_arguments(sub_parser)
    args = parser.parse_args(args_list)
    if args.command is None:
        parser.print_help()
        return 2
    code: int = _module(args._module).run(args)
    return code
