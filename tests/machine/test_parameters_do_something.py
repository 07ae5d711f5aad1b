"""Every parameter the System screen lets a technician change changes what the machine does:
one row per parameter, each compared before and after a change to another allowed value.

What the machine does is read where the machine reads it: the board's plan (geometry,
motion, path and home parameters: what ``plan_board`` gives the cycle), the manual jog's
speeds (``jog_speeds``: what the Manual screen's jogs run at), the shift the counter counts
(``shift_start_s``). The groups the machine takes from its configuration (the axis limits)
are shown read-only, and a parameter the machine does not read is not shown: neither is in
the rows."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from datetime import datetime

import pytest

from app.config import load_config
from app.data.database import Database
from app.data.parameters import (
    CONFIGURATION_GROUPS,
    PARAMETERS,
    UNUSED_PARAMETERS,
    ParameterSpec,
)
from app.machine.cycle_plan import plan_board
from app.machine.process_params import jog_speeds, motion_limits, stave_limits
from app.machine.production import shift_start_s

CONFIG = load_config()
WIDTH_MM = 150.0
# 23:00 local: a time at which each production parameter moves the running shift's start.
LATE_EVENING_S = datetime.now().replace(hour=23, minute=0, second=0, microsecond=0).timestamp()

CHANGED: dict[str, float] = {  # another allowed value (the default's neighbour)
    "home_x_mm": 50.0,
    "home_y_mm": 30.0,
    "home_z_deg": 2.0,
    "tool_radius_mm": 30.0,
    "max_depth_of_cut_mm": 10.0,
    "machine_height_mm": 260.0,
    "start_x_mm": 320.0,
    "start_y_mm": 420.0,
    "xy_speed_mm_s": 80.0,
    "xy_rapid_speed_mm_s": 250.0,
    "xy_accel_mm_s2": 800.0,
    "xy_jerk_mm_s3": 10000.0,
    "z_speed_deg_s": 20.0,
    "z_accel_deg_s2": 100.0,
    "z_jerk_deg_s3": 1000.0,
    "lead_mm": 70.0,
    "tilt_clearance_mm": 120.0,
    "jog_xy_speed_mm_s": 25.0,
    "jog_xy_accel_mm_s2": 250.0,
    "jog_z_speed_deg_s": 4.0,
    "jog_z_accel_deg_s2": 40.0,
    "shift_first_start_h": 7.0,
    "shift_length_h": 6.0,
    "shifts_per_day": 2.0,
}


@pytest.fixture(scope="module")
def factory(tmp_path_factory: pytest.TempPathFactory) -> tuple[dict[str, float], object]:
    """The parameters and the first sample recipe of a new database on this machine."""
    path = tmp_path_factory.mktemp("parameters") / "stave.db"
    with Database.open(path, limits=stave_limits(CONFIG)) as db:
        return db.get_parameters(), db.list_recipes()[0]


def _plan(params: Mapping[str, float], recipe: object) -> tuple[float, ...]:
    home = (params["home_x_mm"], params["home_y_mm"], params["home_z_deg"])
    planned = plan_board(
        recipe,  # type: ignore[arg-type]
        WIDTH_MM,
        params,
        stave_limits(CONFIG),
        motion_limits(CONFIG, params),
        home,
    )
    plan = planned.plan
    times = [plan.duration_s * k / 64 for k in range(65)]
    samples = [plan.sample(t) for t in times]
    return (plan.duration_s, *(v for s in samples for v in (s.x, s.y, s.z)))


OBSERVERS: dict[str, Callable[[Mapping[str, float], object], object]] = {
    "home": _plan,
    "tool": _plan,
    "start": _plan,
    "motion": _plan,
    "path": _plan,
    "jog": lambda params, _recipe: jog_speeds(CONFIG, params),
    "production": lambda params, _recipe: shift_start_s(params, LATE_EVENING_S),
}
SHOWN = [
    spec
    for spec in PARAMETERS
    if spec.group not in CONFIGURATION_GROUPS and spec.name not in UNUSED_PARAMETERS
]


def test_every_parameter_on_the_system_screen_has_a_row() -> None:
    assert {spec.name for spec in SHOWN} == set(CHANGED)
    assert {spec.group for spec in SHOWN} == set(OBSERVERS)


@pytest.mark.parametrize("spec", SHOWN, ids=[spec.name for spec in SHOWN])
def test_the_parameter_changes_what_the_machine_does(
    spec: ParameterSpec, factory: tuple[dict[str, float], object]
) -> None:
    params, recipe = factory
    value = CHANGED[spec.name]
    assert spec.minimum <= value <= spec.maximum and value != params[spec.name]
    observe = OBSERVERS[spec.group]
    before = observe(params, recipe)
    after = observe({**params, spec.name: value}, recipe)
    assert after != before, f"{spec.name} = {value:g} changes nothing the machine does"
