import itertools
import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.geometry.polyline import arc_step_rad, sagitta_mm, to_polyline
from app.geometry.segments import ArcSegment, LineSegment
from app.geometry.toolpath import build_toolpath
from tests.geometry.strategies import DEFAULT_PARAMS, PROPERTY, stave_inputs


def test_step_and_sagitta_agree():
    for radius in (1.0, 40.0, 5005.0, 5e8):
        for bound in (1e-4, 1e-3, 0.1):
            step = arc_step_rad(radius, bound)
            if step < math.pi / 4:
                assert sagitta_mm(radius, step) == pytest.approx(bound, rel=1e-9)
            else:
                assert sagitta_mm(radius, step) <= bound


def test_small_arcs_still_get_several_chords():
    assert arc_step_rad(0.1, 1.0) == math.pi / 4


def test_polyline_of_a_quarter_circle():
    arc = ArcSegment((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), False, 1.0, 1.0, True, "A")
    points = to_polyline([arc], max_chord_error_mm=0.01)
    count = math.ceil((math.pi / 2) / arc_step_rad(10.0, 0.01))
    assert len(points) == count + 1
    assert points[0] == (10.0, 0.0, 1.0, True)
    assert points[-1] == (0.0, 10.0, 1.0, True)
    for x, y, z, cutting in points:
        assert math.hypot(x, y) == pytest.approx(10.0, abs=1e-12)
        assert (z, cutting) == (1.0, True)


def test_lines_are_split_only_when_asked():
    line = LineSegment((0.0, 0.0), (10.0, 0.0), 0.0, 4.0, False, "")
    assert to_polyline([line]) == [(0.0, 0.0, 0.0, False), (10.0, 0.0, 4.0, False)]
    split = to_polyline([line], max_segment_mm=1.0)
    assert len(split) == 11
    assert split[5] == pytest.approx((5.0, 0.0, 2.0, False))


@pytest.mark.parametrize(
    ("kwargs", "fragment"),
    [
        ({"max_chord_error_mm": 0.0}, "max_chord_error_mm = 0.0 is out of range"),
        ({"max_chord_error_mm": math.nan}, "max_chord_error_mm = nan is out of range"),
        ({"max_segment_mm": -1.0}, "max_segment_mm = -1.0 is out of range"),
    ],
)
def test_bad_bounds_are_rejected(kwargs, fragment):
    line = LineSegment((0.0, 0.0), (10.0, 0.0), 0.0, 0.0, False, "")
    with pytest.raises(ValueError, match=fragment):
        to_polyline([line], **kwargs)


def chord_error(arc: ArcSegment, a: tuple[float, float], b: tuple[float, float]) -> float:
    """Largest distance between the arc between two of its points and their chord."""
    cx, cy = arc.center
    mx, my = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
    return arc.radius_mm - math.hypot(mx - cx, my - cy)


@PROPERTY
@given(stave_inputs(), st.sampled_from([1e-4, 1e-3, 1e-2, 0.5]))
def test_toolpath_polyline_stays_within_the_chord_error(stave, bound):
    path = build_toolpath(stave.solve(), DEFAULT_PARAMS)
    points = path.to_polyline(max_chord_error_mm=bound)
    assert points[0][:3] == (*path.segments[0].start, path.segments[0].z_start_deg)
    assert points[-1][:3] == (*path.segments[-1].end, path.segments[-1].z_end_deg)
    # Walk the points segment by segment: every segment's end is a polyline point.
    index = 0
    for segment in path.segments:
        start = index
        while points[index][:2] != segment.end:
            index += 1
        chunk = points[start : index + 1]
        assert all(p[3] == segment.cutting for p in chunk[1:])
        if isinstance(segment, ArcSegment):
            radius = segment.radius_mm
            for x, y, z, _ in chunk:
                on_circle = math.hypot(x - segment.center[0], y - segment.center[1])
                assert abs(on_circle - radius) <= 1e-9 + 8 * math.ulp(radius)
                assert z == segment.z_end_deg
            for a, b in itertools.pairwise(chunk):
                assert chord_error(segment, a[:2], b[:2]) <= bound * (1 + 1e-9) + 1e-9
        else:
            assert len(chunk) == 2
    assert index == len(points) - 1


def test_finer_bound_means_more_points():
    from app.geometry.profile import solve_profile

    path = build_toolpath(solve_profile(1000.0, 150.0, 0.25, 0.75), DEFAULT_PARAMS)
    counts = [len(path.to_polyline(bound)) for bound in (0.1, 0.01, 0.001, 0.0001)]
    assert counts == sorted(counts) and counts[0] < counts[-1]
    # Arc of radius R + rc over 2*B: sqrt(8 R e) per chord.
    assert counts[2] < 200
