"""Recipe to tool path composed once: every stage refuses with its own stage and reasons,
and a board that passes is exactly the profile and tool path of the steps run by hand."""

from __future__ import annotations

import pickle
from dataclasses import dataclass, replace

import pytest

from app.cli.solve import PROCESS_DEFAULTS
from app.geometry.barrel import RoundBarrelTilt
from app.geometry.bevel import FixedTilt, SideTilts
from app.geometry.limits import DEFAULT_LIMITS, StaveLimits
from app.geometry.outline import stave_drawing
from app.geometry.profile import solve_profile
from app.geometry.stave_cut import (
    CutStage,
    StaveCutRefused,
    StaveSpec,
    cut_stave,
    roughing_allowances_mm,
)
from app.geometry.toolpath import ToolPathParams, build_toolpath, keep_out_box
from app.geometry.travel import check_toolpath_travel

STAVE = StaveSpec(1000.0, 30.0, 0.25, 0.75, FixedTilt(3.5))


def refusal(stave: StaveSpec, width_mm: float, **changes: object) -> StaveCutRefused:
    limits = changes.pop("limits", DEFAULT_LIMITS)
    assert isinstance(limits, StaveLimits)
    params = {**PROCESS_DEFAULTS, **changes}
    with pytest.raises(StaveCutRefused) as caught:
        cut_stave(stave, width_mm, params, limits)  # type: ignore[arg-type]
    return caught.value


def test_a_good_board_is_the_steps_run_by_hand() -> None:
    cut = cut_stave(STAVE, 150.0, PROCESS_DEFAULTS, DEFAULT_LIMITS)
    profile = solve_profile(1000.0, 150.0, 0.25, 0.75)
    toolpath = build_toolpath(profile, ToolPathParams.from_parameters(PROCESS_DEFAULTS, 3.5))
    assert cut.tilts == SideTilts(3.5, 3.5)
    assert cut.profile == profile
    assert cut.toolpath == toolpath
    assert cut.width_mm == 150.0


def test_a_barrel_recipe_is_bevelled_for_the_measured_width() -> None:
    stave = replace(STAVE, tilt=RoundBarrelTilt(1500.0))
    narrow = cut_stave(stave, 100.0, PROCESS_DEFAULTS, DEFAULT_LIMITS)
    wide = cut_stave(stave, 200.0, PROCESS_DEFAULTS, DEFAULT_LIMITS)
    assert narrow.tilts.a_deg < wide.tilts.a_deg
    assert wide.toolpath.params.tilt_deg == wide.tilts.a_deg


def test_a_width_the_barrel_cannot_bevel_stops_at_the_tilt() -> None:
    exc = refusal(replace(STAVE, tilt=RoundBarrelTilt(690.0)), 700.0)
    assert exc.stage is CutStage.TILT
    assert exc.fields == ("width_mm",)
    assert exc.tilts is None


def test_a_board_outside_the_limits_stops_at_the_stave_with_every_reason() -> None:
    exc = refusal(replace(STAVE, length_ratio=0.6), 300.0)
    assert exc.stage is CutStage.STAVE
    assert set(exc.fields) == {"width_mm", "length_ratio"}
    assert exc.tilts == SideTilts(3.5, 3.5)


def test_a_missing_or_bad_parameter_is_named() -> None:
    exc = refusal(STAVE, 150.0, lead_mm="long")
    assert exc.stage is CutStage.TOOLPATH
    assert exc.fields == ("lead_mm",)
    assert "lead_mm = 'long' is not a number" in str(exc)


def test_a_home_over_the_board_stops_at_the_tool_path() -> None:
    exc = refusal(STAVE, 150.0, home_x_mm=600.0, home_y_mm=400.0)
    assert exc.stage is CutStage.TOOLPATH
    assert exc.fields == ("home_position_mm",)


def test_a_path_beyond_the_travel_stops_at_the_travel_check() -> None:
    """What the recipe screen used to miss: a valid stave this machine cannot reach."""
    path = cut_stave(STAVE, 150.0, PROCESS_DEFAULTS, DEFAULT_LIMITS).toolpath
    limits = replace(DEFAULT_LIMITS, x_max_mm=1000.0)
    exc = refusal(STAVE, 150.0, limits=limits)
    assert exc.stage is CutStage.TRAVEL
    assert exc.errors == tuple(check_toolpath_travel(path, limits))


def test_two_different_bevels_cut_each_side_at_its_own() -> None:
    @dataclass(frozen=True)
    class Uneven:
        def tilts_for_width(self, width_mm: float, limits: StaveLimits) -> SideTilts:
            return SideTilts(4.0, 3.0)

    cut = cut_stave(replace(STAVE, tilt=Uneven()), 150.0, PROCESS_DEFAULTS, DEFAULT_LIMITS)
    assert cut.tilts == SideTilts(4.0, 3.0)
    params = ToolPathParams.from_parameters(PROCESS_DEFAULTS, 4.0, 3.0)
    assert cut.toolpath == build_toolpath(cut.profile, params)
    assert {s.z_end_deg for s in cut.toolpath.side_segments("A")} == {4.0}
    assert {s.z_end_deg for s in cut.toolpath.side_segments("B")} == {-3.0}


def test_each_distinct_bevel_is_validated() -> None:
    @dataclass(frozen=True)
    class Steep:
        def tilts_for_width(self, width_mm: float, limits: StaveLimits) -> SideTilts:
            return SideTilts(3.5, 60.0)

    exc = refusal(replace(STAVE, tilt=Steep()), 150.0)
    assert exc.stage is CutStage.STAVE
    assert exc.fields == ("tilt_b_deg",)  # the steep side named, not the other
    assert "tilt of side B = 60" in str(exc)


def test_a_refusal_crosses_a_process_boundary_intact() -> None:
    exc = refusal(STAVE, 150.0, limits=replace(DEFAULT_LIMITS, y_max_mm=100.0))
    copy = pickle.loads(pickle.dumps(exc))
    assert (copy.stage, copy.errors, copy.tilts) == (exc.stage, exc.errors, exc.tilts)


def test_the_drawing_follows_the_tool_path() -> None:
    cut = cut_stave(STAVE, 150.0, PROCESS_DEFAULTS, DEFAULT_LIMITS)
    drawing = stave_drawing(cut.toolpath)
    assert drawing.outline_xy[0] == drawing.outline_xy[-1]  # closed
    assert len(drawing.toolpath_xy) == len(drawing.cutting_mask)
    assert any(drawing.cutting_mask) and not all(drawing.cutting_mask)
    assert drawing.toolpath_xy[0] == (PROCESS_DEFAULTS["home_x_mm"], PROCESS_DEFAULTS["home_y_mm"])


def test_a_target_width_is_cut_centred_on_a_wider_board() -> None:
    target = replace(STAVE, target_width_mm=120.0)
    cut = cut_stave(target, 150.0, PROCESS_DEFAULTS, DEFAULT_LIMITS)
    assert (cut.width_mm, cut.board_width_mm) == (120.0, 150.0)
    assert cut.profile == solve_profile(1000.0, 120.0, 0.25, 0.75)  # centred: y = 0 in the middle
    assert cut.depth_per_side_mm == (150.0 - 90.0) / 2.0
    # Travel keeps clear of the whole 150 mm board, not only of the 120 mm stave.
    params = cut.toolpath.params
    assert params.board_width_mm == 150.0
    box = keep_out_box(cut.profile, params)
    assert box == keep_out_box(
        solve_profile(1000.0, 150.0, 0.25, 0.75), replace(params, board_width_mm=None)
    )
    ordinary = cut_stave(STAVE, 150.0, PROCESS_DEFAULTS, DEFAULT_LIMITS)
    assert ordinary.toolpath.params.board_width_mm is None
    assert ordinary.depth_per_side_mm == (150.0 - 112.5) / 2.0


@pytest.mark.parametrize(("board", "text"), [(110.0, "too narrow"), (290.0, "<= 280 mm")])
def test_a_board_outside_the_target_range_is_refused(board: float, text: str) -> None:
    exc = refusal(replace(STAVE, target_width_mm=120.0), board)
    assert exc.stage is CutStage.STAVE and exc.fields == ("width_mm",)
    assert "120 <= width <= 280 mm" in str(exc) and text in str(exc)


def test_more_than_the_depth_of_cut_is_cut_in_equal_passes_roughing_first() -> None:
    target = replace(STAVE, target_width_mm=120.0)
    params = {**PROCESS_DEFAULTS, "max_depth_of_cut_mm": 12.0}
    cut = cut_stave(target, 150.0, params, DEFAULT_LIMITS)
    assert cut.depth_per_side_mm == 30.0  # (150 - 0.75 * 120) / 2 at the heads
    assert cut.passes == 3  # ceil(30 / 12)
    assert cut.toolpath.params.roughing_allowances_mm == (20.0, 10.0)
    one_pass = cut_stave(target, 150.0, {**params, "max_depth_of_cut_mm": 30.0}, DEFAULT_LIMITS)
    assert one_pass.passes == 1 and one_pass.toolpath.params.roughing_allowances_mm == ()


def test_roughing_allowances() -> None:
    assert roughing_allowances_mm(30.0, None) == ()
    assert roughing_allowances_mm(30.0, 30.0) == ()
    assert roughing_allowances_mm(30.0, 29.999) == (15.0,)
    assert roughing_allowances_mm(40.0, 10.0) == (30.0, 20.0, 10.0)
