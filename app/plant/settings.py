"""The ``[opcua]`` table of the machine configuration.

Why strict like every other key: a plant connection that silently falls back to "no security"
because of a misspelt key is worse than no connection. Security policy None and anonymous
access exist only for commissioning and must be asked for by name.
"""

from __future__ import annotations

import ipaddress
from dataclasses import dataclass
from typing import Protocol


class Section(Protocol):
    """What these settings read of a table of the configuration (``app.config.Section``,
    which imports this module: a protocol keeps the imports one way)."""

    def error(self, name: str, value: object, allowed: str) -> Exception: ...

    def number(self, name: str, default: float, minimum: float, maximum: float) -> float: ...

    def integer(self, name: str, default: int, minimum: int, maximum: int) -> int: ...

    def boolean(self, name: str, default: bool) -> bool: ...

    def text(self, name: str, default: str, choices: tuple[str, ...] | None = None) -> str: ...

    def finish(self) -> None: ...


DEFAULT_PORT = 4840  # the IANA port of OPC UA


@dataclass(frozen=True)
class OpcuaSettings:
    enabled: bool = False
    host: str = "127.0.0.1"
    port: int = DEFAULT_PORT
    allow_security_none: bool = False
    allow_anonymous: bool = False
    pki_dir: str = ""  # empty: "opcua-pki" beside the database
    nodesets_dir: str = ""  # empty: the folder the installation put them in
    manufacturer: str = "Stave jointer"
    model: str = "CNC stave jointer"
    serial_number: str = "0000"
    year_of_construction: int = 2026
    location: str = ""
    max_failed_logins: int = 3
    lockout_s: float = 30.0

    @property
    def endpoint_url(self) -> str:
        return f"opc.tcp://{self.host}:{self.port}/stave-jointer/"

    def insecure_choices(self) -> list[str]:
        """The commissioning shortcuts turned on, for the warning in the log and on the
        System screen."""
        found = []
        if self.allow_security_none:
            found.append("security policy None")
        if self.allow_anonymous:
            found.append("anonymous access")
        return found


def read_opcua_settings(section: Section) -> OpcuaSettings:
    """Check every key of ``[opcua]`` (unknown keys refused by ``section.finish``)."""
    d = OpcuaSettings()
    host = section.text("host", d.host)
    try:
        ipaddress.ip_address(host)
    except ValueError:
        raise section.error("host", host, "an IPv4 or IPv6 address, e.g. 127.0.0.1") from None
    settings = OpcuaSettings(
        enabled=section.boolean("enabled", d.enabled),
        host=host,
        port=section.integer("port", d.port, 0, 65535),
        allow_security_none=section.boolean("allow_security_none", d.allow_security_none),
        allow_anonymous=section.boolean("allow_anonymous", d.allow_anonymous),
        pki_dir=section.text("pki_dir", d.pki_dir),
        nodesets_dir=section.text("nodesets_dir", d.nodesets_dir),
        manufacturer=section.text("manufacturer", d.manufacturer),
        model=section.text("model", d.model),
        serial_number=section.text("serial_number", d.serial_number),
        year_of_construction=section.integer(
            "year_of_construction", d.year_of_construction, 1900, 2200
        ),
        location=section.text("location", d.location),
        max_failed_logins=section.integer("max_failed_logins", d.max_failed_logins, 1, 100),
        lockout_s=section.number("lockout_s", d.lockout_s, 1.0, 3600.0),
    )
    section.finish()
    return settings
