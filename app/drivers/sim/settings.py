"""The options of the simulated machine (``[backend.sim]``) and gauge (``[gauge.sim]``).

Why here and not in ``app.config``: the configuration reader hands each backend its own table
unchecked, so that adding an option to one backend does not touch the shared reader. The
simulation therefore checks its own options with the same strictness: a misspelt key or a
value out of range raises :class:`app.config.ConfigError` naming the dotted key (for example
``backend.sim.noise_mm``), the value and what is allowed; nothing falls back silently.

``[backend.sim]`` (every key optional; units in the names, axis units are mm for X/Y and
degrees for Z):

- ``seed`` (int >= 0, default 0): seeds every random choice of the world (start positions of
  incremental axes, board widths), so that a run is reproducible.
- ``start_position`` (table axis -> number): the physical position of an axis at power-up,
  between its two limit switches. Default: ``home_position`` for absolute axes, a seeded
  random position between the soft limits for incremental ones.
- ``home_switch_width`` (table axis -> number > 0, default 20 for mm axes, 5 for degrees): how
  long the home switch cam is. Its reference edge sits at the axis' ``home_switch_position``
  and the cam extends from there in the homing direction.
- ``position_gain_1_s`` (default 60): proportional gain of the drives' position loop.
- ``integral_time_s`` (default 0.1): integral time of the position loop (PI).
- ``velocity_time_constant_s`` (default 0.002): time constant of the inner velocity loop.
- ``torque_limit_factor`` (default 2.5): the drive's acceleration limit (current limit) as a
  multiple of the axis' ``max_acceleration``; quick stops decelerate at 60 % of it.
- ``friction_fraction`` (default 0.02): Coulomb friction as a fraction of
  ``max_acceleration``; it brakes a coasting axis and is what the integral term works against.
- ``following_error_time_s`` (default 0.01): how long the following error may exceed the
  axis' ``following_error_limit`` before the drive faults (CiA 402 0x6066).
- ``heartbeat_timeout_s`` (default 0.1): after this long without the master, a powered drive
  faults (EMCY 0x8130) and the I/O coupler switches its outputs off.
- ``estop_stop_time_s`` (default 0.5): the E-stop is a stop category 1: drives brake on their
  quick-stop ramp, and the safety relay removes torque (STO) at standstill or after this time.
- ``board_present`` (bool, default false): a board lies on the table at power-up.
- ``board_width_mean_mm``, ``board_width_sd_mm``, ``board_width_min_mm``,
  ``board_width_max_mm`` (defaults 140, 15, 100, 175): the true width of a board put on the
  table without a width, a normal distribution cut to [min, max].
- ``auto_load`` (bool, default false): a simulated operator keeps the machine fed (demos,
  ``stave simulate``): a board at power-up, the finished board taken away and a new one put
  in, each ``operator_delay_s`` after the clamps released it.
- ``operator_delay_s`` (default 3.0): the simulated operator's delay.

``[gauge.sim]``:

- ``seed`` (int >= 0, default 0): seeds the gauge's noise (and its own widths, see below).
- ``noise_mm`` (default 0.05): standard deviation of the gaussian measurement noise.
- ``measurement_time_s`` (default 0.3): time from ``request()`` to the reading.
- ``out_of_range_mm`` (default 999.0): what the gauge answers when ``gauge_out_of_range`` is
  injected.
- ``width_mean_mm``, ``width_sd_mm``, ``width_min_mm``, ``width_max_mm`` (defaults 140, 15,
  100, 175): the true widths the gauge measures when there is no simulated world (a gauge
  used beside a real machine backend); with the simulated machine it measures the board on
  the table.
"""

from __future__ import annotations

import math
import random
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from app.config import AxisConfig, ConfigError


@dataclass(frozen=True)
class WidthDistribution:
    """True widths of boards: normal, cut to [min_mm, max_mm]."""

    # Widths every shipped sample recipe cuts on the shipped machine (the narrowest range is
    # Barrique 225 l's, to 178.6 mm: its bevel from the belly reaches the tilt axis's 15 deg).
    mean_mm: float = 140.0
    sd_mm: float = 15.0
    min_mm: float = 100.0
    max_mm: float = 175.0

    def draw(self, rng: random.Random) -> float:
        """One width; redraws outside the bounds (a cut normal), clamps after 100 tries."""
        if self.sd_mm == 0.0:
            return self.mean_mm
        for _ in range(100):
            width = rng.gauss(self.mean_mm, self.sd_mm)
            if self.min_mm <= width <= self.max_mm:
                return width
        return min(max(self.mean_mm, self.min_mm), self.max_mm)


@dataclass(frozen=True)
class SimSettings:
    """The checked ``[backend.sim]`` table (see the module docstring for each option)."""

    seed: int = 0
    start_position: dict[str, float] = field(default_factory=dict)
    home_switch_width: dict[str, float] = field(default_factory=dict)
    position_gain_1_s: float = 60.0
    integral_time_s: float = 0.1
    velocity_time_constant_s: float = 0.002
    torque_limit_factor: float = 2.5
    friction_fraction: float = 0.02
    following_error_time_s: float = 0.01
    heartbeat_timeout_s: float = 0.1
    estop_stop_time_s: float = 0.5
    board_present: bool = False
    board_widths: WidthDistribution = WidthDistribution()
    auto_load: bool = False
    operator_delay_s: float = 3.0


@dataclass(frozen=True)
class GaugeSettings:
    """The checked ``[gauge.sim]`` table (see the module docstring for each option)."""

    seed: int = 0
    noise_mm: float = 0.05
    measurement_time_s: float = 0.3
    out_of_range_mm: float = 999.0
    widths: WidthDistribution = WidthDistribution()


class _Options:
    """One raw table: typed getters that name the dotted key on error, unknown keys refused."""

    def __init__(self, raw: object, prefix: str) -> None:
        if not isinstance(raw, Mapping):
            raise ConfigError(prefix, raw, "a table")
        self._raw: Mapping[str, Any] = raw
        self._prefix = prefix
        self._used: set[str] = set()

    def key(self, name: str) -> str:
        return f"{self._prefix}.{name}"

    def number(
        self,
        name: str,
        default: float,
        minimum: float,
        maximum: float,
        *,
        exclusive_minimum: bool = False,
    ) -> float:
        self._used.add(name)
        value = self._raw.get(name, default)
        allowed = f"a number {'>' if exclusive_minimum else '>='} {minimum:g} and <= {maximum:g}"
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise ConfigError(self.key(name), value, allowed)
        number = float(value)
        too_low = number <= minimum if exclusive_minimum else number < minimum
        if not math.isfinite(number) or too_low or number > maximum:
            raise ConfigError(self.key(name), value, allowed)
        return number

    def integer(self, name: str, default: int, minimum: int, maximum: int) -> int:
        self._used.add(name)
        value = self._raw.get(name, default)
        if (
            isinstance(value, bool)
            or not isinstance(value, int)
            or not (minimum <= value <= maximum)
        ):
            raise ConfigError(self.key(name), value, f"a whole number from {minimum} to {maximum}")
        return value

    def boolean(self, name: str, default: bool) -> bool:
        self._used.add(name)
        value = self._raw.get(name, default)
        if not isinstance(value, bool):
            raise ConfigError(self.key(name), value, "true or false")
        return value

    def axis_table(
        self,
        name: str,
        axes: Mapping[str, AxisConfig],
        bounds: Mapping[str, tuple[float, float]],
        *,
        exclusive_minimum: bool = False,
    ) -> dict[str, float]:
        """A table axis name -> number, each within its axis' bounds."""
        self._used.add(name)
        value = self._raw.get(name, {})
        if not isinstance(value, Mapping):
            raise ConfigError(
                self.key(name), value, "a table of axis name = number, e.g. { X = 100.0 }"
            )
        result: dict[str, float] = {}
        for axis, number in value.items():
            sub = f"{self.key(name)}.{axis}"
            if axis not in axes:
                raise ConfigError(sub, number, "an axis name: one of " + ", ".join(axes))
            lo, hi = bounds[axis]
            op = ">" if exclusive_minimum else ">="
            allowed = f"a number {op} {lo:g} and <= {hi:g} ({axes[axis].unit})"
            if isinstance(number, bool) or not isinstance(number, int | float):
                raise ConfigError(sub, number, allowed)
            n = float(number)
            too_low = n <= lo if exclusive_minimum else n < lo
            if not math.isfinite(n) or too_low or n > hi:
                raise ConfigError(sub, number, allowed)
            result[axis] = n
        return result

    def finish(self) -> None:
        unknown = sorted(set(self._raw) - self._used)
        if unknown:
            known = ", ".join(sorted(self._used))
            raise ConfigError(
                self.key(unknown[0]),
                self._raw[unknown[0]],
                f"a known key of [{self._prefix}]: {known}",
            )


def _distribution(options: _Options, prefix: str) -> WidthDistribution:
    d = WidthDistribution()
    mean = options.number(f"{prefix}_mean_mm", d.mean_mm, 1.0, 1000.0)
    sd = options.number(f"{prefix}_sd_mm", d.sd_mm, 0.0, 500.0)
    low = options.number(f"{prefix}_min_mm", d.min_mm, 0.0, 1000.0)
    high = options.number(f"{prefix}_max_mm", d.max_mm, 0.0, 1000.0)
    if high < low:
        raise ConfigError(
            options.key(f"{prefix}_max_mm"), high, f"a number >= {prefix}_min_mm ({low:g})"
        )
    if not low <= mean <= high:
        raise ConfigError(
            options.key(f"{prefix}_mean_mm"),
            mean,
            f"a number from {prefix}_min_mm ({low:g}) to {prefix}_max_mm ({high:g})",
        )
    return WidthDistribution(mean, sd, low, high)


def parse_sim_settings(raw: object, axes: Mapping[str, AxisConfig]) -> SimSettings:
    """Check ``[backend.sim]``; raises ConfigError with the ``backend.sim.*`` key."""
    options = _Options(raw, "backend.sim")
    d = SimSettings()
    seed = options.integer("seed", d.seed, 0, 2**63 - 1)
    travel = {
        name: (a.min_position - a.limit_switch_margin, a.max_position + a.limit_switch_margin)
        for name, a in axes.items()
    }
    start = options.axis_table("start_position", axes, travel)
    width_bounds = {
        name: (0.0, a.max_position - a.min_position + 100.0) for name, a in axes.items()
    }
    widths = options.axis_table("home_switch_width", axes, width_bounds, exclusive_minimum=True)
    settings = SimSettings(
        seed=seed,
        start_position=start,
        home_switch_width=widths,
        position_gain_1_s=options.number("position_gain_1_s", d.position_gain_1_s, 1.0, 400.0),
        integral_time_s=options.number("integral_time_s", d.integral_time_s, 0.005, 100.0),
        velocity_time_constant_s=options.number(
            "velocity_time_constant_s", d.velocity_time_constant_s, 0.001, 0.1
        ),
        torque_limit_factor=options.number(
            "torque_limit_factor", d.torque_limit_factor, 1.0, 100.0
        ),
        friction_fraction=options.number("friction_fraction", d.friction_fraction, 0.0, 0.5),
        following_error_time_s=options.number(
            "following_error_time_s", d.following_error_time_s, 0.0, 10.0
        ),
        heartbeat_timeout_s=options.number(
            "heartbeat_timeout_s", d.heartbeat_timeout_s, 0.001, 60.0
        ),
        estop_stop_time_s=options.number("estop_stop_time_s", d.estop_stop_time_s, 0.0, 30.0),
        board_present=options.boolean("board_present", d.board_present),
        board_widths=_distribution(options, "board_width"),
        auto_load=options.boolean("auto_load", d.auto_load),
        operator_delay_s=options.number("operator_delay_s", d.operator_delay_s, 0.0, 3600.0),
    )
    options.finish()
    return settings


def parse_gauge_settings(raw: object) -> GaugeSettings:
    """Check ``[gauge.sim]``; raises ConfigError with the ``gauge.sim.*`` key."""
    options = _Options(raw, "gauge.sim")
    d = GaugeSettings()
    settings = GaugeSettings(
        seed=options.integer("seed", d.seed, 0, 2**63 - 1),
        noise_mm=options.number("noise_mm", d.noise_mm, 0.0, 10.0),
        measurement_time_s=options.number("measurement_time_s", d.measurement_time_s, 0.0, 60.0),
        out_of_range_mm=options.number("out_of_range_mm", d.out_of_range_mm, -1e6, 1e6),
        widths=_distribution(options, "width"),
    )
    options.finish()
    return settings
