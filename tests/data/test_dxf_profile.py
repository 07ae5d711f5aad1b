"""Drawn profiles from DXF: found, checked, scaled onto a board and fitted within 0.001 mm."""

from __future__ import annotations

import hashlib
import json

import pytest
from ezdxf.math import BSpline

from app.data.dxf_profile import DxfProfileError, read_dxf_profile
from app.geometry.biarc import FIT_TOLERANCE_MM
from app.geometry.curved_profile import CurvedProfile, solve_side_profile
from app.geometry.drawn_profile import DrawnSpline, shape_from_dict
from app.geometry.errors import GeometryError
from app.geometry.nurbs import Nurbs
from app.geometry.profile_kinds import ProfileKind
from tests.data import dxf_drawings as drawings
from tests.geometry.chain_checks import worst_deviation_mm, worst_gap_mm, worst_tangent_break_rad

L, W, K = 1000.0, 150.0, 0.75
W1 = K * W
C = (W - W1) / 2


def on_board(x_drawn: float, y_drawn: float, span: float, head: float, belly: float):
    """The drawing-to-board map, written out here: length to L, depth so that W1 = k*W."""
    return (x_drawn * L / span, W1 / 2 + C * (y_drawn - head) / (belly - head))


def fitted(data: bytes) -> CurvedProfile:
    drawing = read_dxf_profile("side.dxf", data)
    profile = solve_side_profile(ProfileKind.DRAWN, L, W, K, drawn=drawing.shape)
    assert isinstance(profile, CurvedProfile)
    return profile


def check_chain(profile: CurvedProfile, true_point) -> None:
    chain = profile.edge("A")
    assert worst_deviation_mm(chain, true_point) <= FIT_TOLERANCE_MM
    assert worst_tangent_break_rad(chain) < 1e-7
    assert worst_gap_mm(chain) == 0.0
    assert chain[0].start[0] == 0.0
    assert chain[-1].end[0] == L


def line_arc_line_on_board(t: float):
    x = t * drawings.DRAWN_L
    y = drawings.drawn_half_width(x)
    return on_board(x, y, drawings.DRAWN_L, drawings.DRAWN_HEAD_Y, drawings.DRAWN_BELLY_Y)


def test_lines_and_arcs_scaled_unevenly_are_fitted_within_a_micrometre():
    profile = fitted(drawings.lines_and_arc())
    check_chain(profile, line_arc_line_on_board)
    assert profile.edge("A")[0].start[1] == pytest.approx(W1 / 2, abs=1e-9)


def test_bulged_lwpolyline_drawn_as_the_lower_side_right_to_left():
    profile = fitted(drawings.bulged_polyline_belly_down())
    check_chain(profile, line_arc_line_on_board)


def test_old_style_2d_polyline_with_a_bulge_is_read_like_the_lwpolyline():
    drawing = read_dxf_profile("side.dxf", drawings.bulged_old_polyline())
    assert [p.source.split(" #")[0] for p in drawing.shape.primitives] == ["POLYLINE"] * 3
    assert all("layer SIDE" in p.source for p in drawing.shape.primitives)
    profile = solve_side_profile(ProfileKind.DRAWN, L, W, K, drawn=drawing.shape)
    assert isinstance(profile, CurvedProfile)
    check_chain(profile, line_arc_line_on_board)


def test_head_width_under_60_mm_is_refused_for_a_drawing_too():
    drawing = read_dxf_profile("side.dxf", drawings.spline())
    with pytest.raises(GeometryError) as refused:
        solve_side_profile(ProfileKind.DRAWN, L, 70.0, 0.8, drawn=drawing.shape)
    assert "head_width_mm" in refused.value.fields
    assert "head width >= 60 mm" in str(refused.value)


def test_spline_is_fitted_within_a_micrometre_of_ezdxfs_own_evaluation():
    profile = fitted(drawings.spline())
    reference = BSpline(drawings.SPLINE_POINTS, order=4)

    def true_point(t: float):
        point = reference.point(reference.max_t * t)
        return on_board(point.x, point.y, 500.0, 0.0, reference.point(reference.max_t / 2).y)

    check_chain(profile, true_point)


def test_the_drawing_is_kept_with_its_name_and_hash_and_cuts_the_same_from_the_stored_form():
    data = drawings.spline()
    drawing = read_dxf_profile("house style.dxf", data)
    assert drawing.file_name == "house style.dxf"
    assert drawing.sha256 == hashlib.sha256(data).hexdigest()
    stored = json.loads(json.dumps(drawing.shape.to_dict()))
    again = shape_from_dict(stored)
    first = solve_side_profile(ProfileKind.DRAWN, L, W, K, drawn=drawing.shape)
    second = solve_side_profile(ProfileKind.DRAWN, L, W, K, drawn=again)
    assert first.edge("A") == second.edge("A")


def test_a_layer_can_be_chosen_among_several_candidates():
    def build(space):
        space.add_open_spline(drawings.SPLINE_POINTS, degree=3, dxfattribs={"layer": "PROFILE"})
        space.add_line((0, 100), (500, 100), dxfattribs={"layer": "FRAME"})

    data = drawings.with_entities(build)
    with pytest.raises(DxfProfileError) as refused:
        read_dxf_profile("two.dxf", data)
    message = str(refused.value)
    assert message.startswith("two.dxf: ")
    assert "2 candidate curves" in message
    assert "SPLINE" in message and "layer PROFILE" in message
    assert "LINE" in message and "layer FRAME" in message
    assert refused.value.curve_layers == ("PROFILE", "FRAME")  # what a chooser offers
    chosen = read_dxf_profile("two.dxf", data, layer="PROFILE")
    assert [p.source.split(" #")[0] for p in chosen.shape.primitives] == ["SPLINE"]


def refusal(data: bytes, name: str = "bad.dxf") -> str:
    with pytest.raises(DxfProfileError) as refused:
        read_dxf_profile(name, data)
    message = str(refused.value)
    assert message.startswith(f"{name}: ")
    assert "\n" not in message
    return message


def test_no_usable_curve_names_the_entities_and_layers_found():
    def build(space):
        space.add_circle((0, 0), 10, dxfattribs={"layer": "HOLES"})
        space.add_text("oak", dxfattribs={"layer": "NOTES"})

    message = refusal(drawings.with_entities(build))
    assert "no usable curve" in message
    assert "CIRCLE on layer HOLES" in message and "TEXT on layer NOTES" in message


def test_an_unreadable_entity_on_another_layer_still_offers_every_layer():
    def build(space):
        space.add_polyline3d([(0, 0, 0), (250, 20, 5), (500, 0, 0)], dxfattribs={"layer": "3D"})
        space.add_open_spline(drawings.SPLINE_POINTS, degree=3, dxfattribs={"layer": "PROFILE"})

    data = drawings.with_entities(build)
    with pytest.raises(DxfProfileError) as refused:
        read_dxf_profile("mixed.dxf", data)
    assert "3D polyline" in str(refused.value)
    assert refused.value.curve_layers == ("3D", "PROFILE")
    assert read_dxf_profile("mixed.dxf", data, layer="PROFILE").shape.primitives


def test_a_refusal_on_one_layer_offers_no_layers():
    with pytest.raises(DxfProfileError) as refused:
        read_dxf_profile("bad.dxf", drawings.with_entities(lambda space: space.add_lwpolyline(
            [(0, 0), (250, 20), (500, 0)], dxfattribs={"layer": "SIDE"})))  # fmt: skip
    assert refused.value.curve_layers == ()


def test_an_empty_layer_choice_says_what_the_other_layers_hold():
    with pytest.raises(DxfProfileError, match="found: SPLINE on layer SIDE"):
        read_dxf_profile("bad.dxf", drawings.spline(layer="SIDE"), layer="PROFILE")


def test_a_file_that_is_not_dxf_is_refused_by_name():
    assert "not a readable DXF file" in refusal(b"\x00\x01 this is a photo", "photo.dxf")


def test_a_corner_is_refused_with_its_angle_and_place():
    def build(space):
        space.add_lwpolyline([(0, 0), (250, 20), (500, 0)], dxfattribs={"layer": "0"})

    message = refusal(drawings.with_entities(build))
    assert "corner of" in message and "(250.000, 20.000)" in message
    assert "segment 1" in message and "segment 2" in message


def test_a_curve_that_turns_back_is_not_a_function_of_x():
    def build(space):
        # A bulge of 1.5 sweeps 225 degrees: the arc swings out beyond both its ends.
        space.add_lwpolyline([(0, 0, 0, 0, 1.5), (500, 0, 0, 0, 0)], format="xyseb")

    assert "not a single function of x" in refusal(drawings.with_entities(build))


def test_self_intersection_is_refused_with_the_crossing():
    def build(space):
        space.add_lwpolyline([(0, 0), (100, 10), (50, -5), (50, 20)])

    assert "crosses itself at (50.000, 5.000)" in refusal(drawings.with_entities(build))


def test_a_belly_off_the_middle_is_refused():
    skewed = ((0.0, 0.0), (60.0, 14.0), (120.0, 22.0), (300.0, 14.0), (500.0, 0.0))
    message = refusal(drawings.spline(skewed))
    assert "belly is at x =" in message and "not in the middle" in message


def test_heads_of_different_width_are_refused():
    uneven = ((0.0, 0.0), (120.0, 14.0), (250.0, 22.0), (380.0, 14.0), (500.0, 6.0))
    assert "the two heads differ by 6.000 mm" in refusal(drawings.spline(uneven))


def test_a_closed_outline_is_refused():
    def build(space):
        space.add_lwpolyline([(0, 0, 0, 0, 0.2), (500, 0, 0, 0, 0.2)], format="xyseb", close=True)

    assert "closed" in refusal(drawings.with_entities(build))


def test_a_3d_polyline_is_refused_by_name():
    def build(space):
        space.add_polyline3d([(0, 0, 0), (250, 20, 5), (500, 0, 0)])

    assert "3D polyline" in refusal(drawings.with_entities(build))


def test_a_drawing_whose_scaled_sides_would_meet_is_refused():
    # Troughs between belly and heads as deep as the belly is high: on a wide board with narrow
    # heads (280 mm, k = 0.3) side A crosses the centre line; on the usual board it does not.
    trough = ((0.0, 0.0), (100.0, -30.0), (250.0, 60.0), (400.0, -30.0), (500.0, 0.0))
    drawing = read_dxf_profile("trough.dxf", drawings.spline(trough))
    solve_side_profile(ProfileKind.DRAWN, L, W, K, drawn=drawing.shape)
    with pytest.raises(GeometryError) as refused:
        solve_side_profile(ProfileKind.DRAWN, L, 280.0, 0.3, drawn=drawing.shape)
    assert "sides of the stave meet" in str(refused.value)


def test_a_tampered_stored_drawing_is_checked_again():
    stored = {
        "primitives": [{"type": "spline", "degree": 3, "knots": [0, 1], "control_points": []}]
    }
    with pytest.raises(GeometryError, match="stored drawing is not readable"):
        shape_from_dict(stored)
    spline = DrawnSpline(Nurbs(1, (0.0, 0.0, 1.0, 1.0), ((0.0, 0.0), (1.0, 0.0)), (1.0, 1.0)))
    with pytest.raises(GeometryError, match="no belly"):
        shape_from_dict({"primitives": [spline.to_dict()]})


def test_an_empty_or_cut_short_file_says_so():
    assert "the file is empty" in refusal(b"", "empty.dxf")
    whole = drawings.spline()
    cut_short = whole[: whole.index(b"ENTITIES") + 200]
    assert "ends without the DXF end marker (EOF)" in refusal(cut_short, "cut.dxf")
    # A complete drawing with nothing drawn in it is not called damaged.
    message = refusal(drawings.with_entities(lambda space: None), "blank.dxf")
    assert "no usable curve" in message and "found: nothing" in message
