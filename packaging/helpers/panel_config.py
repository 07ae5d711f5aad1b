"""Build-time helper: the panel PC's /etc/stave-jointer/machine.toml from resources/machine.toml.

    python3 packaging/helpers/panel_config.py resources/machine.toml OUT

Why generated and not a second hand-kept file: the shipped machine.toml is the documented
default (every key with its comment); the panel's file must be the same text with the two
places a packaged install keeps its state set: ``[database] path`` under /var/lib and
``[logging] dir`` under /var/log. Only those two lines change, so the comments the
technician reads stay those of the source. A key that is missing is an error (the source
file changed shape, and the package would otherwise write its database into the operator's
home directory).
"""

from __future__ import annotations

import re
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path

DATABASE_PATH = "/var/lib/stave-jointer/stave.db"
LOG_DIR = "/var/log/stave-jointer"

# (table, key) -> (value, comment)
PANEL_VALUES: Mapping[tuple[str, str], tuple[str, str]] = {
    ("database", "path"): (DATABASE_PATH, "the machine's database (stave-jointer package)"),
    ("logging", "dir"): (LOG_DIR, "rotating log files (stave-jointer package)"),
}

_TABLE = re.compile(r"^\s*\[([^\[\]]+)\]\s*(#.*)?$")
_KEY = re.compile(r"^(\s*)([A-Za-z0-9_-]+)(\s*=\s*)")


class PanelConfigError(Exception):
    """The source configuration does not have the keys the panel's file sets."""


def panel_config(text: str) -> str:
    """``text`` with the values of PANEL_VALUES set, each line's comment replaced."""
    table = ""
    done: set[tuple[str, str]] = set()
    lines = []
    for line in text.splitlines(keepends=True):
        header = _TABLE.match(line)
        if header:
            table = header.group(1).strip()
        key = _KEY.match(line)
        place = (table, key.group(2)) if key else ("", "")
        if key and place in PANEL_VALUES:
            value, comment = PANEL_VALUES[place]
            lines.append(f'{key.group(1)}{key.group(2)}{key.group(3)}"{value}"   # {comment}\n')
            done.add(place)
        else:
            lines.append(line)
    missing = sorted(set(PANEL_VALUES) - done)
    if missing:
        names = ", ".join(f"[{t}] {k}" for t, k in missing)
        raise PanelConfigError(f"the source configuration has no {names} line to set")
    return "".join(lines)


def main(argv: Sequence[str]) -> int:
    if len(argv) != 2:
        print("usage: panel_config.py SOURCE.toml OUT.toml", file=sys.stderr)
        return 2
    source, out = (Path(a) for a in argv)
    try:
        out.write_text(panel_config(source.read_text(encoding="utf-8")), encoding="utf-8")
    except (OSError, PanelConfigError) as exc:
        print(f"panel_config: {source}: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
