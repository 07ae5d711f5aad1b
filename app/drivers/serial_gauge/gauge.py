"""The width gauge on a serial port: :class:`WidthGauge` with pyserial.

How a reading is taken: ``request()`` arms the gauge (request mode: flushes stale input and
sends the request string; stream mode: flushes stale input and skips to the start of the
next line); each ``poll()``
reads what has arrived without waiting (pyserial ``timeout=0``), keeps partial lines, and
returns the first complete line after the request as a :class:`GaugeReading`, once. Garbage
and out-of-range values come back as readings with ``width_mm=None`` and the reason in
``error`` (the machine layer raises the alarm).

How a lost gauge is detected: an unplugged USB adapter or a vanished port makes pyserial
raise (``SerialException``/``OSError``): CommunicationError, and the gauge needs
``configure`` again. A gauge whose cable is pulled behind a still-present adapter just falls
silent: no line within ``reply_timeout_ms`` after a request is CommunicationError too.
``configure`` checks the gauge answers once before anything relies on it.
"""

from __future__ import annotations

import contextlib
import os
import time
from collections.abc import Callable
from typing import NoReturn

import serial

from app.config import MachineConfig
from app.drivers.contracts import (
    CommunicationError,
    GaugeReading,
    LifecycleError,
    LifecycleState,
    MachineBackend,
    WidthGauge,
)
from app.drivers.lifecycle import ManagedLifecycle
from app.drivers.serial_gauge.lines import LineBuffer, parse_line
from app.drivers.serial_gauge.settings import (
    GaugeMode,
    SerialGaugeSettings,
    parse_serial_gauge_settings,
)

DEVICE = "gauge"
CONFIGURE_POLL_S = 0.002


class SerialWidthGauge(ManagedLifecycle, WidthGauge):
    def __init__(
        self, settings: SerialGaugeSettings, clock: Callable[[], float] = time.monotonic
    ) -> None:
        super().__init__(DEVICE)
        self.settings = settings
        self._clock = clock
        self._port: serial.Serial | None = None
        self._buffer = LineBuffer(settings.terminator, settings.max_line_bytes)
        self._armed = False
        self._deadline = 0.0

    # -- lifecycle hooks ----------------------------------------------------------------------
    def _on_configure(self) -> None:
        """Open the port and check the gauge answers (one request, or one streamed line,
        within ``reply_timeout_ms``)."""
        self._close()
        s = self.settings
        try:
            self._port = serial.Serial(
                s.port,
                baudrate=s.baudrate,
                bytesize=s.bytesize,
                parity=s.parity,
                stopbits=s.stopbits,
                timeout=0,
                write_timeout=s.reply_timeout_s,
                exclusive=True,
            )
        except (serial.SerialException, OSError, ValueError) as exc:
            raise CommunicationError(DEVICE, f"cannot open {s.port}: {_reason(exc)}") from None
        try:
            self._arm()
            deadline = time.monotonic() + s.reply_timeout_s
            while not self._take_line():
                if time.monotonic() > deadline:
                    raise CommunicationError(DEVICE, self._silence_message())
                time.sleep(CONFIGURE_POLL_S)
        except CommunicationError:
            self._close()
            raise
        self._armed = False

    def _on_activate(self) -> None:
        self._armed = False
        self._buffer.clear()

    def _on_deactivate(self) -> None:
        self._armed = False

    def _on_shutdown(self) -> None:
        self._close()
        self._armed = False

    def _close(self) -> None:
        if self._port is not None:
            # An unplugged port may fail to close; it is released anyway.
            with contextlib.suppress(serial.SerialException, OSError):
                self._port.close()
            self._port = None

    def fileno(self) -> int:
        """The port's file descriptor, for ``select()`` in tools and tests that want to wait
        for the gauge instead of polling; -1 while the port is closed."""
        return int(self._port.fileno()) if self._port is not None else -1

    def _require_active(self) -> serial.Serial:
        if self._state is not LifecycleState.ACTIVE or self._port is None:
            raise LifecycleError(DEVICE, f"not allowed in state {self._state.value}")
        return self._port

    # -- readings ---------------------------------------------------------------------------
    def request(self) -> None:
        """Ask for a fresh reading (request mode), or wait for the next streamed line."""
        self._require_active()
        self._arm()

    def poll(self) -> GaugeReading | None:
        """The first complete reading since ``request``, once; None while there is none.
        Without a request, arriving lines are read and dropped (nothing stale piles up)."""
        self._require_active()
        reading = self._take_line()
        if reading is not None:
            return reading
        if self._armed and self._clock() > self._deadline:
            self._armed = False
            raise CommunicationError(DEVICE, self._silence_message())
        return None

    def _arm(self) -> None:
        port = self._port
        assert port is not None
        s = self.settings
        try:
            if s.mode is GaugeMode.REQUEST:
                port.reset_input_buffer()
                self._buffer.clear()
                port.write(s.request)
                port.flush()
            else:
                # Lines already queued are older than the request; the flush may cut one
                # in half, so the reading starts after the next terminator.
                port.reset_input_buffer()
                self._buffer.resync()
        except (serial.SerialException, OSError) as exc:
            self._lost(exc)
        self._armed = True
        self._deadline = self._clock() + s.reply_timeout_s

    def _take_line(self) -> GaugeReading | None:
        """Read what has arrived; the first reading-bearing line if armed."""
        port = self._port
        assert port is not None
        try:
            waiting = port.in_waiting
            # read(1) with timeout=0 returns at once; on a vanished port it raises, which is
            # how an unplugged adapter is noticed even when nothing is waiting.
            data = port.read(waiting or 1)
        except (serial.SerialException, OSError) as exc:
            self._lost(exc)
        if not data:
            return None
        for line in self._buffer.feed(data):
            if not self._armed:
                continue
            reading = parse_line(line, self.settings)
            if reading is not None:
                self._armed = False
                return reading
        return None

    def _lost(self, exc: BaseException) -> NoReturn:
        self._close()
        self._armed = False
        self._latch_error()
        raise CommunicationError(
            DEVICE, f"{self.settings.port} is gone (gauge unplugged?): {_reason(exc)}"
        ) from None

    def _silence_message(self) -> str:
        s = self.settings
        what = (
            "no answer to the request"
            if s.mode is GaugeMode.REQUEST
            else "no line from the streaming gauge"
        )
        return (
            f"{what} within {s.reply_timeout_s * 1000:.0f} ms on {s.port} "
            f"(gauge off or unplugged, baud rate or terminator wrong?)"
        )


def _reason(exc: BaseException) -> str:
    """The operating system's reason when there is one ("No such file or directory"),
    without pyserial's repetition of the port name."""
    number = getattr(exc, "errno", None)
    if isinstance(number, int) and number > 0:
        return os.strerror(number)
    return str(exc)


def create_gauge(config: MachineConfig, backend: MachineBackend) -> WidthGauge:
    """The registry's factory: ``[gauge.serial]`` checked here (ConfigError on a bad key);
    the port is opened by ``configure``. ``backend`` is not needed by a serial gauge."""
    del backend
    settings = parse_serial_gauge_settings(config.gauge_settings.get("serial", {}), config)
    return SerialWidthGauge(settings)
