#!/usr/bin/python3
"""``stave-gauge-setup DEVICE``: the width gauge's USB serial adapter becomes /dev/stave-gauge.

Installed as /usr/sbin/stave-gauge-setup. Why a pin written on the machine and not a fixed
rule in the package: /dev/ttyUSB0 and /dev/ttyUSB1 swap with the order in which adapters are
found, and the gauge's adapter is often of the same make as the one of a Modbus RTU bus, so a
rule by vendor and product alone could name the wrong one. The technician plugs the gauge in
and runs this once; it writes /etc/udev/rules.d/69-stave-gauge.rules, which marks exactly that
adapter (by its serial number, or with --by-port by the USB socket it is plugged into) with
``STAVE_DEVICE=gauge``; the package's /lib/udev/rules.d/70-stave-jointer.rules turns the mark
into /dev/stave-gauge (group dialout). machine.toml then says ``port = "/dev/stave-gauge"``.

    stave-gauge-setup /dev/ttyUSB0        pin this adapter (its serial number; its socket if none)
    stave-gauge-setup --by-port /dev/ttyUSB0   pin the USB socket (a replacement cable works)
    stave-gauge-setup --list              show the USB serial adapters and the gauge's name
    stave-gauge-setup --remove            forget the pin

Exit codes: 0 done; 1 udev failed or the name did not appear; 2 bad input (one line saying why).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path

PIN_RULES = Path("/etc/udev/rules.d/69-stave-gauge.rules")
GAUGE_LINK = Path("/dev/stave-gauge")
BY_ID = Path("/dev/serial/by-id")
# Characters udev would read as a pattern or that would end the quoted value.
_UNSAFE = set('"\\*?[]|\n')


class SetupError(Exception):
    """Input the pin cannot be made from; the message says what and why (exit code 2)."""


class UdevError(SetupError):
    """udevadm is missing or failed (exit code 1)."""


def parse_properties(text: str) -> dict[str, str]:
    """``udevadm info --query=property`` output (KEY=value lines) as a dict."""
    properties: dict[str, str] = {}
    for line in text.splitlines():
        key, sep, value = line.partition("=")
        if sep:
            properties[key.strip()] = value.strip()
    return properties


def _match(properties: Mapping[str, str], key: str) -> str:
    value = properties.get(key, "")
    if not value:
        raise SetupError(f"the device has no {key}: pin it with --by-port instead")
    if _UNSAFE & set(value):
        raise SetupError(f"{key} = {value!r} has characters udev cannot match literally")
    return f'ENV{{{key}}}=="{value}"'


def pin_rule(properties: Mapping[str, str], by_port: bool = False) -> str:
    """The udev rule that marks exactly this adapter as the gauge.

    By serial number (vendor, product, serial and, on multi-port adapters, the interface
    number): the adapter may move to any USB socket. By port (``ID_PATH``): the socket is
    fixed, so an identical replacement adapter works without running this again. An adapter
    without a serial number can only be pinned by port.
    """
    device = properties.get("DEVNAME", "the device")
    subsystem, bus = properties.get("SUBSYSTEM"), properties.get("ID_BUS")
    if subsystem != "tty":
        raise SetupError(f"{device} is not a serial port (SUBSYSTEM={subsystem})")
    if bus != "usb":
        raise SetupError(f"{device} is not a USB serial adapter (ID_BUS={bus})")
    if by_port or not properties.get("ID_SERIAL_SHORT"):
        keys = ["ID_PATH"]
    else:
        keys = ["ID_VENDOR_ID", "ID_MODEL_ID", "ID_SERIAL_SHORT"]
        if properties.get("ID_USB_INTERFACE_NUM"):
            keys.append("ID_USB_INTERFACE_NUM")
    matches = ", ".join(_match(properties, key) for key in keys)
    what = " ".join(
        properties.get(k, "") for k in ("ID_VENDOR", "ID_MODEL", "ID_SERIAL_SHORT")
    ).strip()
    how = "the USB socket it is plugged into" if keys == ["ID_PATH"] else "its serial number"
    return (
        "# Written by stave-gauge-setup: the width gauge's USB serial adapter\n"
        f"# ({what or 'no name'}, {device} when pinned), recognised by {how}.\n"
        "# /lib/udev/rules.d/70-stave-jointer.rules names it /dev/stave-gauge.\n"
        f'SUBSYSTEM=="tty", {matches}, ENV{{STAVE_DEVICE}}="gauge"\n'
    )


def _run(*command: str) -> str:
    try:
        done = subprocess.run(command, check=False, capture_output=True, text=True)
    except FileNotFoundError:
        raise UdevError(f"{command[0]} not found (is udev installed?)") from None
    if done.returncode != 0:
        raise UdevError(f"{' '.join(command)} failed: {done.stderr.strip()}")
    return done.stdout


def _reload() -> None:
    _run("udevadm", "control", "--reload-rules")
    _run("udevadm", "trigger", "--action=change", "--subsystem-match=tty")
    _run("udevadm", "settle", "--timeout=10")


def _list() -> int:
    adapters = sorted(BY_ID.iterdir()) if BY_ID.is_dir() else []
    for link in adapters:
        print(f"{link.resolve()}  {link.name}")
    if not adapters:
        print("no USB serial adapter found (plugged in? `dmesg | tail` shows the kernel's view)")
    gauge = f"-> {GAUGE_LINK.resolve()}" if GAUGE_LINK.exists() else "not present"
    pinned = "pinned" if PIN_RULES.exists() else f"not pinned ({PIN_RULES} missing)"
    print(f"{GAUGE_LINK}: {gauge}; {pinned}")
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="stave-gauge-setup", description="name the width gauge's adapter /dev/stave-gauge"
    )
    parser.add_argument("device", nargs="?", help="the gauge's port now, e.g. /dev/ttyUSB0")
    parser.add_argument("--by-port", action="store_true", help="pin the USB socket instead")
    parser.add_argument("--dry-run", action="store_true", help="print the rule, change nothing")
    parser.add_argument("--list", action="store_true", help="show adapters and the gauge's name")
    parser.add_argument("--remove", action="store_true", help="forget the pinned adapter")
    args = parser.parse_args(argv)
    try:
        if args.list:
            return _list()
        if not args.dry_run and os.geteuid() != 0:
            raise SetupError("run it as root: sudo stave-gauge-setup ...")
        if args.remove:
            PIN_RULES.unlink(missing_ok=True)
            _reload()
            print(f"stave-gauge-setup: {PIN_RULES} removed; {GAUGE_LINK} is gone")
            return 0
        if not args.device:
            raise SetupError("name the gauge's port, e.g. stave-gauge-setup /dev/ttyUSB0")
        device = str(Path(args.device).resolve())
        if not Path(device).exists():
            raise SetupError(f"{args.device}: no such device (see stave-gauge-setup --list)")
        rule = pin_rule(
            parse_properties(_run("udevadm", "info", "--query=property", f"--name={device}")),
            args.by_port,
        )
        if args.dry_run:
            print(rule, end="")
            return 0
        PIN_RULES.write_text(rule, encoding="utf-8")
        _reload()
    except SetupError as exc:
        print(f"stave-gauge-setup: {exc}", file=sys.stderr)
        return 1 if isinstance(exc, UdevError) else 2
    if not GAUGE_LINK.exists() or str(GAUGE_LINK.resolve()) != device:
        print(f"stave-gauge-setup: {GAUGE_LINK} did not appear for {device}", file=sys.stderr)
        return 1
    print(f"stave-gauge-setup: {GAUGE_LINK} -> {device} (pinned in {PIN_RULES})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
