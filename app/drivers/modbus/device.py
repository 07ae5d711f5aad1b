"""The lifecycle every device on the shared :class:`ModbusBus` follows: :class:`BusDevice`.

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
    DriverError,
    Lifecycle,
    LifecycleError,
    LifecycleState,
)
from app.drivers.modbus.bus import DeviceAddress, ModbusBus
from app.drivers.modbus.link import ModbusLink

T = TypeVar("T")


class BusDevice(Lifecycle):
    """A :class:`Lifecycle` over a shared bus. ``user`` is this device's claim on the bus
    (``acquire``/``release``); ``source`` names it in the errors it raises."""

    def __init__(self, bus: ModbusBus, user: str, source: str) -> None:
        self._bus = bus
        self._user = user
        self._source = source
        self._state = LifecycleState.UNCONFIGURED
        self._generation = -1

    @property
    def lifecycle_state(self) -> LifecycleState:
        return self._state

    def _sync_state(self) -> None:
        """ACTIVE/INACTIVE on a link lost (or reopened by the other device) since this
        device's configure is ERROR: only configure may follow."""
        if self._state in (LifecycleState.ACTIVE, LifecycleState.INACTIVE) and self._bus.stale(
            self._generation
        ):
            self._state = LifecycleState.ERROR

    def _check_configurable(self) -> None:
        """The first step of ``configure``: refused while ACTIVE or FINALIZED."""
        self._sync_state()
        if self._state not in (
            LifecycleState.UNCONFIGURED,
            LifecycleState.INACTIVE,
            LifecycleState.ERROR,
        ):
            raise LifecycleError(self._source, f"configure in state {self._state.value}")

    def _open(self, first_exchange: Callable[[], object]) -> None:
        """The rest of ``configure``: claim the bus, run ``first_exchange`` (the device must
        answer), INACTIVE; on a DriverError the claim is given back and the state is ERROR."""
        try:
            self._bus.acquire(self._user)
            self._generation = self._bus.generation
            first_exchange()
        except DriverError:
            self._state = LifecycleState.ERROR
            self._bus.release(self._user)
            raise
        self._state = LifecycleState.INACTIVE

    def shutdown(self) -> None:
        if self._state is LifecycleState.FINALIZED:
            return
        try:
            self.deactivate()
        except DriverError:
            pass  # shutdown must always finish; the link's loss has already been reported
        finally:
            self._bus.release(self._user)
            self._state = LifecycleState.FINALIZED

    def _check(self, *allowed: LifecycleState) -> None:
        self._sync_state()
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
                self._state = LifecycleState.ERROR
            raise
