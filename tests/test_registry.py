"""Backends are looked up by name and imported only when chosen."""

from __future__ import annotations

import subprocess
import sys
from dataclasses import replace

import pytest

from app.config import ConfigError, load_config
from app.drivers import registry
from app.drivers.contracts import MachineBackend, WidthGauge


def test_unknown_backend_lists_the_valid_ones() -> None:
    config = replace(load_config(), backend="profinet")
    with pytest.raises(ConfigError) as info:
        registry.create_backend(config)
    assert info.value.key == "backend.name"
    assert "canopen, modbus, sim" in str(info.value)


def test_unknown_gauge_lists_the_valid_ones() -> None:
    config = load_config()
    backend = registry.create_backend(config)
    with pytest.raises(ConfigError, match="serial, sim"):
        registry.create_gauge(replace(config, gauge="laser"), backend)


def test_sim_backend_and_gauge_by_name() -> None:
    config = load_config()
    backend = registry.create_backend(config)
    assert isinstance(backend, MachineBackend) and backend.name == "sim"
    assert isinstance(registry.create_gauge(config, backend), WidthGauge)


def test_choosing_sim_imports_no_fieldbus_library() -> None:
    code = (
        "import sys\n"
        "from app.config import load_config\n"
        "from app.drivers import registry\n"
        "c = load_config()\n"
        "b = registry.create_backend(c)\n"
        "registry.create_gauge(c, b)\n"
        "heavy = ('pymodbus', 'canopen', 'can', 'serial', 'PySide6')\n"
        "bad = [m for m in heavy if m in sys.modules]\n"
        "print(','.join(bad))\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=True
    ).stdout.strip()
    assert out == ""


def test_every_registered_module_exists() -> None:
    import importlib.util

    for table in (registry.MOTION_BACKENDS, registry.GAUGE_BACKENDS):
        for module_name, _attribute in table.values():
            assert importlib.util.find_spec(module_name) is not None, module_name
