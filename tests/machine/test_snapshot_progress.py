"""What the snapshot says while the machine works, computed by the machine layer: the wait for
the board apart from the cycle's work, the measured width as soon as it is measured, progress
only along the path, the distance to go and the path speed, the feed override applied, and
which axis homes."""

from __future__ import annotations

import pytest

from app.machine import commands as cmd
from app.machine.snapshot import MachineSnapshot
from app.machine.states import CycleStep, MachineState
from tests.machine.conftest import Rig


def snap(rig: Rig) -> MachineSnapshot:
    return rig.controller.snapshot()


def test_the_wait_for_a_board_is_apart_and_has_no_progress(rig: Rig) -> None:
    rig.home()
    rig.select()
    rig.world.remove_board()
    rig.send(cmd.Start())
    rig.run(3.0)
    waiting = snap(rig).cycle
    assert waiting.step is CycleStep.WAIT_FOR_PART
    assert waiting.waited_s == pytest.approx(waiting.elapsed_s, abs=0.01) and waiting.waited_s > 2.9
    assert waiting.working_s == 0.0
    assert waiting.progress is None and waiting.move_to_go_mm is None
    rig.world.load_board(150.0)
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.CUTTING_A, 60.0)
    cutting = snap(rig).cycle
    assert cutting.waited_s == pytest.approx(3.0, abs=0.1)
    assert cutting.working_s == pytest.approx(cutting.elapsed_s - cutting.waited_s, abs=0.01)
    rig.until(lambda c: c.state is MachineState.READY, 200.0)
    done = snap(rig)
    assert done.last_wait_s == pytest.approx(3.0, abs=0.1)
    assert done.last_cycle_time_s is not None and done.last_cycle_time_s > done.last_wait_s + 5


def test_the_width_is_shown_once_measured_not_once_the_piece_is_done(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.STARTING_SPINDLE, 60.0)
    measured = snap(rig)
    assert measured.last_width_mm is None and measured.pieces_total == 0
    assert measured.cycle.width_mm == pytest.approx(150.0, abs=1.0)


def test_progress_distance_to_go_and_speed_follow_the_path(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.MEASURING, 60.0)
    assert snap(rig).cycle.progress is None, "a measurement has no known length"
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.CUTTING_A, 60.0)
    rig.run(3.0)
    first = snap(rig).cycle
    rig.run(1.0)
    second = snap(rig).cycle
    for view in (first, second):
        assert view.progress is not None and 0.0 < view.progress < 1.0
        assert view.move_to_go_mm is not None and view.phase_to_go_mm is not None
        assert 0.0 < view.move_to_go_mm <= view.phase_to_go_mm
        assert view.path_velocity_mm_s is not None and view.path_velocity_mm_s > 1.0
    assert first.progress is not None and second.progress is not None
    assert second.progress > first.progress
    assert first.phase_to_go_mm is not None and second.phase_to_go_mm is not None
    # One second at the path speed off the distance to go.
    assert first.phase_to_go_mm - second.phase_to_go_mm == pytest.approx(
        second.path_velocity_mm_s, rel=0.05
    )
    rig.send(cmd.Stop())
    stopping = snap(rig)
    assert stopping.state is MachineState.STOPPING
    assert stopping.cycle.progress is None, "a stop has no bar: its end is not the plan's"


def test_the_feed_override_slows_the_cut_and_is_refused_beyond_its_range(ready_rig: Rig) -> None:
    rig = ready_rig
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.CUTTING_A, 60.0)
    rig.run(3.0)
    full = snap(rig).cycle.path_velocity_mm_s
    rig.send(cmd.SetFeedOverride(50.0), run_s=2.0)
    half = snap(rig)
    assert half.feed_override_pct == 50.0
    assert full is not None and half.cycle.path_velocity_mm_s == pytest.approx(full / 2, rel=0.02)
    rig.send(cmd.SetFeedOverride(130.0))
    assert snap(rig).feed_override_pct == 50.0
    assert "130" in str(rig.controller.message)


def test_homing_names_the_axis_homing_and_those_done(rig: Rig) -> None:
    assert snap(rig).homing is None
    rig.send(cmd.Home())
    seen: list[tuple[str, tuple[str, ...]]] = []

    def record(c) -> bool:  # type: ignore[no-untyped-def]
        homing = c.snapshot().homing
        if homing is not None and (not seen or seen[-1] != (homing.current, homing.done)):
            assert homing.axes == ("Z", "Y", "X")
            seen.append((homing.current, homing.done))
        return c.state is MachineState.READY

    rig.until(record, 300.0)
    assert seen == [("Z", ()), ("Y", ("Z",)), ("X", ("Z", "Y"))]
    assert snap(rig).homing is None
