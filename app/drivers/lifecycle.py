"""The one driver lifecycle: :class:`ManagedLifecycle` owns the state and its transitions.

Why one owner (ros2_control's split): five hand-written variants used to allow different
transitions, so the machine layer guarded every call ("configure unless INACTIVE", "deactivate
if ACTIVE") to paper over them. Here the base decides what is allowed and what a failure
means; a backend only fills in the hooks (``_on_configure``, ``_on_activate``,
``_on_deactivate``, ``_on_error``, ``_on_shutdown``), each of which may raise DriverError.

The transitions:

- ``configure`` from UNCONFIGURED, INACTIVE or ERROR (configuring again is how a lost link is
  reopened), to INACTIVE; refused while ACTIVE or FINALIZED.
- ``activate`` from INACTIVE to ACTIVE; refused otherwise.
- ``deactivate`` from ACTIVE to INACTIVE; from ERROR it is a best-effort safe stop of what can
  still be reached (``_on_error``, failures logged) and the state stays ERROR; anywhere else it
  does nothing. Calling it twice is harmless.
- ``shutdown`` from any state, to FINALIZED: deactivates an ACTIVE device first, then
  releases (``_on_shutdown``); never raises, and calling it twice is harmless.
- A DriverError raised by a hook of configure, activate or deactivate leaves the device in
  ERROR and is re-raised to the caller; a backend that loses its link between transitions
  latches ERROR with :meth:`_latch_error`.

Events from before a reconnect are not news after it: ``configure`` first drops whatever the
device had queued until then (``_pending_events``), so a COMMUNICATION_LOST of the old
connection is never delivered after the link was reopened, and the operator's first Reset
after a lost link works. What configure itself finds (a drive already in fault) is news.
"""

from __future__ import annotations

import logging
from collections.abc import Callable

from app.drivers.contracts import (
    DeviceEvent,
    DriverError,
    Lifecycle,
    LifecycleError,
    LifecycleState,
)

log = logging.getLogger(__name__)
L = LifecycleState


class ManagedLifecycle(Lifecycle):
    """The lifecycle of one device; ``label`` names it in the errors it raises."""

    def __init__(self, label: str) -> None:
        self._state = L.UNCONFIGURED
        self._lifecycle_label = label

    @property
    def lifecycle_label(self) -> str:
        """The device's name in the errors and logs of its transitions."""
        return self._lifecycle_label

    @property
    def lifecycle_state(self) -> LifecycleState:
        self._refresh_state()
        return self._state

    # -- what a backend fills in -------------------------------------------------------------
    def _on_configure(self) -> None:
        """Open links and check the devices answer; no power is applied."""

    def _on_activate(self) -> None:
        """Start cyclic exchange; command positions are set to the measured ones."""

    def _on_deactivate(self) -> None:
        """Stop cyclic exchange; drives disabled, outputs off."""

    def _on_error(self) -> None:
        """From ERROR: bring whatever can still be reached to a safe state (best effort)."""

    def _on_shutdown(self) -> None:
        """Release every resource (links, threads, the bus claim)."""

    def _pending_events(self) -> list[DeviceEvent]:
        """Take the events queued since the last call (oldest first)."""
        return []

    def _refresh_state(self) -> None:
        """Latch ERROR for a loss noticed outside this object (a shared bus); default none."""

    # -- the transitions ---------------------------------------------------------------------
    def configure(self) -> None:
        self._refresh_state()
        if self._state in (L.ACTIVE, L.FINALIZED):
            raise LifecycleError(
                self.lifecycle_label, f"configure refused: the device is {self._state.value}"
            )
        stale = self._pending_events()
        if stale:
            log.info(
                "%s: %d event(s) from before configure dropped", self.lifecycle_label, len(stale)
            )
        self._run(self._on_configure, L.INACTIVE)

    def activate(self) -> None:
        self._refresh_state()
        if self._state is not L.INACTIVE:
            raise LifecycleError(
                self.lifecycle_label,
                f"activate refused: the device is {self._state.value}, it must be inactive",
            )
        self._run(self._on_activate, L.ACTIVE)

    def deactivate(self) -> None:
        self._refresh_state()
        if self._state is L.ERROR:
            try:
                self._on_error()
            except DriverError as exc:
                log.warning("%s: safe stop from error: %s", self.lifecycle_label, exc)
            return
        if self._state is not L.ACTIVE:
            return
        try:
            self._on_deactivate()
        except DriverError:
            self._state = L.ERROR
            raise
        self._state = L.INACTIVE

    def shutdown(self) -> None:
        if self._state is L.FINALIZED:
            return
        try:
            if self._state is L.ACTIVE:
                self.deactivate()
        except DriverError as exc:
            log.warning("%s: deactivate at shutdown: %s", self.lifecycle_label, exc)
        try:
            self._on_shutdown()
        except DriverError as exc:
            log.warning("%s: shutdown: %s", self.lifecycle_label, exc)
        self._state = L.FINALIZED

    def events(self) -> list[DeviceEvent]:
        return self._pending_events()

    # -- for the backends ------------------------------------------------------------------------
    def _latch_error(self) -> None:
        """The link was lost between transitions: only configure may follow."""
        if self._state in (L.INACTIVE, L.ACTIVE):
            self._state = L.ERROR

    def _require(self, what: str, *states: LifecycleState) -> None:
        """Refuse ``what`` unless the device is in one of ``states``."""
        self._refresh_state()
        if self._state not in states:
            allowed = " or ".join(s.value for s in states)
            raise LifecycleError(
                self.lifecycle_label,
                f"{what} refused: the device is {self._state.value}, it must be {allowed}",
            )

    def _run(self, hook: Callable[[], None], to: LifecycleState) -> None:
        try:
            hook()
        except DriverError:
            self._state = L.ERROR
            raise
        self._state = to
