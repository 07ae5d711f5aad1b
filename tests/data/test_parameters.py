"""System parameters: the catalogue as data, validation on write, roles, the change log."""

from __future__ import annotations

import math

import pytest

from app.data.database import Database
from app.data.errors import ParameterError, PermissionDeniedError
from app.data.parameters import (
    DEFAULT_PARAMETERS,
    PARAMETER_BY_NAME,
    PARAMETERS,
    check_parameter_set,
    check_parameter_value,
)
from app.data.users import Role, User

from .conftest import SimClock

# What the System / Manual screens need (docs/MACHINE.md section 5).
REQUIRED = {
    "home_x_mm",
    "home_y_mm",
    "home_z_deg",
    "tool_radius_mm",
    "machine_height_mm",
    "solver_tolerance_mm",
    "start_x_mm",
    "start_y_mm",
    "xy_speed_mm_s",
    "xy_accel_mm_s2",
    "z_speed_deg_s",
    "z_accel_deg_s2",
    "lead_mm",
    "tilt_clearance_mm",
    "xy_jerk_mm_s3",
    "jog_xy_speed_mm_s",
    "jog_xy_accel_mm_s2",
    "jog_z_speed_deg_s",
    "jog_z_accel_deg_s2",
}
UNIT_OF_SUFFIX = {
    "_mm": "mm",
    "_deg": "deg",
    "_mm_s": "mm/s",
    "_mm_s2": "mm/s²",
    "_mm_s3": "mm/s³",
    "_deg_s": "deg/s",
    "_deg_s2": "deg/s²",
    "_deg_s3": "deg/s³",
    "_h": "h",
}


def test_the_catalogue_covers_the_screens() -> None:
    assert set(PARAMETER_BY_NAME) >= REQUIRED
    assert len(PARAMETER_BY_NAME) == len(PARAMETERS)  # names are unique


@pytest.mark.parametrize("spec", PARAMETERS, ids=lambda spec: spec.name)
def test_each_catalogue_row_is_consistent(spec: object) -> None:
    from app.data.parameters import ParameterSpec

    assert isinstance(spec, ParameterSpec)
    assert spec.minimum < spec.maximum
    assert check_parameter_value(spec, spec.default) is None
    assert spec.description and spec.group
    suffixes = [s for s in UNIT_OF_SUFFIX if spec.name.endswith(s)]
    if suffixes:
        # The unit in the name is the unit shown (the longest matching suffix decides).
        assert UNIT_OF_SUFFIX[max(suffixes, key=len)] == spec.unit
    else:
        assert spec.integer and spec.unit == ""


def test_the_defaults_satisfy_the_rules_between_parameters() -> None:
    assert check_parameter_set(DEFAULT_PARAMETERS) == []


def test_a_new_database_holds_the_defaults(db: Database) -> None:
    assert db.get_parameters() == dict(DEFAULT_PARAMETERS)
    assert list(db.get_parameters()) == [spec.name for spec in PARAMETERS]
    assert db.parameter_history() == []  # defaults are not somebody's change


def test_a_change_is_stored_and_logged_with_user_time_old_and_new(
    db: Database, users: dict[Role, User], clock: SimClock
) -> None:
    clock.advance(60)
    db.set_parameter("xy_speed_mm_s", 120.0, users[Role.TECHNICIAN])
    assert db.get_parameter("xy_speed_mm_s") == 120.0
    [change] = db.parameter_history()
    assert (change.name, change.old_value, change.new_value) == ("xy_speed_mm_s", 100.0, 120.0)
    assert (change.user_name, change.user_role, change.time) == (
        "technician",
        "technician",
        clock.now,
    )


def test_an_unchanged_value_is_not_logged(db: Database, users: dict[Role, User]) -> None:
    db.set_parameter("xy_speed_mm_s", DEFAULT_PARAMETERS["xy_speed_mm_s"], users[Role.SERVICE])
    assert db.parameter_history() == []


@pytest.mark.parametrize(
    ("name", "value"),
    [
        ("xy_speed_mm_s", 0.5),
        ("xy_speed_mm_s", 501.0),
        ("xy_speed_mm_s", math.nan),
        ("xy_speed_mm_s", math.inf),
        ("xy_speed_mm_s", "fast"),
        ("xy_speed_mm_s", True),
        ("shifts_per_day", 2.5),
    ],
)
def test_an_invalid_value_is_refused_and_nothing_changes(
    db: Database, users: dict[Role, User], name: str, value: object
) -> None:
    before = db.get_parameters()
    with pytest.raises(ParameterError) as caught:
        db.set_parameter(name, value, users[Role.SERVICE])  # type: ignore[arg-type]
    [error] = caught.value.errors
    assert error.field == name
    assert name in str(caught.value) and error.allowed in str(caught.value)
    assert db.get_parameters() == before
    assert db.parameter_history() == []


def test_an_unknown_name_suggests_the_close_ones(db: Database, users: dict[Role, User]) -> None:
    with pytest.raises(ParameterError, match="did you mean xy_speed_mm_s"):
        db.set_parameter("xy_sped_mm_s", 100.0, users[Role.SERVICE])


def test_the_required_role_is_enforced(db: Database, users: dict[Role, User]) -> None:
    assert PARAMETER_BY_NAME["machine_height_mm"].required_role is Role.SERVICE
    with pytest.raises(PermissionDeniedError, match="needs the role service"):
        db.set_parameter("machine_height_mm", 300.0, users[Role.TECHNICIAN])
    with pytest.raises(PermissionDeniedError, match="needs the role technician"):
        db.set_parameter("xy_speed_mm_s", 90.0, users[Role.OPERATOR])
    db.set_parameter("jog_xy_speed_mm_s", 30.0, users[Role.OPERATOR])  # the Manual screen's
    db.set_parameter("machine_height_mm", 300.0, users[Role.SERVICE])
    assert db.get_parameter("machine_height_mm") == 300.0


def test_a_claimed_role_is_not_trusted(db: Database, users: dict[Role, User]) -> None:
    """The stored role counts: an operator's User object with SERVICE written in is refused."""
    forged = User(users[Role.OPERATOR].id, "operator", Role.SERVICE)
    with pytest.raises(PermissionDeniedError):
        db.set_parameter("machine_height_mm", 300.0, forged)
    stranger = User(99, "nobody", Role.SERVICE)
    with pytest.raises(PermissionDeniedError, match="not a user"):
        db.set_parameter("xy_speed_mm_s", 90.0, stranger)


def test_rules_between_parameters(db: Database, users: dict[Role, User]) -> None:
    service = users[Role.SERVICE]
    with pytest.raises(ParameterError, match="lead_mm"):
        db.set_parameter("tool_radius_mm", 80.0, service)  # lead 60 would not clear the cutter
    with pytest.raises(ParameterError, match="x_max_mm"):
        db.set_parameter("x_min_mm", 5000.0, service)
    with pytest.raises(ParameterError, match="shift_length_h"):
        db.set_parameter("shift_length_h", 9.0, service)  # 3 shifts of 9 h
    # Changed together, in one transaction, both are fine.
    db.set_parameters({"lead_mm": 120.0, "tool_radius_mm": 80.0}, service)
    assert (db.get_parameter("lead_mm"), db.get_parameter("tool_radius_mm")) == (120.0, 80.0)


def test_a_set_is_all_or_nothing(db: Database, users: dict[Role, User]) -> None:
    before = db.get_parameters()
    with pytest.raises(ParameterError) as caught:
        db.set_parameters(
            {"xy_speed_mm_s": 150.0, "z_speed_deg_s": -1.0, "lead_mm": 0.0},
            users[Role.SERVICE],
        )
    assert {e.field for e in caught.value.errors} == {"z_speed_deg_s", "lead_mm"}
    assert db.get_parameters() == before


def test_history_filters(db: Database, users: dict[Role, User], clock: SimClock) -> None:
    tech = users[Role.TECHNICIAN]
    db.set_parameter("xy_speed_mm_s", 110.0, tech)
    middle = clock.advance(3600)
    db.set_parameter("xy_speed_mm_s", 120.0, tech)
    db.set_parameter("z_speed_deg_s", 20.0, tech)
    assert [c.new_value for c in db.parameter_history("xy_speed_mm_s")] == [120.0, 110.0]
    assert [c.name for c in db.parameter_history(start=middle)] == [
        "z_speed_deg_s",
        "xy_speed_mm_s",
    ]
    assert [c.new_value for c in db.parameter_history(end=middle)] == [110.0]
    assert len(db.parameter_history(limit=1)) == 1


def test_parameters_survive_reopening(db_path: object, users: dict[Role, User]) -> None:
    from pathlib import Path

    assert isinstance(db_path, Path)
    with Database.open(db_path) as first:
        first.set_parameter("start_x_mm", 321.5, users[Role.SERVICE])
    with Database.open(db_path) as second:
        assert second.get_parameter("start_x_mm") == 321.5
        assert second.parameter_history("start_x_mm")[0].new_value == 321.5
