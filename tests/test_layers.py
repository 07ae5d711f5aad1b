"""The layering rules, checked on the source: geometry, programs, machine, drivers and data
import no Qt; geometry and the program writers import nothing of the other layers; screens
import no driver and no motion code.

Every import statement counts, including those inside functions (lazy imports), because a
lazy import of Qt in the machine process is as wrong as a top-level one.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

APP = Path(__file__).resolve().parent.parent / "app"
QT = ("PySide6", "shiboken6", "pyqtgraph")
FIELDBUS = ("pymodbus", "can", "canopen", "serial")

# package -> forbidden module prefixes
RULES: dict[str, tuple[str, ...]] = {
    "geometry": (*QT, *FIELDBUS, "app.machine", "app.drivers", "app.data", "app.screens"),
    "programs": (
        *QT,
        *FIELDBUS,
        "app.machine",
        "app.drivers",
        "app.data",
        "app.screens",
        "app.cli",
    ),
    "machine": (*QT, "app.screens", "app.cli"),
    "drivers": (*QT, "app.screens", "app.machine", "app.data"),
    "data": (*QT, *FIELDBUS, "app.screens", "app.machine", "app.drivers"),
    "screens": (
        *FIELDBUS,
        "app.drivers.sim",
        "app.drivers.modbus",
        "app.drivers.canopen",
        "app.drivers.serial_gauge",
        "app.drivers.registry",
        "app.machine.planner",
        "app.machine.executor",
        "app.machine.runtime",
        "app.machine.controller",
        "app.machine.process_link",
        "app.machine.local_link",
    ),
}


def imported_modules(path: Path) -> list[tuple[int, str]]:
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found: list[tuple[int, str]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.extend((node.lineno, alias.name) for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            found.append((node.lineno, node.module))
            found.extend((node.lineno, f"{node.module}.{alias.name}") for alias in node.names)
    return found


def violations(package: str) -> list[str]:
    bad: list[str] = []
    for path in sorted((APP / package).rglob("*.py")):
        for lineno, module in imported_modules(path):
            for prefix in RULES[package]:
                if module == prefix or module.startswith(prefix + "."):
                    bad.append(f"{path.relative_to(APP.parent)}:{lineno} imports {module}")
                    break
    return bad


@pytest.mark.parametrize("package", sorted(RULES))
def test_layer_rules(package: str) -> None:
    assert (APP / package).is_dir()
    assert violations(package) == []


def test_checker_catches_a_forbidden_import(tmp_path: Path) -> None:
    """The checker itself must be able to fail: a Qt import is reported."""
    sample = tmp_path / "sample.py"
    sample.write_text("def f():\n    from PySide6.QtWidgets import QLabel\n    return QLabel\n")
    modules = [m for _, m in imported_modules(sample)]
    assert "PySide6.QtWidgets" in modules
