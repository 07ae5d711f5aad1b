"""The USB pendant as a Linux input device: found by path or by name, read without
blocking once per period, and reopened when it comes back after an unplug (hot-plug).

Why polling and no reader thread: the machine loop owns time and reads every device once per
period; an evdev device's ``read`` returns what is queued or raises ``BlockingIOError`` at
once. An unplugged device raises ``OSError`` (ENODEV): the pendant reads as at rest and a
reopen is tried every ``REOPEN_READS`` reads (about a second at 4 ms), never blocking longer
than opening a device node takes.
"""

from __future__ import annotations

import contextlib
import logging

import evdev
from evdev import ecodes

from app.drivers.contracts import PendantReading
from app.drivers.evdev_pendant.mapping import AxisRange, EventMapping
from app.pendant_settings import EvdevSettings

log = logging.getLogger(__name__)

REOPEN_READS = 250
KINDS = {"ABS": ecodes.EV_ABS, "REL": ecodes.EV_REL, "BTN": ecodes.EV_KEY, "KEY": ecodes.EV_KEY}


def event_code(name: str) -> tuple[int, int]:
    """(type, code) of an event code name such as BTN_TL or ABS_X; ValueError if unknown."""
    code = ecodes.ecodes.get(name)
    kind = KINDS.get(name.split("_", 1)[0])
    if code is None or kind is None:
        raise ValueError(f"pendant event code {name!r} is not known to the Linux input layer")
    return kind, int(code)


def find_device(wanted: str) -> evdev.InputDevice[str] | None:
    """The device at path ``wanted``, or the first whose name is ``wanted``; None if absent."""
    if wanted.startswith("/"):
        try:
            return evdev.InputDevice(wanted)
        except OSError:
            return None
    for path in evdev.list_devices():
        try:
            device = evdev.InputDevice(path)
        except OSError:
            continue
        if device.name == wanted:
            return device
        device.close()
    return None


class EvdevPendant:
    def __init__(self, settings: EvdevSettings) -> None:
        self.settings = settings
        self.codes = {role: event_code(name) for role, name in settings.code_names().items()}
        self._device: evdev.InputDevice[str] | None = None
        self._mapping = EventMapping(self.codes, {})
        self._reads_since_try = REOPEN_READS  # try at the first read

    @property
    def connected(self) -> bool:
        return self._device is not None

    def _open(self) -> None:
        self._reads_since_try = 0
        device = find_device(self.settings.device)
        if device is None:
            return
        ranges: dict[int, AxisRange] = {}
        for role in ("stick_x", "stick_y", "stick_z"):
            if role in self.codes:
                code = self.codes[role][1]
                try:
                    info = device.absinfo(code)
                except (OSError, KeyError):
                    continue
                ranges[code] = AxisRange(info.min, info.max)
        self._mapping = EventMapping(self.codes, ranges)
        self._device = device
        log.info("pendant %r connected (%s)", device.name, device.path)

    def _lost(self, exc: OSError) -> None:
        log.warning("pendant %s lost: %s", self.settings.device, exc)
        self.close()
        self._mapping.release()

    def read(self) -> PendantReading:
        if self._device is None:
            self._reads_since_try += 1
            if self._reads_since_try >= REOPEN_READS:
                self._open()
            if self._device is None:
                return PendantReading()
        assert self._device is not None
        try:
            for event in self._device.read():
                self._mapping.feed(event.type, event.code, event.value)
        except BlockingIOError:
            pass  # nothing queued this period
        except OSError as exc:
            self._lost(exc)
            return PendantReading()
        return self._mapping.reading()

    def close(self) -> None:
        if self._device is not None:
            with contextlib.suppress(OSError):  # an unplugged device's node is gone already
                self._device.close()
            self._device = None
