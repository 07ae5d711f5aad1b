"""Exceptions of the data layer.

Every refusal says what was refused and why, naming the field, the value and what is allowed,
so a screen can show it as it is and a command-line user can fix the input at once. Validation
errors carry the geometry's FieldError records, so the recipe screen highlights a field the same
way whether the geometry or the database refused it.
"""

from __future__ import annotations

from collections.abc import Iterable

from app.geometry.errors import FieldError


class DataError(Exception):
    """Base of every error the data layer raises on purpose."""


class FieldValidationError(DataError, ValueError):
    """Something was not stored because one or more fields are invalid."""

    def __init__(self, what: str, errors: Iterable[FieldError]) -> None:
        self.errors: tuple[FieldError, ...] = tuple(errors)
        details = "; ".join(error.message for error in self.errors)
        super().__init__(f"{what} not saved: {details}")


class RecipeValidationError(FieldValidationError):
    """A recipe was refused; nothing was stored."""


class ParameterError(FieldValidationError):
    """A system parameter change was refused; nothing was stored."""


class RecordError(DataError, ValueError):
    """A production record or alarm event was refused (message names the field)."""


class NotFoundError(DataError, LookupError):
    """The recipe or user asked for does not exist (any more)."""


class PermissionDeniedError(DataError):
    """The user's role does not allow the action (message says which role it needs)."""


class PinError(DataError, ValueError):
    """A PIN was refused (format, or already used by another user)."""


class StorageError(DataError):
    """SQLite could not complete a write (disk full, I/O error, locked too long); nothing of
    that write was stored."""


class DatabaseOpenError(DataError):
    """The file cannot be used as this application's database (message says why)."""


class SchemaVersionError(DatabaseOpenError):
    """The file was written by newer software (a schema version this one does not know)."""


class RecipeFormatError(DataError, ValueError):
    """A recipe row (JSON object, CSV line) could not be read; ``errors`` names every bad key."""

    def __init__(self, errors: Iterable[FieldError]) -> None:
        self.errors: tuple[FieldError, ...] = tuple(errors)
        super().__init__("; ".join(error.message for error in self.errors))


class PinEntryRefused(PinError):
    """PIN entry is throttled or locked: the PIN was not even looked at.

    ``retry_after_s`` is how long until an attempt is looked at again; ``locked`` tells a
    lockout (lifted by time or by a service user) from the growing delay.
    """

    def __init__(self, message: str, retry_after_s: float, locked: bool) -> None:
        super().__init__(message)
        self.retry_after_s = retry_after_s
        self.locked = locked
