"""The plant connection's pure parts: settings, login throttle, trust list, alarm changes,
jobs, users in the database, and the English/Slovenian alarm titles."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from app.config import ConfigError, parse_config
from app.data.database import Database
from app.data.plant_users import (
    PlantRole,
    add_plant_user,
    authenticate_plant_user,
    list_plant_users,
    remove_plant_user,
)
from app.geometry.barrel_section import BarrelSection
from app.machine.barrel_set import BarrelSet
from app.machine.barrel_view import barrel_view
from app.machine.snapshot import AlarmState, AlarmView
from app.plant.alarm_events import alarm_changes
from app.plant.alarm_texts import alarm_titles
from app.plant.login_throttle import LoginThrottle
from app.plant.state_map import OFFLINE_FLAGS
from app.plant.state_times import StateTimes, load_state_times, save_state_times
from app.plant.trust import TrustList
from tests.plant.certificates import client_certificate_der


def test_opcua_settings_are_checked_like_every_key() -> None:
    config = parse_config({"opcua": {"enabled": True, "port": 4841}})
    assert config.opcua.enabled and config.opcua.endpoint_url.endswith(":4841/stave-jointer/")
    for bad, key in (
        ({"opcua": {"prot": 1}}, "opcua.prot"),
        ({"opcua": {"port": 70000}}, "opcua.port"),
        ({"opcua": {"host": "plant.local"}}, "opcua.host"),
        ({"opcua": {"allow_anonymous": "yes"}}, "opcua.allow_anonymous"),
    ):
        with pytest.raises(ConfigError) as caught:
            parse_config(bad)
        assert caught.value.key == key


def test_insecure_choices_are_named() -> None:
    config = parse_config({"opcua": {"allow_security_none": True, "allow_anonymous": True}})
    assert config.opcua.insecure_choices() == ["security policy None", "anonymous access"]


def test_login_throttle_locks_and_doubles() -> None:
    now = [0.0]
    throttle = LoginThrottle(3, 10.0, lambda: now[0])
    for _ in range(2):
        throttle.failed("mes")
    assert throttle.locked_for_s("mes") == 0.0
    throttle.failed("MES")
    assert throttle.locked_for_s("mes") == 10.0
    now[0] = 10.5
    assert throttle.locked_for_s("mes") == 0.0
    throttle.failed("mes")
    assert throttle.locked_for_s("mes") == 20.0
    throttle.succeeded("mes")
    assert throttle.locked_for_s("mes") == 0.0


def test_plant_users_hashed_in_the_database(tmp_path: Path) -> None:
    with Database.open(tmp_path / "s.db") as db:
        add_plant_user(db, "mes", PlantRole.PLANT, "long-enough")
        row = db._conn.execute("SELECT password_hash FROM opcua_users").fetchone()
        assert str(row[0]).startswith("scrypt$") and "long-enough" not in str(row[0])
        assert authenticate_plant_user(db, "mes", "long-enough") is not None
        assert authenticate_plant_user(db, "mes", "wrong-one!") is None
        assert authenticate_plant_user(db, "nobody", "long-enough") is None
        with pytest.raises(ValueError, match="password"):
            add_plant_user(db, "x", PlantRole.PLANT, "short")
        assert [u.name for u in list_plant_users(db)] == ["mes"]
        remove_plant_user(db, "mes")
        assert list_plant_users(db) == []


def test_trust_list_accept_and_reject(tmp_path: Path) -> None:
    der = client_certificate_der()
    trust = TrustList(tmp_path)
    trust.create_folders()
    assert not trust.is_trusted(der)
    print_ = trust.note_rejected(der)
    assert [c.thumbprint for c in trust.rejected()] == [print_]
    trust.accept(print_)
    assert trust.is_trusted(der) and trust.rejected() == []
    trust.reject(print_.upper())
    assert not trust.is_trusted(der)
    with pytest.raises(ValueError, match="40 hexadecimal digits"):
        trust.accept("xyz")


def _alarm(alarm_id: int, state: AlarmState) -> AlarmView:
    return AlarmView(alarm_id, "E001", "Emergency stop", "chain", state, 0.0, "fault")


def test_alarm_changes_include_the_return_to_normal() -> None:
    raised = (_alarm(1, AlarmState.ACTIVE_UNACKED),)
    acked = (_alarm(1, AlarmState.ACTIVE_ACKED),)
    changes = alarm_changes((), raised) + alarm_changes(raised, acked) + alarm_changes(acked, ())
    assert [(c.from_state, c.to_state) for c in changes] == [
        (AlarmState.NORMAL, AlarmState.ACTIVE_UNACKED),
        (AlarmState.ACTIVE_UNACKED, AlarmState.ACTIVE_ACKED),
        (AlarmState.ACTIVE_ACKED, AlarmState.NORMAL),
    ]
    assert alarm_changes(acked, acked) == []


def test_alarm_titles_in_english_and_slovenian() -> None:
    titles = alarm_titles("E001")
    assert titles["en"] == "Emergency stop" and titles["sl"] == "Zasilna zaustavitev"


READY_FLAGS = replace(
    OFFLINE_FLAGS, machine_on=True, power_present=True, machine_initialized=True, calibrated=True
)


def test_state_times_count_by_condition_and_continue_after_a_restart(tmp_path: Path) -> None:
    times = StateTimes()
    times.add(READY_FLAGS, 1000.0)
    cutting = replace(READY_FLAGS, recipe_in_run=True, workpiece_present=True)
    times.add(cutting, 500.0)
    times.add(replace(READY_FLAGS, recipe_in_run=True, wait_load=True), 300.0)
    times.add(OFFLINE_FLAGS, 200.0)
    values = times.values()
    assert values["RelativeReadyTime"] == 1000 and values["RelativeWorkingTime"] == 800
    assert values["RelativeMachineOnTime"] == values["AbsolutePowerPresentTime"] == 1800
    assert values["AbsoluteProductionTime"] == 500
    assert values["AbsoluteProductionWithoutWorkpieceTime"] == 300
    assert values["AbsoluteProductionWaitWorkpieceTime"] == 300
    assert values["AbsoluteMachineOffTime"] == 200
    save_state_times(times, tmp_path / "s.db", saved_at=1000.0)
    # Started again 30 s later: the absolute times go on, the relative ones start at zero,
    # and the 30 s the machine was off count as off.
    again = load_state_times(tmp_path / "s.db", started_at=1030.0).values()
    assert again["AbsoluteReadyTime"] == 1000 and again["RelativeReadyTime"] == 0
    assert again["AbsoluteMachineOffTime"] == 30200
    assert StateTimes.from_json("{not json", 0.0).values() == StateTimes().values()


def test_barrel_view_for_the_plant() -> None:
    barrel = BarrelSet(BarrelSection.circle(600.0), 80.0)
    empty = barrel_view(barrel, None, None)
    assert empty is not None and (empty.staves_done, empty.staves_left, empty.gap_mm) == (
        0,
        None,
        None,
    )
    for _ in range(3):
        barrel = barrel.with_stave(barrel.place(100.0))
    view = barrel_view(barrel, None, None)
    assert view is not None and view.staves_done == 3 and not view.closed
    assert view.staves_left == barrel.staves_left_estimate() and view.gap_mm == barrel.gap_mm
