"""What the main screen's I/O strip says about the machine's sensors, as a pure function of
the input image, and the words for every digital input and output.

Why a table of sensor pairs: clamps and centering each have two end switches; both or neither
made means the device is moving (or a switch is broken, which E041/E042 then name), and that
is what a technician needs to see, not two raw bits. The colours follow IEC 60073 as the
status lamp does: green = in its working position, red = a safety chain open, yellow = between
positions, grey = at rest.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication

from app.drivers.contracts import InputImage
from app.screens.texts import QT_TRANSLATE_NOOP
from app.screens.widgets.lamp import LampColor

IO_CONTEXT = "IoSignals"


class Device(enum.Enum):
    SPINDLE = QT_TRANSLATE_NOOP("IoSignals", "Spindle")
    CLAMPS = QT_TRANSLATE_NOOP("IoSignals", "Clamps")
    CENTERING = QT_TRANSLATE_NOOP("IoSignals", "Centering")
    PART = QT_TRANSLATE_NOOP("IoSignals", "Board")
    GUARD = QT_TRANSLATE_NOOP("IoSignals", "Guard")
    ESTOP = QT_TRANSLATE_NOOP("IoSignals", "E-stop chain")


class Condition(enum.Enum):
    RUNNING = QT_TRANSLATE_NOOP("IoSignals", "running")
    STOPPED = QT_TRANSLATE_NOOP("IoSignals", "stopped")
    CLOSED = QT_TRANSLATE_NOOP("IoSignals", "closed")
    OPEN = QT_TRANSLATE_NOOP("IoSignals", "open")
    OPEN_ALERT = QT_TRANSLATE_NOOP("IoSignals", "OPEN")
    MOVING = QT_TRANSLATE_NOOP("IoSignals", "moving")
    EXTENDED = QT_TRANSLATE_NOOP("IoSignals", "extended")
    RETRACTED = QT_TRANSLATE_NOOP("IoSignals", "retracted")
    PRESENT = QT_TRANSLATE_NOOP("IoSignals", "present")
    ABSENT = QT_TRANSLATE_NOOP("IoSignals", "none")
    HEALTHY = QT_TRANSLATE_NOOP("IoSignals", "OK")
    BROKEN = QT_TRANSLATE_NOOP("IoSignals", "BROKEN")


@dataclass(frozen=True)
class DeviceStatus:
    device: Device
    condition: Condition
    color: LampColor


def _pair(device: Device, working: bool, rest: bool, on: Condition, off: Condition) -> DeviceStatus:
    """A device with a switch at each end: exactly one made, or it is between them."""
    if working and not rest:
        return DeviceStatus(device, on, LampColor.GREEN)
    if rest and not working:
        return DeviceStatus(device, off, LampColor.OFF)
    return DeviceStatus(device, Condition.MOVING, LampColor.YELLOW)


def _safety(device: Device, healthy: bool, broken: Condition, ok: Condition) -> DeviceStatus:
    if healthy:
        return DeviceStatus(device, ok, LampColor.GREEN)
    return DeviceStatus(device, broken, LampColor.RED)


def device_statuses(inputs: InputImage) -> tuple[DeviceStatus, ...]:
    """The strip's lamps, left to right."""
    return (
        DeviceStatus(Device.SPINDLE, Condition.RUNNING, LampColor.GREEN)
        if inputs.spindle_running
        else DeviceStatus(Device.SPINDLE, Condition.STOPPED, LampColor.OFF),
        _pair(
            Device.CLAMPS,
            inputs.clamps_closed,
            inputs.clamps_open,
            Condition.CLOSED,
            Condition.OPEN,
        ),
        _pair(
            Device.CENTERING,
            inputs.centering_extended,
            inputs.centering_retracted,
            Condition.EXTENDED,
            Condition.RETRACTED,
        ),
        DeviceStatus(Device.PART, Condition.PRESENT, LampColor.GREEN)
        if inputs.part_present
        else DeviceStatus(Device.PART, Condition.ABSENT, LampColor.OFF),
        _safety(Device.GUARD, inputs.guard_closed, Condition.OPEN_ALERT, Condition.CLOSED),
        _safety(Device.ESTOP, inputs.estop_ok, Condition.BROKEN, Condition.HEALTHY),
    )


def device_text(device: Device) -> str:
    return QCoreApplication.translate(IO_CONTEXT, device.value)


def condition_text(condition: Condition) -> str:
    return QCoreApplication.translate(IO_CONTEXT, condition.value)


# Every digital input of InputImage and every OutputImage field -> its name on the I/O page.
SIGNAL_NAMES: dict[str, str] = {
    "part_present": QT_TRANSLATE_NOOP("IoSignals", "Board present"),
    "centering_extended": QT_TRANSLATE_NOOP("IoSignals", "Centering extended"),
    "centering_retracted": QT_TRANSLATE_NOOP("IoSignals", "Centering retracted"),
    "clamps_closed": QT_TRANSLATE_NOOP("IoSignals", "Clamps closed"),
    "clamps_open": QT_TRANSLATE_NOOP("IoSignals", "Clamps open"),
    "spindle_running": QT_TRANSLATE_NOOP("IoSignals", "Spindle running"),
    "guard_closed": QT_TRANSLATE_NOOP("IoSignals", "Guard closed"),
    "estop_ok": QT_TRANSLATE_NOOP("IoSignals", "E-stop chain closed"),
    "start_button": QT_TRANSLATE_NOOP("IoSignals", "Start push button"),
    "stop_button": QT_TRANSLATE_NOOP("IoSignals", "Stop push button"),
    "reset_button": QT_TRANSLATE_NOOP("IoSignals", "Reset push button"),
    "handwheel_x": QT_TRANSLATE_NOOP("IoSignals", "Handwheel selector X"),
    "handwheel_y": QT_TRANSLATE_NOOP("IoSignals", "Handwheel selector Y"),
    "handwheel_z": QT_TRANSLATE_NOOP("IoSignals", "Handwheel selector Z (tilt)"),
    "handwheel_x10": QT_TRANSLATE_NOOP("IoSignals", "Handwheel multiplier x10"),
    "handwheel_x100": QT_TRANSLATE_NOOP("IoSignals", "Handwheel multiplier x100"),
    "jog_enable": QT_TRANSLATE_NOOP("IoSignals", "Jog enable button"),
    "centering_extend": QT_TRANSLATE_NOOP("IoSignals", "Extend centering"),
    "clamps_close": QT_TRANSLATE_NOOP("IoSignals", "Close clamps"),
    "spindle_on": QT_TRANSLATE_NOOP("IoSignals", "Spindle contactor"),
    "lamp_green": QT_TRANSLATE_NOOP("IoSignals", "Green lamp"),
    "lamp_yellow": QT_TRANSLATE_NOOP("IoSignals", "Yellow lamp"),
    "lamp_red": QT_TRANSLATE_NOOP("IoSignals", "Red lamp"),
}


def signal_text(signal: str) -> str:
    """The signal's name in the current language (the field name if the table lacks it, so a
    new field shows up on the page and in the test of this table)."""
    name = SIGNAL_NAMES.get(signal)
    return QCoreApplication.translate(IO_CONTEXT, name) if name else signal
