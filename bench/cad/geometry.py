"""Plane areas and volumes the closed-formula references need (circle strips, keyways,
holes through curved walls, circle intersections, Pappus for edge treatments). Written for
the reference side only; nothing here reads the synthesizer."""

from __future__ import annotations

from collections.abc import Callable
from math import acos, asin, pi, sin, sqrt


def circle_strip(r: float, h: float) -> float:
    """The area of the part of a circle of radius r with |y| <= h."""
    h = min(h, r)
    return 2 * (h * sqrt(r * r - h * h) + r * r * asin(h / r))


def keyway_area(r_bore: float, width: float, x_outer: float) -> float:
    """The plan area a keyway of this width takes from the wall of a bore: from the bore's
    surface out to the plane x = x_outer."""
    return width * x_outer - circle_strip(r_bore, width / 2) / 2


def lens(r: float, c: float, a: float) -> float:
    """The area common to a circle of radius r at the origin and one of radius a at
    distance c."""
    if c >= r + a:
        return 0.0
    if c <= abs(r - a):
        return pi * min(r, a) ** 2
    alpha = acos((c * c + r * r - a * a) / (2 * c * r))
    beta = acos((c * c + a * a - r * r) / (2 * c * a))
    return r * r * (alpha - 0.5 * sin(2 * alpha)) + a * a * (beta - 0.5 * sin(2 * beta))


def annulus_disc_area(r1: float, r2: float, c: float, a: float) -> float:
    """The area common to the annulus r1 <= |p| <= r2 and a disc of radius a at distance c."""
    return lens(r2, c, a) - lens(r1, c, a)


def _simpson(f: Callable[[float], float], lo: float, hi: float, n: int = 4000) -> float:
    step = (hi - lo) / n
    total = f(lo) + f(hi)
    for k in range(1, n):
        total += (4 if k % 2 else 2) * f(lo + k * step)
    return total * step / 3


def hole_through_wall(d: float, r_in: float, r_out: float, inner_is_plane: bool = False) -> float:
    """The volume a radial hole of diameter d takes from one side of a tube wall between
    the radii r_in and r_out (or, with `inner_is_plane`, between the plane x = r_in and the
    outer surface)."""
    a = d / 2

    def chord(y: float) -> float:
        inner = r_in if inner_is_plane else sqrt(max(r_in * r_in - y * y, 0.0))
        return 2 * sqrt(max(a * a - y * y, 0.0)) * (sqrt(r_out * r_out - y * y) - inner)

    return _simpson(chord, -a, a)


def cyl_chamfer(r: float, h: float, k: float) -> float:
    """A cylinder with both circular edges chamfered k (Pappus on the cut triangles)."""
    return pi * r * r * h - 2 * 2 * pi * (r - k / 3) * (k * k / 2)


def cyl_fillet(r: float, h: float, f: float) -> float:
    """A cylinder with both circular edges filleted f (Pappus on the cut corners)."""
    area = f * f * (1 - pi / 4)
    xbar = f * (5 / 6 - pi / 4) / (1 - pi / 4)
    return pi * r * r * h - 2 * 2 * pi * (r - xbar) * area
