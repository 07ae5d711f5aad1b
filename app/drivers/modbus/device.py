"""What every device on the shared :class:`ModbusBus` adds to the one lifecycle: :class:`BusDevice`.

Why one class: the drives and the I/O coupler share one bus, and a link lost (or reopened by
the other device's ``configure``) must end both the same way: ACTIVE/INACTIVE become ERROR,
only ``configure`` may follow, and a call made meanwhile says the link was lost instead of a
bare "not allowed". Written twice, the two devices could drift apart on exactly the path that
only a real cable fault exercises. The subclasses keep what differs: what ``configure`` reads
first, what ``activate``/``deactivate`` write, and their events.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

from app.drivers.contracts import (
    CommunicationError,
    LifecycleError,
    LifecycleState,
)
from app.drivers.lifecycle import ManagedLifecycle
from app.drivers.modbus.bus import DeviceAddress, ModbusBus
from app.drivers.modbus.link import ModbusLink

T = TypeVar("T")


class BusDevice(ManagedLifecycle):
    """A :class:`ManagedLifecycle` over a shared bus. ``user`` is this device's claim on
    the bus (``acquire``/``release``); ``source`` names it in the errors it raises."""

    def __init__(self, bus: ModbusBus, user: str, source: str) -> None:
        super().__init__(source)
        self._bus = bus
        self._user = user
        self._source = source
        self._generation = -1

    def _refresh_state(self) -> None:
        """ACTIVE/INACTIVE on a link lost (or reopened by the other device) since this
        device's configure is ERROR: only configure may follow."""
        if self._bus.stale(self._generation):
            self._latch_error()

    def _first_exchange(self) -> None:
        """What configure reads first (the device must answer)."""

    def _on_configure(self) -> None:
        """Claim the bus (opening the links again after a loss), then the first exchange;
        on a DriverError the claim is given back."""
        self._bus.acquire(self._user)
        self._generation = self._bus.generation
        try:
            self._first_exchange()
        except Exception:
            self._bus.release(self._user)
            raise

    def _on_shutdown(self) -> None:
        self._bus.release(self._user)

    def _check(self, *allowed: LifecycleState) -> None:
        self._refresh_state()
        if self._state not in allowed:
            if self._state is LifecycleState.ERROR and self._bus.stale(self._generation):
                raise CommunicationError(
                    self._source,
                    "Modbus link lost; an operator's reset must reconfigure the backend",
                )
            raise LifecycleError(self._source, f"not allowed in state {self._state.value}")

    def _exchange(
        self, device: DeviceAddress, operation: Callable[[ModbusLink], T], *, tolerate: bool
    ) -> T:
        """:meth:`ModbusBus.exchange`; a CommunicationError that lost the link makes this
        device ERROR before it propagates (a TransientError passes through untouched)."""
        try:
            return self._bus.exchange(device, operation, tolerate=tolerate)
        except CommunicationError:
            if self._bus.lost:
                self._latch_error()
            raise
