"""Throttling of failed OPC UA logins.

Why per user name: a plant network is shared, and the attacker's address tells little (NAT,
one gateway for a whole hall), while a password guesser must name the account it attacks.
After ``max_failures`` failed logins in a row a name is locked for ``lockout_s``, doubling for
each further failure up to an hour; while locked even the right password is refused, so
guessing gains nothing. A successful login clears the count. The clock is handed in, so the
tests run on simulated time.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

MAX_LOCKOUT_S = 3600.0


@dataclass
class _Record:
    failures: int = 0
    locked_until: float = 0.0


@dataclass
class LoginThrottle:
    max_failures: int
    lockout_s: float
    clock: Callable[[], float]
    _records: dict[str, _Record] = field(default_factory=dict)

    def _key(self, name: str) -> str:
        return name.casefold()

    def locked_for_s(self, name: str) -> float:
        """Seconds the name stays locked (0: it may try)."""
        record = self._records.get(self._key(name))
        return 0.0 if record is None else max(0.0, record.locked_until - self.clock())

    def failed(self, name: str) -> None:
        record = self._records.setdefault(self._key(name), _Record())
        record.failures += 1
        beyond = record.failures - self.max_failures
        if beyond >= 0:
            lockout = min(MAX_LOCKOUT_S, self.lockout_s * 2.0 ** min(beyond, 20))
            record.locked_until = self.clock() + lockout

    def succeeded(self, name: str) -> None:
        self._records.pop(self._key(name), None)
