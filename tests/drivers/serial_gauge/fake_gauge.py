"""A serial width gauge at the far end of a pty: what the gauge driver's tests talk to.

The driver opens :attr:`FakeGauge.path` as it would open /dev/ttyUSB0. In ``request`` mode a
thread answers every request string with :attr:`reply` (when :attr:`auto` is set); in
``stream`` mode it sends :attr:`line` every ``interval_s`` while :attr:`streaming` is set,
as a free-running gauge does. ``unplug()`` closes the far end: the driver's next read fails
like an unplugged USB adapter.
"""

from __future__ import annotations

import contextlib
import os
import select
import threading
import tty
from collections.abc import Callable


class FakeGauge:
    def __init__(
        self,
        *,
        mode: str = "request",
        request: bytes = b"?\r\n",
        reply: bytes = b"W=123.45\r\n",
        interval_s: float = 0.01,
    ) -> None:
        self._master, self._slave = os.openpty()
        tty.setraw(self._slave)
        self.path = os.ttyname(self._slave)
        self.mode = mode
        self.request = request
        self.reply = reply
        self.reply_for: Callable[[], bytes] | None = None  # overrides reply when set
        self.line = reply
        self.auto = True
        self.streaming = mode == "stream"
        self.interval_s = interval_s
        self.requests = 0
        self._received = b""
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._plugged = True
        self._thread = threading.Thread(target=self._run, name="fake-gauge", daemon=True)
        self._thread.start()

    def _run(self) -> None:
        while not self._stop.is_set():
            with self._lock:
                if not self._plugged:
                    return
                ready, _, _ = select.select([self._master], [], [], self.interval_s)
                if ready:
                    with contextlib.suppress(OSError):
                        self._received += os.read(self._master, 4096)
                if self.mode == "request" and self.auto:
                    while self.request in self._received:
                        _, _, self._received = self._received.partition(self.request)
                        self.requests += 1
                        answer = self.reply_for() if self.reply_for else self.reply
                        os.write(self._master, answer)
                elif self.mode == "stream" and self.streaming:
                    os.write(self._master, self.line)

    def take_request(self) -> bytes:
        """Manual mode (``auto`` off): wait for one request string and return it."""
        data = b""
        while self.request not in data:
            ready, _, _ = select.select([self._master], [], [], 2.0)
            assert ready, "no request from the driver"
            data += os.read(self._master, 4096)
        return data

    def write(self, data: bytes) -> None:
        os.write(self._master, data)

    def stop_thread(self) -> None:
        """Everything from here on is written by the test itself."""
        self._stop.set()
        self._thread.join(timeout=5.0)

    def unplug(self) -> None:
        self.stop_thread()
        with self._lock:
            self._plugged = False
            os.close(self._master)

    def close(self) -> None:
        self.stop_thread()
        fds = [self._slave] + ([self._master] if self._plugged else [])
        self._plugged = False
        for fd in fds:
            with contextlib.suppress(OSError):
                os.close(fd)
