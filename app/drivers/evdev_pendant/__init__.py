"""USB pendants and gamepads through the Linux input layer (python-evdev).

Why a package of its own and a lazy import: only a machine with ``[pendant.evdev] device``
set loads evdev (a compiled module, Linux only); the mapping from events to a
:class:`~app.drivers.contracts.PendantReading` is pure (``mapping``) and tested on recorded
event streams, the device (``device``) only opens, reads without blocking and reopens.
"""

from __future__ import annotations

from app.config import MachineConfig
from app.drivers.contracts import PendantDevice


def create_pendant(config: MachineConfig) -> PendantDevice | None:
    """The configured USB pendant, or None when ``[pendant.evdev] device`` is empty. A
    device that is not plugged in is no error: it reads as at rest until it appears."""
    settings = config.pendant.evdev
    if not settings.device:
        return None
    from app.drivers.evdev_pendant.device import EvdevPendant

    return EvdevPendant(settings)
