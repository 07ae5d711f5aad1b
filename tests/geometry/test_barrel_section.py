"""Staves around round and oval barrels: the worked examples of docs/MACHINE.md section 7 and
the properties every placement must have (widths, shared joints, bevels, the closing stave)."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.geometry.barrel_section import (
    FULL_TURN_RAD,
    BarrelSection,
    chord_stave,
    closing_stave,
    face_normal,
    next_joint_t,
    plan_barrel,
    staves_to_close,
    validate_section,
    validate_widths,
)
from app.geometry.errors import GeometryError

BARREL_PROPERTY = settings(max_examples=60, deadline=None)
OVAL = BarrelSection(350.0, 250.0)


def _angle_deg(u, v):
    return math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1]))


def test_round_600_with_100_mm_staves():
    plan = plan_barrel(BarrelSection.circle(600.0), [100.0] * 18)
    assert len(plan.staves) == 18 and plan.overrun_number is None
    for stave in plan.staves:
        assert stave.bevel_start_deg == pytest.approx(9.594068, abs=5e-7)
        assert stave.bevel_end_deg == pytest.approx(9.594068, abs=5e-7)
    assert plan.closing is not None
    assert plan.closing.width_mm == pytest.approx(76.3091, abs=5e-5)
    assert plan.closing.bevel_start_deg == pytest.approx(7.306772, abs=5e-7)
    assert plan.closing.bevel_end_deg == pytest.approx(7.306772, abs=5e-7)
    assert plan.section.perimeter_mm == pytest.approx(600.0 * math.pi, rel=1e-15)


def test_round_600_a_nineteenth_100_mm_stave_overruns():
    plan = plan_barrel(BarrelSection.circle(600.0), [100.0] * 19)
    assert plan.overrun_number == 19
    assert len(plan.staves) == 18 and plan.closing is None


@pytest.mark.parametrize(
    ("index", "t_start", "t_end", "bevel_start", "bevel_end"),
    [
        (0, 0.0, 22.652673, 15.6644, 14.6323),
        (1, 22.652673, 42.999860, 11.7900, 10.4619),
        (2, 42.999860, 61.207327, 8.3781, 7.6402),
    ],
)
def test_oval_350_by_250_table(index, t_start, t_end, bevel_start, bevel_end):
    stave = plan_barrel(OVAL, [100.0] * 3).staves[index]
    assert stave.number == index + 1
    assert stave.start_angle_deg == pytest.approx(t_start, abs=5e-7)
    assert stave.end_angle_deg == pytest.approx(t_end, abs=5e-7)
    assert stave.bevel_start_deg == pytest.approx(bevel_start, abs=5e-5)
    assert stave.bevel_end_deg == pytest.approx(bevel_end, abs=5e-5)


def test_oval_closing_after_18_staves_and_perimeter():
    plan = plan_barrel(OVAL, [100.0] * 18)
    assert plan.staves[-1].end_angle_deg == pytest.approx(339.929654, abs=5e-7)
    closing = plan.closing
    assert closing is not None and closing.number == 19
    assert closing.width_mm == pytest.approx(88.3871, abs=5e-5)
    assert closing.bevel_start_deg == pytest.approx(13.1755, abs=5e-5)
    assert closing.bevel_end_deg == pytest.approx(13.9145, abs=5e-5)
    assert OVAL.perimeter_mm == pytest.approx(1898.07, abs=5e-3)


def test_a_gap_of_half_the_barrel_is_no_closing_stave():
    circle = BarrelSection.circle(600.0)
    assert closing_stave(circle, 2, math.pi) is not None  # the diameter: one chord
    assert plan_barrel(circle, [100.0]).closing is None  # 1.9 m of gap: not one stave


def test_n_equal_staves_close_a_circle_exactly():
    diameter, count = 900.0, 24
    width = diameter * math.sin(math.pi / count)
    plan = plan_barrel(BarrelSection.circle(diameter), [width] * count)
    assert plan.overrun_number is None and plan.closing is None
    assert plan.staves[-1].end_t_rad == FULL_TURN_RAD


def test_staves_left_estimate():
    assert staves_to_close(BarrelSection.circle(600.0), 0.0, 100.0) == 19  # 18 and a closing
    after = plan_barrel(OVAL, [100.0] * 18).end_t_rad
    assert staves_to_close(OVAL, after, 100.0) == 1


def test_a_width_beyond_every_chord_is_refused():
    with pytest.raises(GeometryError) as caught:
        next_joint_t(BarrelSection.circle(240.0), 0.0, 260.0)
    assert caught.value.fields == ("width_mm",)


def test_section_validation_names_the_field_value_and_range():
    assert validate_section(diameter_mm=600.0) == []
    assert validate_section(a_mm=350.0, b_mm=250.0) == []
    (error,) = validate_section(diameter_mm=5000.0)
    assert error.field == "barrel_diameter_mm" and "5000" in error.message
    assert "240 <= diameter <= 4500 mm" in error.message
    (error,) = validate_section(a_mm=2300.0, b_mm=250.0)
    assert error.field == "barrel_a_mm" and "120 <= a <= 2250 mm" in error.message
    (error,) = validate_section(a_mm=250.0, b_mm=350.0)
    assert error.field == "barrel_b_mm" and "b <= a = 250 mm" in error.message
    (error,) = validate_section(a_mm=1000.0, b_mm=400.0)
    assert error.field == "barrel_b_mm" and "500 <= b <= a mm" in error.message
    fields = [e.field for e in validate_section(a_mm=math.nan, b_mm="x")]
    assert fields == ["barrel_a_mm", "barrel_b_mm"]
    assert [e.field for e in validate_widths([100.0, 0.0, 281.0, math.inf, True])] == [
        "width_mm"
    ] * 4


@st.composite
def ovals_and_widths(draw):
    b = draw(st.floats(120.0, 2250.0))
    a = draw(st.floats(b, min(2250.0, 2.0 * b)))  # every oval validate_section accepts
    section = BarrelSection(a, b)
    top = min(280.0, b)  # a stave as wide as the semi-minor axis: far beyond real barrels
    count = math.ceil(section.perimeter_mm / 40.0) + 2
    widths = draw(st.lists(st.floats(40.0, top), min_size=count, max_size=count))
    return section, widths


@BARREL_PROPERTY
@given(ovals_and_widths())
def test_placed_staves_have_their_widths_share_joints_and_bevels_add_up(case):
    section, widths = case
    plan = plan_barrel(section, widths)
    assert plan.overrun_number is not None  # enough boards to go round
    for stave, width in zip(plan.staves, widths, strict=False):
        start, end = section.point(stave.start_t_rad), section.point(stave.end_t_rad)
        assert abs(math.dist(start, end) - width) <= 1e-9
        assert 0.0 < stave.bevel_start_deg < 90.0 and 0.0 < stave.bevel_end_deg < 90.0
    for before, after in zip(plan.staves, plan.staves[1:], strict=False):
        assert before.end_t_rad == after.start_t_rad  # one joint point for both
        faces = _angle_deg(
            face_normal(section, before.start_t_rad, before.end_t_rad),
            face_normal(section, after.start_t_rad, after.end_t_rad),
        )
        assert before.bevel_end_deg + after.bevel_start_deg == pytest.approx(faces, abs=1e-9)


@BARREL_PROPERTY
@given(ovals_and_widths())
def test_the_closing_stave_leaves_no_gap(case):
    section, widths = case
    plan = plan_barrel(section, widths)
    closing = closing_stave(section, len(plan.staves) + 1, plan.end_t_rad)
    assert closing is not None  # the board that overran was wider than the gap
    assert closing.width_mm < widths[len(plan.staves)]
    # A board cut to the closing width, placed after the last stave, ends on the first joint.
    end_t = next_joint_t(section, plan.end_t_rad, closing.width_mm)
    assert math.dist(section.point(end_t), section.point(0.0)) <= 1e-9
    first = plan.staves[0]
    faces = _angle_deg(
        face_normal(section, closing.start_t_rad, closing.end_t_rad),
        face_normal(section, first.start_t_rad, first.end_t_rad),
    )
    assert closing.bevel_end_deg + first.bevel_start_deg == pytest.approx(faces, abs=1e-9)


@BARREL_PROPERTY
@given(st.floats(240.0, 4500.0), st.lists(st.floats(20.0, 280.0), min_size=1, max_size=30))
def test_on_a_circle_both_bevels_are_asin_w_over_d(diameter, widths):
    section = BarrelSection.circle(diameter)
    # A stave as wide as the barrel (a bevel of 90 degrees) has a joint angle that depends
    # on the width without bound (d asin(x)/dx at x = 1): compare where it is well posed.
    widths = [w for w in widths if w < 0.99 * diameter]
    plan = plan_barrel(section, widths)
    turned = 0.0
    for stave in plan.staves:
        bevel = math.degrees(math.asin(stave.width_mm / diameter))
        assert stave.bevel_start_deg == pytest.approx(bevel, abs=1e-9)
        assert stave.bevel_end_deg == pytest.approx(bevel, abs=1e-9)
        turned += 2.0 * math.asin(stave.width_mm / diameter)
        assert stave.end_t_rad == pytest.approx(turned, abs=1e-9)
    if plan.overrun_number is not None:  # the central angles would pass 360 degrees
        overrun_width = widths[plan.overrun_number - 1]
        assert turned + 2.0 * math.asin(overrun_width / diameter) > FULL_TURN_RAD


def test_chord_stave_of_a_circle_is_symmetric():
    stave = chord_stave(BarrelSection.circle(1000.0), 1, 0.3, 0.5)
    assert stave.bevel_start_deg == pytest.approx(stave.bevel_end_deg, abs=1e-12)
    assert stave.bevel_start_deg == pytest.approx(math.degrees(0.1), abs=1e-12)


def test_the_length_along_the_section() -> None:
    oval = BarrelSection(350.0, 250.0)
    assert oval.arc_length_mm(0.0, FULL_TURN_RAD) == pytest.approx(1898.07, abs=5e-3)
    assert oval.arc_length_mm(0.0, FULL_TURN_RAD) == pytest.approx(oval.perimeter_mm, rel=1e-9)
    quarter = oval.arc_length_mm(0.0, math.pi / 2)
    assert 2 * quarter == pytest.approx(oval.arc_length_mm(math.pi / 2, 3 * math.pi / 2))
    assert BarrelSection.circle(600.0).arc_length_mm(1.0, 2.5) == pytest.approx(450.0)
    assert oval.arc_length_mm(2.0, 1.0) == 0.0
