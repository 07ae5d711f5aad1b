"""The OPC UA users of the plant connection, kept in the product's database.

Why separate from the panel's users: a panel user is a person at the machine with a PIN; a
plant user is a system (an MES, a SCADA) or a person in the office with a user name and a
password, and it may do far less: read, or (role ``plant``) hand the machine a job. Passwords
are stored only as salted scrypt hashes, the same scheme as the panel's PINs.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from app.data.database import Database
from app.data.errors import NotFoundError
from app.data.users import hash_secret, verify_secret

PASSWORD_MIN_CHARS = 8
PASSWORD_MAX_CHARS = 128
NAME_MAX_CHARS = 40


class PlantRole(enum.Enum):
    READ_ONLY = "read-only"  # browse, read, subscribe
    PLANT = "plant"  # also the job methods (select or download a recipe)

    @classmethod
    def from_label(cls, label: str) -> PlantRole:
        for role in cls:
            if role.value == label:
                return role
        allowed = ", ".join(repr(r.value) for r in cls)
        raise ValueError(f"role = {label!r} is not allowed: one of {allowed}")


@dataclass(frozen=True)
class PlantUser:
    name: str
    role: PlantRole


def check_user_name(name: str) -> None:
    if not (1 <= len(name) <= NAME_MAX_CHARS) or name != name.strip() or not name.isprintable():
        raise ValueError(
            f"name = {name!r} is not allowed: 1 to {NAME_MAX_CHARS} printable characters "
            "without leading or trailing spaces"
        )


def check_password(password: str) -> None:
    if not PASSWORD_MIN_CHARS <= len(password) <= PASSWORD_MAX_CHARS:
        raise ValueError(
            f"password ({len(password)} characters) is not allowed: "
            f"{PASSWORD_MIN_CHARS} to {PASSWORD_MAX_CHARS} characters"
        )


def add_plant_user(db: Database, name: str, role: PlantRole, password: str) -> PlantUser:
    """Create the user, or replace its role and password if the name exists."""
    check_user_name(name)
    check_password(password)
    hashed = hash_secret(password)
    with db._write() as conn:
        conn.execute(
            "INSERT INTO opcua_users (name, role, password_hash, updated_at) VALUES (?, ?, ?, ?) "
            "ON CONFLICT (name) DO UPDATE SET role = excluded.role, "
            "password_hash = excluded.password_hash, updated_at = excluded.updated_at",
            (name, role.value, hashed, db._now()),
        )
    return PlantUser(name, role)


def remove_plant_user(db: Database, name: str) -> None:
    with db._write() as conn:
        cursor = conn.execute("DELETE FROM opcua_users WHERE name = ?", (name,))
        if cursor.rowcount == 0:
            raise NotFoundError(f"name = {name!r} is not an OPC UA user of this database")


def list_plant_users(db: Database) -> list[PlantUser]:
    rows = db._conn.execute("SELECT name, role FROM opcua_users ORDER BY name").fetchall()
    return [PlantUser(str(r["name"]), PlantRole.from_label(str(r["role"]))) for r in rows]


def authenticate_plant_user(db: Database, name: str, password: str) -> PlantUser | None:
    """The user if the password matches; None otherwise (also for an unknown name)."""
    row = db._conn.execute(
        "SELECT name, role, password_hash FROM opcua_users WHERE name = ?", (name,)
    ).fetchone()
    if row is None:
        # Hash anyway, so that an unknown name costs as long as a wrong password.
        verify_secret(password, hash_secret("timing"))
        return None
    if not verify_secret(password, str(row["password_hash"])):
        return None
    return PlantUser(str(row["name"]), PlantRole.from_label(str(row["role"])))
