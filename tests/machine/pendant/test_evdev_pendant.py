"""USB pendants and gamepads: a recorded event stream (an evtest capture of a gamepad, these
machines have no /dev/uinput to make a virtual one) replayed into the product's mapping and
into the machine; a configured pendant that is not plugged in; code names checked at start."""

from __future__ import annotations

import tomllib
from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path

import pytest

from app.config import ConfigError, default_config_path, parse_config
from app.drivers.evdev_pendant import create_pendant
from app.drivers.evdev_pendant.device import EvdevPendant
from app.drivers.evdev_pendant.mapping import EV_SYN, SYN_DROPPED, SYN_REPORT, EventMapping
from app.drivers.settings_check import check_settings
from app.machine import commands as cmd
from app.machine.runtime import MachineRuntime
from app.machine.snapshot import JogSource
from app.machine.states import MachineState
from app.pendant_settings import EvdevSettings
from tests.machine.pendant.evtest_replay import DATA, ReplayedPendant, read_capture

GAMEPAD = EvdevSettings(
    enable="BTN_TL",
    stick_x="ABS_X",
    stick_y="ABS_Y",
    wheel="REL_DIAL",
    select_y="BTN_EAST",
    step_x10="BTN_NORTH",
)
CAPTURE = read_capture(DATA / "gamepad-evtest.txt")


def pendant_config(evdev: dict[str, object]):  # type: ignore[no-untyped-def]
    data = tomllib.loads(default_config_path().read_text(encoding="utf-8"))
    for axis in ("X", "Y"):
        data["axes"][axis]["encoder"] = "absolute"
    data["pendant"]["evdev"].update(evdev)
    data["pendant"]["handwheel"]["fitted"] = False
    data["pendant"]["joystick"]["fitted"] = False
    return parse_config(data, "machine.toml")


def test_the_capture_maps_to_enable_stick_axis_multiplier_and_detents() -> None:
    assert CAPTURE.name == "Microsoft X-Box 360 pad"
    pendant = ReplayedPendant(CAPTURE, GAMEPAD, 0.004)
    readings = []
    while not pendant.finished:
        readings.append(pendant.read())
    unenabled = [r for r in readings[:20] if r.sticks.get("X", 0.0) > 0.9]
    assert unenabled and not any(r.enable for r in unenabled)  # pushed without the button
    enabled = [r for r in readings if r.enable and r.sticks.get("X", 0.0) == 1.0]
    assert len(enabled) > 200  # held at full deflection for about a second
    assert readings[-1].axis == "Y" and readings[-1].multiplier == 10
    assert sum(r.increments for r in readings) == 50  # 5 detents at x10
    assert all(r.increments == 0 or r.enable for r in readings)
    assert readings[-1].sticks["X"] == pytest.approx(0.0, abs=0.01)  # back at rest


def test_a_dropped_batch_is_discarded_and_releases_everything() -> None:
    codes = {"enable": (1, 310), "wheel": (2, 7)}
    mapping = EventMapping(codes, {})
    for event in [(1, 310, 1), (EV_SYN, SYN_REPORT, 0), (2, 7, 3), (EV_SYN, SYN_DROPPED, 0)]:
        mapping.feed(*event)
    mapping.feed(2, 7, 4)
    mapping.feed(EV_SYN, SYN_REPORT, 0)  # closes the lost batch
    reading = mapping.reading()
    assert not reading.enable and reading.increments == 0


@pytest.fixture
def machine(tmp_path: Path) -> Iterator[tuple[MachineRuntime, ReplayedPendant]]:
    config = pendant_config({})
    pendant = ReplayedPendant(CAPTURE, GAMEPAD, config.period_s)
    settings = replace(config.pendant, evdev=replace(GAMEPAD))
    config = replace(config, pendant=settings)
    runtime = MachineRuntime.create(config, tmp_path / "stave.db", pendant=pendant)
    runtime.start()
    yield runtime, pendant
    runtime.shutdown()


def test_the_replayed_gamepad_jogs_the_machine(
    machine: tuple[MachineRuntime, ReplayedPendant],
) -> None:
    runtime, pendant = machine
    c = runtime.controller
    c.post(cmd.EnterManual())
    runtime.run_for(0.1)
    assert c.state is MachineState.MANUAL
    x0, y0 = c.manual.position("X"), c.manual.position("Y")
    runtime.run_for(0.2)  # the stick was pushed without the enable button
    assert c.manual.position("X") == x0
    assert c.message is not None and "enable" in str(c.message)
    sources = []
    runtime.on_tick.append(lambda rt: sources.append(rt.controller.snapshot().pendant.jog_source))
    assert runtime.run_until(lambda m: pendant.finished, 10.0)
    runtime.run_for(1.0)
    assert JogSource.PENDANT in sources
    jog_speed = c.manual.speed("XY")[0]
    assert c.manual.position("X") > x0 + 0.7 * jog_speed  # about a second at full jog speed
    assert c.manual.position("Y") == pytest.approx(y0 + 0.05, abs=1e-9)  # 5 detents x10
    assert c.manual.at_rest


def test_a_pendant_not_plugged_in_reads_at_rest_and_the_machine_starts(tmp_path: Path) -> None:
    config = pendant_config({"device": str(tmp_path / "no-such-event-device")})
    pendant = create_pendant(config)
    assert isinstance(pendant, EvdevPendant)
    assert pendant.read().enable is False and not pendant.connected
    runtime = MachineRuntime.create(config, tmp_path / "stave.db")
    runtime.start()
    runtime.run_for(0.1)
    view = runtime.controller.snapshot().pendant
    assert runtime.controller.state is MachineState.READY and not view.pendant_connected
    runtime.shutdown()
    assert create_pendant(pendant_config({})) is None  # no device named: nothing opened


def test_an_unknown_event_code_stops_the_start_with_its_key() -> None:
    config = pendant_config({"device": "Some pad", "select_x": "BTN_NO_SUCH"})
    with pytest.raises(ConfigError, match=r"pendant\.evdev\.select_x = 'BTN_NO_SUCH'"):
        check_settings(config)
