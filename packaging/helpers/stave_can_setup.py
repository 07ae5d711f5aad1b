#!/usr/bin/python3
"""``stave-can-setup up|down INTERFACE``: bring a SocketCAN interface up at the configured bitrate.

Installed as /usr/lib/stave-jointer/stave-can-setup and run by ``stave-can@INTERFACE.service``,
which udev starts whenever a CAN interface appears (at boot, or when a USB CAN adapter is
plugged in again), so a re-plugged adapter comes back at the right bitrate without a reboot.

Why the bitrate is read from machine.toml: the CANopen backend's ``[backend.canopen]`` table
already names the channel and the bitrate the drives use; a second place to type the bitrate
would sooner or later disagree with it, and a wrong bitrate looks like dead drives. Only the
configured channel with ``interface = "socketcan"`` is touched; any other CAN interface, or a
machine without a ``[backend.canopen]`` table, is left alone (exit 0).

Why stdlib only (run by /usr/bin/python3, not the application's virtualenv): it runs as root
at boot, before and independently of the application, and must not break with it.
Exit codes: 0 done or nothing to do; 1 ``ip`` failed; 2 bad configuration (one line naming the
key, the value and what is allowed).
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

DEFAULT_CONFIG = "/etc/stave-jointer/machine.toml"
# The bitrates the CANopen backend accepts (app.drivers.canopen.settings.BITRATES; a test
# keeps the two lists equal).
BITRATES: tuple[int, ...] = (10_000, 20_000, 50_000, 125_000, 250_000, 500_000, 800_000, 1_000_000)
DEFAULT_BITRATE = 1_000_000
DEFAULT_CHANNEL = "can0"
# Automatic recovery from bus-off after this long: a short circuit on the bus or a drive
# rebooting must not leave the interface dead until the next power-up.
RESTART_MS = 100


class SetupError(Exception):
    """A configuration the interface cannot be set up from; the message names the key."""


@dataclass(frozen=True)
class CanPlan:
    """What to do with one interface: the commands, or why nothing is done."""

    commands: tuple[tuple[str, ...], ...]
    reason: str


def _canopen_table(data: Mapping[str, Any], source: str) -> Mapping[str, Any] | None:
    backend = data.get("backend", {})
    if not isinstance(backend, Mapping):
        raise SetupError(f"{source}: backend = {backend!r} is not allowed: a table")
    table = backend.get("canopen")
    if table is None:
        return None
    if not isinstance(table, Mapping):
        raise SetupError(f"{source}: backend.canopen = {table!r} is not allowed: a table")
    return table


def plan(data: Mapping[str, Any], action: str, interface: str, source: str = "") -> CanPlan:
    """The ``ip`` commands that set ``interface`` up (or down) as the configuration says."""
    table = _canopen_table(data, source)
    if table is None:
        return CanPlan((), f"no [backend.canopen] in {source}: {interface} left alone")
    kind = table.get("interface", "socketcan")
    if kind != "socketcan":
        return CanPlan((), f"backend.canopen.interface is {kind!r}: {interface} left alone")
    channel = table.get("channel", DEFAULT_CHANNEL)
    if str(channel) != interface:
        return CanPlan((), f"backend.canopen.channel is {channel!r}: {interface} left alone")
    if action == "down":
        return CanPlan((("ip", "link", "set", interface, "down"),), f"{interface} down")
    bitrate = table.get("bitrate", DEFAULT_BITRATE)
    if isinstance(bitrate, bool) or bitrate not in BITRATES:
        allowed = ", ".join(str(b) for b in BITRATES)
        raise SetupError(
            f"{source}: backend.canopen.bitrate = {bitrate!r} is not allowed: one of {allowed}"
        )
    settings = ("type", "can", "bitrate", str(bitrate), "restart-ms", str(RESTART_MS))
    commands = (
        ("ip", "link", "set", interface, "down"),
        ("ip", "link", "set", interface, *settings),
        ("ip", "link", "set", interface, "up"),
    )
    return CanPlan(commands, f"{interface} up at {bitrate} bit/s")


def load(path: Path) -> dict[str, Any]:
    try:
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        why = f"a readable file ({exc.strerror})"
        raise SetupError(f"--config {path} is not allowed: {why}") from None
    except tomllib.TOMLDecodeError as exc:
        raise SetupError(f"--config {path} is not allowed: valid TOML ({exc})") from None


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="stave-can-setup", description="set a SocketCAN interface up as machine.toml says"
    )
    parser.add_argument("action", choices=("up", "down"))
    parser.add_argument("interface", help="network interface, e.g. can0")
    parser.add_argument("--config", type=Path, default=Path(DEFAULT_CONFIG), metavar="FILE")
    parser.add_argument(
        "--dry-run", action="store_true", help="print the commands instead of running them"
    )
    args = parser.parse_args(argv)
    try:
        result = plan(load(args.config), args.action, args.interface, str(args.config))
    except SetupError as exc:
        print(f"stave-can-setup: {exc}", file=sys.stderr)
        return 2
    print(f"stave-can-setup: {result.reason}")
    gone = not Path("/sys/class/net", args.interface).exists()
    if args.action == "down" and gone and not args.dry_run:
        return 0  # the adapter is gone already (unplugged): nothing to bring down
    for command in result.commands:
        if args.dry_run:
            print(" ".join(command))
            continue
        done = subprocess.run(command, check=False, capture_output=True, text=True)
        if done.returncode != 0:
            why = done.stderr.strip() or f"exit status {done.returncode}"
            print(f"stave-can-setup: {' '.join(command)} failed: {why}", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
