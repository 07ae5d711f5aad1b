"""The machine configuration: one TOML file that describes the hardware.

Why a strict reader: a configuration file is typed in by a technician on a panel PC. A
misspelt key or an out-of-range value must stop the start-up with one line that names the
key, the value and what is allowed (exit code 2), not be silently replaced by a default,
and never end in a traceback.

What lives here and what does not: the file describes the machine (axes and their limits,
I/O timings, the backend and its connection, the gauge, where the database and logs go) and
the factory defaults of the process parameters. The values a technician tunes on the System
screen (tool radius, start position, feeds, ...) live in the database with their change
history; the file only seeds them.
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from app.pendant_settings import PendantSettings, read_pendant_settings
from app.plant.settings import OpcuaSettings, read_opcua_settings
from app.resources import resource_path
from app.table_outlines import TableDevices, read_table_devices

DEFAULT_CONFIG_NAME = "machine.toml"


class ConfigError(ValueError):
    """A bad configuration value: ``key`` is the dotted TOML key, ``allowed`` says what is."""

    def __init__(self, key: str, value: object, allowed: str, source: str = "") -> None:
        where = f"{source}: " if source else ""
        super().__init__(f"{where}{key} = {value!r} is not allowed: {allowed}")
        self.key = key
        self.value = value
        self.allowed = allowed


class Section:
    """Reads one TOML table, checking types and ranges and refusing unknown keys."""

    def __init__(self, data: object, path: str, source: str) -> None:
        if not isinstance(data, Mapping):
            raise ConfigError(path, data, "a table", source)
        self._data: Mapping[str, Any] = data
        self._path = path
        self._source = source
        self._used: set[str] = set()

    def _key(self, name: str) -> str:
        return f"{self._path}.{name}" if self._path else name

    def error(self, name: str, value: object, allowed: str) -> ConfigError:
        return ConfigError(self._key(name), value, allowed, self._source)

    def number(
        self,
        name: str,
        default: float,
        minimum: float | None = None,
        maximum: float | None = None,
        *,
        exclusive_minimum: bool = False,
    ) -> float:
        self._used.add(name)
        value = self._data.get(name, default)
        lo = "-inf" if minimum is None else f"{minimum:g}"
        hi = "inf" if maximum is None else f"{maximum:g}"
        allowed = f"a number {'>' if exclusive_minimum else '>='} {lo} and <= {hi}"
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise self.error(name, value, allowed)
        try:
            number = float(value)
        except OverflowError:  # an integer like 10**400
            raise self.error(
                name, f"{str(value)[:12]}... ({len(str(value))} digits)", allowed
            ) from None
        below = minimum is not None and (
            number <= minimum if exclusive_minimum else number < minimum
        )
        if not math.isfinite(number) or below or (maximum is not None and number > maximum):
            raise self.error(name, value, allowed)
        return number

    def integer(self, name: str, default: int, minimum: int, maximum: int) -> int:
        self._used.add(name)
        value = self._data.get(name, default)
        if isinstance(value, bool) or not isinstance(value, int) or not minimum <= value <= maximum:
            raise self.error(name, value, f"a whole number from {minimum} to {maximum}")
        return value

    def boolean(self, name: str, default: bool) -> bool:
        self._used.add(name)
        value = self._data.get(name, default)
        if not isinstance(value, bool):
            raise self.error(name, value, "true or false")
        return value

    def text(self, name: str, default: str, choices: tuple[str, ...] | None = None) -> str:
        self._used.add(name)
        value = self._data.get(name, default)
        if not isinstance(value, str) or (choices is not None and value not in choices):
            allowed = "one of " + ", ".join(repr(c) for c in choices) if choices else "a string"
            raise self.error(name, value, allowed)
        return value

    def table(self, name: str) -> Section:
        self._used.add(name)
        return Section(self._data.get(name, {}), self._key(name), self._source)

    def table_list(self, name: str, maximum: int) -> list[Section]:
        """An array of tables (``name = [{...}, {...}]``), each checked like a table; the
        keys in messages read ``path.name[0].key``."""
        self._used.add(name)
        value = self._data.get(name, [])
        if not isinstance(value, list) or len(value) > maximum:
            raise self.error(name, value, f"a list of at most {maximum} tables")
        return [
            Section(item, f"{self._key(name)}[{i}]", self._source) for i, item in enumerate(value)
        ]

    def raw_table(self, name: str) -> dict[str, Any]:
        """A table handed over unchecked to the module that owns it (a backend's settings)."""
        self._used.add(name)
        value = self._data.get(name, {})
        if not isinstance(value, Mapping):
            raise self.error(name, value, "a table")
        return dict(value)

    def keys(self) -> list[str]:
        return list(self._data.keys())

    def __contains__(self, name: object) -> bool:
        return name in self._data

    def finish(self) -> None:
        """Refuse keys nobody read: a misspelt key must not silently fall back to a default."""
        unknown = sorted(set(self._data) - self._used)
        if unknown:
            raise self.error(
                unknown[0],
                self._data[unknown[0]],
                f"a known key of [{self._path}]" if self._path else "a known top-level table",
            )


@dataclass(frozen=True)
class AxisConfig:
    """One servo axis. Positions are in the axis unit (mm for X and Y, degrees for Z);
    velocities in unit/s, accelerations in unit/s^2, jerk in unit/s^3."""

    name: str
    unit: str
    min_position: float
    max_position: float
    max_velocity: float
    max_acceleration: float
    max_jerk: float
    jog_velocity: float
    jog_acceleration: float
    home_position: float
    home_switch_position: float
    homing_direction: int  # -1 or +1: the side the drive searches the home switch from
    homing_velocity: float
    absolute_encoder: bool
    following_error_limit: float
    limit_switch_margin: float  # how far beyond the soft limit the hardware limit switch sits


@dataclass(frozen=True)
class IOConfig:
    """Timings of the pneumatic and electric devices around the axes."""

    centering_time_s: float
    clamp_time_s: float
    spindle_runup_s: float
    sensor_timeout_s: float  # how long the machine waits for a sensor before an alarm


@dataclass(frozen=True)
class CycleConfig:
    """Which steps of the automatic cycle overlap, and how the axes settle before a cut.

    Why configurable: whether the centering device may retract while the clamps close
    depends on the mechanics (the board must be held by one or the other at every moment);
    off unless the machine's builder says so. The settle threshold replaces a fixed dwell:
    the cut starts as soon as every axis' following error is below it, at most
    ``settle_max_s`` after the axes came to rest (the former fixed dwell)."""

    centering_retract_while_clamping: bool = False
    settle_error_mm: float = 0.01  # X and Y following error below which a cut may start
    settle_error_deg: float = 0.01  # the same for the tilt
    settle_max_s: float = 0.1
    return_home_between_boards: bool = False  # False: the next approach starts at side B's end


def _read_cycle(section: Section) -> CycleConfig:
    d = CycleConfig()
    cycle = CycleConfig(
        centering_retract_while_clamping=section.boolean(
            "centering_retract_while_clamping", d.centering_retract_while_clamping
        ),
        settle_error_mm=section.number(
            "settle_error_mm", d.settle_error_mm, 0.0, 1.0, exclusive_minimum=True
        ),
        settle_error_deg=section.number(
            "settle_error_deg", d.settle_error_deg, 0.0, 1.0, exclusive_minimum=True
        ),
        settle_max_s=section.number("settle_max_s", d.settle_max_s, 0.0, 5.0),
        return_home_between_boards=section.boolean(
            "return_home_between_boards", d.return_home_between_boards
        ),
    )
    section.finish()
    return cycle


@dataclass(frozen=True)
class ProcessDefaults:
    """Factory values of the process parameters; the database holds the current ones."""

    tool_radius_mm: float
    machine_height_mm: float
    start_x_mm: float
    start_y_mm: float
    feed_mm_s: float
    lead_mm: float
    tilt_clearance_mm: float


@dataclass(frozen=True)
class MachineConfig:
    source: str
    backend: str
    backend_settings: dict[str, Any]
    gauge: str
    gauge_settings: dict[str, Any]
    period_s: float
    axes: dict[str, AxisConfig]
    io: IOConfig
    process: ProcessDefaults
    database_path: str  # empty: the user's data directory
    log_dir: str  # empty: the user's log directory
    log_level: str
    language: str
    extra: dict[str, Any] = field(default_factory=dict)
    given_keys: frozenset[str] = frozenset()
    opcua: OpcuaSettings = field(default_factory=OpcuaSettings)
    pendant: PendantSettings = field(default_factory=PendantSettings)
    cycle: CycleConfig = field(default_factory=CycleConfig)
    table_devices: TableDevices = field(default_factory=TableDevices)

    def with_backend(self, backend: str | None = None, gauge: str | None = None) -> MachineConfig:
        """The same configuration with the backends chosen on the command line."""
        return replace(self, backend=backend or self.backend, gauge=gauge or self.gauge)


_AXIS_DEFAULTS: dict[str, dict[str, Any]] = {
    "X": {
        "unit": "mm",
        "min": -5.0,
        "max": 3900.0,
        "vmax": 400.0,
        "amax": 2000.0,
        "jmax": 20000.0,
        "home": 0.0,
        "dir": -1,
        "fe": 2.0,
    },
    "Y": {
        "unit": "mm",
        "min": -5.0,
        "max": 800.0,
        "vmax": 300.0,
        "amax": 2000.0,
        "jmax": 20000.0,
        "home": 0.0,
        "dir": -1,
        "fe": 2.0,
    },
    "Z": {
        "unit": "deg",
        "min": -15.0,
        "max": 15.0,
        "vmax": 30.0,
        "amax": 150.0,
        "jmax": 1500.0,
        "home": 0.0,
        "dir": -1,
        "fe": 0.5,
    },
}


AXIS_REACH: dict[str, float] = {"X": 20_000.0, "Y": 5_000.0, "Z": 60.0}
"""No stave jointer's axis reaches further from its origin (mm, mm, degrees): a limit beyond
is a typing error (``-1e12``), and homing towards it would never end."""


def _read_axis(section: Section, name: str) -> AxisConfig:
    d = _AXIS_DEFAULTS[name]
    unit = section.text("unit", d["unit"], (d["unit"],))
    reach = AXIS_REACH[name]
    lo = section.number("min_position", d["min"], -reach, reach)
    hi = section.number("max_position", d["max"], -reach, reach)
    if hi <= lo:
        raise section.error("max_position", hi, f"greater than min_position ({lo:g})")
    vmax = section.number("max_velocity", d["vmax"], 0.0, 10000.0, exclusive_minimum=True)
    amax = section.number("max_acceleration", d["amax"], 0.0, 100000.0, exclusive_minimum=True)
    jmax = section.number("max_jerk", d["jmax"], 0.0, 10_000_000.0, exclusive_minimum=True)
    jog_v = section.number("jog_velocity", vmax / 4, 0.0, vmax, exclusive_minimum=True)
    jog_a = section.number("jog_acceleration", amax / 4, 0.0, amax, exclusive_minimum=True)
    home = section.number("home_position", d["home"], lo, hi)
    switch = section.number("home_switch_position", lo, lo, hi)
    direction = section.integer("homing_direction", d["dir"], -1, 1)
    if direction == 0:
        raise section.error("homing_direction", 0, "-1 or 1")
    homing_v = section.number("homing_velocity", vmax / 10, 0.0, vmax, exclusive_minimum=True)
    absolute = section.text("encoder", "absolute", ("absolute", "incremental")) == "absolute"
    fe = section.number("following_error_limit", d["fe"], 0.0, 100.0, exclusive_minimum=True)
    margin = section.number("limit_switch_margin", 5.0, 0.0, 100.0)
    section.finish()
    return AxisConfig(
        name,
        unit,
        lo,
        hi,
        vmax,
        amax,
        jmax,
        jog_v,
        jog_a,
        home,
        switch,
        direction,
        homing_v,
        absolute,
        fe,
        margin,
    )


BACKENDS_KNOWN = ("sim", "modbus", "canopen")
GAUGES_KNOWN = ("sim", "serial")


def parse_config(data: Mapping[str, Any], source: str = "") -> MachineConfig:
    """Build a MachineConfig from parsed TOML, raising ConfigError on the first bad value."""
    root = Section(data, "", source)

    backend = root.table("backend")
    backend_name = backend.text("name", "sim", BACKENDS_KNOWN)
    period_ms = backend.number("period_ms", 4.0, 1.0, 50.0)
    backend_settings = {n: backend.raw_table(n) for n in BACKENDS_KNOWN if n in backend}
    backend.finish()

    gauge = root.table("gauge")
    gauge_name = gauge.text("name", "sim", GAUGES_KNOWN)
    gauge_settings = {n: gauge.raw_table(n) for n in GAUGES_KNOWN if n in gauge}
    gauge.finish()

    axes_section = root.table("axes")
    axes = {name: _read_axis(axes_section.table(name), name) for name in ("X", "Y", "Z")}
    axes_section.finish()

    io = root.table("io")
    io_config = IOConfig(
        centering_time_s=io.number("centering_time_s", 0.8, 0.0, 30.0),
        clamp_time_s=io.number("clamp_time_s", 0.6, 0.0, 30.0),
        spindle_runup_s=io.number("spindle_runup_s", 2.0, 0.0, 60.0),
        sensor_timeout_s=io.number("sensor_timeout_s", 3.0, 0.1, 120.0),
    )
    io.finish()

    proc = root.table("process")
    process = ProcessDefaults(
        tool_radius_mm=proc.number("tool_radius_mm", 40.0, 1.0, 200.0),
        machine_height_mm=proc.number("machine_height_mm", 250.0, 0.0, 2000.0),
        start_x_mm=proc.number("start_x_mm", 100.0),
        start_y_mm=proc.number("start_y_mm", 400.0),
        feed_mm_s=proc.number("feed_mm_s", 120.0, 1.0, 1000.0),
        lead_mm=proc.number("lead_mm", 60.0, 1.0, 500.0),
        tilt_clearance_mm=proc.number("tilt_clearance_mm", 50.0, 0.0, 1000.0),
    )
    proc.finish()
    if process.lead_mm <= process.tool_radius_mm:
        raise ConfigError(
            "process.lead_mm",
            process.lead_mm,
            f"greater than process.tool_radius_mm ({process.tool_radius_mm:g})",
            source,
        )

    db = root.table("database")
    database_path = db.text("path", "")
    db.finish()

    log = root.table("logging")
    log_dir = log.text("dir", "")
    log_level = log.text("level", "INFO", ("DEBUG", "INFO", "WARNING", "ERROR"))
    log.finish()

    ui = root.table("ui")
    language = ui.text("language", "en", ("en", "sl"))
    ui.finish()

    opcua = read_opcua_settings(root.table("opcua"))
    pendant = read_pendant_settings(root.table("pendant"))
    cycle = _read_cycle(root.table("cycle"))
    table_devices = read_table_devices(root.table("keep_out"))

    root.finish()
    return MachineConfig(
        source,
        backend_name,
        backend_settings,
        gauge_name,
        gauge_settings,
        period_ms / 1000.0,
        axes,
        io_config,
        process,
        database_path,
        log_dir,
        log_level,
        language,
        opcua=opcua,
        pendant=pendant,
        cycle=cycle,
        table_devices=table_devices,
    )


def default_config_path() -> Path:
    return resource_path(DEFAULT_CONFIG_NAME)


def load_config(path: Path | str | None = None) -> MachineConfig:
    """Read and check a configuration file (the shipped default when ``path`` is None)."""
    file = Path(path) if path is not None else default_config_path()
    try:
        size = file.stat().st_size
        if size > MAX_CONFIG_BYTES:
            raise ConfigError("--config", str(file), f"a file of at most {MAX_CONFIG_BYTES} bytes")
        text = file.read_text(encoding="utf-8")
    except OSError as exc:
        raise ConfigError("--config", str(file), f"a readable file ({exc.strerror})") from exc
    except UnicodeDecodeError as exc:
        raise ConfigError(
            "--config", str(file), f"UTF-8 text (byte {exc.start} is not: {exc.reason})"
        ) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError("--config", str(file), f"valid TOML ({exc})") from exc
    except RecursionError:
        raise ConfigError("--config", str(file), "TOML nested at most a few levels deep") from None
    config = parse_config(data, str(file))
    return replace(config, given_keys=given_keys(data))


MAX_CONFIG_BYTES = 1024 * 1024
"""Largest configuration file read (the commented samples are about 20 kB)."""


def given_keys(data: Mapping[str, Any], prefix: str = "", depth: int = 0) -> frozenset[str]:
    """Every dotted key the file itself sets (tables too), so that rules can tell a value
    typed in from a default (see :func:`real_backend_problem`)."""
    keys: set[str] = set()
    for name, value in data.items():
        key = f"{prefix}{name}"
        keys.add(key)
        if isinstance(value, Mapping) and depth < 8:
            keys |= given_keys(value, f"{key}.", depth + 1)
    return frozenset(keys)


REAL_BACKEND_REQUIRED_KEYS: tuple[str, ...] = tuple(
    f"axes.{axis}.{key}"
    for axis in ("X", "Y", "Z")
    for key in ("min_position", "max_position", "home_switch_position")
)


def real_backend_problem(config: MachineConfig) -> ConfigError | None:
    """Why this configuration must not drive real hardware, or None.

    An empty or truncated file would run real drives with the simulation's default travel:
    so a real backend needs its own table and every axis's limits and home switch written
    in the file itself.
    """
    if config.backend == "sim":
        return None
    required = [f"backend.{config.backend}", *REAL_BACKEND_REQUIRED_KEYS]
    if config.gauge != "sim":
        required.append(f"gauge.{config.gauge}")
    missing = [key for key in required if key not in config.given_keys]
    if not missing:
        return None
    return ConfigError(
        missing[0],
        "(not in the file)",
        f"set in the file for backend {config.backend!r}: a real machine never runs on "
        f"default travel ({len(missing)} key(s) missing, the file is empty or truncated?)",
        config.source,
    )
