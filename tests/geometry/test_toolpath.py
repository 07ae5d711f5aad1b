import json
import math
from dataclasses import replace

import pytest
from hypothesis import assume, example, given
from hypothesis import strategies as st

from app.geometry.errors import GeometryError
from app.geometry.profile import StaveProfile, solve_profile
from app.geometry.segments import ArcSegment, LineSegment
from app.geometry.toolpath import (
    ToolPath,
    ToolPathParams,
    build_toolpath,
    keep_out_box,
)
from tests.geometry.strategies import (
    DEFAULT_PARAMS,
    PROPERTY,
    close,
    mirror_y,
    stave_inputs,
    toolpath_params,
)

EXAMPLE = solve_profile(1000.0, 150.0, 0.25, 0.75)


def side_pieces(profile: StaveProfile, side: str) -> list:
    """The profile edge of one side as exact segments (independent of the tool path code)."""
    names = ("P1", "P2", "P3", "P4") if side == "A" else ("P5", "P6", "P7", "P8")
    p1, p2, p3, p4 = (profile.points[n] for n in names)
    centre = profile.arc_center_a if side == "A" else profile.arc_center_b
    arc = ArcSegment(p2, p3, centre, True, 0.0, 0.0, False, side)
    if p1 == p2:  # lambda = 0: one arc
        return [arc]
    return [
        LineSegment(p1, p2, 0.0, 0.0, False, side),
        arc,
        LineSegment(p3, p4, 0.0, 0.0, False, side),
    ]


def unshift(point, params: ToolPathParams, side: str):
    """Machine pivot position -> profile frame point where the cutter's axis meets the table."""
    sign = 1.0 if side == "A" else -1.0
    return (
        point[0] - params.start_x_mm,
        point[1] - params.start_y_mm + sign * params.pivot_shift_mm,
    )


def samples(segment, count: int = 25):
    length = segment.length_mm
    return [segment.point_at(length * i / count) for i in range(count + 1)]


def test_worked_example_motion_sequence():
    path = build_toolpath(EXAMPLE, DEFAULT_PARAMS)
    summary = [
        (type(s).__name__[0], s.side, s.cutting, s.z_start_deg, s.z_end_deg) for s in path.segments
    ]
    assert summary == [
        ("L", "", False, 0.0, 3.5),  # home -> side A lead-in start, tilting to +alpha
        ("L", "A", True, 3.5, 3.5),  # lead-in
        ("L", "A", True, 3.5, 3.5),  # P1 -> P2
        ("A", "A", True, 3.5, 3.5),  # P2 -> P3
        ("L", "A", True, 3.5, 3.5),  # P3 -> P4
        ("L", "A", True, 3.5, 3.5),  # lead-out
        ("L", "", False, 3.5, 3.5),  # out to the tilt position
        ("L", "", False, 3.5, -3.5),  # tilt change while crossing to side B
        ("L", "", False, -3.5, -3.5),  # in to the side B lead-in start
        ("L", "B", True, -3.5, -3.5),  # lead-in
        ("L", "B", True, -3.5, -3.5),  # P5 -> P6
        ("A", "B", True, -3.5, -3.5),  # P6 -> P7
        ("L", "B", True, -3.5, -3.5),  # P7 -> P8
        ("L", "B", True, -3.5, -3.5),  # lead-out
        ("L", "", False, -3.5, 0.0),  # home, tilting back
    ]
    assert path.segments[0].start == (0.0, 0.0) == path.segments[-1].end
    # The tilt change happens at L + r + clearance beyond the left end (P0x = 100).
    assert path.segments[7].start[0] == path.segments[7].end[0] == 100 + 1000 + 40 + 50


def test_worked_example_compensation_against_the_spec_formula():
    path = build_toolpath(EXAMPLE, DEFAULT_PARAMS)
    rc = 40 / math.cos(math.radians(3.5))
    shift = 250 * math.tan(math.radians(3.5))
    # At the belly the normal is along y: y_pivot = y_edge + r/cos(alpha) - Hm*tan(alpha)
    # on side A, i.e. docs/MACHINE.md section 3's y_cut = y_pivot + Hm*tan(alpha) - r/cos(alpha).
    arc_a, arc_b = path.segments[3], path.segments[11]
    top_a = arc_a.point_at(arc_a.length_mm / 2)
    assert top_a[0] == pytest.approx(600.0, abs=1e-9)
    assert top_a[1] + shift - rc == pytest.approx(400 + 75.0, abs=1e-9)
    bottom_b = arc_b.point_at(arc_b.length_mm / 2)
    assert bottom_b[1] - shift + rc == pytest.approx(400 - 75.0, abs=1e-9)
    assert arc_a.radius_mm == pytest.approx(EXAMPLE.R + rc, rel=1e-12)
    assert arc_a.center == (600.0, 400 + EXAMPLE.arc_center_a[1] - shift)
    assert arc_a.clockwise and arc_b.clockwise


def test_effective_radius_and_pivot_shift():
    assert DEFAULT_PARAMS.effective_radius_mm == 40 / math.cos(math.radians(3.5))
    assert DEFAULT_PARAMS.pivot_shift_mm == 250 * math.tan(math.radians(3.5))


@PROPERTY
@given(stave_inputs(), toolpath_params())
def test_compensated_path_is_at_r_over_cos_alpha_from_the_profile(stave, params):
    profile = stave.solve()
    path = build_toolpath(profile, params)
    rc = params.tool_radius_mm / math.cos(math.radians(params.tilt_deg))
    for side in ("A", "B"):
        cut = [s for s in path.segments if s.cutting and s.side == side]
        assert cut, side
        pieces = side_pieces(profile, side)
        lead_in, core, lead_out = cut[0], cut[1:-1], cut[-1]
        for segment in core:
            for point in samples(segment):
                q = unshift(point, params, side)
                distance = min(piece.distance_to(q) for piece in pieces)
                assert abs(distance - rc) <= 1e-6
        # The leads run along the straight sections' extensions, rc away from them, and
        # start and end with the cutter (rc in plan view) clear of the board's ends.
        for lead, edge_point in ((lead_in, pieces[0].start), (lead_out, pieces[-1].end)):
            for point in samples(lead, 5):
                q = unshift(point, params, side)
                if lead is lead_in:
                    direction = pieces[0].tangent_at(0.0)
                else:
                    direction = pieces[-1].tangent_at(pieces[-1].length_mm)
                normal_distance = abs(
                    (q[0] - edge_point[0]) * direction[1] - (q[1] - edge_point[1]) * direction[0]
                )
                assert abs(normal_distance - rc) <= 1e-6
            assert lead.length_mm == pytest.approx(params.lead_mm, abs=1e-9)
        first = unshift(lead_in.start, params, side)[0]
        last = unshift(lead_out.end, params, side)[0]
        if side == "A":
            assert first + rc < 0.0 and last - rc > profile.length_mm
        else:
            assert first - rc > profile.length_mm and last + rc < 0.0


@PROPERTY
@given(stave_inputs(), toolpath_params())
def test_path_is_continuous_and_tangent_continuous_while_cutting(stave, params):
    path = build_toolpath(stave.solve(), params)
    for before, after in zip(path.segments, path.segments[1:], strict=False):
        assert before.end == after.start
        assert before.z_end_deg == after.z_start_deg
        if before.cutting and after.cutting and before.side == after.side:
            t0 = before.tangent_at(before.length_mm)
            t1 = after.tangent_at(0.0)
            assert abs(t0[0] * t1[1] - t0[1] * t1[0]) < 1e-9
            assert t0[0] * t1[0] + t0[1] * t1[1] > 0.0
    for segment in path.segments:
        if segment.cutting:
            expected = params.tilt_deg if segment.side == "A" else -params.tilt_deg
            assert segment.z_start_deg == segment.z_end_deg == expected


@PROPERTY
@given(stave_inputs(), toolpath_params())
def test_the_two_sides_are_mirror_images(stave, params):
    path = build_toolpath(stave.solve(), params)
    side_a = [s for s in path.segments if s.cutting and s.side == "A"]
    side_b = [s for s in path.segments if s.cutting and s.side == "B"]
    assert len(side_a) == len(side_b)
    axis = params.start_y_mm
    tolerance = 1e-9 * max(1.0, *(abs(c) for s in side_a for c in s.start + s.end))
    for a, b in zip(side_a, reversed(side_b), strict=True):
        assert type(a) is type(b)
        assert close(b.start, mirror_y(a.end, axis), tolerance)
        assert close(b.end, mirror_y(a.start, axis), tolerance)
        assert b.z_end_deg == -a.z_end_deg
        assert b.length_mm == pytest.approx(a.length_mm, rel=1e-9, abs=1e-9)
        if isinstance(a, ArcSegment):
            assert isinstance(b, ArcSegment)
            assert close(b.center, mirror_y(a.center, axis), 1e-9 * max(1.0, abs(a.center[1])))
            assert a.clockwise == b.clockwise  # reversed and mirrored: still clockwise
    assert path.cutting_length_mm("A") == pytest.approx(path.cutting_length_mm("B"), rel=1e-12)
    assert path.cutting_length_mm() == pytest.approx(2 * path.cutting_length_mm("A"))


def assert_clear_of_board(path: ToolPath, profile: StaveProfile, params: ToolPathParams) -> None:
    """Physical check, independent of keep_out_box: at every sampled travel position the
    cutter (reach r along X at any tilt; r/cos(z) + Hm*tan|z| across) misses the raw board."""
    for segment in path.segments:
        if segment.cutting:
            continue
        for index in range(41):
            s = segment.length_mm * index / 40
            x, y = segment.point_at(s)
            x -= params.start_x_mm
            y -= params.start_y_mm
            z = math.radians(segment.z_at(s))
            along = max(0.0 - x, x - profile.length_mm)  # > 0 beyond an end
            across = abs(y) - profile.width_mm / 2
            reach = params.tool_radius_mm / math.cos(z) + params.machine_height_mm * abs(
                math.tan(z)
            )
            assert along >= params.tool_radius_mm - 1e-9 or across >= reach - 1e-9


@PROPERTY
@given(stave_inputs(), toolpath_params())
def test_travel_moves_never_touch_the_board(stave, params):
    profile = stave.solve()
    assert_clear_of_board(build_toolpath(profile, params), profile, params)


@PROPERTY
@given(
    stave_inputs(),
    st.floats(-3000.0, 6000.0),
    st.floats(-1500.0, 1500.0),
    st.floats(-10.0, 10.0),
)
@example(stave=None, home_x=2000.0, home_y=0.0, home_z=0.0)  # level with the board, right
@example(stave=None, home_x=500.0, home_y=-1000.0, home_z=5.0)  # below the board
@example(stave=None, home_x=500.0, home_y=1000.0, home_z=0.0)  # above the board
def test_routes_from_any_home_position_go_round_the_board(stave, home_x, home_y, home_z):
    profile = EXAMPLE if stave is None else stave.solve()
    params = replace(
        DEFAULT_PARAMS,
        start_x_mm=0.0,
        start_y_mm=0.0,
        home_x_mm=home_x,
        home_y_mm=home_y,
        home_z_deg=home_z,
    )
    assume(not keep_out_box(profile, params).contains((home_x, home_y)))
    path = build_toolpath(profile, params)
    assert path.segments[0].start == (home_x, home_y) == path.segments[-1].end
    assert path.segments[0].z_start_deg == home_z == path.segments[-1].z_end_deg
    assert_clear_of_board(path, profile, params)


def test_home_over_the_board_is_rejected():
    params = replace(DEFAULT_PARAMS, home_x_mm=500.0, home_y_mm=400.0)
    with pytest.raises(GeometryError) as info:
        build_toolpath(EXAMPLE, params)
    (error,) = info.value.errors
    assert error.field == "home_position_mm"
    assert error.message.startswith(
        "home_position_mm = (500, 400) puts the tool over the board: allowed X <= 60 or "
        "X >= 1140 or Y <= "
    )


def test_home_equal_to_the_lead_in_start_only_tilts():
    first = build_toolpath(EXAMPLE, DEFAULT_PARAMS).segments[1]
    params = replace(DEFAULT_PARAMS, home_x_mm=first.start[0], home_y_mm=first.start[1])
    path = build_toolpath(EXAMPLE, params)
    tilt = path.segments[0]
    assert tilt.length_mm == 0.0 and (tilt.z_start_deg, tilt.z_end_deg) == (0.0, 3.5)
    at_tilt = replace(params, home_z_deg=3.5)
    assert build_toolpath(EXAMPLE, at_tilt).segments[0].cutting


@pytest.mark.parametrize(
    ("changes", "field", "fragment"),
    [
        ({"lead_mm": 40.0}, "lead_mm", "lead_mm = 40 is out of range: allowed lead > 40.075 mm"),
        ({"tool_radius_mm": 0.0}, "tool_radius_mm", "allowed tool radius > 0 mm"),
        ({"tool_radius_mm": math.nan}, "tool_radius_mm", "is not a finite number"),
        ({"machine_height_mm": -1.0}, "machine_height_mm", "allowed machine height >= 0 mm"),
        ({"tilt_deg": -3.5}, "tilt_deg", "allowed 0 <= tilt < 90 deg"),
        ({"tilt_deg": 90.0}, "tilt_deg", "allowed 0 <= tilt < 90 deg"),
        ({"home_z_deg": 95.0}, "home_z_deg", "allowed -90 < home tilt < 90 deg"),
        ({"tilt_clearance_mm": -1.0}, "tilt_clearance_mm", "allowed tilt clearance >= 0 mm"),
        ({"start_x_mm": math.inf}, "start_x_mm", "is not a finite number"),
        ({"home_y_mm": "0"}, "home_y_mm", "is not a finite number"),
    ],
)
def test_invalid_params_raise_geometry_error(changes, field, fragment):
    with pytest.raises(GeometryError) as info:
        build_toolpath(EXAMPLE, replace(DEFAULT_PARAMS, **changes))
    assert info.value.fields == (field,)
    assert fragment in str(info.value)


def test_lead_just_longer_than_the_effective_radius_is_accepted():
    rc = DEFAULT_PARAMS.effective_radius_mm
    build_toolpath(EXAMPLE, replace(DEFAULT_PARAMS, lead_mm=rc * (1 + 1e-9)))


def test_all_invalid_params_are_reported_together():
    params = replace(DEFAULT_PARAMS, tool_radius_mm=-1.0, tilt_clearance_mm=-1.0, lead_mm=math.nan)
    with pytest.raises(GeometryError) as info:
        build_toolpath(EXAMPLE, params)
    assert set(info.value.fields) == {"tool_radius_mm", "tilt_clearance_mm", "lead_mm"}


def test_length_ratio_zero_path_has_no_straight_sections():
    profile = solve_profile(1000.0, 150.0, 0.0, 0.75)
    path = build_toolpath(profile, DEFAULT_PARAMS)
    side_a = [type(s).__name__ for s in path.side_segments("A")]
    assert side_a == ["LineSegment", "ArcSegment", "LineSegment"]  # lead-in, arc, lead-out


def test_to_json_list_format():
    path = build_toolpath(EXAMPLE, DEFAULT_PARAMS)
    items = path.to_json_list()
    assert len(items) == len(path.segments)
    json.dumps(items)  # plain JSON types only
    assert items[0] == {
        "type": "line",
        "start": [0.0, 0.0],
        "end": list(path.segments[0].end),
        "z_deg": 3.5,
        "z_start_deg": 0.0,
        "cutting": False,
    }
    arc = items[3]
    assert set(arc) == {"type", "start", "end", "center", "direction", "z_deg", "cutting"}
    assert (arc["type"], arc["direction"], arc["z_deg"], arc["cutting"]) == ("arc", "cw", 3.5, True)
    assert items[11]["z_deg"] == -3.5


def test_side_segments_rejects_unknown_side():
    with pytest.raises(ValueError, match="side must be 'A' or 'B'"):
        build_toolpath(EXAMPLE, DEFAULT_PARAMS).side_segments("C")


def test_two_bevels_side_a_at_plus_alpha_a_side_b_at_minus_alpha_b():
    """An oval barrel's stave: each side has its own tilt, offset r/cos and pivot shift."""
    params = replace(DEFAULT_PARAMS, tilt_deg=15.6644, tilt_b_deg=14.6323)
    path = build_toolpath(EXAMPLE, params)
    assert {s.z_end_deg for s in path.side_segments("A")} == {15.6644}
    assert {s.z_end_deg for s in path.side_segments("B")} == {-14.6323}
    tilt_change = path.segments[7]
    assert (tilt_change.z_start_deg, tilt_change.z_end_deg) == (15.6644, -14.6323)
    for side, alpha, sign in (("A", 15.6644, 1.0), ("B", 14.6323, -1.0)):
        rc = 40 / math.cos(math.radians(alpha))
        shift = 250 * math.tan(math.radians(alpha))
        assert params.side_effective_radius_mm(side) == rc
        assert params.side_pivot_shift_mm(side) == shift
        arc = next(s for s in path.side_segments(side) if isinstance(s, ArcSegment))
        belly = arc.point_at(arc.length_mm / 2)
        assert belly[1] + sign * (shift - rc) == pytest.approx(400 + sign * 75.0, abs=1e-9)
        assert arc.radius_mm == pytest.approx(EXAMPLE.R + rc, rel=1e-12)
    # The larger bevel sets the lead's minimum and the keep-out box.
    assert params.effective_radius_mm == 40 / math.cos(math.radians(15.6644))
    wider = keep_out_box(EXAMPLE, replace(params, tilt_deg=14.6323, tilt_b_deg=15.6644))
    assert keep_out_box(EXAMPLE, params) == wider


def test_equal_bevels_given_twice_are_the_one_bevel_path():
    twice = build_toolpath(EXAMPLE, replace(DEFAULT_PARAMS, tilt_b_deg=DEFAULT_PARAMS.tilt_deg))
    assert twice.segments == build_toolpath(EXAMPLE, DEFAULT_PARAMS).segments


def test_side_b_bevel_is_validated_by_name():
    with pytest.raises(GeometryError) as caught:
        build_toolpath(EXAMPLE, replace(DEFAULT_PARAMS, tilt_b_deg=95.0))
    assert "tilt_b_deg" in caught.value.fields
    with pytest.raises(GeometryError) as caught:
        build_toolpath(EXAMPLE, replace(DEFAULT_PARAMS, tilt_b_deg=math.nan))
    assert caught.value.fields == ("tilt_b_deg",)


def test_roughing_passes_come_first_each_side_ends_with_the_finishing_pass():
    params = replace(DEFAULT_PARAMS, roughing_allowances_mm=(20.0, 10.0))
    path = build_toolpath(EXAMPLE, params)
    single = build_toolpath(EXAMPLE, DEFAULT_PARAMS)
    assert params.passes == 3
    for side in ("A", "B"):
        cuts = path.side_segments(side)
        finishing = single.side_segments(side)
        assert cuts[-len(finishing) :] == finishing  # the last pass is the one-pass cut
        assert len(cuts) == 3 * len(finishing)
        # Each roughing pass is the same edge offset further out by its allowance.
        for number, allowance in enumerate((20.0, 10.0)):
            arc = cuts[number * len(finishing) + 2]
            assert isinstance(arc, ArcSegment)
            assert arc.radius_mm == pytest.approx(finishing[2].radius_mm + allowance, rel=1e-12)
    # Between passes the cutter goes back round the board, outside the keep-out box.
    box = keep_out_box(EXAMPLE, params).moved(params.start_x_mm, params.start_y_mm)
    backs = [s for s in path.segments if not s.cutting and s.side in ("A", "B")]
    assert len(backs) == 2 * 2 * 3  # up, across, down; twice on each side
    for segment in backs:
        assert not box.blocks(segment.start, segment.end)
        assert segment.z_start_deg == segment.z_end_deg == (3.5 if segment.side == "A" else -3.5)
    for before, after in zip(path.segments, path.segments[1:], strict=False):
        assert before.end == after.start


def test_roughing_allowances_are_validated():
    for bad in ((10.0, 20.0), (0.0,), (math.nan,), [5.0]):
        with pytest.raises(GeometryError) as caught:
            build_toolpath(EXAMPLE, replace(DEFAULT_PARAMS, roughing_allowances_mm=bad))
        assert caught.value.fields == ("roughing_allowances_mm",)
