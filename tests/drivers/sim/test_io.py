"""The machine's I/O: cylinders with their sensors and times, the spindle, buttons, safety
chain, lamps, the board on the table and the simulated operator."""

from __future__ import annotations

import pytest

from app.drivers.contracts import DIGITAL_INPUTS, InputImage, OutputImage
from tests.drivers.sim.rig import Rig, make_config


def inputs(rig: Rig) -> InputImage:
    return rig.io.read_inputs()


def time_until(rig: Rig, field: str, timeout_s: float = 10.0) -> float:
    return rig.run_until(lambda: getattr(inputs(rig), field), timeout_s)


def test_power_up_inputs() -> None:
    rig = Rig(make_config())
    # retracted, open, chain closed, no board (the handwheel and the joystick read values)
    image, rest = inputs(rig), InputImage()
    assert [getattr(image, n) for n in DIGITAL_INPUTS] == [getattr(rest, n) for n in DIGITAL_INPUTS]


@pytest.mark.parametrize(
    ("output", "extended", "retracted", "time_key", "time_s"),
    [
        ("centering_extend", "centering_extended", "centering_retracted", "centering_time_s", 0.8),
        ("clamps_close", "clamps_closed", "clamps_open", "clamp_time_s", 0.6),
        ("centering_extend", "centering_extended", "centering_retracted", "centering_time_s", 1.5),
        ("clamps_close", "clamps_closed", "clamps_open", "clamp_time_s", 0.25),
    ],
)
def test_cylinders_take_their_configured_time_and_sensors_mark_the_ends(
    output: str, extended: str, retracted: str, time_key: str, time_s: float
) -> None:
    rig = Rig(make_config(io={time_key: time_s}))
    rig.io.write_outputs(OutputImage(**{output: True}))
    rig.tick()
    mid = inputs(rig)
    assert not getattr(mid, extended) and not getattr(mid, retracted)  # on its way
    assert time_until(rig, extended) == pytest.approx(time_s - rig.period_s, abs=0.0041)
    assert not getattr(inputs(rig), retracted)
    rig.io.write_outputs(OutputImage())
    assert time_until(rig, retracted) == pytest.approx(time_s, abs=0.0041)
    assert not getattr(inputs(rig), extended)


def test_spindle_runs_up_then_reports_running_and_stops_with_the_output() -> None:
    rig = Rig(make_config(io={"spindle_runup_s": 2.0}))
    rig.io.write_outputs(OutputImage(spindle_on=True))
    assert time_until(rig, "spindle_running") == pytest.approx(2.0, abs=0.0041)
    assert rig.world.io.spindle.contactor
    rig.io.write_outputs(OutputImage())
    rig.tick()
    assert not inputs(rig).spindle_running and not rig.world.io.spindle.contactor


def test_estop_drops_the_spindle_and_it_needs_a_fresh_start_after_release() -> None:
    rig = Rig(make_config(io={"spindle_runup_s": 0.5}))
    on = OutputImage(spindle_on=True)
    rig.io.write_outputs(on)
    time_until(rig, "spindle_running")
    rig.world.set_estop(True)
    rig.tick()
    assert not inputs(rig).estop_ok and not inputs(rig).spindle_running
    rig.world.set_estop(False)
    rig.run(1.0)  # the output is still on: the seal-in contactor stays out
    assert inputs(rig).estop_ok and not inputs(rig).spindle_running
    rig.io.write_outputs(OutputImage())
    rig.tick()
    rig.io.write_outputs(on)
    assert time_until(rig, "spindle_running") == pytest.approx(0.5, abs=0.0081)


def test_spindle_cannot_start_while_the_chain_is_open() -> None:
    rig = Rig(make_config(io={"spindle_runup_s": 0.5}))
    rig.world.set_estop(True)
    rig.io.write_outputs(OutputImage(spindle_on=True))
    rig.run(2.0)
    assert not inputs(rig).spindle_running


@pytest.mark.parametrize("button", ["start", "stop", "reset"])
def test_push_buttons_are_momentary(button: str) -> None:
    rig = Rig(make_config())
    getattr(rig.world, f"press_{button}")()
    field = f"{button}_button"
    rig.tick()
    assert getattr(inputs(rig), field)
    others = {"start_button", "stop_button", "reset_button"} - {field}
    assert not any(getattr(inputs(rig), other) for other in others)
    rig.run(0.092)
    assert getattr(inputs(rig), field)  # 96 ms after the press
    rig.tick()
    assert not getattr(inputs(rig), field)  # released after 100 ms


def test_guard_and_estop_inputs() -> None:
    rig = Rig(make_config())
    rig.world.set_guard(False)
    assert not inputs(rig).guard_closed
    rig.world.set_guard(True)
    rig.world.set_estop(True)
    image = inputs(rig)
    assert image.guard_closed and not image.estop_ok
    rig.run(1.0)
    assert not inputs(rig).estop_ok  # the E-stop latches until released


def test_lamps_are_outputs_that_can_be_read_back() -> None:
    rig = Rig(make_config())
    lamps = OutputImage(lamp_green=True, lamp_red=True)
    rig.io.write_outputs(lamps)
    assert rig.world.outputs == lamps


def test_boards_given_queued_or_drawn() -> None:
    rig = Rig(
        make_config(
            {
                "board_width_mean_mm": 150.0,
                "board_width_sd_mm": 40.0,
                "board_width_min_mm": 120.0,
                "board_width_max_mm": 180.0,
            }
        )
    )
    world = rig.world
    assert world.board is None and not inputs(rig).part_present
    assert world.load_board(210.5).true_width_mm == 210.5
    assert inputs(rig).part_present
    world.remove_board()
    assert not inputs(rig).part_present
    world.queue_board_widths([141.0, 142.0])
    assert [world.load_board().true_width_mm for _ in range(2)] == [141.0, 142.0]
    drawn = [world.load_board().true_width_mm for _ in range(200)]
    assert all(120.0 <= w <= 180.0 for w in drawn)
    assert 140.0 < sum(drawn) / len(drawn) < 160.0
    assert world.board is not None and world.board.number == 203
    with pytest.raises(ValueError, match=r"width_mm = -3\.0 is not allowed"):
        world.load_board(-3.0)


def test_board_present_at_power_up_is_an_option() -> None:
    assert Rig(make_config({"board_present": True})).io.read_inputs().part_present


def test_simulated_operator_replaces_the_finished_board() -> None:
    rig = Rig(make_config({"auto_load": True, "operator_delay_s": 1.0}))
    world = rig.world
    assert world.board is not None and world.board.number == 1
    rig.run(5.0)
    assert world.board.number == 1  # not clamped yet: the operator waits
    rig.io.write_outputs(OutputImage(clamps_close=True))
    time_until(rig, "clamps_closed")
    rig.io.write_outputs(OutputImage())
    time_until(rig, "clamps_open")
    assert inputs(rig).part_present
    gone = rig.run_until(lambda: not inputs(rig).part_present, 2.0)
    assert gone == pytest.approx(1.0, abs=0.01)
    back = rig.run_until(lambda: inputs(rig).part_present, 2.0)
    assert back == pytest.approx(1.0, abs=0.01)
    assert world.board is not None and world.board.number == 2


def test_simulated_operator_refills_after_a_board_is_taken_away() -> None:
    rig = Rig(make_config({"auto_load": True, "operator_delay_s": 0.5}))
    rig.world.remove_board()
    assert rig.run_until(lambda: inputs(rig).part_present, 2.0) == pytest.approx(0.5, abs=0.01)
