"""Two pseudo-terminals joined back to back: a null-modem cable inside the test process.

Each side opens its pty's slave device by path (``left``/``right``), as it would open
/dev/ttyUSB0; a relay thread copies bytes between the two masters. ``unplug_right()`` closes
the right master: the right side's next read or write fails like an unplugged USB adapter.
"""

from __future__ import annotations

import contextlib
import os
import select
import threading
import tty


class PtyBridge:
    def __init__(self) -> None:
        self._left_master, self._left_slave = os.openpty()
        self._right_master, self._right_slave = os.openpty()
        for fd in (self._left_slave, self._right_slave):
            tty.setraw(fd)
        self.left = os.ttyname(self._left_slave)
        self.right = os.ttyname(self._right_slave)
        self._stop = threading.Event()
        self._right_plugged = True
        self._unplug = threading.Event()
        self._unplugged = threading.Event()
        self._thread = threading.Thread(target=self._relay, name="pty-bridge", daemon=True)
        self._thread.start()

    def _relay(self) -> None:
        peers = {self._left_master: self._right_master, self._right_master: self._left_master}
        while not self._stop.is_set():
            if self._unplug.is_set() and self._right_plugged:
                self._right_plugged = False  # closed here: never under a select()
                os.close(self._right_master)
                self._unplugged.set()
            masters = [self._left_master] + ([self._right_master] if self._right_plugged else [])
            ready, _, _ = select.select(masters, [], [], 0.01)
            for fd in ready:
                try:
                    data = os.read(fd, 4096)
                except OSError:  # no slave open on that side yet
                    continue
                target = peers[fd]
                if target == self._right_master and not self._right_plugged:
                    continue
                with contextlib.suppress(OSError):
                    os.write(target, data)

    def unplug_right(self) -> None:
        self._unplug.set()
        assert self._unplugged.wait(timeout=5.0)

    def close(self) -> None:
        self._stop.set()
        self._thread.join(timeout=5.0)
        fds = [self._left_master, self._left_slave, self._right_slave]
        if self._right_plugged:
            fds.append(self._right_master)
        for fd in fds:
            with contextlib.suppress(OSError):
                os.close(fd)
