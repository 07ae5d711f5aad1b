"""What the panel shows of the plant connection, without talking OPC UA.

Why data and a protocol: the System screen shows whether the server runs, where, with which
commissioning shortcuts, and the client certificates it refused; it reads the first three
from the operator application's side of the connection (``PlantFeedLink``) and the last from
the trust folder with the functions ``stave opcua trust`` uses. A panel without the plant
connection has a link that is no ``PlantStatusSource`` and shows it as off.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Protocol, runtime_checkable

from app.plant.settings import OpcuaSettings

LISTENING = "OPC UA server listening on"  # the notice the server process sends once it serves


@dataclass(frozen=True)
class PlantStatus:
    settings: OpcuaSettings
    pki_dir: Path
    running: bool  # the server's process is alive
    notices: tuple[str, ...]  # what it said, oldest first ("listening on ...", refusals)

    @property
    def listening(self) -> bool:
        return self.running and any(n.startswith(LISTENING) for n in self.notices)

    @property
    def failure(self) -> str:
        """Why the server does not serve ("" while it does, or while it is starting)."""
        for notice in reversed(self.notices):
            if notice.startswith("OPC UA server did not start"):
                return notice
        return ""


@runtime_checkable
class PlantStatusSource(Protocol):
    def plant_status(self) -> PlantStatus: ...
