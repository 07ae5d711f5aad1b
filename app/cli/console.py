"""What every `stave` tool does the same way at the console: exit codes, output, usage errors.

Why one module: the tools promise the same contract (exit 2 and one line naming the field on
bad input; a reader that goes away is not an error), so they share one implementation of it.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable, Sequence
from typing import NoReturn

EXIT_OK = 0
EXIT_INVALID_INPUT = 2


class CliInputError(Exception):
    """Invalid command-line input that is not a geometry rule (bad number, bad config file)."""


def emit(text: str) -> None:
    """Print to stdout; a reader that went away (`stave solve | head`) is not an error."""
    try:
        print(text)
        sys.stdout.flush()
    except BrokenPipeError:
        # Point stdout at /dev/null so the interpreter's final flush does not fail again.
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)


class OneLineParser(argparse.ArgumentParser):
    """argparse, but a usage error is one line on stderr (exit 2), like every other error."""

    def error(self, message: str) -> NoReturn:
        self.exit(EXIT_INVALID_INPUT, f"{self.prog}: {message}\n")


def run_parsed(
    parser: argparse.ArgumentParser,
    run: Callable[[argparse.Namespace], int],
    argv: Sequence[str] | None,
) -> int:
    """Parse and run one tool standalone; the exit code is returned instead of exiting."""
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else EXIT_INVALID_INPUT
    return run(args)
