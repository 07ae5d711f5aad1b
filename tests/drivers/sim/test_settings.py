"""The ``[backend.sim]`` and ``[gauge.sim]`` options: checked strictly, documented in the
shipped machine.toml, and every documented option actually read."""

from __future__ import annotations

import dataclasses
import re
import tomllib
from typing import Any

import pytest

from app.config import ConfigError, default_config_path
from app.drivers import registry
from app.drivers.sim import settings as settings_module
from app.drivers.sim.settings import (
    GaugeSettings,
    SimSettings,
    WidthDistribution,
    parse_gauge_settings,
    parse_sim_settings,
)
from tests.drivers.sim.rig import make_config

AXES = make_config().axes


def commented_options(table: str) -> dict[str, Any]:
    """The ``# key = value`` lines of one table of the shipped machine.toml, parsed."""
    text = default_config_path().read_text(encoding="utf-8")
    section = text.split(f"[{table}]\n", 1)[1].split("\n[", 1)[0]
    lines = [m.group(1) for m in re.finditer(r"^# (\w+ = .+?) {2,}#", section, re.M)]
    lines += [m.group(1) for m in re.finditer(r"^# (\w+ = [^#\n]+)$", section, re.M)]
    return tomllib.loads("\n".join(lines))


def test_the_shipped_defaults_parse() -> None:
    config = make_config()
    assert parse_sim_settings(config.backend_settings["sim"], config.axes) == SimSettings()
    assert parse_gauge_settings(config.gauge_settings["sim"]) == GaugeSettings()


def test_the_commented_options_in_machine_toml_are_all_the_options_and_valid() -> None:
    backend = commented_options("backend.sim")
    gauge = commented_options("gauge.sim")
    sim_fields = {f.name for f in dataclasses.fields(SimSettings)} - {"board_widths"}
    sim_fields |= {f"board_width_{p}_mm" for p in ("mean", "sd", "min", "max")}
    gauge_fields = {f.name for f in dataclasses.fields(GaugeSettings)} - {"widths"}
    gauge_fields |= {f"width_{p}_mm" for p in ("mean", "sd", "min", "max")}
    assert set(backend) == sim_fields
    assert set(gauge) == gauge_fields
    parsed = parse_sim_settings(backend, AXES)
    defaults = SimSettings()
    assert parsed.start_position == {"X": 1000.0}
    assert dataclasses.replace(parsed, start_position={}, home_switch_width={}) == defaults
    assert parse_gauge_settings(gauge) == GaugeSettings()
    doc = settings_module.__doc__ or ""
    assert all(f"``{name}``" in doc or name in doc for name in sim_fields | gauge_fields)


@pytest.mark.parametrize(
    ("raw", "key", "fragment"),
    [
        ({"noise": 1}, "backend.sim.noise", "a known key of [backend.sim]"),
        ({"seed": -1}, "backend.sim.seed", "a whole number from 0"),
        ({"seed": 1.5}, "backend.sim.seed", "a whole number"),
        ({"position_gain_1_s": 0}, "backend.sim.position_gain_1_s", ">= 1 and <= 400"),
        ({"integral_time_s": "fast"}, "backend.sim.integral_time_s", "a number"),
        ({"torque_limit_factor": float("nan")}, "backend.sim.torque_limit_factor", "a number"),
        ({"auto_load": 1}, "backend.sim.auto_load", "true or false"),
        ({"start_position": 5.0}, "backend.sim.start_position", "a table of axis name"),
        ({"start_position": {"W": 1.0}}, "backend.sim.start_position.W", "one of X, Y, Z"),
        (
            {"start_position": {"X": 3906.0}},
            "backend.sim.start_position.X",
            ">= -10 and <= 3905 (mm)",
        ),
        ({"start_position": {"Z": True}}, "backend.sim.start_position.Z", "(deg)"),
        ({"home_switch_width": {"Y": 0.0}}, "backend.sim.home_switch_width.Y", "> 0"),
        (
            {"board_width_min_mm": 200.0, "board_width_max_mm": 150.0},
            "backend.sim.board_width_max_mm",
            ">= board_width_min_mm (200)",
        ),
        (
            {"board_width_mean_mm": 300.0},
            "backend.sim.board_width_mean_mm",
            "from board_width_min_mm (100) to board_width_max_mm (175)",
        ),
        ({"operator_delay_s": -1.0}, "backend.sim.operator_delay_s", ">= 0"),
    ],
)
def test_bad_backend_options_name_key_value_and_what_is_allowed(
    raw: dict[str, Any], key: str, fragment: str
) -> None:
    with pytest.raises(ConfigError) as info:
        parse_sim_settings(raw, AXES)
    assert info.value.key == key
    assert fragment in str(info.value)
    assert key in str(info.value)


@pytest.mark.parametrize(
    ("raw", "key", "fragment"),
    [
        ({"noise_mm": -0.1}, "gauge.sim.noise_mm", ">= 0 and <= 10"),
        ({"measurement_time_s": "soon"}, "gauge.sim.measurement_time_s", "a number"),
        ({"width_sd_mm": -1}, "gauge.sim.width_sd_mm", ">= 0"),
        ({"seed": True}, "gauge.sim.seed", "a whole number"),
        ({"delay": 1}, "gauge.sim.delay", "a known key of [gauge.sim]"),
    ],
)
def test_bad_gauge_options(raw: dict[str, Any], key: str, fragment: str) -> None:
    with pytest.raises(ConfigError) as info:
        parse_gauge_settings(raw)
    assert info.value.key == key and fragment in str(info.value)


def test_the_factories_check_their_tables() -> None:
    with pytest.raises(ConfigError, match=r"backend\.sim\.noise_mm"):
        registry.create_backend(make_config({"noise_mm": 0.1}))
    config = make_config(gauge={"noise_mm": "big"})
    backend = registry.create_backend(config)
    with pytest.raises(ConfigError, match=r"gauge\.sim\.noise_mm = 'big'"):
        registry.create_gauge(config, backend)


def test_a_cut_normal_distribution_stays_in_its_bounds() -> None:
    import random

    rng = random.Random(3)
    distribution = WidthDistribution(100.0, 500.0, 99.0, 101.0)
    assert all(99.0 <= distribution.draw(rng) <= 101.0 for _ in range(50))
    assert WidthDistribution(150.0, 0.0, 100.0, 200.0).draw(rng) == 150.0
