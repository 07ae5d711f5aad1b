"""Entry point of the CANopen backend for the registry: ``create_backend(config)``.

The returned backend is not yet configured: the machine layer (or ``stave probe``) calls
``configure()`` and ``activate()`` on both devices. Nothing here opens the bus; the settings
are checked at once, so a bad ``[backend.canopen]`` stops the start-up with a ConfigError.
``extras["canopen"]`` is the shared :class:`CanopenBus`; its ``probe_report()`` is what
``stave probe`` prints about the link.
"""

from __future__ import annotations

from app.config import MachineConfig
from app.drivers.canopen.bus import CanopenBus
from app.drivers.canopen.digital_io import CanopenIO
from app.drivers.canopen.motion import CanopenMotion
from app.drivers.canopen.settings import settings_from_config
from app.drivers.contracts import MachineBackend


def create_backend(config: MachineConfig) -> MachineBackend:
    settings = settings_from_config(config)
    bus = CanopenBus(settings)
    motion = CanopenMotion(bus, settings, config)
    io = CanopenIO(bus, settings)
    return MachineBackend("canopen", motion, io, extras={"canopen": bus})
