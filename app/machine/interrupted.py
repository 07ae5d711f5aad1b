"""An interrupted cut is a state of the machine, not a fresh start.

Why it is persisted: a board partly cut stays partly cut across a stop, an E-stop, a fault, a
power loss or a crash of either process. Starting a fresh cycle on it would start the spindle
wherever the cutter stands and drive through the clamped board; counting it as good would
ship a ruined stave. So from the moment the cut begins until the board is finished or
abandoned, the machine keeps (in the database, written at each phase of the cut and at the
interruption) which board it is, which phase of the cut it was in and where the cutter was.
Start then offers resume or abandon (``app.machine.planner.continuation``); a restart finds
the record and keeps the clamps closed.
"""

from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass
from typing import Any

from app.machine.planner.trajectory import Phase

CUT_PHASES = (Phase.APPROACH, Phase.CUT_A, Phase.REPOSITION, Phase.CUT_B, Phase.RETURN)


class InterruptedRecordError(ValueError):
    """A stored record that cannot be read back (named field, value, what is allowed)."""


@dataclass(frozen=True)
class InterruptedBoard:
    """The board on the table whose cut began and did not end."""

    recipe_id: int | None
    recipe_name: str
    width_mm: float
    phase: Phase  # the phase of the cut when it stopped (or was last recorded)
    x_mm: float  # where the cutter was (commanded), machine coordinates
    y_mm: float
    z_deg: float
    reason: str = ""  # the alarm code that stopped it, "stop", or "" while still cutting
    started_s: float = 0.0  # machine time the cycle began
    unclamped: bool = False  # the clamps opened since: the board may have moved

    @property
    def side(self) -> str:
        """The side being cut, for the operator ("A", "B" or "")."""
        return {Phase.CUT_A: "A", Phase.CUT_B: "B"}.get(self.phase, "")

    def describe(self) -> str:
        """One line for the operator."""
        where = f"side {self.side}" if self.side else self.phase.value
        return (
            f"board {self.width_mm:.1f} mm of {self.recipe_name!r} partly cut ({where}, "
            f"cutter at X {self.x_mm:.1f} Y {self.y_mm:.1f} mm)"
        )

    def to_json(self) -> str:
        data: dict[str, Any] = asdict(self)
        data["phase"] = self.phase.name
        return json.dumps(data, sort_keys=True)

    @classmethod
    def from_json(cls, text: str) -> InterruptedBoard:
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise InterruptedRecordError(f"interrupted board: not JSON ({exc})") from exc
        if not isinstance(data, dict):
            raise InterruptedRecordError("interrupted board: not a JSON object")
        phase_name = data.get("phase")
        allowed = ", ".join(p.name for p in CUT_PHASES)
        if phase_name not in {p.name for p in CUT_PHASES}:
            raise InterruptedRecordError(
                f"interrupted board: phase = {phase_name!r} is not allowed: one of {allowed}"
            )
        numbers = {}
        for name in ("width_mm", "x_mm", "y_mm", "z_deg", "started_s"):
            value = data.get(name)
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise InterruptedRecordError(
                    f"interrupted board: {name} = {value!r} is not allowed: a number"
                )
            if not math.isfinite(value):
                raise InterruptedRecordError(
                    f"interrupted board: {name} = {value!r} is not allowed: a finite number"
                )
            numbers[name] = float(value)
        recipe_id = data.get("recipe_id")
        if recipe_id is not None and (
            isinstance(recipe_id, bool) or not isinstance(recipe_id, int)
        ):
            raise InterruptedRecordError(
                f"interrupted board: recipe_id = {recipe_id!r} is not allowed: an integer or null"
            )
        recipe_name = data.get("recipe_name")
        reason = data.get("reason", "")
        unclamped = data.get("unclamped", False)
        if not isinstance(unclamped, bool):
            raise InterruptedRecordError(
                f"interrupted board: unclamped = {unclamped!r} is not allowed: true or false"
            )
        if not isinstance(recipe_name, str) or not isinstance(reason, str):
            raise InterruptedRecordError("interrupted board: recipe_name and reason must be text")
        return cls(
            recipe_id=recipe_id,
            recipe_name=recipe_name,
            phase=Phase[phase_name],
            reason=reason,
            unclamped=unclamped,
            **numbers,
        )
