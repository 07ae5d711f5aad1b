import math

import pytest

from app.geometry.segments import ArcSegment, LineSegment


def quarter_arc(clockwise: bool) -> ArcSegment:
    # Centre (0, 0), radius 10, from (10, 0) to (0, 10): a quarter ccw, three quarters cw.
    return ArcSegment((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), clockwise, 2.0, 2.0, True, "A")


def test_line_length_point_tangent_tilt():
    line = LineSegment((0.0, 0.0), (3.0, 4.0), 0.0, 10.0, False, "")
    assert line.length_mm == 5.0
    assert line.point_at(0.0) == (0.0, 0.0)
    assert line.point_at(2.5) == (1.5, 2.0)
    assert line.point_at(5.0) == (3.0, 4.0)
    assert line.tangent_at(1.0) == (0.6, 0.8)
    assert line.z_at(2.5) == 5.0
    assert line.bounds() == (0.0, 0.0, 3.0, 4.0)


def test_line_distance():
    line = LineSegment((0.0, 0.0), (10.0, 0.0), 1.0, 1.0, True, "A")
    assert line.distance_to((5.0, 3.0)) == 3.0
    assert line.distance_to((-3.0, 4.0)) == 5.0
    assert line.distance_to((13.0, -4.0)) == 5.0


def test_zero_length_line_is_a_pure_tilt_move():
    tilt = LineSegment((5.0, 5.0), (5.0, 5.0), 3.0, -3.0, False, "")
    assert tilt.length_mm == 0.0
    assert tilt.point_at(0.0) == (5.0, 5.0)
    assert tilt.z_at(0.0) == -3.0
    with pytest.raises(ValueError, match="no tangent"):
        tilt.tangent_at(0.0)


def test_arc_directions_sweep_and_length():
    ccw, cw = quarter_arc(False), quarter_arc(True)
    assert ccw.radius_mm == 10.0
    assert ccw.sweep_rad == pytest.approx(math.pi / 2)
    assert cw.sweep_rad == pytest.approx(3 * math.pi / 2)
    assert ccw.length_mm == pytest.approx(5 * math.pi)
    assert cw.length_mm == pytest.approx(15 * math.pi)


def test_arc_point_and_tangent():
    ccw, cw = quarter_arc(False), quarter_arc(True)
    half = ccw.point_at(ccw.length_mm / 2)
    assert half == pytest.approx((10 / math.sqrt(2), 10 / math.sqrt(2)))
    assert ccw.tangent_at(0.0) == pytest.approx((0.0, 1.0))
    assert cw.tangent_at(0.0) == pytest.approx((0.0, -1.0))
    assert cw.point_at(cw.length_mm / 3) == pytest.approx((0.0, -10.0))
    assert ccw.point_at(ccw.length_mm) == (0.0, 10.0)
    assert ccw.z_at(3.0) == 2.0


def test_arc_bounds_include_extremes_inside_the_sweep():
    assert quarter_arc(False).bounds() == pytest.approx((0.0, 0.0, 10.0, 10.0))
    assert quarter_arc(True).bounds() == pytest.approx((-10.0, -10.0, 10.0, 10.0))


def test_arc_distance():
    ccw = quarter_arc(False)
    assert ccw.distance_to((3.0, 4.0)) == pytest.approx(5.0)  # inside the sweep
    assert ccw.distance_to((20.0, 20.0)) == pytest.approx(math.hypot(20, 20) - 10)
    assert ccw.distance_to((10.0, -5.0)) == pytest.approx(5.0)  # nearest is the start
    assert quarter_arc(True).distance_to((10.0, -5.0)) == pytest.approx(math.hypot(10, 5) - 10)


def test_tiny_sweep_on_a_huge_radius():
    radius = 5e8
    angle = 1e-6
    start = (-radius * math.sin(angle), radius * math.cos(angle))
    end = (radius * math.sin(angle), radius * math.cos(angle))
    arc = ArcSegment(start, end, (0.0, 0.0), True, 0.0, 0.0, True, "A")
    assert arc.sweep_rad == pytest.approx(2 * angle, rel=1e-9)
    assert arc.length_mm == pytest.approx(2 * angle * radius, rel=1e-9)
    assert arc.point_at(arc.length_mm / 2)[0] == pytest.approx(0.0, abs=1e-6)


@pytest.mark.parametrize(
    ("kwargs", "fragment"),
    [
        ({"start": (math.nan, 0.0)}, "segment start must be two finite numbers"),
        ({"side": "C"}, "segment side must be one of"),
        ({"z_end_deg": 3.0}, "a cutting segment keeps its tilt"),
        ({"z_start_deg": math.inf}, "segment tilt must be finite"),
    ],
)
def test_line_validation(kwargs, fragment):
    fields = {
        "start": (0.0, 0.0),
        "end": (1.0, 0.0),
        "z_start_deg": 1.0,
        "z_end_deg": 1.0,
        "cutting": True,
        "side": "A",
    }
    with pytest.raises(ValueError, match=fragment):
        LineSegment(**{**fields, **kwargs})


@pytest.mark.parametrize(
    ("kwargs", "fragment"),
    [
        ({"end": (0.0, 10.1)}, "not on one circle"),
        ({"center": (10.0, 0.0)}, "radius > 0"),
        ({"end": (10.0, 0.0)}, "zero sweep"),
        ({"center": (math.nan, 0.0)}, "arc center must be two finite numbers"),
    ],
)
def test_arc_validation(kwargs, fragment):
    fields = {
        "start": (10.0, 0.0),
        "end": (0.0, 10.0),
        "center": (0.0, 0.0),
        "clockwise": False,
        "z_start_deg": 0.0,
        "z_end_deg": 0.0,
        "cutting": False,
        "side": "",
    }
    with pytest.raises(ValueError, match=fragment):
        ArcSegment(**{**fields, **kwargs})


@pytest.mark.parametrize("s", [-0.1, 5.1])
def test_positions_outside_the_segment_are_rejected(s):
    line = LineSegment((0.0, 0.0), (3.0, 4.0), 0.0, 0.0, False, "")
    with pytest.raises(ValueError, match="outside the segment"):
        line.point_at(s)
    with pytest.raises(ValueError, match="outside the segment"):
        quarter_arc(False).point_at(s * 10)
