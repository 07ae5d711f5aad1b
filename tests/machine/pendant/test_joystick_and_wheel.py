"""The joystick's deadband, curve and start-up calibration; the handwheel's selector,
multiplier and increments, as pure functions of the inputs."""

from __future__ import annotations

from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.drivers.contracts import InputImage
from app.machine.pendant.handwheel import Handwheel, wheel_selection
from app.machine.pendant.joystick import Joystick, shaped
from app.pendant_settings import HandwheelSettings, JoystickSettings


@pytest.mark.parametrize(
    ("deflection", "expected"),
    [(0.0, 0.0), (0.05, 0.0), (-0.05, 0.0), (1.0, 1.0), (-1.0, -1.0), (1.7, 1.0), (0.525, 0.25)],
)
def test_deadband_and_square_curve(deflection: float, expected: float) -> None:
    assert shaped(deflection, 0.05, 2.0) == pytest.approx(expected)


@settings(max_examples=200, deadline=None)
@given(
    a=st.floats(-1.0, 1.0),
    b=st.floats(-1.0, 1.0),
    deadband=st.floats(0.0, 0.5),
    exponent=st.floats(1.0, 4.0),
)
def test_the_curve_is_odd_monotonic_and_bounded(
    a: float, b: float, deadband: float, exponent: float
) -> None:
    fa, fb = shaped(a, deadband, exponent), shaped(b, deadband, exponent)
    assert -1.0 <= fa <= 1.0
    assert shaped(-a, deadband, exponent) == -fa
    if a <= b:
        assert fa <= fb
    if abs(a) <= deadband:
        assert fa == 0.0


def stick(x: int, y: int) -> InputImage:
    return InputImage(joystick_x=x, joystick_y=y)


def test_the_centre_is_calibrated_at_start_up_only_when_the_stick_rests() -> None:
    settings_ = JoystickSettings(fitted=True, full_scale_counts=10000, centre_tolerance_counts=1500)
    joystick = Joystick(settings_)
    assert joystick.read(stick(4000, 0)) == {}  # held at start-up: not the centre
    assert joystick.off_centre == ("X", 4000)
    assert joystick.read(stick(120, -80)) == {"X": 0.0, "Y": 0.0}  # let go: calibrated here
    speeds = joystick.read(stick(120 + 10000, -80))
    assert speeds["X"] == pytest.approx(1.0) and speeds["Y"] == 0.0
    assert joystick.read(InputImage()) == {}  # unread: nothing


def test_selector_and_multiplier_from_the_inputs() -> None:
    base = InputImage()
    assert wheel_selection(base).axis == ""
    assert wheel_selection(replace(base, handwheel_y=True)).axis == "Y"
    assert wheel_selection(replace(base, handwheel_x=True, handwheel_z=True)).axis == ""
    assert wheel_selection(replace(base, handwheel_x10=True)).multiplier == 10
    assert wheel_selection(replace(base, handwheel_x100=True)).multiplier == 100
    both = replace(base, handwheel_x10=True, handwheel_x100=True)
    assert wheel_selection(both).multiplier == 1  # a broken switch never gives more


def test_counts_per_increment_keeps_the_remainder() -> None:
    wheel = Handwheel(HandwheelSettings(fitted=True, counts_per_increment=4), 0.004)
    image = replace(InputImage(), handwheel_x=True, handwheel_count=100)
    assert wheel.read(image).increments == 0  # first read
    moved = [wheel.read(replace(image, handwheel_count=100 + n)).increments for n in range(1, 10)]
    assert sum(moved) == 2 and moved[3] == 1 and moved[7] == 1


def test_the_wheel_stops_at_the_boards_keep_out_as_a_held_jog_does() -> None:
    from app.config import load_config
    from app.machine.manual import ManualControl
    from app.machine.planner.keepout import TableKeepOut
    from app.machine.refusals import Reason

    params = {
        "start_x_mm": 300.0,
        "start_y_mm": 400.0,
        "tool_radius_mm": 25.0,
        "machine_height_mm": 250.0,
        "tilt_clearance_mm": 100.0,
    }
    config = load_config()
    manual = ManualControl(config.axes)
    board = TableKeepOut.for_board(1000.0, 200.0, params)
    manual.keep_out = board
    edge = board.box(0.0).y_min
    for name, where in (("X", 600.0), ("Y", edge - 5.0), ("Z", 0.0)):
        manual._joggers[name].set_position(where)  # beside the board, below its edge

    from app.drivers.registry import create_backend
    from app.machine.axes import AxisGroup

    axes = AxisGroup(config.axes, create_backend(config).motion)  # no feedback yet: no switch
    taken, reason = manual.follow("Y", edge + 20.0, axes)
    assert taken == pytest.approx(edge)
    assert reason is not None and reason.reason is Reason.JOG_STOPS_AT_BOARD
