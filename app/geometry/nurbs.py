"""Rational B-spline curves (the DXF SPLINE entity): point and first derivative.

Why our own evaluation rather than the DXF library's: geometry imports no file format library,
and the profile needs the curve under an anisotropic scaling (length to the recipe, depth to
the board). A B-spline is affinely invariant, so the scaled curve is the same spline with
scaled control points; evaluating it here keeps the true curve exact after scaling.
Evaluation is de Boor's algorithm on homogeneous coordinates; the derivative comes from the
derivative spline (degree p - 1) by the quotient rule.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass

Point = tuple[float, float]
Vector3 = tuple[float, float, float]


@dataclass(frozen=True)
class Nurbs:
    """A planar NURBS curve: degree p, knots (len = n + p + 1), n control points and weights.

    The parameter runs over [knots[p], knots[n]]; `point_at(u)` and `derivative_at(u)` take u
    in that interval.
    """

    degree: int
    knots: tuple[float, ...]
    control_points: tuple[Point, ...]
    weights: tuple[float, ...]

    def __post_init__(self) -> None:
        n, p = len(self.control_points), self.degree
        if p < 1:
            raise ValueError(f"spline degree must be >= 1, got {p}")
        if n < p + 1:
            raise ValueError(f"a degree-{p} spline needs >= {p + 1} control points, got {n}")
        if len(self.knots) != n + p + 1:
            raise ValueError(
                f"a spline with {n} control points of degree {p} needs {n + p + 1} knots, "
                f"got {len(self.knots)}"
            )
        if len(self.weights) != n:
            raise ValueError(f"spline needs {n} weights, got {len(self.weights)}")
        if any(b < a for a, b in zip(self.knots, self.knots[1:], strict=False)):
            raise ValueError("spline knots must not decrease")
        if not all(math.isfinite(w) and w > 0.0 for w in self.weights):
            raise ValueError("spline weights must be finite and > 0")
        if not all(math.isfinite(c) for point in self.control_points for c in point):
            raise ValueError("spline control points must be finite")
        if not self.domain[1] > self.domain[0]:
            raise ValueError("spline parameter range is empty")

    @property
    def domain(self) -> tuple[float, float]:
        return self.knots[self.degree], self.knots[len(self.control_points)]

    def mapped(self, scale_x: float, scale_y: float, dx: float, dy: float) -> Nurbs:
        """The image under (x, y) -> (scale_x*x + dx, scale_y*y + dy) (affine invariance)."""
        points = tuple((scale_x * x + dx, scale_y * y + dy) for x, y in self.control_points)
        return Nurbs(self.degree, self.knots, points, self.weights)

    def _weighted(self) -> tuple[Vector3, ...]:
        return tuple(
            (x * w, y * w, w) for (x, y), w in zip(self.control_points, self.weights, strict=True)
        )

    def _derivative_coefficients(self) -> tuple[Vector3, ...]:
        """Coefficients of the derivative of the homogeneous curve (degree p - 1)."""
        p = self.degree
        weighted = self._weighted()
        result = []
        for i in range(len(weighted) - 1):
            span = self.knots[i + p + 1] - self.knots[i + 1]
            factor = 0.0 if span == 0.0 else p / span
            result.append(
                (
                    factor * (weighted[i + 1][0] - weighted[i][0]),
                    factor * (weighted[i + 1][1] - weighted[i][1]),
                    factor * (weighted[i + 1][2] - weighted[i][2]),
                )
            )
        return tuple(result)

    def point_at(self, u: float) -> Point:
        wx, wy, w = _de_boor(self.degree, self.knots, self._weighted(), u)
        return (wx / w, wy / w)

    def derivative_at(self, u: float) -> Point:
        wx, wy, w = _de_boor(self.degree, self.knots, self._weighted(), u)
        dwx, dwy, dw = _de_boor(
            self.degree - 1, self.knots[1:-1], self._derivative_coefficients(), u
        )
        return ((dwx * w - wx * dw) / (w * w), (dwy * w - wy * dw) / (w * w))


def _de_boor(
    degree: int, knots: tuple[float, ...], coefficients: tuple[Vector3, ...], u: float
) -> Vector3:
    """The spline of `coefficients` at u (clamped to its domain), by de Boor's algorithm.

    Degree 0 (the derivative of a polyline) is the coefficient of u's span.
    """
    p, n = degree, len(coefficients)
    low, high = knots[p], knots[n]
    if u >= high:
        # The last non-empty span, so that u = end evaluates to the end of the curve.
        k = bisect.bisect_left(knots, high, 0, n + 1) - 1
    else:
        k = max(p, bisect.bisect_right(knots, max(u, low)) - 1)
    d = [coefficients[k - p + j] for j in range(p + 1)]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = j + k - p
            left, right = knots[i], knots[i + 1 + p - r]
            alpha = 0.0 if right == left else (u - left) / (right - left)
            a, b = d[j - 1], d[j]
            d[j] = (
                (1.0 - alpha) * a[0] + alpha * b[0],
                (1.0 - alpha) * a[1] + alpha * b[1],
                (1.0 - alpha) * a[2] + alpha * b[2],
            )
    return d[p]
