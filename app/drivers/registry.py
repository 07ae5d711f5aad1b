"""Backends looked up by name, imported only when chosen (after python-can's interface table).

Why lazy: the Modbus and CANopen stacks pull in large libraries and open ports; a panel PC
running the simulation, or an office PC preparing recipes, must not import them at all.
Why one table: adding a backend is one line here plus its module, and an unknown name gets
the list of valid ones in one clear message.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import cast

from app.config import ConfigError, MachineConfig
from app.drivers.contracts import MachineBackend, WidthGauge

# name -> (module, factory). Factories: create_backend(config) -> MachineBackend;
# create_gauge(config, backend) -> WidthGauge.
MOTION_BACKENDS: dict[str, tuple[str, str]] = {
    "sim": ("app.drivers.sim.backend", "create_backend"),
    "modbus": ("app.drivers.modbus.backend", "create_backend"),
    "canopen": ("app.drivers.canopen.backend", "create_backend"),
}

GAUGE_BACKENDS: dict[str, tuple[str, str]] = {
    "sim": ("app.drivers.sim.gauge", "create_gauge"),
    "serial": ("app.drivers.serial_gauge.gauge", "create_gauge"),
}


def _factory(table: dict[str, tuple[str, str]], name: str, key: str) -> Callable[..., object]:
    if name not in table:
        raise ConfigError(key, name, "one of " + ", ".join(sorted(table)))
    module_name, attribute = table[name]
    module = importlib.import_module(module_name)
    return cast(Callable[..., object], getattr(module, attribute))


def create_backend(config: MachineConfig) -> MachineBackend:
    """The motion and I/O backend the configuration names, configured but not yet active."""
    backend = _factory(MOTION_BACKENDS, config.backend, "backend.name")(config)
    if not isinstance(backend, MachineBackend):
        raise TypeError(f"backend {config.backend!r} factory returned {type(backend).__name__}")
    return backend


def create_gauge(config: MachineConfig, backend: MachineBackend) -> WidthGauge:
    """The width gauge the configuration names; the simulated gauge measures the simulated
    board when the motion backend is the simulation too."""
    gauge = _factory(GAUGE_BACKENDS, config.gauge, "gauge.name")(config, backend)
    if not isinstance(gauge, WidthGauge):
        raise TypeError(f"gauge {config.gauge!r} factory returned {type(gauge).__name__}")
    return gauge
