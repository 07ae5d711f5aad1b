"""LinuxCNC's standalone interpreter, rs274, run on a program file, and its canonical calls read.

`rs274 -g FILE` interprets the whole program the way LinuxCNC's task would and prints one
line per canonical machine call (STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED, SET_FEED_RATE,
...), coordinates with 4 decimals. It needs no tool table or INI file for these programs.
Missing interpreter: the tests skip, except under CI, where they fail (the project's
scripts/ensure-env.sh installs the Debian package linuxcnc-uspace when run as root).
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

import pytest

PACKAGE = "linuxcnc-uspace"
_CALL = re.compile(r"^\s*\d+\s+N\S*\s+([A-Z][A-Z0-9_]*)\((.*)\)\s*$")
_MOTION = ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "ARC_FEED")


def rs274_path() -> str:
    """The interpreter's path; pytest.fail under CI, pytest.skip elsewhere, when missing."""
    path = shutil.which("rs274")
    if path is None:
        message = f"rs274 not found (Debian package {PACKAGE}; scripts/ensure-env.sh installs it)"
        if os.environ.get("CI"):
            pytest.fail(message)
        pytest.skip(message)
    return path


@dataclass(frozen=True)
class CanonicalMove:
    """One motion call: its kind, where it ends (x, y, a), the arc's centre and rotation
    (-1 clockwise, +1 counter-clockwise), and the feed rate in force (mm/min)."""

    call: str
    x: float
    y: float
    a: float
    feed_mm_min: float
    center: tuple[float, float] | None = None
    rotation: int = 0


@dataclass(frozen=True)
class Interpretation:
    returncode: int
    stderr: str
    moves: tuple[CanonicalMove, ...]
    calls: tuple[str, ...]  # every canonical call's name, in order
    arguments: tuple[str, ...] = ()  # and its arguments as printed, in the same order


def interpret(program: Path) -> Interpretation:
    done = subprocess.run(
        [rs274_path(), "-g", str(program)],
        capture_output=True,
        text=True,
        timeout=60,
        cwd=program.parent,
        check=False,
    )
    moves: list[CanonicalMove] = []
    calls: list[str] = []
    arguments_of: list[str] = []
    feed = 0.0
    for line in done.stdout.splitlines():
        match = _CALL.match(line)
        if match is None:
            continue
        name, arguments = match.group(1), match.group(2)
        calls.append(name)
        arguments_of.append(arguments)
        if name == "SET_FEED_RATE":
            feed = float(arguments)
        if name not in _MOTION:
            continue
        values = [float(v) for v in arguments.split(",")]
        if name == "ARC_FEED":
            # end_x, end_y, centre_x, centre_y, rotation, z, a, b, c
            moves.append(
                CanonicalMove(
                    name,
                    values[0],
                    values[1],
                    values[6],
                    feed,
                    (values[2], values[3]),
                    int(values[4]),
                )
            )
        else:
            moves.append(CanonicalMove(name, values[0], values[1], values[3], feed))
    return Interpretation(
        done.returncode, done.stderr, tuple(moves), tuple(calls), tuple(arguments_of)
    )


def without_standstill(
    moves: tuple[CanonicalMove, ...], start: tuple[float, float, float]
) -> list[CanonicalMove]:
    """The moves that go somewhere: a call that ends where the previous one did (x, y and a
    as printed) moves nothing and is left out."""
    kept: list[CanonicalMove] = []
    position = start
    for move in moves:
        end = (move.x, move.y, move.a)
        if end != position or move.call == "ARC_FEED":
            kept.append(move)
        position = end
    return kept
