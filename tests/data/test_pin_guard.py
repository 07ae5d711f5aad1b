"""Wrong PINs: a growing delay, then a lockout with an alarm, a log line and the time until it
lifts; a right PIN or a service unlock resets it. The same rule through the database API and
the command line (the panel's PIN pad is in tests/screens/test_other_screens.py)."""

from __future__ import annotations

import logging
import subprocess
import sys
from datetime import UTC, datetime
from pathlib import Path

import pytest

from app.data.database import Database
from app.data.errors import PermissionDeniedError, PinEntryRefused
from app.data.pin_guard import (
    FREE_FAILURES,
    LOCKOUT_ALARM_CODE,
    LOCKOUT_S,
    MAX_DELAY_S,
    delay_after,
)
from app.data.users import Role, User

from .conftest import SimClock


def wrong_until_locked(db: Database, clock: SimClock) -> list[float]:
    """Wrong PINs, each as soon as it is allowed; returns the delays met on the way."""
    delays: list[float] = []
    while db.pin_guard_state().locked_until is None:
        assert db.authenticate("5555") is None
        state = db.pin_guard_state()
        seconds = delay_after(state.failures)
        if seconds and state.locked_until is None:
            with pytest.raises(PinEntryRefused):
                db.authenticate("1234")  # even the right PIN is not looked at yet
            delays.append(seconds)
            clock.advance(seconds)
    return delays


def test_the_delay_grows_then_pin_entry_locks_with_an_alarm_and_a_log_line(
    db: Database, clock: SimClock, caplog: pytest.LogCaptureFixture
) -> None:
    for _ in range(FREE_FAILURES - 1):
        assert db.authenticate("5555") is None  # a slip of the finger costs nothing
    assert db.authenticate("1234") is not None  # and the right PIN resets the count
    assert db.pin_guard_state().failures == 0

    with caplog.at_level(logging.WARNING, logger="app.data.database"):
        delays = wrong_until_locked(db, clock)
    assert delays == sorted(delays) and delays[0] == 1.0 and max(delays) <= MAX_DELAY_S
    with pytest.raises(PinEntryRefused) as refused:
        db.authenticate("1234")
    assert refused.value.locked and refused.value.retry_after_s == pytest.approx(LOCKOUT_S)
    assert "locked" in str(refused.value) and "lifts in 15 min 00 s" in str(refused.value)
    assert any("PIN entry is locked" in r.getMessage() for r in caplog.records)
    alarm = db.list_alarm_events()[0]
    assert alarm.code == LOCKOUT_ALARM_CODE and alarm.to_state.value == "active_unacked"

    clock.advance(LOCKOUT_S - 1)
    with pytest.raises(PinEntryRefused, match="lifts in 0 min 01 s"):
        db.authenticate("1234")
    clock.advance(1)
    assert db.authenticate("5555") is None  # after the lockout one more wrong PIN ...
    with pytest.raises(PinEntryRefused, match="locked"):
        db.authenticate("1234")  # ... locks again at once
    clock.advance(LOCKOUT_S)
    assert db.authenticate("1234") is not None
    assert db.pin_guard_state().failures == 0


def test_a_service_user_can_unlock_and_nobody_else(
    db: Database, clock: SimClock, users: dict[Role, User]
) -> None:
    wrong_until_locked(db, clock)
    with pytest.raises(PermissionDeniedError, match="service"):
        db.unlock_pin_entry(users[Role.TECHNICIAN])
    db.unlock_pin_entry(users[Role.SERVICE])
    assert db.authenticate("1234") == users[Role.TECHNICIAN]
    back = db.list_alarm_events()[0]
    assert back.code == LOCKOUT_ALARM_CODE and back.to_state.value == "normal"
    assert back.user_name == "service"


def test_the_counter_is_shared_by_every_connection(
    db: Database, db_path: Path, clock: SimClock
) -> None:
    wrong_until_locked(db, clock)
    with (
        Database.open(db_path, clock=clock) as other,  # another program, the same rule
        pytest.raises(PinEntryRefused, match="locked"),
    ):
        other.authenticate("1234")


def stave_db(
    *argv: str, pin: str | None = None, stdin: str = ""
) -> subprocess.CompletedProcess[str]:
    env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": str(Path(__file__).resolve().parents[2])}
    if pin is not None:
        env["STAVE_PIN"] = pin
    return subprocess.run(
        [sys.executable, "-m", "app.cli.db", *argv],
        input=stdin,
        capture_output=True,
        text=True,
        check=False,
        timeout=60,
        env=env,
    )


def test_the_command_line_counts_wrong_pins_and_is_locked_too(
    db_path: Path, tmp_path: Path
) -> None:
    source = tmp_path / "in.csv"
    source.write_text("name,length_mm,thickness_mm,length_ratio,width_ratio,tilt_deg\n")
    wrong = stave_db("import", str(source), "--db", str(db_path), pin="5555")
    assert wrong.returncode == 2 and "belongs to no user" in wrong.stderr
    clock = SimClock(datetime.now(UTC))
    with Database.open(db_path, clock=clock) as db:
        assert db.pin_guard_state().failures == 1  # the command line's attempt counted
        wrong_until_locked(db, clock)
    refused = stave_db("import", str(source), "--db", str(db_path), stdin="1234\n")
    assert refused.returncode == 2 and "PIN entry is locked" in refused.stderr
    assert refused.stderr.count("\n") == 1


def test_the_pin_comes_from_standard_input_and_never_from_the_arguments(
    db_path: Path, tmp_path: Path
) -> None:
    source = tmp_path / "in.csv"
    source.write_text("name,length_mm,thickness_mm,length_ratio,width_ratio,tilt_deg\n")
    done = stave_db("import", str(source), "--db", str(db_path), stdin="1234\n")
    assert done.returncode == 0, done.stderr
    assert "0 accepted" in done.stdout
    refused = stave_db("import", str(source), "--db", str(db_path), "--pin", "1234")
    assert refused.returncode == 2 and "--pin" in refused.stderr


def test_unlock_from_the_machine_account(db: Database, db_path: Path, clock: SimClock) -> None:
    wrong_until_locked(db, clock)
    done = stave_db("unlock-pins", "--db", str(db_path))
    assert done.returncode == 0 and "unlocked (10 wrong PINs" in done.stdout
    assert db.authenticate("1234") is not None
