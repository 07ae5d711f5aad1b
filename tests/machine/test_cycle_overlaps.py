"""The overlapped cycle through the operator's commands on the simulated machine: what runs
at the same time, that it never touches the board off the tool path, that a spindle which
does not come up leaves the cutter before the board, and how close it comes to its floor."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from app.config import ConfigError, MachineConfig, load_config, parse_config
from app.drivers.sim.settings import parse_gauge_settings
from app.machine import commands as cmd
from app.machine.cycle_floor import cycle_floor, jerk_limited_cut_s
from app.machine.planner.keepout import TableKeepOut
from app.machine.planner.trajectory import Phase
from app.machine.process_params import motion_limits
from app.machine.runtime import MachineRuntime
from app.machine.states import LATCHED_STATES, CycleStep, MachineState
from tests.machine.conftest import Rig, make_rig
from tests.machine.keepout_watch import KeepOutWatch

WIDTH_MM = 150.0


def _config(**cycle: object) -> MachineConfig:
    config = load_config()
    axes = {n: replace(a, absolute_encoder=True) for n, a in config.axes.items()}
    return replace(config, axes=axes, cycle=replace(config.cycle, **cycle))


def _watched(rig: Rig) -> KeepOutWatch:
    rig.select()
    c = rig.controller
    assert c.recipe is not None and rig.state is MachineState.READY
    watch = KeepOutWatch(dict(c.store.parameters()), c.recipe.length_mm, WIDTH_MM)
    rig.runtime.on_tick.append(watch)
    return watch


def _board(rig: Rig) -> None:
    done = rig.controller.pieces_total
    rig.load(WIDTH_MM)
    rig.send(cmd.Start())
    rig.until(lambda c: c.pieces_total > done and c.state is MachineState.READY, 200.0)


class _Overlaps:
    """What ran at the same time, seen period by period."""

    def __init__(self) -> None:
        self.retracting_while_clamping = False
        self.unclamped_during_side_b = False
        self.returned = False

    def __call__(self, runtime: MachineRuntime) -> None:
        cycle = runtime.controller.cycle
        if cycle is None:
            return
        outputs = runtime.controller.outputs
        if cycle.step is CycleStep.CLAMPING and not outputs.centering_extend:
            self.retracting_while_clamping = True
        if cycle.step is CycleStep.CUTTING_B and not outputs.clamps_close:
            self.unclamped_during_side_b = True
        if cycle.step is CycleStep.RETURNING:
            self.returned = True


def test_two_boards_overlapped_stay_off_the_board_and_within_5_percent_of_the_floor(
    tmp_path: Path,
) -> None:
    rig = make_rig(tmp_path, _config(centering_retract_while_clamping=True))
    try:
        watch = _watched(rig)
        seen = _Overlaps()
        rig.runtime.on_tick.append(seen)
        _board(rig)
        end_of_first = rig.positions()
        _board(rig)
        assert watch.violations == [] and watch.touching_periods > 0
        assert seen.retracting_while_clamping and seen.unclamped_during_side_b
        assert not seen.returned  # the second approach starts where side B ended
        c = rig.controller
        piece, cycle = c.finished_cycles[-1]
        assert cycle.planned is not None
        plan = cycle.planned.plan
        first_move = next(ch.chunk for ch in plan.chunks if ch.chunk.phase is Phase.APPROACH)
        assert first_move.start_xyz() == pytest.approx(end_of_first, abs=0.05)
        steps = piece.step_times_s
        assert "return" not in steps and steps["spindle"] < 0.05  # centering already back
        limits = motion_limits(c.config, c.params)
        measure_s = parse_gauge_settings({}).measurement_time_s
        floor = cycle_floor(plan, limits, c.config.io, c.config.cycle, measure_s)
        assert floor.total_s <= piece.cycle_time_s <= 1.05 * floor.total_s
        # The cuts are at the jerk-limited optimum (the planner's own figure).
        assert steps["side_a"] == pytest.approx(floor.parts_s["side_a"], rel=1e-3)
    finally:
        rig.runtime.shutdown()


def test_a_spindle_that_never_comes_up_stops_the_approach_before_the_board(
    tmp_path: Path,
) -> None:
    rig = make_rig(tmp_path, _config())
    try:
        watch = _watched(rig)
        start = rig.positions()
        rig.load(WIDTH_MM)
        rig.faults.inject("spindle", "")
        rig.send(cmd.Start())
        rig.until(lambda c: c.state in LATCHED_STATES, 60.0)
        c = rig.controller
        assert {a.code for a in c.snapshot().alarms} >= {"E042"}
        rig.run(1.0)
        here = rig.positions()
        assert here != pytest.approx(start, abs=1.0)  # it did approach, with the spindle off
        assert watch.touching_periods == 0 and watch.violations == []
        assert c.recipe is not None
        keep_out = TableKeepOut.for_board(c.recipe.length_mm, WIDTH_MM, c.store.parameters())
        assert not keep_out.inside(here), f"stopped at {here} inside the keep-out"
    finally:
        rig.runtime.shutdown()


@pytest.mark.parametrize(
    ("table", "key"),
    [
        ({"settle_error_mm": 0}, "cycle.settle_error_mm"),
        ({"settle_max_s": -1}, "cycle.settle_max_s"),
        ({"centering_retract_while_clamping": "yes"}, "cycle.centering_retract_while_clamping"),
        ({"return_home": True}, "cycle.return_home"),
    ],
)
def test_a_bad_cycle_key_names_itself(table: dict[str, object], key: str) -> None:
    with pytest.raises(ConfigError) as caught:
        parse_config({"cycle": table}, "machine.toml")
    assert caught.value.key == key


def test_the_floor_adds_the_centering_retract_only_when_it_may_not_overlap() -> None:
    from tests.machine.planner.support import LIMITS, plan

    stave = plan()
    config = parse_config({})
    after = cycle_floor(stave, LIMITS, config.io, config.cycle, 0.3, 0.4)
    during = cycle_floor(
        stave,
        LIMITS,
        config.io,
        replace(config.cycle, centering_retract_while_clamping=True),
        0.3,
        0.4,
    )
    io = config.io
    # Retract after the clamps: 0.8 s + approach 0.4 vs measure 0.3 + run-up 2.0: run-up wins.
    assert after.parts_s["to_lead_in"] == pytest.approx(0.3 + io.spindle_runup_s)
    slow_spindle = replace(io, spindle_runup_s=0.1)
    slower = cycle_floor(stave, LIMITS, slow_spindle, config.cycle, 0.3, 0.4)
    assert slower.parts_s["to_lead_in"] == pytest.approx(io.centering_time_s + 0.4)
    assert during.total_s == pytest.approx(after.total_s)
    assert 0.0 <= after.parts_s["unclamping"] < io.clamp_time_s
    for side in ("A", "B"):
        bound = jerk_limited_cut_s(stave.cut_path(side), LIMITS)
        assert bound <= stave.cut_time_s(side) <= bound * 1.0001
    assert after.total_s == pytest.approx(sum(after.parts_s.values()))
