"""The I/O strip on the main screen and the technicians' I/O page: the strip's words as a
table of input images, and the whole way from a tap on the Manual screen's clamp button to
the strip and the page."""

from __future__ import annotations

from dataclasses import fields

import pytest

from app.drivers.contracts import DIGITAL_INPUTS, InputImage, OutputImage
from app.machine.states import MachineState
from app.screens.io_status import (
    SIGNAL_NAMES,
    Condition,
    Device,
    device_statuses,
)
from app.screens.widgets.lamp import LampColor
from tests.screens.helpers import find_button, wait_for

REST = InputImage()


def _status(inputs: InputImage, device: Device) -> tuple[Condition, LampColor]:
    status = next(s for s in device_statuses(inputs) if s.device is device)
    return status.condition, status.color


@pytest.mark.parametrize(
    ("inputs", "device", "expected"),
    [
        (REST, Device.SPINDLE, (Condition.STOPPED, LampColor.OFF)),
        (InputImage(spindle_running=True), Device.SPINDLE, (Condition.RUNNING, LampColor.GREEN)),
        (REST, Device.CLAMPS, (Condition.OPEN, LampColor.OFF)),
        (
            InputImage(clamps_closed=True, clamps_open=False),
            Device.CLAMPS,
            (Condition.CLOSED, LampColor.GREEN),
        ),
        (InputImage(clamps_open=False), Device.CLAMPS, (Condition.MOVING, LampColor.YELLOW)),
        (InputImage(clamps_closed=True), Device.CLAMPS, (Condition.MOVING, LampColor.YELLOW)),
        (REST, Device.CENTERING, (Condition.RETRACTED, LampColor.OFF)),
        (
            InputImage(centering_extended=True, centering_retracted=False),
            Device.CENTERING,
            (Condition.EXTENDED, LampColor.GREEN),
        ),
        (
            InputImage(centering_retracted=False),
            Device.CENTERING,
            (Condition.MOVING, LampColor.YELLOW),
        ),
        (REST, Device.PART, (Condition.ABSENT, LampColor.OFF)),
        (InputImage(part_present=True), Device.PART, (Condition.PRESENT, LampColor.GREEN)),
        (REST, Device.GUARD, (Condition.CLOSED, LampColor.GREEN)),
        (InputImage(guard_closed=False), Device.GUARD, (Condition.OPEN_ALERT, LampColor.RED)),
        (REST, Device.ESTOP, (Condition.HEALTHY, LampColor.GREEN)),
        (InputImage(estop_ok=False), Device.ESTOP, (Condition.BROKEN, LampColor.RED)),
    ],
)
def test_strip_words_and_colours(
    inputs: InputImage, device: Device, expected: tuple[Condition, LampColor]
) -> None:
    assert _status(inputs, device) == expected


def test_strip_shows_each_device_once_in_order() -> None:
    assert [s.device for s in device_statuses(REST)] == list(Device)


def test_every_input_and_output_has_a_name() -> None:
    signals = set(DIGITAL_INPUTS) | {f.name for f in fields(OutputImage)}
    assert set(SIGNAL_NAMES) == signals


def test_clamps_closed_by_hand_show_on_the_strip_and_the_io_page(qtbot, window, tap) -> None:
    main = window.page("main")
    assert main.io_strip.labels[Device.CLAMPS].text() == "Clamps\nopen"
    tap(find_button(window, "ioStrip"))
    assert window.current_key == "io"
    assert not any(b.isChecked() for b in window.nav.buttons.values())
    page = window.page("io")
    assert len(page.rows) == len(DIGITAL_INPUTS) + len(fields(OutputImage))
    assert page.rows["clamps_closed"].address.text() == "simulated"
    assert page.rows["clamps_closed"].state.text() == "off"

    window.show_screen("manual")
    tap(find_button(window, "enterManualButton"))
    wait_for(qtbot, window, lambda s: s.state is MachineState.MANUAL)
    tap(find_button(window, "clampsButton"))
    wait_for(qtbot, window, lambda s: s.inputs.clamps_closed and not s.inputs.clamps_open)
    window.show_screen("io")
    assert page.rows["clamps_closed"].state.text() == "ON"
    assert page.rows["clamps_close"].state.text() == "ON"
    assert page.rows["clamps_close"].lamp.color is LampColor.GREEN
    tap(find_button(window, "ioBack"))
    assert window.current_key == "main"
    assert main.io_strip.labels[Device.CLAMPS].text() == "Clamps\nclosed"
