"""The lamp, the hold button, the plan view (with a soak test), the theme and the formatting."""

from __future__ import annotations

import math
import re
from dataclasses import replace

import numpy as np
import pytest
from PySide6.QtCore import Qt

from app.data.parameters import DEFAULT_PARAMETERS
from app.data.recipe import BarrelType, Recipe
from app.geometry.limits import DEFAULT_LIMITS
from app.geometry.ratio import Ratio
from app.machine.commands import JOG_DEADMAN_S, JOG_REFRESH_S
from app.machine.snapshot import PlanPreview
from app.machine.states import MachineState
from app.screens.formatting import format_duration, format_number, format_position
from app.screens.recipe_preview import preview_recipe
from app.screens.theme import scale_for_size, stylesheet
from app.screens.widgets.hold_button import HoldButton
from app.screens.widgets.lamp import LampColor, StatusLamp, lamp_color
from app.screens.widgets.plan_view import PlanView, split_toolpath

EXAMPLE = Recipe(
    id=None,
    name="Example",
    length_mm=1000.0,
    thickness_mm=27.0,
    length_ratio=Ratio(1, 4),
    width_ratio=Ratio(3, 4),
    barrel_type=BarrelType.FIXED_TILT,
    tilt_deg=7.5,
    barrel_diameter_mm=None,
    barrel_perimeter_mm=None,
)


# -- lamp ------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("state", "color"),
    [
        (MachineState.AUTOMATIC, LampColor.GREEN),
        (MachineState.HOMING, LampColor.GREEN),
        (MachineState.ERROR, LampColor.RED),
        (MachineState.EMERGENCY_STOP, LampColor.RED),
        (MachineState.READY, LampColor.WHITE),
        (MachineState.NOT_HOMED, LampColor.BLUE),
        (MachineState.MANUAL, LampColor.YELLOW),
        (MachineState.STOPPING, LampColor.YELLOW),
        (MachineState.POWER_UP, LampColor.OFF),
        (None, LampColor.RED),
    ],
)
def test_lamp_colour_follows_the_state(state, color) -> None:
    assert lamp_color(state) is color


def test_every_state_has_a_lamp_colour() -> None:
    assert {lamp_color(s) for s in MachineState} <= set(LampColor)


def test_lamp_paints_its_colour(qtbot) -> None:
    lamp = StatusLamp(40)
    qtbot.addWidget(lamp)
    lamp.set_color(LampColor.RED)
    image = lamp.grab().toImage()
    centre = image.pixelColor(image.width() // 2 + 8, image.height() // 2 + 8)
    assert centre.red() > 200 and centre.green() < 100


# -- hold button ----------------------------------------------------------------------------


def test_refresh_period_beats_the_dead_man() -> None:
    assert JOG_REFRESH_S * 2 < JOG_DEADMAN_S


def test_hold_button_refreshes_while_held_and_ends_on_release(qtbot) -> None:
    button = HoldButton("X+")
    qtbot.addWidget(button)
    button.show()
    events: list[str] = []
    button.holdStarted.connect(lambda: events.append("start"))
    button.holdRefresh.connect(lambda: events.append("refresh"))
    button.holdEnded.connect(lambda: events.append("end"))
    qtbot.mousePress(button, Qt.MouseButton.LeftButton)
    assert button.held and events == ["start"]
    with qtbot.waitSignal(button.holdRefresh, timeout=2000):
        pass
    with qtbot.waitSignal(button.holdRefresh, timeout=2000):
        pass
    qtbot.mouseRelease(button, Qt.MouseButton.LeftButton)
    assert not button.held
    assert events[0] == "start" and events[-1] == "end"
    assert events.count("refresh") >= 2
    assert not button.refreshing  # no refresh after release


def test_hold_ends_when_the_button_is_disabled_or_hidden(qtbot) -> None:
    button = HoldButton("Z+")
    qtbot.addWidget(button)
    button.show()
    ended: list[bool] = []
    button.holdEnded.connect(lambda: ended.append(True))
    qtbot.mousePress(button, Qt.MouseButton.LeftButton)
    button.setEnabled(False)
    assert ended == [True] and not button.held
    button.setEnabled(True)
    qtbot.mousePress(button, Qt.MouseButton.LeftButton)
    button.hide()
    assert ended == [True, True]


# -- plan view -----------------------------------------------------------------------------------


def test_split_toolpath_per_point_and_per_segment() -> None:
    points = [(0, 0), (1, 0), (2, 0), (3, 0), (4, 0)]
    cut, rapid = split_toolpath(points, [False, False, True, True, False])
    assert cut[:, 0].tolist() == [1, 2, 3]
    assert np.isnan(rapid).any()  # two rapid pieces separated by NaN
    assert [x for x in rapid[:, 0] if not math.isnan(x)] == [0, 1, 3, 4]
    cut2, _ = split_toolpath(points, [False, True, True, False])
    assert cut2[:, 0].tolist() == [1, 2, 3]
    empty_cut, empty_rapid = split_toolpath([(0, 0)], [True])
    assert empty_cut.shape == (0, 2) and empty_rapid.shape == (0, 2)


def example_plan(plan_id: int = 1, width_mm: float = 150.0) -> PlanPreview:
    preview = preview_recipe(EXAMPLE, width_mm, DEFAULT_PARAMETERS, DEFAULT_LIMITS)
    assert preview.ok, preview.errors
    return PlanPreview(plan_id, preview.outline, preview.toolpath, preview.cutting)


def test_plan_view_draws_a_real_plan(qtbot) -> None:
    view = PlanView()
    qtbot.addWidget(view)
    view.resize(600, 300)
    view.show()
    plan = example_plan()
    view.set_plan(plan)
    assert view.plan_id == 1
    xs, _ys = view.outline_item.getData()
    assert len(xs) == len(plan.outline_xy)
    cut_x, _ = view.cut_item.getData()
    assert np.isfinite(cut_x).sum() > 10
    view.set_cutter(plan.toolpath_xy[5][0], plan.toolpath_xy[5][1])
    cx, cy = view.cutter_item.getData()
    assert (cx[0], cy[0]) == plan.toolpath_xy[5]
    view.set_plan(None)
    xs, _ys = view.outline_item.getData()
    assert view.plan_id == 0 and (xs is None or len(xs) == 0)


def test_plan_view_survives_thousands_of_updates(qtbot) -> None:
    """Soak test of the live plot (PySide6 6.12 crashed after ~1000 setData calls)."""
    view = PlanView()
    qtbot.addWidget(view)
    view.resize(640, 320)
    view.show()
    plans = [example_plan(1, 150.0), example_plan(2, 200.0)]
    path = plans[0].toolpath_xy
    for index in range(4000):
        x, y = path[index % len(path)]
        view.set_cutter(x + (index % 7) * 0.1, y)
        if index % 500 == 0:
            view.set_plan(plans[(index // 500) % 2])
        if index % 50 == 0:
            qtbot.wait(0)
            view.repaint()
    assert view.updates > 3500
    image = view.grab().toImage()
    assert not image.isNull() and image.width() > 100


# -- preview, theme, formatting -------------------------------------------------------------


def test_preview_matches_the_worked_example_of_the_spec() -> None:
    preview = preview_recipe(EXAMPLE, 150.0, DEFAULT_PARAMETERS, DEFAULT_LIMITS)
    assert preview.ok
    assert preview.d_mm == pytest.approx(12.502603, abs=1e-6)
    assert preview.r_mm == pytest.approx(5005.2066, abs=1e-4)
    assert preview.head_width_mm == pytest.approx(112.5)
    assert preview.tilt_deg == 7.5
    assert any(preview.cutting) and not all(preview.cutting)
    x0 = DEFAULT_PARAMETERS["start_x_mm"]
    assert min(x for x, _ in preview.outline) == pytest.approx(x0)


def test_preview_reports_a_bad_width_instead_of_raising() -> None:
    preview = preview_recipe(EXAMPLE, 300.0, DEFAULT_PARAMETERS, DEFAULT_LIMITS)
    assert not preview.ok
    assert "A board of 300 mm is outside the widths this machine takes: up to 280 mm" in (
        preview.errors
    )
    narrow = preview_recipe(EXAMPLE, 70.0, DEFAULT_PARAMETERS, DEFAULT_LIMITS)
    assert "The head would be 52.5 mm wide: allowed 60 mm or more" in narrow.errors
    for error in (*preview.errors, *narrow.errors):  # words, no program field names
        assert not re.search(r"\b[A-Za-z][A-Za-z0-9]*_[A-Za-z0-9_]+\b", error), error


def test_preview_refuses_a_stave_beyond_the_axis_travel_as_the_machine_does() -> None:
    """The editor must not draw a stave the machine then refuses with E050."""
    short_x = replace(DEFAULT_LIMITS, x_max_mm=EXAMPLE.length_mm)
    preview = preview_recipe(EXAMPLE, 150.0, DEFAULT_PARAMETERS, short_x)
    assert not preview.ok and preview.outline == ()
    assert any(
        e.startswith("The tool path reaches X = ") and "beyond the axis travel" in e
        for e in preview.errors
    )
    assert preview.tilt_deg == 7.5


def test_theme_has_no_unreplaced_tokens_and_scales() -> None:
    for scale in (1.0, 1.4):
        assert "$" not in stylesheet(scale)
    assert "font-size: 17px" in stylesheet(1.0)
    assert scale_for_size(1024, 768) == 1.0
    assert scale_for_size(800, 600) == 1.0
    assert 1.3 < scale_for_size(1920, 1080) <= 1.45


@pytest.mark.parametrize(
    ("value", "text"),
    [(12.5, "12.5"), (1000.0, "1000"), (-0.0001, "0"), (0.1234567, "0.123"), (math.nan, "—")],
)
def test_format_number(value: float, text: str) -> None:
    assert format_number(value) == text


def test_format_position_and_duration() -> None:
    assert format_position(-0.001) == "0.00"
    assert format_position(1234.5678) == "1234.57"
    assert format_duration(None) == "—"
    assert format_duration(75.4) == "1:15"
    assert format_duration(3725) == "1:02:05"
