"""Value types for what the machine reports: finished pieces, alarm transitions, parameter changes.

They are plain frozen dataclasses so the machine layer can build them without touching the
database, and so a record read back compares equal to the one written. Times are timezone-aware;
a naive datetime is taken as the machine's local time (Python's own convention) and everything is
stored in UTC, so a change of daylight-saving time never reorders the history.
"""

from __future__ import annotations

import dataclasses
import json
import math
from dataclasses import dataclass
from datetime import UTC, datetime
from enum import Enum
from typing import Any, Protocol

OPERATOR_NAME_MAX_CHARS = 40
"""The longest name an operator gives himself for a shift (the production table's limit)."""


class PieceResult(Enum):
    """How one board ended."""

    OK = "ok"  # both sides cut, counted as a finished stave
    REJECTED = "rejected"  # refused before cutting (width out of limits, not measurable, ...)
    ABORTED = "aborted"  # cutting started and was stopped (stop, emergency stop, fault)


class AlarmState(Enum):
    """ISA-18.2 alarm states; every transition between two of them is one history row."""

    NORMAL = "normal"
    ACTIVE_UNACKED = "active_unacked"
    ACTIVE_ACKED = "active_acked"
    RETURNED_UNACKED = "returned_unacked"
    SHELVED = "shelved"


def to_utc(moment: datetime) -> datetime:
    """Return ``moment`` in UTC; a naive datetime is local time."""
    return moment.astimezone(UTC)


def format_utc(moment: datetime) -> str:
    """The stored form: fixed-width ISO 8601 in UTC, so text order is time order."""
    return to_utc(moment).strftime("%Y-%m-%dT%H:%M:%S.%fZ")


def parse_utc(text: str) -> datetime:
    """Inverse of :func:`format_utc`."""
    return datetime.strptime(text, "%Y-%m-%dT%H:%M:%S.%fZ").replace(tzinfo=UTC)


def _finite_or_none(field: str, value: float | None) -> str | None:
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        return f"{field}: {value!r} is not allowed; expected a finite number or None"
    return None


@dataclass(frozen=True)
class ProductionRecord:
    """One board through the machine.

    ``recipe_name`` is kept beside ``recipe_id`` because a recipe may later be renamed or
    deleted, and the production record must still say what was made. ``d_mm`` and ``r_mm`` are
    the solved rise and arc radius (None when nothing was computed, or when the arc is straight,
    as with a width ratio of 1). ``width_mm`` is None when the gauge gave no finite number.
    """

    time: datetime
    recipe_id: int | None
    recipe_name: str
    width_mm: float | None
    d_mm: float | None
    r_mm: float | None
    cycle_time_s: float
    result: PieceResult
    alarm_code: str | None = None
    tilt_deg: float | None = None
    id: int | None = None
    resumed: bool = False  # the cut was interrupted and resumed (every part of both sides cut)
    step_times_s: dict[str, float] = dataclasses.field(default_factory=dict)
    """Where the cycle's seconds went: step name -> seconds (empty for records kept before
    the step times were)."""
    barrel_number: int | None = None  # the barrel this board was cut for (None: single staves)
    stave_number: int | None = None  # its place in that barrel, 1 = the first stave
    operator_name: str | None = None
    """Who ran the machine: the operator of the shift as he named himself, else the panel's
    user (None for records kept before the name was)."""

    def problems(self) -> list[str]:
        """Everything that makes this record unstorable, as messages naming the field."""
        found: list[str] = []
        if not isinstance(self.time, datetime):
            found.append(f"time: {self.time!r} is not allowed; expected a datetime")
        if not isinstance(self.recipe_name, str) or not self.recipe_name.strip():
            found.append(f"recipe_name: {self.recipe_name!r} is not allowed; expected a name")
        for field, value in (
            ("width_mm", self.width_mm),
            ("d_mm", self.d_mm),
            ("r_mm", self.r_mm),
            ("tilt_deg", self.tilt_deg),
        ):
            message = _finite_or_none(field, value)
            if message:
                found.append(message)
        if (
            isinstance(self.cycle_time_s, bool)
            or not isinstance(self.cycle_time_s, int | float)
            or not math.isfinite(self.cycle_time_s)
            or self.cycle_time_s < 0
        ):
            found.append(
                f"cycle_time_s: {self.cycle_time_s!r} is not allowed; expected a finite number >= 0"
            )
        if not isinstance(self.result, PieceResult):
            allowed = ", ".join(r.value for r in PieceResult)
            found.append(f"result: {self.result!r} is not allowed; allowed: {allowed}")
        elif self.result is PieceResult.OK and self.width_mm is None:
            found.append("width_mm: None is not allowed for a finished piece (result ok)")
        if self.alarm_code is not None and (
            not isinstance(self.alarm_code, str) or not self.alarm_code.strip()
        ):
            found.append(f"alarm_code: {self.alarm_code!r} is not allowed; expected a code or None")
        found.extend(_step_time_problems(self.step_times_s))
        found.extend(self._barrel_problems())
        if self.operator_name is not None and (
            not isinstance(self.operator_name, str)
            or not self.operator_name.strip()
            or len(self.operator_name) > OPERATOR_NAME_MAX_CHARS
        ):
            found.append(
                f"operator_name: {self.operator_name!r} is not allowed; expected a name of "
                f"1 to {OPERATOR_NAME_MAX_CHARS} characters or None"
            )
        return found

    def _barrel_problems(self) -> list[str]:
        found = [
            f"{field}: {value!r} is not allowed; expected a whole number >= 1 or None"
            for field, value in (
                ("barrel_number", self.barrel_number),
                ("stave_number", self.stave_number),
            )
            if value is not None
            and (isinstance(value, bool) or not isinstance(value, int) or value < 1)
        ]
        if (self.barrel_number is None) != (self.stave_number is None):
            found.append(
                f"stave_number: {self.stave_number!r} is not allowed with barrel_number = "
                f"{self.barrel_number!r}; both are given or neither"
            )
        return found


def _step_time_problems(step_times_s: object) -> list[str]:
    allowed = "expected step name -> finite seconds >= 0"
    if not isinstance(step_times_s, dict):
        return [f"step_times_s: {step_times_s!r} is not allowed; {allowed}"]
    return [
        f"step_times_s[{name!r}]: {seconds!r} is not allowed; {allowed}"
        for name, seconds in step_times_s.items()
        if not isinstance(name, str)
        or not name
        or isinstance(seconds, bool)
        or not isinstance(seconds, int | float)
        or not math.isfinite(seconds)
        or seconds < 0
    ]


@dataclass(frozen=True)
class AlarmEvent:
    """One transition of one alarm (ISA-18.2 history row).

    ``source`` says where it came from: an axis ("X", "Y", "Z") or a subsystem ("gauge",
    "estop", "spindle", ...). ``user_name`` is who acknowledged or shelved, when a person did.
    """

    time: datetime
    code: str
    text: str
    source: str
    from_state: AlarmState
    to_state: AlarmState
    user_name: str | None = None
    id: int | None = None
    detail_json: str | None = None
    """What was found as the machine's message code and arguments (JSON, written and read by
    ``app.machine.refusals``), so the screens show it in the user's language; ``text`` is the
    English line for logs, exports and the plant. None: no coded message (older rows too)."""

    def problems(self) -> list[str]:
        """Everything that makes this event unstorable, as messages naming the field."""
        found: list[str] = []
        if not isinstance(self.time, datetime):
            found.append(f"time: {self.time!r} is not allowed; expected a datetime")
        for field, value in (("code", self.code), ("text", self.text), ("source", self.source)):
            if not isinstance(value, str) or not value.strip():
                found.append(f"{field}: {value!r} is not allowed; expected non-empty text")
        allowed = ", ".join(s.value for s in AlarmState)
        for field, state in (("from_state", self.from_state), ("to_state", self.to_state)):
            if not isinstance(state, AlarmState):
                found.append(f"{field}: {state!r} is not allowed; allowed: {allowed}")
        if self.from_state == self.to_state:
            found.append(
                f"to_state: {self.to_state!r} is not allowed; a transition must change the state"
            )
        if self.detail_json is not None and not _is_json_object(self.detail_json):
            found.append(
                f"detail_json: {self.detail_json!r} is not allowed; expected a JSON object or None"
            )
        return found


def _is_json_object(text: object) -> bool:
    try:
        return isinstance(text, str) and isinstance(json.loads(text), dict)
    except ValueError:
        return False


@dataclass(frozen=True)
class AlarmEventFilter:
    """What :meth:`Database.list_alarm_events` returns: all given conditions must hold.

    ``start`` is inclusive and ``end`` exclusive; the newest events come first, at most ``limit``.
    """

    start: datetime | None = None
    end: datetime | None = None
    code: str | None = None
    source: str | None = None
    limit: int = 1000


@dataclass(frozen=True)
class ParameterChange:
    """One logged change of a system parameter: who, when, from what to what."""

    id: int
    time: datetime
    name: str
    old_value: float | None
    new_value: float
    user_name: str
    user_role: str


@dataclass(frozen=True)
class RecipeChange:
    """One logged change of a recipe, with the full recipe before and after as JSON text.

    Deleting a recipe is allowed, losing it is not: the last version of a deleted recipe stays
    here and can be imported back.
    """

    id: int
    time: datetime
    recipe_id: int | None
    recipe_name: str
    action: str  # "create", "update", "delete"
    user_name: str
    before_json: str | None
    after_json: str | None


class Fields(Protocol):
    """A row by column name: ``sqlite3.Row`` or a dict (a line of the write journal)."""

    def __getitem__(self, key: str, /) -> Any: ...

    def keys(self) -> Any: ...


def optional_float(value: Any) -> float | None:
    return None if value is None else float(value)


def optional_int(value: Any) -> int | None:
    return None if value is None else int(value)


def _id(fields: Fields) -> int | None:
    # keys(): ``in`` on an sqlite3.Row looks at the values, not the column names
    return optional_int(fields["id"]) if "id" in fields.keys() else None  # noqa: SIM118


def production_fields(record: ProductionRecord) -> dict[str, Any]:
    """The stored columns of a record (time in the stored text form), without its id."""
    return {
        "time": format_utc(record.time),
        "recipe_id": record.recipe_id,
        "recipe_name": record.recipe_name,
        "width_mm": optional_float(record.width_mm),
        "d_mm": optional_float(record.d_mm),
        "r_mm": optional_float(record.r_mm),
        "tilt_deg": optional_float(record.tilt_deg),
        "cycle_time_s": float(record.cycle_time_s),
        "result": record.result.value,
        "alarm_code": record.alarm_code,
        "resumed": int(bool(record.resumed)),
        "step_times_json": json.dumps(record.step_times_s) if record.step_times_s else None,
        "barrel_number": record.barrel_number,
        "stave_number": record.stave_number,
        "operator_name": record.operator_name,
    }


def production_from_fields(fields: Fields) -> ProductionRecord:
    """Inverse of :func:`production_fields` (a stored row, or a journal line)."""
    return ProductionRecord(
        id=_id(fields),
        time=parse_utc(fields["time"]),
        recipe_id=optional_int(fields["recipe_id"]),
        recipe_name=str(fields["recipe_name"]),
        width_mm=optional_float(fields["width_mm"]),
        d_mm=optional_float(fields["d_mm"]),
        r_mm=optional_float(fields["r_mm"]),
        tilt_deg=optional_float(fields["tilt_deg"]),
        cycle_time_s=float(fields["cycle_time_s"]),
        result=PieceResult(fields["result"]),
        alarm_code=fields["alarm_code"],
        # Journal lines written before the column existed have no "resumed"; keys(), because
        # `in` on an sqlite3.Row looks at the values.
        resumed=bool(fields["resumed"]) if "resumed" in fields.keys() else False,  # noqa: SIM118
        step_times_s=_step_times(fields),
        barrel_number=_optional_field(fields, "barrel_number"),
        stave_number=_optional_field(fields, "stave_number"),
        operator_name=_optional_text(fields, "operator_name"),
    )


def _step_times(fields: Fields) -> dict[str, float]:
    """The stored step times (none in rows and journal lines from before the column)."""
    if "step_times_json" not in fields.keys():  # noqa: SIM118
        return {}
    text = fields["step_times_json"]
    if text is None:
        return {}
    loaded = json.loads(text)
    if not isinstance(loaded, dict):
        return {}
    return {str(name): float(seconds) for name, seconds in loaded.items()}


def _optional_field(fields: Fields, key: str) -> int | None:
    """A column that journal lines written before it existed do not have (None then)."""
    return optional_int(fields[key]) if key in fields.keys() else None  # noqa: SIM118


def _optional_text(fields: Fields, key: str) -> str | None:
    """A text column that older rows and journal lines do not have (None then)."""
    if key not in fields.keys():  # noqa: SIM118
        return None
    value = fields[key]
    return None if value is None else str(value)


def alarm_fields(event: AlarmEvent) -> dict[str, Any]:
    """The stored columns of an alarm transition (time in the stored text form), without id."""
    return {
        "time": format_utc(event.time),
        "code": event.code,
        "text": event.text,
        "source": event.source,
        "from_state": event.from_state.value,
        "to_state": event.to_state.value,
        "user_name": event.user_name,
        "detail_json": event.detail_json,
    }


def alarm_from_fields(fields: Fields) -> AlarmEvent:
    """Inverse of :func:`alarm_fields`."""
    return AlarmEvent(
        id=_id(fields),
        time=parse_utc(fields["time"]),
        code=str(fields["code"]),
        text=str(fields["text"]),
        source=str(fields["source"]),
        from_state=AlarmState(fields["from_state"]),
        to_state=AlarmState(fields["to_state"]),
        user_name=fields["user_name"],
        detail_json=_optional_text(fields, "detail_json"),
    )
