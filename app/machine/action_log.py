"""The machine log's record of what people did: every accepted command once, with the user
who gave it, and refusals without the flood.

Why here and not in each handler: accountability (who switched the spindle on, who reset
after the fault, who acknowledged) needs every action in one place, the same way; and the
screens repeat some commands on purpose (a held jog button re-sends its jog ten times a
second as a dead-man refresh, a refused one is refused ten times a second), which must give
one line, not a screenful. So a held jog is one action until it is released or stopped, and
a refusal repeated within ``REFUSAL_REPEAT_S`` is counted and reported with the next line.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.machine import commands as cmd
from app.machine.refusals import Refusal

REFUSAL_REPEAT_S = 5.0
NO_USER = "(nobody named)"

# Commands that are not a person's action (a release ends the held jog; the rest is the
# panel's own bookkeeping).
NOT_ACTIONS: tuple[type, ...] = (cmd.JogRelease, cmd.ReloadParameters)


def who(user: str) -> str:
    return user or NO_USER


@dataclass
class ActionLog:
    """Decides the lines; the caller writes them (the machine process's log)."""

    _jogging: dict[str, int] = field(default_factory=dict)  # axis -> direction held
    _last_refusal: Refusal | None = None
    _last_refusal_s: float = -1e9
    _repeats: int = 0

    def accepted(self, command: cmd.Command, user: str) -> str | None:
        """The line for an accepted command, or None when it is no new action."""
        match command:
            case cmd.JogContinuous(axis=axis, direction=direction):
                if self._jogging.get(axis) == direction:
                    return None  # the held button's refresh
                self._jogging[axis] = direction
            case cmd.JogRelease(axis=axis):
                self._jogging.pop(axis, None)
            case cmd.SetUser(name=name):
                return f"at the panel now: {who(name)}"
        if isinstance(command, NOT_ACTIONS):
            return None
        return f"{command} by {who(user)}"

    def stopped(self, axis: str) -> None:
        """The held jog on ``axis`` ended without a release (dead-man, a stop, a fault): the
        next press is a new action."""
        self._jogging.pop(axis, None)

    def stopped_all(self) -> None:
        self._jogging.clear()

    def refused(self, refusal: Refusal, now_s: float, user: str) -> str | None:
        """The line for a refusal, or None for the same one again within the repeat time."""
        if refusal == self._last_refusal and now_s - self._last_refusal_s < REFUSAL_REPEAT_S:
            self._repeats += 1
            return None
        line = f"refused for {who(user)}: {refusal}"
        if self._repeats:
            line += f" (the one before repeated {self._repeats} more times)"
        self._last_refusal, self._last_refusal_s, self._repeats = refusal, now_s, 0
        return line
