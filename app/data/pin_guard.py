"""The rule against guessing PINs: a growing delay after wrong PINs, then a lockout.

Why one counter for the whole database and not one per user: a PIN identifies its user, so a
guess is not aimed at anybody in particular; and the panel's PIN pad, ``stave db`` and any
other program using :class:`app.data.database.Database` share the same row, so switching from
the panel to the command line (or starting many processes at once) gains nothing. An attempt
is counted as wrong *before* the hash is checked and forgiven when it matches, so parallel
attempts cannot all slip through one gap.

Figures: the first :data:`FREE_FAILURES` wrong PINs cost nothing (a finger slips); then each
further one doubles the wait before the next attempt is looked at (1 s, 2 s, 4 s ... at most
:data:`MAX_DELAY_S`), and the :data:`LOCKOUT_FAILURES`-th locks PIN entry for
:data:`LOCKOUT_S`. After a lockout lapses, every further wrong PIN locks again at once; a
right PIN, or a service user's unlock, resets the counter. At that rate a 6-digit PIN takes
years to find by trying.
"""

from __future__ import annotations

from dataclasses import dataclass
from datetime import datetime, timedelta

FREE_FAILURES = 3
LOCKOUT_FAILURES = 10
MAX_DELAY_S = 60.0
LOCKOUT_S = 15 * 60.0

LOCKOUT_ALARM_CODE = "W104"
"""The alarm the lockout records in the alarm history (catalogued in app.machine.alarms)."""
LOCKOUT_ALARM_TEXT = "PIN entry locked after repeated wrong PINs"
LOCKOUT_ALARM_SOURCE = "PIN entry"


@dataclass(frozen=True)
class PinGuardState:
    """The one stored row: wrong PINs in a row, the last one's time, the lockout's end."""

    failures: int = 0
    last_failure_at: datetime | None = None
    locked_until: datetime | None = None


def delay_after(failures: int) -> float:
    """Seconds to wait after the ``failures``-th wrong PIN in a row before the next attempt."""
    if failures < FREE_FAILURES:
        return 0.0
    return min(MAX_DELAY_S, 2.0 ** (failures - FREE_FAILURES))


def wait_s(state: PinGuardState, now: datetime) -> tuple[float, bool]:
    """(seconds until the next attempt is looked at, whether that is a lockout); 0 means now."""
    if state.locked_until is not None and now < state.locked_until:
        return (state.locked_until - now).total_seconds(), True
    if state.last_failure_at is None:
        return 0.0, False
    ready = state.last_failure_at + timedelta(seconds=delay_after(state.failures))
    return max(0.0, (ready - now).total_seconds()), False


def after_claim(state: PinGuardState, now: datetime) -> PinGuardState:
    """The attempt about to be checked counts as wrong until it matches."""
    return PinGuardState(state.failures + 1, now, state.locked_until)


def after_wrong(state: PinGuardState, now: datetime) -> PinGuardState:
    """A claimed attempt did not match: lock once the count reaches LOCKOUT_FAILURES."""
    if state.failures >= LOCKOUT_FAILURES:
        return PinGuardState(state.failures, now, now + timedelta(seconds=LOCKOUT_S))
    return state


def refusal_text(seconds: float, locked: bool) -> str:
    """The one line the panel and the command line show."""
    whole = max(1, int(seconds + 0.999))
    if locked:
        minutes, secs = divmod(whole, 60)
        return (
            f"pin: PIN entry is locked after {LOCKOUT_FAILURES} wrong PINs; it lifts in "
            f"{minutes} min {secs:02d} s (or a service user unlocks it)"
        )
    return f"pin: too many wrong PINs; try again in {whole} s"
