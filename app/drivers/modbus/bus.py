"""Every Modbus link of the backend, with the trade's error handling.

The rules (what a PLC's Modbus master does, and what a technician expects):

- Retry only what a retry can cure: a request that got no valid reply (timeout, garbled
  frame) and a "server device busy" exception (0x06). Each is retried at once, up to
  ``retries`` times, within the same period.
- Any other exception reply (illegal address, illegal value, device failure, ...) is the
  device refusing the request: retrying would get the same answer. It is raised at once as a
  :class:`DriverError` carrying the exception code, and does not count as a link failure
  (the device did answer).
- A request that still failed after its retries is one failure of that device. Below
  ``max_consecutive_failures`` in a row it is tolerated: the caller skips this period's
  exchange (a read keeps the previous period's values, a write is sent again next period);
  one valid reply resets the count. The count is per device, so that one dead drive on an
  RTU line is noticed even while the others answer.
- At ``max_consecutive_failures``, or at once when a connection closes, the link is LOST: a
  COMMUNICATION_LOST event is queued, every connection is closed, and every further exchange
  raises :class:`CommunicationError` without touching the wire. Nothing reconnects by itself:
  only ``acquire`` (from a device's ``configure``, after an operator's reset) opens the links
  again.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import TypeVar

from app.drivers.contracts import (
    CommunicationError,
    DeviceEvent,
    DeviceEventKind,
    DriverError,
)
from app.drivers.modbus.link import (
    BUSY,
    ExceptionReplyError,
    LinkClosedError,
    ModbusLink,
    NoReplyError,
)
from app.drivers.modbus.settings import Endpoint, LinkSettings

T = TypeVar("T")
log = logging.getLogger(__name__)


class TransientError(Exception):
    """One failed exchange below the loss threshold: skip it this period."""


@dataclass(frozen=True)
class DeviceAddress:
    """A device on the bus: its name in our messages ("X", "io"), where it is, its unit id."""

    name: str
    endpoint: Endpoint | None  # None: the link's default server, or the RTU line
    device_id: int


@dataclass
class BusStatistics:
    """Counters a technician reads with ``stave probe``."""

    transactions: int = 0
    retries: int = 0
    failures: int = 0
    exception_replies: int = 0
    total_time_s: float = 0.0
    max_time_s: float = 0.0

    @property
    def mean_time_s(self) -> float:
        return self.total_time_s / self.transactions if self.transactions else 0.0


@dataclass
class _LostState:
    lost: bool = False
    reason: str = ""
    failures: dict[str, int] = field(default_factory=dict)


class ModbusBus:
    def __init__(
        self,
        settings: LinkSettings,
        devices: Iterable[DeviceAddress],
        clock: Callable[[], float] = time.perf_counter,
    ) -> None:
        self.settings = settings
        self._clock = clock
        self._devices = {d.name: d for d in devices}
        self._links: dict[Endpoint | None, ModbusLink] = {}
        for device in self._devices.values():
            if device.endpoint not in self._links:
                self._links[device.endpoint] = self._make_link(device.endpoint)
        self._users: set[str] = set()
        self._state = _LostState()
        self._events: list[DeviceEvent] = []
        self.statistics = BusStatistics()
        self.generation = 0  # counts (re)openings: a device configured before is stale

    def _make_link(self, endpoint: Endpoint | None) -> ModbusLink:
        s = self.settings
        if endpoint is not None:
            return ModbusLink(f"tcp {endpoint}", s.timeout_s, endpoint=endpoint)
        if s.serial is not None:
            return ModbusLink(s.name, s.timeout_s, line=s.serial)
        assert s.endpoint is not None
        return ModbusLink(f"tcp {s.endpoint}", s.timeout_s, endpoint=s.endpoint)

    # -- where things are -----------------------------------------------------------------
    def describe(self, device: DeviceAddress) -> str:
        return f"unit {device.device_id} on {self._links[device.endpoint].name}"

    @property
    def link_names(self) -> list[str]:
        return [link.name for link in self._links.values()]

    @property
    def lost(self) -> bool:
        return self._state.lost

    def stale(self, generation: int) -> bool:
        """Whether a device configured at ``generation`` lost its link since (the link may
        have been reopened by the other device's configure)."""
        return self._state.lost or generation != self.generation

    @property
    def is_open(self) -> bool:
        return bool(self._links) and all(link.is_open for link in self._links.values())

    # -- opening and closing ----------------------------------------------------------------
    def acquire(self, user: str) -> None:
        """Open every link (again after a loss); raises CommunicationError naming the link
        that cannot be reached, with every link closed."""
        if self._state.lost or not self.is_open:
            self._close_all()
            for link in self._links.values():
                try:
                    link.open()
                except LinkClosedError as exc:
                    self._close_all()
                    raise CommunicationError("modbus", str(exc)) from None
            self._state = _LostState()
            self.generation += 1
        self._users.add(user)

    def release(self, user: str) -> None:
        """A device no longer needs the links; the last one closes them."""
        self._users.discard(user)
        if not self._users:
            self._close_all()

    def _close_all(self) -> None:
        for link in self._links.values():
            link.close()

    def events(self) -> list[DeviceEvent]:
        events, self._events = self._events, []
        return events

    # -- one exchange -----------------------------------------------------------------------
    def exchange(
        self, device: DeviceAddress, operation: Callable[[ModbusLink], T], *, tolerate: bool = True
    ) -> T:
        """Run ``operation`` on the device's link under the rules above.

        ``tolerate``: a failure below the threshold raises :class:`TransientError` (cyclic
        exchange); with False it raises CommunicationError at once (``configure`` checks)."""
        state = self._state
        if state.lost:
            raise CommunicationError(
                device.name,
                f"Modbus link lost ({state.reason}); "
                "an operator's reset must reconfigure the backend",
            )
        link = self._links[device.endpoint]
        if not link.is_open:
            raise CommunicationError(device.name, f"{link.name} is not open (configure first)")
        stats = self.statistics
        attempt = 0
        while True:
            started = self._clock()
            try:
                result = operation(link)
            except LinkClosedError as exc:
                self._account(started)
                self._declare_lost(device, str(exc))
                raise CommunicationError(device.name, str(exc)) from None
            except ExceptionReplyError as exc:
                self._account(started)
                if exc.code != BUSY:
                    stats.exception_replies += 1
                    raise DriverError(
                        device.name, f"{self.describe(device)} answered {exc}", exc.code
                    ) from None
                failure = f"{self.describe(device)} answered {exc}"
            except NoReplyError as exc:
                self._account(started)
                failure = f"{self.describe(device)}: {exc}"
            else:
                self._account(started)
                state.failures[device.name] = 0
                return result
            if attempt < self.settings.retries:
                attempt += 1
                stats.retries += 1
                continue
            break
        stats.failures += 1
        count = state.failures.get(device.name, 0) + 1
        state.failures[device.name] = count
        if not tolerate:
            raise CommunicationError(device.name, failure)
        limit = self.settings.max_consecutive_failures
        if count >= limit:
            reason = f"{failure}; {count} failed exchanges in a row"
            self._declare_lost(device, reason)
            raise CommunicationError(device.name, reason)
        log.warning(
            "%s: %s (failure %d of %d in a row, tolerated)", device.name, failure, count, limit
        )
        raise TransientError(failure)

    def _account(self, started: float) -> None:
        elapsed = self._clock() - started
        stats = self.statistics
        stats.transactions += 1
        stats.total_time_s += elapsed
        stats.max_time_s = max(stats.max_time_s, elapsed)

    def _declare_lost(self, device: DeviceAddress, reason: str) -> None:
        if self._state.lost:
            return
        self._state.lost = True
        self._state.reason = f"{device.name}: {reason}"
        log.error("Modbus link lost: %s", self._state.reason)
        self._close_all()
        self._events.append(
            DeviceEvent(DeviceEventKind.COMMUNICATION_LOST, device.name, text=reason)
        )
