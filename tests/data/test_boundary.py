"""The data layer is used only through its API: nothing outside ``app/data`` talks SQL.

Checked on the source (every import, lazy ones included): no module outside the package
imports ``sqlite3``, reaches into a Database's connection, or imports a private name.
"""

from __future__ import annotations

import ast
from pathlib import Path

APP = Path(__file__).resolve().parents[2] / "app"


def offences(path: Path) -> list[str]:
    """What ``path`` does that only the data package may do, one line each."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [f"imports {a.name}" for a in node.names if a.name.split(".")[0] == "sqlite3"]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            if node.module.split(".")[0] == "sqlite3":
                found.append(f"imports from {node.module}")
            if node.module.startswith("app.data"):
                found += [
                    f"imports the private {node.module}.{a.name}"
                    for a in node.names
                    if a.name.startswith("_")
                ]
        elif isinstance(node, ast.Attribute) and node.attr == "_conn":
            found.append("uses a Database's private connection")
    return [f"{path.name}: {message}" for message in found]


def test_nothing_outside_the_data_package_talks_sql() -> None:
    outside = [p for p in sorted(APP.rglob("*.py")) if "data" not in p.relative_to(APP).parts[:1]]
    assert outside  # the rest of the application is there to check
    assert [o for path in outside for o in offences(path)] == []


def test_the_checker_finds_an_offence(tmp_path: Path) -> None:
    sample = tmp_path / "screen.py"
    sample.write_text(
        "def f(db):\n    import sqlite3\n    from app.data.database import _recipe_from_row\n"
        "    return db._conn\n"
    )
    assert len(offences(sample)) == 3
