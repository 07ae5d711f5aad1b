"""Users, roles and PIN hashing.

The panel is a shared touch screen on the shop floor, so a user is identified by a short numeric
PIN typed on the keypad, not by a name and password. Roles are ordered: whatever an operator may
do, a technician may do too, and a service engineer may do everything. A PIN is stored only as a
salted scrypt hash with its cost parameters in the same string, so the cost can be raised later
without invalidating stored PINs. (A 4-digit PIN has only 10,000 values: the hash keeps PINs out
of plain sight in a copied database file; it is not a defence against a determined attacker with
the file, which is why settings are also guarded by the operating system's file permissions.)
"""

from __future__ import annotations

import hashlib
import hmac
import secrets
from dataclasses import dataclass
from enum import IntEnum

PIN_MIN_DIGITS = 4
SIMULATION_ACTOR = "simulation"
CONFIGURATION_ACTOR = "configuration"
"""The name the parameter log gives the factory values a new database takes from the machine's
configuration on the first start: nobody changed them, the service user least of all."""
"""The name the change logs give what the simulated machine changes (its factory parameters,
the recipes ``stave simulate`` is given): on the service user's authority, but never confused
with a service engineer's own change."""
PIN_MAX_DIGITS = 8

# scrypt cost: about 60 ms per hash on the 2-core panel PC class of machine; authenticate()
# checks each user's hash, so a log-in costs a fraction of a second with a handful of users.
_SCRYPT_N = 2**14
_SCRYPT_R = 8
_SCRYPT_P = 1
_DKLEN = 32
_SALT_BYTES = 16


class Role(IntEnum):
    """User roles, ordered by what they may do (compare with ``>=``)."""

    OPERATOR = 1
    TECHNICIAN = 2
    SERVICE = 3

    @property
    def label(self) -> str:
        """The lowercase name stored in the database and shown in reports."""
        return self.name.lower()

    @classmethod
    def from_label(cls, label: str) -> Role:
        """Parse a stored or typed role name ("operator", "technician", "service")."""
        try:
            return cls[label.strip().upper()]
        except KeyError:
            allowed = ", ".join(role.label for role in cls)
            raise ValueError(f"role {label!r} is unknown; allowed: {allowed}") from None


@dataclass(frozen=True)
class User:
    """A user as the data layer hands it out (never with the PIN or its hash)."""

    id: int
    name: str
    role: Role


# The users a brand-new database starts with and their PINs (documented in the README; the
# first thing a commissioning engineer does is change them on the Users screen).
DEFAULT_USERS: tuple[tuple[str, Role, str], ...] = (
    ("operator", Role.OPERATOR, "0000"),
    ("technician", Role.TECHNICIAN, "1234"),
    ("service", Role.SERVICE, "9999"),
)


def check_pin_format(pin: str) -> None:
    """Raise ValueError naming the rule unless ``pin`` is 4 to 8 decimal digits."""
    if not isinstance(pin, str) or not (
        PIN_MIN_DIGITS <= len(pin) <= PIN_MAX_DIGITS and pin.isascii() and pin.isdigit()
    ):
        raise ValueError(
            f"pin: {'****' if isinstance(pin, str) else type(pin).__name__} is not allowed; "
            f"a PIN is {PIN_MIN_DIGITS} to {PIN_MAX_DIGITS} digits 0-9"
        )


def hash_secret(secret: str) -> str:
    """Return ``scrypt$N$r$p$salt_hex$hash_hex`` for a PIN or a password (UTF-8)."""
    salt = secrets.token_bytes(_SALT_BYTES)
    digest = hashlib.scrypt(
        secret.encode("utf-8"), salt=salt, n=_SCRYPT_N, r=_SCRYPT_R, p=_SCRYPT_P, dklen=_DKLEN
    )
    return f"scrypt${_SCRYPT_N}${_SCRYPT_R}${_SCRYPT_P}${salt.hex()}${digest.hex()}"


def verify_secret(secret: str, stored: str) -> bool:
    """True if ``secret`` matches a hash made by :func:`hash_secret` (constant-time compare)."""
    try:
        scheme, n_text, r_text, p_text, salt_hex, digest_hex = stored.split("$")
        if scheme != "scrypt":
            return False
        salt = bytes.fromhex(salt_hex)
        expected = bytes.fromhex(digest_hex)
        n, r, p = int(n_text), int(r_text), int(p_text)
    except ValueError:
        return False
    if not isinstance(secret, str):
        return False
    digest = hashlib.scrypt(secret.encode("utf-8"), salt=salt, n=n, r=r, p=p, dklen=len(expected))
    return hmac.compare_digest(digest, expected)


def hash_pin(pin: str) -> str:
    """Return ``scrypt$N$r$p$salt_hex$hash_hex`` for a PIN (format-checked first)."""
    check_pin_format(pin)
    return hash_secret(pin)


def verify_pin(pin: str, stored: str) -> bool:
    """True if ``pin`` matches a hash made by :func:`hash_pin` (constant-time compare)."""
    if not isinstance(pin, str) or not pin.isascii():
        return False
    return verify_secret(pin, stored)
