"""Typed validation errors that a screen can show next to the offending field.

Every check in the geometry package reports *all* violations at once (an operator fixing a
recipe wants the whole list, not one error per attempt), each as a `FieldError` carrying the
field's name, the rejected value and the allowed range as text. `GeometryError` bundles them
into one exception so that callers which only want "valid or not" can still use try/except.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, replace

from app.geometry.rule_texts import RuleText


@dataclass(frozen=True)
class FieldError:
    """One violated rule: which field, what value, what would have been allowed.

    `message` is the complete one-line text (it names the field, the value and the range),
    ready for a status line, a command line or an import report. `rule` and `args` say the
    same in words for a screen: the rule's English template (``RuleText``, "" when the check
    has none) and its arguments, already formatted.
    """

    field: str
    value: object
    allowed: str
    message: str
    rule: str = ""
    args: tuple[str, ...] = ()

    def __str__(self) -> str:
        return self.message


class GeometryError(ValueError):
    """Invalid input to the geometry; `errors` holds every violation found.

    str() is one line per error, e.g.
    "width_mm = 300 is out of range: allowed 0 < width <= 280 mm".
    """

    errors: tuple[FieldError, ...]

    def __init__(self, errors: Iterable[FieldError]) -> None:
        collected = tuple(errors)
        if not collected:
            raise ValueError("GeometryError needs at least one FieldError")
        self.errors = collected
        super().__init__("\n".join(error.message for error in collected))

    def __reduce__(self) -> tuple[object, ...]:
        # Exceptions pickle through their args (the joined text); rebuild from the errors
        # instead, so a GeometryError survives crossing a process boundary intact.
        return (GeometryError, (self.errors,))

    @property
    def fields(self) -> tuple[str, ...]:
        """The names of the offending fields, in the order found (may repeat)."""
        return tuple(error.field for error in self.errors)


def worded(error: FieldError, rule: RuleText, *args: object) -> FieldError:
    """``error`` with the words a screen shows for it (numbers formatted as typed)."""
    return replace(error, rule=rule.value, args=tuple(_argument(a) for a in args))


def _argument(value: object) -> str:
    return value if isinstance(value, str) else format_value(value)


def format_value(value: object) -> str:
    """Show a number the way an operator typed it: 300.0 -> "300", 0.1 -> "0.1"."""
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, float):
        if math.isfinite(value) and value == int(value) and abs(value) < 1e15:
            return str(int(value))
        return f"{value:.10g}"
    if isinstance(value, str):
        return repr(value)
    return str(value)


def out_of_range(field: str, value: object, allowed: str, note: str = "") -> FieldError:
    """The standard "out of range" error; `note` adds a reason after the range."""
    message = f"{field} = {format_value(value)} is out of range: allowed {allowed}"
    if note:
        message += f" ({note})"
    return FieldError(field=field, value=value, allowed=allowed, message=message)


def not_a_number(field: str, value: object, allowed: str) -> FieldError:
    """The error for NaN, infinities and values that are not numbers at all."""
    message = f"{field} = {format_value(value)} is not a finite number: allowed {allowed}"
    return FieldError(field=field, value=value, allowed=allowed, message=message)
