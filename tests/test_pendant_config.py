"""``[pendant]`` is checked like every other table: the shipped files load with their
commented pendant tables, a misspelt key or a bad value is one line naming it, and the
application exits 2 on it."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from app.config import ConfigError, default_config_path, load_config, parse_config
from app.resources import resource_path


def with_pendant(table: dict[str, object]) -> dict[str, object]:
    data = tomllib.loads(default_config_path().read_text(encoding="utf-8"))
    data["pendant"] = table
    return data


@pytest.mark.parametrize("name", ["machine.toml", "machine-modbus.toml", "machine-canopen.toml"])
def test_the_shipped_configurations_describe_the_pendant(name: str) -> None:
    path = resource_path(name)
    assert "[pendant.handwheel]" in path.read_text(encoding="utf-8")
    config = load_config(path)
    assert config.pendant.joystick.deadband == pytest.approx(0.05)


def test_the_simulated_machine_has_a_handwheel_and_a_joystick() -> None:
    pendant = load_config().pendant
    assert pendant.handwheel.fitted and pendant.joystick.fitted
    assert pendant.evdev.device == ""  # no USB pendant unless one is named


@pytest.mark.parametrize(
    ("table", "key", "allowed"),
    [
        ({"handwheel": {"fited": True}}, "pendant.handwheel.fited", "a known key"),
        ({"wheel": {}}, "pendant.wheel", "a known key of [pendant]"),
        ({"handwheel": {"max_counts_per_s": 0}}, "pendant.handwheel.max_counts_per_s", ">= 1"),
        ({"joystick": {"deadband": 0.7}}, "pendant.joystick.deadband", "<= 0.5"),
        ({"joystick": {"curve_exponent": "cubic"}}, "pendant.joystick.curve_exponent", "number"),
        (
            {"joystick": {"centre_tolerance_counts": 20000}},
            "pendant.joystick.centre_tolerance_counts",
            "less than full_scale_counts",
        ),
        ({"evdev": {"enable": "L1"}}, "pendant.evdev.enable", "BTN_TL"),
        ({"evdev": {"stick_x": "REL_X"}}, "pendant.evdev.stick_x", "ABS_"),
        ({"evdev": {"wheel": "ABS_WHEEL"}}, "pendant.evdev.wheel", "REL_"),
    ],
)
def test_a_bad_pendant_key_names_itself(table: dict[str, object], key: str, allowed: str) -> None:
    with pytest.raises(ConfigError) as caught:
        parse_config(with_pendant(table), "machine.toml")
    assert caught.value.key == key
    assert allowed in str(caught.value)


def test_the_application_exits_2_on_an_unknown_pendant_key(tmp_path: Path) -> None:
    bad = tmp_path / "machine.toml"
    text = default_config_path().read_text(encoding="utf-8")
    bad.write_text(text.replace("[pendant.joystick]\n", "[pendant.joystick]\ndeadzone = 0.1\n", 1))
    result = subprocess.run(
        [sys.executable, "-m", "app", "--config", str(bad)],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "pendant.joystick.deadzone" in lines[0]
