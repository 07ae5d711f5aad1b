"""A simulated cycle cuts every profile kind: the actual path within 0.01 mm of the exact
offset curve.

Run as the operator would, through `stave simulate` (home, select, board in, Start) with the
profile options; the trace's *actual* axis positions (the simulated drives, not the commands)
are taken back to the profile frame (P0 and the pivot shift Hm*tan(z) undone) and their
distance to the true curve, computed here from its own equations or from ezdxf's evaluation
of the drawing, must be the cutter's radius at the table, r/cos(z), within 0.01 mm.
"""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from ezdxf.math import BSpline

from app.cli import main
from tests.data import dxf_drawings as drawings

BARRIQUE = "Barrique 225 l Bordeaux"  # L 950, k 4/5 in the sample recipes
L, W, K = 950.0, 150.0, 0.8
TOLERANCE_MM = 0.01
SAMPLES = 20_001


Curve = Callable[[float], np.ndarray]
"""The true side A for a board of the measured width: (x, y) rows from head to head."""


def lame(exponent: float, ratio: float) -> Curve:
    def curve(width: float) -> np.ndarray:
        depth = width * (1 - K) / 2
        a = ratio * L / 2
        b = depth / (1 - (1 - ratio**-exponent) ** (1 / exponent))
        x = np.linspace(0.0, L, SAMPLES)
        t = np.abs(x - L / 2) / a
        return np.column_stack([x, width / 2 - b + b * (1 - t**exponent) ** (1 / exponent)])

    return curve


def parabola(width: float) -> np.ndarray:
    x = np.linspace(0.0, L, SAMPLES)
    u = (x - L / 2) / (L / 2)
    return np.column_stack([x, K * width / 2 + width * (1 - K) / 2 * (1 - u * u)])


def drawn_curve(
    points_of: Callable[[np.ndarray], np.ndarray], span: float, head: float, belly: float
) -> Curve:
    """The drawing on this board: x to L, depth so that the heads are k*W (the product's rule)."""

    def curve(width: float) -> np.ndarray:
        drawn = points_of(np.linspace(0.0, 1.0, SAMPLES))
        x = drawn[:, 0] * L / span
        y = K * width / 2 + width * (1 - K) / 2 * (drawn[:, 1] - head) / (belly - head)
        return np.column_stack([x, y])

    return curve


def _line_arc_line(t: np.ndarray) -> np.ndarray:
    x = t * drawings.DRAWN_L
    return np.column_stack([x, [drawings.drawn_half_width(v) for v in x]])


def _spline(t: np.ndarray) -> np.ndarray:
    reference = BSpline(drawings.SPLINE_POINTS, order=4)
    return np.array([tuple(reference.point(v * reference.max_t))[:2] for v in t])


LAL = drawn_curve(_line_arc_line, drawings.DRAWN_L, drawings.DRAWN_HEAD_Y, drawings.DRAWN_BELLY_Y)
CASES = {
    "parabola": (["--profile", "parabola"], parabola),
    "ellipse": (["--profile", "ellipse", "--semi-axis-ratio", "1.2"], lame(2.0, 1.2)),
    "superellipse": (
        ["--profile", "superellipse", "--exponent", "5", "--semi-axis-ratio", "1.1"],
        lame(5.0, 1.1),
    ),
    "drawn-lines-arcs": (drawings.lines_and_arc, LAL),
    "drawn-bulges": (drawings.bulged_polyline_belly_down, LAL),
    "drawn-spline": (drawings.spline, drawn_curve(_spline, 500.0, 0.0, 18.0)),
}


def _distances(points: np.ndarray, curve: np.ndarray) -> np.ndarray:
    """Distance of each point to the densely sampled curve (its vertices 0.05 mm apart)."""
    result = np.empty(len(points))
    for start in range(0, len(points), 256):
        chunk = points[start : start + 256]
        d = np.hypot(chunk[:, None, 0] - curve[None, :, 0], chunk[:, None, 1] - curve[None, :, 1])
        result[start : start + 256] = d.min(axis=1)
    return result


@pytest.mark.slow
@pytest.mark.parametrize("case", list(CASES))
def test_simulated_cut_follows_the_exact_offset_curve(capsys, tmp_path: Path, case: str):
    options, curve = CASES[case]
    if callable(options):
        path = tmp_path / "side.dxf"
        path.write_bytes(options())
        options = ["--dxf", str(path)]
    trace = tmp_path / "trace.csv"
    code = main(
        [
            "simulate",
            "--recipe-file",
            "resources/recipes/sample_recipes.json",
            "--width",
            str(W),
            "--trace",
            str(trace),
            "--json",
            *options,
        ]
    )
    out, err = capsys.readouterr()
    assert code == 0, err
    result = json.loads(out)
    assert result["cycles"][0]["result"] == "ok"
    params = result["params"]
    x0, y0 = params["P0"]
    radius, height = params["tool_radius_mm"], params["machine_height_mm"]
    with trace.open() as f:
        rows = [r for r in csv.DictReader(f) if r["state"] == "automatic"]
    actual = np.array([[float(r["x_act"]), float(r["y_act"]), float(r["z_act"])] for r in rows])
    z = np.radians(actual[:, 2])
    px = actual[:, 0] - x0
    py = actual[:, 1] - y0 + height * np.tan(z)
    reach = radius / np.cos(z)
    true = curve(result["cycles"][0]["measured_width_mm"])  # the gauge's reading
    near_edge = np.abs(np.abs(py) - np.interp(px, true[:, 0], true[:, 1]) - reach) < 1.0
    on_board = (px >= 0.0) & (px <= L) & near_edge & (np.abs(actual[:, 2]) > 1.0)
    assert on_board.sum() > 2000  # both sides, every period while the cutter shapes the board
    points = np.column_stack([px[on_board], np.abs(py[on_board])])
    error = np.abs(_distances(points, true) - reach[on_board])
    assert error.max() <= TOLERANCE_MM, f"{case}: worst {error.max():.4f} mm"
    assert math.isfinite(result["cycles"][0]["cycle_time_s"])
