"""Every backend's and gauge's table of a configuration checked at once, opening nothing.

Why here and not only where each backend starts: the backends start in the machine process,
and a wrong key there used to kill that process with a traceback while the screens opened
anyway ("The machine is not running"). The operator application runs this in its own process
before it starts the machine process, so a bad table ends the start-up with one line and exit
status 2, the same as every other configuration error (``stave probe`` runs it too). Each
table is read by the very parser its backend uses, so there is one copy of each rule.

Besides each table alone, the rules that span tables: the serial gauge's range must lie
within what the machine can hold (the Y travel), and a real backend needs a configuration
that really describes the machine (:func:`app.config.real_backend_problem`).
"""

from __future__ import annotations

from collections.abc import Callable

from app.config import ConfigError, MachineConfig, real_backend_problem


def _sim(config: MachineConfig) -> None:
    from app.drivers.sim.settings import parse_sim_settings

    parse_sim_settings(config.backend_settings.get("sim", {}), config.axes)


def _modbus(config: MachineConfig) -> None:
    from app.drivers.modbus.settings import parse_modbus_settings

    parse_modbus_settings(config.backend_settings.get("modbus", {}), config)


def _canopen(config: MachineConfig) -> None:
    from app.drivers.canopen.settings import parse_settings

    parse_settings(config.backend_settings.get("canopen", {}), config)


def _sim_gauge(config: MachineConfig) -> None:
    from app.drivers.sim.settings import parse_gauge_settings

    parse_gauge_settings(config.gauge_settings.get("sim", {}))


def _serial_gauge(config: MachineConfig) -> None:
    from app.drivers.serial_gauge.settings import parse_serial_gauge_settings

    settings = parse_serial_gauge_settings(config.gauge_settings.get("serial", {}), config)
    y = config.axes["Y"]
    travel_mm = y.max_position - y.min_position
    if settings.max_width_mm > travel_mm:
        raise ConfigError(
            "gauge.serial.max_width_mm",
            settings.max_width_mm,
            f"at most the Y travel ({travel_mm:g} mm): no wider board fits the machine",
            config.source,
        )


BACKEND_CHECKS: dict[str, Callable[[MachineConfig], None]] = {
    "sim": _sim,
    "modbus": _modbus,
    "canopen": _canopen,
}
GAUGE_CHECKS: dict[str, Callable[[MachineConfig], None]] = {
    "sim": _sim_gauge,
    "serial": _serial_gauge,
}


def _evdev_pendant(config: MachineConfig) -> None:
    """A USB pendant's event code names must be ones the Linux input layer knows."""
    settings = config.pendant.evdev
    if not settings.device:
        return
    from app.drivers.evdev_pendant.device import event_code

    for role, name in settings.code_names().items():
        try:
            event_code(name)
        except ValueError:
            raise ConfigError(
                f"pendant.evdev.{role}",
                name,
                "an event code name the Linux input layer knows (see evtest's list)",
                config.source,
            ) from None


def check_settings(config: MachineConfig, *, to_run: bool = True) -> None:
    """ConfigError (one line, the dotted key) for the first bad table: the chosen backend's
    and gauge's, and every other backend or gauge table the file has. ``to_run``: the machine
    is to run on it (the operator application), not only be looked at (``stave probe``,
    which never enables a drive), so a real backend needs a complete machine description."""
    problem = real_backend_problem(config) if to_run else None
    if problem is not None:
        raise problem
    for name in dict.fromkeys([config.backend, *config.backend_settings]):
        BACKEND_CHECKS[name](config)
    for name in dict.fromkeys([config.gauge, *config.gauge_settings]):
        GAUGE_CHECKS[name](config)
    _evdev_pendant(config)
