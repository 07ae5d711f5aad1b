"""The configuration reader: the shipped default loads, and every kind of bad value is one
clear line naming the key, the value and what is allowed."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from app.config import ConfigError, default_config_path, load_config, parse_config


def default_data() -> dict:
    return tomllib.loads(default_config_path().read_text(encoding="utf-8"))


def test_shipped_default_loads() -> None:
    config = load_config()
    assert config.backend == "sim" and config.gauge == "sim"
    assert config.period_s == pytest.approx(0.004)
    assert set(config.axes) == {"X", "Y", "Z"}
    assert config.axes["Z"].unit == "deg"


@pytest.mark.parametrize(
    ("edit", "key", "allowed"),
    [
        (lambda d: d["backend"].update(name="profibus"), "backend.name", "'sim'"),
        (lambda d: d["backend"].update(period_ms=0.1), "backend.period_ms", ">= 1"),
        (lambda d: d["axes"]["X"].update(max_velocity=-3), "axes.X.max_velocity", "> 0"),
        (lambda d: d["axes"]["X"].update(max_velocity="fast"), "axes.X.max_velocity", "number"),
        (
            lambda d: d["axes"]["Y"].update(max_position=-10),
            "axes.Y.max_position",
            "greater than min_position",
        ),
        (lambda d: d["axes"]["Z"].update(encoder="optical"), "axes.Z.encoder", "'absolute'"),
        (lambda d: d["axes"]["Z"].update(homing_direction=0), "axes.Z.homing_direction", "-1"),
        (lambda d: d["axes"]["X"].update(max_velocityy=3), "axes.X.max_velocityy", "known key"),
        (lambda d: d.update(spindle={}), "spindle", "known top-level"),
        (lambda d: d["process"].update(lead_mm=10), "process.lead_mm", "tool_radius"),
        (lambda d: d["io"].update(clamp_time_s=float("nan")), "io.clamp_time_s", "number"),
        (lambda d: d["gauge"].update(name=3), "gauge.name", "'serial'"),
    ],
)
def test_bad_values_name_key_value_and_allowed(edit, key: str, allowed: str) -> None:
    data = default_data()
    edit(data)
    with pytest.raises(ConfigError) as info:
        parse_config(data, "machine.toml")
    assert info.value.key == key
    assert allowed in str(info.value)
    assert "\n" not in str(info.value)


def test_unreadable_and_malformed_files(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match="readable file"):
        load_config(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("[backend\nname = 'sim'\n")
    with pytest.raises(ConfigError, match="valid TOML"):
        load_config(bad)


def test_command_line_overrides_backend() -> None:
    config = load_config().with_backend("modbus", "serial")
    assert (config.backend, config.gauge) == ("modbus", "serial")


def test_app_exits_2_with_one_line_on_bad_config(tmp_path: Path) -> None:
    bad = tmp_path / "machine.toml"
    bad.write_text(
        default_config_path().read_text().replace('name = "sim"', 'name = "ethercat"', 1)
    )
    result = subprocess.run(
        [sys.executable, "-m", "app", "--config", str(bad)],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1
    assert "backend.name" in lines[0] and "ethercat" in lines[0] and "'modbus'" in lines[0]
