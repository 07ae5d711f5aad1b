"""The layering rules, checked on the source, as an allow-list per package, and the import
graph of app/ checked for circles.

Each package (and each top-level module) of app/ names the packages it may import besides the
standard library and itself; anything else is a violation, so a new package or a new library
has to be given its rules here before its first import passes. In short: geometry imports
nothing but itself; the program writers only geometry; data adds geometry; drivers add the
configuration and the fieldbus libraries; machine adds data, drivers and the planner's
libraries, never Qt or the screens; screens and the plant connection reach the machine only
through its link, commands, snapshot and rules, and no driver backend.

Every import statement counts, including those inside functions (lazy imports, because a
lazy import of Qt in the machine process is as wrong as a top-level one) and those only for
the type checker (an import circle hidden behind TYPE_CHECKING is still a circle in the
design).
"""

from __future__ import annotations

import ast
import sys
from collections.abc import Iterable
from pathlib import Path

import pytest

APP = Path(__file__).resolve().parent.parent / "app"
QT = ("PySide6", "shiboken6", "pyqtgraph")
FIELDBUS = ("pymodbus", "can", "canopen", "serial")
VERSION = "app.__version__"

# package or top-level module of app/ -> what it may import (module prefixes), besides the
# standard library and itself
ALLOWED: dict[str, tuple[str, ...]] = {
    "__init__": (),
    "__main__": ("app.main",),
    "config": ("app.resources", "app.plant.settings", "app.pendant_settings", "app.table_outlines"),
    "pendant_settings": (),
    "table_outlines": (),
    "resources": (),
    "logging_setup": ("platformdirs",),
    "geometry": (),
    "programs": ("app.geometry", "ezdxf"),
    "data": ("app.geometry", "app.resources", "ezdxf", "platformdirs"),
    "drivers": ("app.config", "app.pendant_settings", "evdev", *FIELDBUS),
    "machine": (
        VERSION,
        "app.config",
        "app.pendant_settings",
        "app.table_outlines",
        "app.data",
        "app.drivers",
        "app.geometry",
        "app.programs",
        "app.logging_setup",
        "numpy",
        "ruckig",
    ),
    "screens": (
        *QT,
        "numpy",
        "app.data",
        "app.geometry",
        "app.resources",
        "app.drivers.contracts",
        "app.machine.alarms",
        "app.machine.barrel_set",
        "app.machine.barrel_view",
        "app.machine.commands",
        "app.machine.link",
        "app.machine.permissions",
        "app.machine.program_export",
        "app.machine.refusals",
        "app.machine.snapshot",
        "app.machine.states",
        "app.plant.settings",
        "app.plant.status",
        "app.plant.trust",
    ),
    "plant": (
        VERSION,
        "app.config",
        "app.data",
        "app.logging_setup",
        "app.resources",
        "app.machine.alarms",
        "app.machine.barrel_view",
        "app.machine.commands",
        "app.machine.link",
        "app.machine.refusals",
        "app.machine.snapshot",
        "app.machine.states",
        "asyncua",
        "cryptography",
    ),
    "cli": (
        VERSION,
        "app.config",
        "app.data",
        "app.drivers",
        "app.geometry",
        "app.machine",
        "app.plant",
        "app.programs",
        "numpy",
    ),
    "main": (
        *QT,
        VERSION,
        "app.config",
        "app.drivers.settings_check",
        "app.data",
        "app.logging_setup",
        "app.machine",
        "app.plant",
        "app.screens",
    ),
}


def unit_of(path: Path) -> str:
    """The package (first directory under app/) or top-level module a file belongs to."""
    relative = path.relative_to(APP)
    return relative.parts[0] if len(relative.parts) > 1 else relative.stem


def imported_modules(path: Path) -> list[tuple[int, str]]:
    """(line, dotted name) of every import; ``from m import n`` gives ``m.n`` (a submodule
    or a name in m: a prefix rule covers both)."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found: list[tuple[int, str]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.extend((node.lineno, alias.name) for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            found.extend((node.lineno, f"{node.module}.{alias.name}") for alias in node.names)
    return found


def _matches(module: str, prefixes: Iterable[str]) -> bool:
    return any(module == p or module.startswith(p + ".") for p in prefixes)


def violations(unit: str, files: Iterable[Path]) -> list[str]:
    allowed = (f"app.{unit}", *ALLOWED[unit])
    bad: list[str] = []
    for path in files:
        for lineno, module in imported_modules(path):
            if module.split(".")[0] in sys.stdlib_module_names:
                continue
            if not _matches(module, allowed):
                shown = path.relative_to(APP.parent) if path.is_relative_to(APP) else path
                bad.append(f"{shown}:{lineno} imports {module}")
    return bad


def app_files() -> list[Path]:
    return sorted(APP.rglob("*.py"))


def test_every_package_and_module_of_app_has_rules() -> None:
    assert {unit_of(path) for path in app_files()} <= set(ALLOWED)


@pytest.mark.parametrize("unit", sorted(ALLOWED))
def test_layer_rules(unit: str) -> None:
    files = [path for path in app_files() if unit_of(path) == unit]
    assert files, f"app/{unit} has no source: remove its rules"
    assert violations(unit, files) == []


def test_checker_catches_a_forbidden_import(tmp_path: Path) -> None:
    """The checker itself must be able to fail: Qt in geometry, a driver backend in the
    screens, a library nobody allowed; the standard library passes."""
    sample = tmp_path / "sample.py"
    sample.write_text(
        "import math\n"
        "from app.drivers.contracts import InputImage\n"
        "def f():\n"
        "    from PySide6.QtWidgets import QLabel\n"
        "    from app.drivers.modbus import backend\n"
        "    import requests\n"
        "    return QLabel, backend, requests, math, InputImage\n"
    )
    modules = [m for _, m in imported_modules(sample)]
    assert "PySide6.QtWidgets.QLabel" in modules
    assert len(violations("geometry", [sample])) == 4
    screens = violations("screens", [sample])
    assert [line.rsplit(" ", 1)[1] for line in screens] == [
        "app.drivers.modbus.backend",
        "requests",
    ]


# ----------------------------------------------------------------------------- import circles


def module_name(path: Path, root: Path) -> str:
    parts = list(path.relative_to(root).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def import_graph(files: Iterable[Path], root: Path = APP.parent) -> dict[str, set[str]]:
    """Module -> the modules of app/ it imports (a ``from package import name`` counts as the
    submodule when there is one, else as the package). A package's own ``__init__`` is not
    an edge of its submodules: importing ``app.geometry.limits`` runs it, but it is not what
    limits depends on."""
    paths = {module_name(path, root): path for path in files}
    graph: dict[str, set[str]] = {}
    for name, path in paths.items():
        edges: set[str] = set()
        for _, module in imported_modules(path):
            if module in paths:
                edges.add(module)
            elif module.rpartition(".")[0] in paths:
                edges.add(module.rpartition(".")[0])
        edges.discard(name)
        graph[name] = edges
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    for root in sorted(graph):
        if root in index:
            continue
        work: list[tuple[str, list[str]]] = [(root, sorted(graph[root]))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, pending = work[-1]
            if pending:
                child = pending.pop()
                if child not in graph:
                    continue
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, sorted(graph[child])))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                component: list[str] = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def test_app_has_no_import_circle() -> None:
    assert cycles(import_graph(app_files())) == []


def test_the_circle_finder_finds_a_circle(tmp_path: Path) -> None:
    package = tmp_path / "app" / "pkg"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text("from app.pkg.a import x\n")
    (package / "a.py").write_text("from app.pkg.b import y\nx = 1\n")
    (package / "b.py").write_text(
        "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from app.pkg.c import z\ny = 2\n"
    )
    (package / "c.py").write_text("def f():\n    from app.pkg import a\n    return a\nz = 3\n")
    (package / "d.py").write_text("from app.pkg.a import x\n")
    graph = import_graph(sorted(package.rglob("*.py")), tmp_path)
    assert graph["app.pkg.d"] == {"app.pkg.a"}
    assert cycles(graph) == [["app.pkg.a", "app.pkg.b", "app.pkg.c"]]
