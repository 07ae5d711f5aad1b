"""The clamps and the centering device in the keep-out model: their outlines from the
configuration (checked like every key), which count with which sensors, moves routed around
the union of the boxes or refused naming the device, jogs and the handwheel stopped at them,
and one go-to-position and a handwheel jog on the simulated machine kept off a closed clamp."""

from __future__ import annotations

import tomllib
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

from app.config import ConfigError, default_config_path, parse_config
from app.data.database import Database
from app.drivers.contracts import InputImage
from app.geometry.limits import StaveLimits
from app.machine import commands as cmd
from app.machine.alarms import AlarmCode
from app.machine.cycle_plan import PlanningError, plan_board
from app.machine.planner.chunk import Chunk
from app.machine.planner.jog_keepout import jog_reach
from app.machine.planner.keepout import KeepOutRefused, TableKeepOut
from app.machine.planner.trajectory import Phase
from app.machine.process_params import motion_limits, stave_limits
from app.machine.refusals import Reason
from app.machine.states import MachineState
from app.table_outlines import TableDevices, TableOutline
from tests.machine.conftest import homed_at_power_up, make_rig

PARAMS = {
    "start_x_mm": 100.0,
    "start_y_mm": 400.0,
    "tool_radius_mm": 40.0,
    "machine_height_mm": 250.0,
    "tilt_clearance_mm": 50.0,
}
# A clamp closed beyond the end of a 1000 mm board (X 100..1100), on its centre line.
CLAMP = TableOutline("clamp 1", 1300.0, 1400.0, 380.0, 420.0)
PUSHER = TableOutline("the centering device", 400.0, 460.0, 150.0, 330.0)
BOARD = TableKeepOut.for_board(1000.0, 140.0, PARAMS, devices=(CLAMP,))


def test_the_clamp_beyond_the_board_is_an_obstacle_of_its_own() -> None:
    assert not TableKeepOut.for_board(1000.0, 140.0, PARAMS).inside((1350.0, 400.0, 0.0))
    assert BOARD.inside((1350.0, 400.0, 0.0))
    assert BOARD.inside((1350.0 + 0.0, 420.0 + 39.0, 0.0))  # grown by the cutter's reach
    assert not BOARD.inside((1350.0, 420.0 + 41.0, 0.0))
    assert BOARD.inside((1350.0, 420.0 + 41.0, 15.0))  # and more when tilted
    assert not BOARD.inside((1200.0, 400.0, 0.0))  # the gap between board and clamp


def test_a_move_goes_around_the_union_of_board_and_clamp_or_is_refused_naming_it() -> None:
    start, end = (1250.0, 100.0, 0.0), (1250.0, 700.0, 0.0)  # through the gap: clear
    assert BOARD.route(start, end) == [start, end]
    start, end = (1350.0, 100.0, 0.0), (1350.0, 700.0, 0.0)  # through the clamp
    route = BOARD.route(start, end)
    assert len(route) > 2 and BOARD.crossing(route) is None
    with pytest.raises(KeepOutRefused, match="over clamp 1"):
        BOARD.route(start, (1350.0, 400.0, 0.0))
    # No way round within the X travel: refused, the obstacles named.
    blocked = replace(BOARD, x_travel_mm=(1300.0, 1400.0))
    with pytest.raises(KeepOutRefused, match="around the board and clamp 1"):
        blocked.route(start, end)


def test_jogs_stop_at_the_nearest_box_and_the_tilt_at_the_clamp() -> None:
    clamp_box = dict(BOARD.boxes(0.0))["clamp 1"]
    assert jog_reach(BOARD, (1350.0, 100.0, 0.0), "Y", 800.0) == clamp_box.y_min
    assert jog_reach(BOARD, (1700.0, 400.0, 0.0), "X", 0.0) == clamp_box.x_max
    assert jog_reach(BOARD, (1200.0, 400.0, 0.0), "X", 3000.0) == clamp_box.x_min
    assert jog_reach(BOARD, (1200.0, 400.0, 0.0), "Y", 800.0) == 800.0  # in the gap
    beside = (1350.0, clamp_box.y_max + 10.0, 0.0)
    assert 0.0 < jog_reach(BOARD, beside, "Z", 15.0) < 15.0


def test_which_outlines_count_follows_the_sensors() -> None:
    devices = TableDevices(clamps=(CLAMP,), centering=(PUSHER,))
    way = devices.in_the_way
    assert way(board_on_table=False, clamps_closed=False, centering_retracted=True) == ()
    assert way(board_on_table=True, clamps_closed=False, centering_retracted=True) == (CLAMP,)
    assert way(board_on_table=False, clamps_closed=True, centering_retracted=True) == (CLAMP,)
    assert way(board_on_table=False, clamps_closed=False, centering_retracted=False) == (PUSHER,)
    empty = TableKeepOut.devices_only((PUSHER,), PARAMS, limits=_limits())
    assert empty.inside((430.0, 250.0, 0.0)) and not empty.inside((600.0, 400.0, 0.0))
    with pytest.raises(KeepOutRefused, match="the centering device"):
        empty.route((430.0, 0.0, 0.0), (430.0, 250.0, 0.0))


def _limits() -> StaveLimits:
    return stave_limits(parse_config({}))


def _shipped() -> dict[str, Any]:
    return tomllib.loads(default_config_path().read_text(encoding="utf-8"))


@pytest.mark.parametrize(
    ("outline", "key"),
    [
        ({"x_min_mm": 1.0, "x_max_mm": 2.0, "y_min_mm": 1.0, "y_max_mm": 2.0, "z": 1}, ".z"),
        ({"x_min_mm": 5.0, "x_max_mm": 2.0, "y_min_mm": 1.0, "y_max_mm": 2.0}, ".x_max_mm"),
        ({"x_min_mm": 1.0, "x_max_mm": 2.0, "y_min_mm": 1.0, "y_max_mm": 1.0}, ".y_max_mm"),
        ({"x_min_mm": "a", "x_max_mm": 2.0, "y_min_mm": 1.0, "y_max_mm": 2.0}, ".x_min_mm"),
    ],
)
def test_a_bad_outline_is_refused_with_its_key(outline: dict[str, Any], key: str) -> None:
    data = _shipped()
    data["keep_out"]["clamps"][1] = outline
    with pytest.raises(ConfigError) as error:
        parse_config(data, "machine.toml")
    assert error.value.key == "keep_out.clamps[1]" + key


def test_unknown_keys_and_non_lists_in_keep_out_are_refused() -> None:
    data = _shipped()
    data["keep_out"]["clampz"] = []
    with pytest.raises(ConfigError, match=r"keep_out\.clampz"):
        parse_config(data)
    data = _shipped()
    data["keep_out"]["centering_device"] = {"x_min_mm": 1.0}
    with pytest.raises(ConfigError, match=r"keep_out\.centering_device .*a list of at most"):
        parse_config(data)


@pytest.mark.parametrize("name", ["machine.toml", "machine-modbus.toml", "machine-canopen.toml"])
def test_the_shipped_outlines_lie_inside_every_board_the_table_takes(name: str) -> None:
    """Closed on any board, the clamps cost the cycle nothing: their boxes lie in the board's."""
    config = parse_config(
        tomllib.loads((default_config_path().parent / name).read_text(encoding="utf-8"))
    )
    devices = config.table_devices
    assert len(devices.clamps) == 2 and len(devices.centering) == 2
    limits = _limits()
    params = {**PARAMS, "start_x_mm": config.process.start_x_mm}
    params["start_y_mm"] = config.process.start_y_mm
    smallest = TableKeepOut.for_board(
        limits.min_length_mm, limits.min_head_width_mm, params, devices=devices.clamps
    )
    board = smallest.box(15.0)
    for _, box in smallest.boxes(15.0)[1:]:
        assert board.x_min <= box.x_min and box.x_max <= board.x_max
        assert board.y_min <= box.y_min and box.y_max <= board.y_max
    assert InputImage().centering_retracted  # the default image: the device is in


def test_go_to_position_goes_around_a_closed_clamp_on_the_machine(tmp_path: Path) -> None:
    data = _shipped()
    data["keep_out"] = {
        "clamps": [{"x_min_mm": 550.0, "x_max_mm": 650.0, "y_min_mm": 100.0, "y_max_mm": 150.0}]
    }
    rig = make_rig(tmp_path, homed_at_power_up(parse_config(data, "machine.toml")))
    try:
        c = rig.controller
        rig.set_parameters({"xy_rapid_speed_mm_s": 300.0, "jog_xy_speed_mm_s": 100.0})
        rig.send(cmd.EnterManual(), run_s=0.1)
        assert c.state is MachineState.MANUAL and c.manual.keep_out is None
        rig.send(cmd.MoveTo(600.0, 30.0, 0.0))
        rig.until(lambda ctl: not ctl.manual_move.running, 30.0)
        rig.send(cmd.SetClamps(True), run_s=1.0)
        keep_out = c.manual.keep_out
        assert keep_out is not None and [d.name for d in keep_out.devices] == ["clamp 1"]
        commanded: list[tuple[float, ...]] = []

        def watch(runtime) -> None:  # type: ignore[no-untyped-def]
            commanded.append(tuple(runtime.controller.axes.command[n] for n in ("X", "Y", "Z")))

        rig.runtime.on_tick.append(watch)
        rig.send(cmd.MoveTo(600.0, 200.0, 0.0))  # straight up runs through the clamp
        rig.until(lambda ctl: not ctl.manual_move.running, 30.0)
        rig.runtime.on_tick.remove(watch)
        assert not [xyz for xyz in commanded if keep_out.inside(xyz)]
        assert max(abs(xyz[0] - 600.0) for xyz in commanded) > 50.0  # it went round
        assert (c.manual.position("X"), c.manual.position("Y")) == pytest.approx(
            (600.0, 200.0), abs=0.05
        )
        rig.send(cmd.MoveTo(600.0, 125.0, 0.0))  # onto the clamp
        assert c.message is not None and c.message.reason is Reason.MOVE_REFUSED
        assert "clamp 1" in str(c.message.args)

        # The handwheel as the screen's jogs: it stops at the clamp's box, and backs off.
        edge = dict(keep_out.boxes(0.0))["clamp 1"].y_max
        rig.send(cmd.SelectHandwheel("Y", 100), run_s=0.6)  # the screen's move let go
        rig.send(cmd.HoldJogEnable(True))
        rig.send(cmd.TurnHandwheel(-200, 500.0), run_s=1.0)  # 20 mm toward it, 10 mm away
        assert c.manual.position("Y") == pytest.approx(edge)
        assert c.message is not None
        assert c.message.reason in (Reason.JOG_STOPS_AT_BOARD, Reason.JOG_AT_BOARD)
        rig.send(cmd.TurnHandwheel(-50, 500.0), run_s=0.5)  # on into it: nothing
        assert c.manual.position("Y") == pytest.approx(edge)
        rig.send(cmd.TurnHandwheel(100, 500.0), run_s=0.8)  # away from it: as always
        assert c.manual.position("Y") == pytest.approx(edge + 10.0)
    finally:
        rig.runtime.shutdown()


def test_the_cycle_refuses_a_board_whose_travel_runs_through_a_clamp(tmp_path: Path) -> None:
    config = parse_config({})
    with Database.open(tmp_path / "stave.db", limits=stave_limits(config)) as db:
        params, recipe = db.get_parameters(), db.list_recipes()[0]
    home = (params["home_x_mm"], params["home_y_mm"], params["home_z_deg"])

    def plan(devices: tuple[TableOutline, ...]) -> list[Chunk]:
        planned = plan_board(
            recipe,
            150.0,
            params,
            stave_limits(config),
            motion_limits(config, params),
            home,
            devices=devices,
        )
        chunks = [c.chunk for c in planned.plan.chunks if c.chunk.phase is Phase.APPROACH]
        return [c for c in chunks if c.path is not None]  # the travel, not the tilt

    travel = plan(())[0]  # from home to the first lead-in
    (ax, ay, _), (bx, by, _) = travel.start_xyz(), travel.end_xyz()
    mx, my = (ax + bx) / 2.0, (ay + by) / 2.0
    clamp = TableOutline("clamp 1", mx - 5.0, mx + 5.0, my - 5.0, my + 5.0)
    with pytest.raises(PlanningError) as refused:
        plan((clamp,))
    assert refused.value.code is AlarmCode.APPROACH_CROSSES_BOARD
    assert "runs through clamp 1" in str(refused.value)
    aside = TableOutline("clamp 1", 3000.0, 3100.0, 385.0, 415.0)  # beyond the board: clear
    assert plan((aside,)) == plan(())
