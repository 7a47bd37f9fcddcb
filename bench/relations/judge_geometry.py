"""Plane geometry for the relation judge: convex footprints, distances, angles, hulls.

Everything here works on the floor plane (x east, y north, metres). A footprint is a
convex polygon given as an (k, 2) array of corners in order (either orientation).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

Arr = NDArray[np.float64]


def unit(v: Arr) -> Arr | None:
    """Return the unit vector along `v`, or None when `v` is (nearly) zero."""
    n = float(np.linalg.norm(v))
    if n < 1e-9:
        return None
    return np.asarray(v, dtype=np.float64) / n


def perp(v: Arr) -> Arr:
    """`v` turned 90 degrees counter-clockwise."""
    return np.array([-v[1], v[0]], dtype=np.float64)


def angle_deg(u: Arr, v: Arr) -> float:
    """Return the angle between two directions, 0..180 degrees."""
    uu, vv = unit(u), unit(v)
    if uu is None or vv is None:
        return 180.0
    return math.degrees(math.acos(max(-1.0, min(1.0, float(uu @ vv)))))


def axis_angle_deg(u: Arr, v: Arr) -> float:
    """Return the angle between two undirected axes, 0..90 degrees."""
    a = angle_deg(u, v)
    return min(a, 180.0 - a)


def project(poly: Arr, d: Arr) -> tuple[float, float]:
    """Return the interval a polygon covers along direction `d`."""
    p = poly @ d
    return float(p.min()), float(p.max())


def interval_gap(a: tuple[float, float], b: tuple[float, float]) -> float:
    """Return the clear gap between two intervals (negative when they overlap)."""
    return max(b[0] - a[1], a[0] - b[1])


def interval_overlap(a: tuple[float, float], b: tuple[float, float]) -> float:
    """Return the length two intervals share (0 when disjoint)."""
    return max(0.0, min(a[1], b[1]) - max(a[0], b[0]))


def _edge_normals(poly: Arr) -> list[Arr]:
    out = []
    for i in range(len(poly)):
        e = poly[(i + 1) % len(poly)] - poly[i]
        n = unit(perp(e))
        if n is not None:
            out.append(n)
    return out


def overlap_depth(a: Arr, b: Arr) -> float:
    """How deep two convex polygons overlap (separating-axis test): > 0 overlap, <= 0 apart."""
    depth = math.inf
    for n in _edge_normals(a) + _edge_normals(b):
        pa, pb = project(a, n), project(b, n)
        depth = min(depth, -interval_gap(pa, pb))
    return depth


def point_segment_distance(p: Arr, a: Arr, b: Arr) -> float:
    """Distance from point `p` to segment `ab` (any dimension)."""
    ab = b - a
    den = float(ab @ ab)
    t = 0.0 if den < 1e-12 else max(0.0, min(1.0, float((p - a) @ ab) / den))
    return float(np.linalg.norm(p - (a + t * ab)))


def poly_distance(a: Arr, b: Arr) -> float:
    """Return the clear distance between two convex polygons; 0 when they touch or overlap."""
    if overlap_depth(a, b) >= 0.0:
        return 0.0
    best = math.inf
    for p, q in ((a, b), (b, a)):
        for v in p:
            for i in range(len(q)):
                best = min(best, point_segment_distance(v, q[i], q[(i + 1) % len(q)]))
    return best


def point_in_convex(p: Arr, poly: Arr, margin: float = 0.0) -> bool:
    """Whether `p` lies inside a convex polygon grown by `margin` (shrunk when negative)."""
    c = poly.mean(axis=0)
    for i in range(len(poly)):
        a, b = poly[i], poly[(i + 1) % len(poly)]
        n = unit(perp(b - a))
        if n is None:
            continue
        if float((c - a) @ n) > 0:  # make n point outwards
            n = -n
        if float((p - a) @ n) > margin:
            return False
    return True


def convex_hull(points: Arr) -> Arr:
    """Return the convex hull of a set of points (Andrew's monotone chain), counter-clockwise."""
    pts = sorted({(round(float(x), 9), round(float(y), 9)) for x, y in points})
    if len(pts) <= 2:
        return np.array(pts, dtype=np.float64)

    def cross(o: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower: list[tuple[float, float]] = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    upper: list[tuple[float, float]] = []
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return np.array(lower[:-1] + upper[:-1], dtype=np.float64)


def shrink(poly: Arr, by: float) -> Arr:
    """Return a polygon pulled towards its centre by `by` metres at most (keeps it non-empty)."""
    c = poly.mean(axis=0)
    out = []
    for v in poly:
        d = v - c
        n = float(np.linalg.norm(d))
        out.append(c + d * max(0.0, n - by) / n if n > 1e-9 else v)
    return np.array(out, dtype=np.float64)


def rect(centre: Arr, axis_x: Arr, half_x: float, half_y: float) -> Arr:
    """Return a rectangle with its first half-size along `axis_x`."""
    ax = unit(axis_x)
    if ax is None:
        ax = np.array([1.0, 0.0])
    ay = perp(ax)
    return np.array(
        [
            centre + ax * half_x + ay * half_y,
            centre - ax * half_x + ay * half_y,
            centre - ax * half_x - ay * half_y,
            centre + ax * half_x - ay * half_y,
        ],
        dtype=np.float64,
    )


def principal_axis(points: Arr) -> Arr:
    """Return the direction along which a set of points spreads most (x for a single point)."""
    if len(points) < 2:
        return np.array([1.0, 0.0])
    q = points - points.mean(axis=0)
    w, v = np.linalg.eigh(q.T @ q)
    return np.asarray(v[:, int(np.argmax(w))], dtype=np.float64)
