"""How long the machine's last message stays in the top bar.

Why it expires: the machine keeps its last refusal or notice ("resuming the board", "OPC UA
server listening") until it has another one; a line that stays for minutes and follows the
operator to every screen is read as the machine's present state when it is history. So a
message shows for ``MESSAGE_S`` from the moment it was given (the snapshot counts every
message, the same text given again too) and a change of screen clears it.
"""

from __future__ import annotations

import time
from collections.abc import Callable

from app.machine.refusals import Refusal

MESSAGE_S = 10.0


class ExpiringMessage:
    """The message to show now, given the snapshot's message and its serial number."""

    def __init__(
        self, lifetime_s: float = MESSAGE_S, clock: Callable[[], float] = time.monotonic
    ) -> None:
        self.lifetime_s = lifetime_s
        self._clock = clock
        self._serial = -1
        self._since_s = 0.0
        self._dismissed = False

    def current(self, message: Refusal | None, serial: int) -> Refusal | None:
        now_s = self._clock()
        if serial != self._serial:
            self._serial = serial
            self._since_s = now_s
            self._dismissed = False
        if message is None or self._dismissed or now_s - self._since_s >= self.lifetime_s:
            return None
        return message

    def dismiss(self) -> None:
        """The operator moved on (another screen): the message is over."""
        self._dismissed = True
