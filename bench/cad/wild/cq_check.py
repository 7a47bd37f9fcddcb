"""A third route for the wild corpus: every part that refs.py gives a closed formula for,
built again as a small hand-written CadQuery program from the description's words, measured
exactly (OCCT's volume and tight bounding box) and compared with the formula. It exists to
catch mistakes in the formulas; the references themselves are refs.py's.

Run from the checkout root with the CadQuery venv:
    .cache/cad-venv/bin/python bench/cad/wild/cq_check.py [ID ...]
Exit status 1 when a program fails, is not one valid solid, or disagrees with its formula
(extents 0.1 % + 0.01 mm, volume 0.1 %).
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from math import cos, pi, radians, sin, sqrt, tan
from typing import Any

import cadquery as cq

from refs import CLEAR, INCH, SWG16, TAP, dev, heldout, heldout2

Shape = Any  # a CadQuery solid; cadquery ships no type information
I = INCH  # noqa: E741 - an inch, written the way the descriptions write it

EXTENT_TOL, EXTENT_SLACK, VOLUME_TOL = 1e-3, 0.01, 1e-3


# --- primitives (all sizes in mm; centred unless corners are given) ----------------------


def box(a: float, b: float, c: float, x: float = 0, y: float = 0, z: float = 0) -> Shape:
    return cq.Solid.makeBox(a, b, c, cq.Vector(x - a / 2, y - b / 2, z - c / 2))


def span(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> Shape:
    return cq.Solid.makeBox(x1 - x0, y1 - y0, z1 - z0, cq.Vector(x0, y0, z0))


def cz(d: float, z0: float, z1: float, x: float = 0, y: float = 0) -> Shape:
    return cq.Solid.makeCylinder(d / 2, z1 - z0, cq.Vector(x, y, z0), cq.Vector(0, 0, 1))


def cx(d: float, x0: float, x1: float, y: float = 0, z: float = 0) -> Shape:
    return cq.Solid.makeCylinder(d / 2, x1 - x0, cq.Vector(x0, y, z), cq.Vector(1, 0, 0))


def cy(d: float, y0: float, y1: float, x: float = 0, z: float = 0) -> Shape:
    return cq.Solid.makeCylinder(d / 2, y1 - y0, cq.Vector(x, y0, z), cq.Vector(0, 1, 0))


def prism(points: list[tuple[float, float]], h: float) -> Shape:
    """A plan outline in XY extruded from z = 0 to h."""
    return cq.Workplane("XY").polyline(points).close().extrude(h).val()


def ngon(n: int, ac: float, h: float) -> Shape:
    """A regular n-gon bar across corners `ac`, a corner on +X, from z = 0 to h."""
    return cq.Workplane("XY").polygon(n, ac).extrude(h).val()


def hexbar(af: float, h: float) -> Shape:
    return ngon(6, af / cos(pi / 6), h)


def revolve(points: list[tuple[float, float]]) -> Shape:
    """A profile in (radius, z) revolved about Z."""
    return cq.Workplane("XZ").polyline(points).close().revolve(360, (0, 0, 0), (0, 1, 0)).val()


def pyramid(a: float, b: float, h: float, ta: float = 0.0, tb: float = 0.0) -> Shape:
    """A rectangle a x b rising to a centred ta x tb top at height h (0 x 0: a pyramid)."""
    w = cq.Solid.makeWedge(a, h, b, (a - ta) / 2, (b - tb) / 2, (a + ta) / 2, (b + tb) / 2)
    return w.rotate(cq.Vector(0, 0, 0), cq.Vector(1, 0, 0), 90).translate(cq.Vector(-a / 2, b / 2, 0))


def tube(od: float, id_: float, z0: float, z1: float) -> Shape:
    return cz(od, z0, z1).cut(cz(id_, z0 - 1, z1 + 1))


def cut(s: Shape, *others: Shape) -> Shape:
    for o in others:
        s = s.cut(o)
    return s


def fuse(s: Shape, *others: Shape) -> Shape:
    for o in others:
        s = s.fuse(o)
    return s.clean()


def on_edges(s: Shape, selector: str | cq.Selector | None, op: str, size: float) -> Shape:
    w = cq.Workplane("XY").add(s).edges(selector)
    return (w.chamfer(size) if op == "chamfer" else w.fillet(size)).val()


def pcd(n: int, d: float, start_deg: float = 0.0) -> list[tuple[float, float]]:
    r = d / 2
    return [(r * cos(radians(start_deg + 360 * k / n)), r * sin(radians(start_deg + 360 * k / n))) for k in range(n)]


def holes(d: float, pts: list[tuple[float, float]], z0: float = -500, z1: float = 500) -> list[Shape]:
    return [cz(d, z0, z1, x, y) for x, y in pts]


def corners(a: float, b: float) -> list[tuple[float, float]]:
    return [(sx * a / 2, sy * b / 2) for sx in (-1, 1) for sy in (-1, 1)]


def scaled(s: Shape, k: float) -> Shape:
    return s.scale(k)


R = cq.selectors.RadiusNthSelector


# --- the programs ------------------------------------------------------------------------


def programs() -> dict[str, Callable[[], Shape]]:
    p: dict[str, Callable[[], Shape]] = {}
    p["WH_001"] = lambda: tube(38, 30, 0, 75)
    p["WH_002"] = lambda: on_edges(cz(16, 0, 60), "%CIRCLE", "chamfer", 1)
    p["WH_003"] = lambda: cut(box(120, 80, 8), *holes(9, corners(100, 60)))
    p["WH_004"] = lambda: cut(on_edges(cz(110, 0, 14), "%CIRCLE", "chamfer", 1), cz(50, -1, 15), *holes(11, pcd(6, 85)))
    p["WH_005"] = lambda: tube(25, 10.5, 0, 12)
    p["WH_006"] = lambda: cut(box(80, 50, 30), cy(22, -30, 30), *holes(8.5, [(-28, 0), (28, 0)]))
    p["WH_007"] = lambda: tube(24, 13, 0, 2.5)
    p["WH_008"] = lambda: cut(hexbar(7, 25), cz(TAP[4], -1, 26))
    p["WH_009"] = lambda: cut(tube(36, 20, 0, 14), cx(TAP[6], 0, 30, 0, 7))
    p["WH_010"] = lambda: cut(
        fuse(box(76, 76, 12, z=6), cz(50, 12, 22)), cz(30, -1, 23), *holes(CLEAR[10], corners(60, 60))
    )
    p["WH_011"] = lambda: box(25, 25, 150)
    p["WH_012"] = lambda: cut(cz(8, 0, 15), cz(TAP[3], -1, 16))
    p["WH_013"] = lambda: cut(fuse(cz(30, 0, 25), cz(40, 0, 3)), cz(20, -1, 26))
    p["WH_014"] = lambda: tube(60, 50, 0, 8)
    p["WH_015"] = lambda: cut(box(40, 40, 40), cz(20, -30, 30))
    p["WH_016"] = lambda: cut(
        box(100, 100, 6),
        cz(38.1, -5, 5),
        *holes(CLEAR[5], corners(47.14, 47.14)),
        *holes(CLEAR[6], corners(84, 84)),
    )
    p["WH_017"] = lambda: cut(cz(50, 0, 20), cz(44, -1, 17))
    p["WH_018"] = lambda: cut(
        fuse(cz(30, 0, 10), cz(20, 0, 10, 80), box(80, 12, 10, 40, 0, 5)), cz(12, -1, 11), cz(8, -1, 11, 80)
    )
    p["WH_019"] = lambda: cut(cz(40, 0, 12), cz(8, -1, 13), *holes(CLEAR[5], pcd(3, 28)))
    p["WH_020"] = lambda: on_edges(box(25, 25, 150), "|Z", "fillet", 3)
    p["WH_021"] = lambda: cut(box(60, 40, 20), *holes(CLEAR[6], corners(44, 24)))
    p["WH_022"] = lambda: cut(
        cz(60, 0, 20), cz(20, -1, 21), span(0, 12.8, -3, 3, -1, 21), *holes(TAP[6], pcd(4, 44, 45), 8, 21)
    )
    p["WH_023"] = lambda: cut(on_edges(cz(25, 0, 80), "%CIRCLE", "chamfer", 1), span(8.5, 20, -4, 4, 10, 50))
    p["WH_024"] = lambda: hexbar(24, 50)
    p["WH_025"] = lambda: scaled(cut(box(3, 2, 0.25), *holes(0.25, corners(3 - 0.75, 2 - 0.75))), I)
    p["WH_026"] = lambda: scaled(tube(1.5, 1.25, 0, 6), I)
    p["WH_027"] = lambda: scaled(cut(box(6, 2, 0.5), *holes(0.375, [(-2, 0), (2, 0)])), I)
    p["WH_028"] = lambda: cq.Solid.makeSphere(0.75 * I / 2, angleDegrees1=-90, angleDegrees2=90)
    p["WH_029"] = lambda: scaled(cut(tube(6, 2.38, 0, 0.875), *holes(0.75, pcd(4, 4.75))), I)
    p["WH_030"] = lambda: scaled(on_edges(cz(1, 0, 4), "%CIRCLE", "chamfer", 1 / 16), I)
    p["WH_031"] = lambda: cut(cz(30, 0, 100), span(12, 20, -20, 20, -1, 101))
    p["WH_032"] = lambda: prism([(0, 0), (40, 0), (40, 5), (5, 5), (5, 40), (0, 40)], 200)
    p["WH_033"] = lambda: cut(box(60, 40, 20), cz(12, -20, 20))
    p["WH_034"] = lambda: on_edges(cut(cz(80, 0, 10), cz(25, -1, 11)), R(0), "chamfer", 1)
    p["WH_035"] = lambda: cut(box(150, 100, 10), cz(40, -10, 10, -25, 0), *holes(9, corners(120, 70)))
    p["WH_036"] = lambda: cut(fuse(cz(30, 0, 20), cz(50, 20, 30)), cz(10, -1, 31))
    p["WH_037"] = lambda: pyramid(40, 40, 30, 20, 20)
    p["WH_038"] = lambda: cq.Solid.makeTorus(30, 6)
    p["WH_039"] = lambda: prism([(0, 0), (40, 0), (0, 30)], 15)
    p["WH_040"] = lambda: cq.Solid.makeCone(25, 0, 60)
    p["WH_041"] = lambda: pyramid(50, 50, 40)
    p["WH_042"] = lambda: cut(box(40, 40, 250), box(34, 34, 260))
    wb = 10 - 2 * 8 * tan(radians(20))
    groove = [(7.5, 0), (40, 0), (40, 5), (32, 10 - wb / 2), (32, 10 + wb / 2), (40, 15), (40, 20), (7.5, 20)]
    p["WH_043"] = lambda: revolve(groove)
    p["WH_044"] = lambda: cut(prism([(0, 0), (80, 0), (0, 60)], 6), *holes(8.5, [(20, 12), (12, 20)]))
    p["WH_045"] = lambda: cut(span(-20, 20, -15, 15, 0, 50), span(-8, 8, -20, 20, 15, 51), cx(10, -30, 30, 0, 40))
    p["WH_046"] = lambda: cut(fuse(cx(25, -30, 30), cz(25, 0, 30)), cx(21, -31, 31), cz(21, 0, 31))
    p["WH_047"] = lambda: cut(hexbar(17, 8), cz(TAP[10], -1, 9))
    channel = [(-25, 0), (25, 0), (25, 25), (22, 25), (22, 3), (-22, 3), (-22, 25), (-25, 25)]
    p["WH_048"] = lambda: cut(
        cq.Workplane("YZ").polyline(channel).close().extrude(300).val(),
        *holes(CLEAR[6], [(150 + 60 * k, 0) for k in range(-2, 3)]),
    )
    p["WH_049"] = lambda: cut(cz(25, 0, 40), cz(8, -1, 20), cz(0.25 * I, 20, 41))
    p["WH_050"] = lambda: box(50, 50, 50)
    p["WH_051"] = lambda: tube(60, 50, 0, 200)
    p["WH_052"] = lambda: cut(box(100, 60, 5), cz(10, -5, 5))
    p["WH_053"] = lambda: cz(40, -10, 10)
    p["WH_054"] = lambda: cut(
        fuse(span(0, 50, 0, 30, 0, 4), span(0, 4, 0, 30, 0, 40)),
        cz(CLEAR[6], -1, 5, 25, 15),
        cx(CLEAR[6], -1, 5, 15, 25),
    )

    p["WD_001"] = lambda: tube(50, 40, 0, 100)
    p["WD_002"] = lambda: on_edges(cz(20, 0, 50), "%CIRCLE", "chamfer", 1)
    p["WD_003"] = lambda: tube(42, 36, 0, 120)
    p["WD_004"] = lambda: cut(box(150, 100, 10), *holes(11, corners(120, 70)))
    p["WD_005"] = lambda: cut(fuse(cz(80, 0, 8), cz(50, 0, 30)), cz(20, -1, 31), *holes(CLEAR[6], pcd(4, 65)))
    p["WD_006"] = lambda: cut(box(40, 40, 60, z=30), cz(16, 35, 61))
    p["WD_007"] = lambda: cut(on_edges(cz(100, 0, 6), "%CIRCLE", "fillet", 2), cz(40, -1, 7))
    p["WD_008"] = lambda: cut(
        fuse(span(0, 80, 0, 50, 0, 6), span(0, 80, 44, 50, 0, 60)),
        *holes(9, [(15, 20), (65, 20)]),
        cy(9, 40, 55, 15, 40),
        cy(9, 40, 55, 65, 40),
    )
    p["WD_009"] = lambda: cut(on_edges(cz(30, 0, 120), "%CIRCLE", "chamfer", 1), cx(10, -20, 20, 0, 20))
    p["WD_010"] = lambda: tube(30, 13, 0, 3)
    p["WD_011"] = lambda: on_edges(box(20, 20, 100), None, "chamfer", 1)
    p["WD_012"] = lambda: cut(
        on_edges(box(200, 120, 5), "|Z", "fillet", 10), *holes(5.5, [*corners(180, 100), (-90, 0), (90, 0)])
    )
    p["WD_013"] = lambda: tube(16, 8.4, 0, 1.6)
    p["WD_014"] = lambda: cut(hexbar(13, 6.8), cz(TAP[8], -1, 8))
    p["WD_015"] = lambda: cut(tube(25, 12, 0, 10), cx(TAP[5], 0, 20, 0, 5))
    p["WD_016"] = lambda: tube(10, 5.3, 0, 8)
    p["WD_017"] = lambda: cut(hexbar(5.5, 30), cz(TAP[3], -1, 31))
    p["WD_018"] = lambda: cut(
        fuse(span(-63.5, 63.5, -19, 19, 0, 16), cy(60, -19, 19, 0, 33.3)),
        cy(40, -20, 20, 0, 33.3),
        *holes(14, [(-47.5, 0), (47.5, 0)]),
    )
    p["WD_019"] = lambda: box(300, 50, 10)
    p["WD_020"] = lambda: tube(I, I - 2 * SWG16, 0, 500)
    p["WD_021"] = lambda: cut(fuse(cz(90, 0, 14), cz(45, 0, 40)), cz(25, -1, 41), *holes(CLEAR[8], pcd(4, 68, 45)))
    p["WD_022"] = lambda: cut(cz(12, 0, 50), cx(4, -10, 10, 0, 5))
    p["WD_023"] = lambda: prism([(0, 0), (50, 0), (50, 6), (6, 6), (6, 50), (0, 50)], 1000)
    p["WD_024"] = lambda: cut(box(42.3, 42.3, 5), cz(22, -5, 5), *holes(CLEAR[3], corners(31, 31)))
    p["WD_025"] = lambda: tube(50, 45, 0, 70)
    p["WD_026"] = lambda: on_edges(box(60, 60, 60), None, "fillet", 5)
    p["WD_027"] = lambda: cut(cz(30, 0, 15), cz(6, -1, 10))
    p["WD_028"] = lambda: cut(
        fuse(box(100, 20, 8, z=4), cz(20, 0, 8, -50), cz(20, 0, 8, 50)), *holes(8, [(-50, 0), (50, 0)]), cz(6, -1, 9)
    )
    p["WD_029"] = lambda: cut(hexbar(20, 100), cz(10, -1, 101))
    p["WD_030"] = lambda: cut(fuse(cz(120, 0, 20), cz(30, 20, 170)), cz(10, -1, 171))
    p["WD_031"] = lambda: cq.Solid.makeSphere(12.5, angleDegrees1=-90, angleDegrees2=90)
    p["WD_032"] = lambda: cut(span(0, 80, 0, 60, 0, 40), span(2, 78, 2, 58, 2, 41))
    p["WD_033"] = lambda: cut(pyramid(25, 25, 700, 40, 40), cz(TAP[8], 680, 701))
    p["WD_034"] = lambda: cut(tube(100, 60, 0, 3), *holes(9, pcd(8, 80)))
    p["WD_035"] = lambda: cut(box(80, 50, 10), box(30, 20, 20))
    p["WD_036"] = lambda: cq.Solid.makeSphere(30, angleDegrees1=0, angleDegrees2=90)
    p["WD_037"] = lambda: cut(on_edges(cz(30, 0, 12), "%CIRCLE", "chamfer", 1), cz(10, -1, 13))
    p["WD_038"] = lambda: cut(on_edges(box(100, 50, 10), "|Z", "fillet", 5), *holes(8, [(-30, 0), (30, 0)]))
    p["WD_039"] = lambda: cut(cz(50, 0, 25), cz(25, -1, 26), cz(35, 20, 26), *holes(TAP[4], pcd(3, 42), -1, 8))
    p["WD_040"] = lambda: cut(
        on_edges(on_edges(box(30, 30, 80, z=40), ">Z", "chamfer", 0.5), "<Z", "chamfer", 0.5), cz(12, 60, 81)
    )
    p["WD_041"] = lambda: cz(40, 0, 200)
    p["WD_042"] = lambda: cut(on_edges(cz(20, 0, 60), "%CIRCLE", "chamfer", 0.5), cx(5, -20, 20, 0, 8))
    p["WD_043"] = lambda: cut(
        box(100, 60, 25, z=12.5),
        box(60, 30, 10, z=20),
        *holes(CLEAR[6], corners(80, 40)),
        *holes(8, [(-35, 0), (35, 0)], 13, 26),
    )
    p["WD_044"] = lambda: cut(cz(100, 0, 8), *holes(8.5, pcd(6, 80)))
    p["WD_045"] = lambda: hexbar(17, 30)
    p["WD_046"] = lambda: cut(cz(16, 0, 100), span(6, 10, -10, 10, 70, 101))
    cb = [cz(15, 3, 13, x, y) for x, y in corners(60, 60)]
    p["WD_047"] = lambda: cut(box(80, 80, 12, z=6), cz(30, -1, 13), *holes(9, corners(60, 60)), *cb)
    p["WD_048"] = lambda: cut(
        cz(60, 0, 40), cz(20, -1, 41), span(0, 12.8, -3, 3, -1, 41), cy(TAP[6], 0, 40, 0, 20), cx(TAP[6], -40, 0, 0, 20)
    )
    p["WD_049"] = lambda: scaled(box(4, 2, 1), I)
    p["WD_050"] = lambda: scaled(cut(box(6, 4, 0.75), cz(1, -1, 1)), I)
    p["WD_051"] = lambda: scaled(cz(2, 0, 3), I)
    p["WD_052"] = lambda: scaled(tube(0.625, 0.375, 0, 0.5), I)
    p["WD_053"] = lambda: scaled(cut(box(3, 3, 0.5), *holes(0.5, corners(1.5, 1.5))), I)
    p["WD_054"] = lambda: scaled(cut(box(2.5, 1.5, 1), cy(0.75, -1, 1), *holes(0.201, [(-0.875, 0), (0.875, 0)])), I)
    p["WD_055"] = lambda: scaled(tube(1, 1 - 0.13, 0, 12), I)
    p["WD_056"] = lambda: cq.Solid.makeSphere(0.75 * I, angleDegrees1=-90, angleDegrees2=90)
    p["WD_057"] = lambda: scaled(cut(cz(4, 0, 0.5), *holes(0.375, pcd(6, 3))), I)
    p["WD_058"] = lambda: scaled(
        cut(
            fuse(span(0, 3, 0, 2, 0, 0.25), span(0, 0.25, 0, 2, 0, 2)),
            cz(0.375, -1, 1, 1.625, 1),
            cx(0.375, -1, 1, 1, 1.125),
        ),
        I,
    )
    p["WD_059"] = lambda: scaled(on_edges(box(1, 1, 5), None, "chamfer", 0.125), I)
    p["WD_060"] = lambda: scaled(cut(cz(1.25, 0, 2), cx(0.25, -1, 1, 0, 1)), I)
    p["WD_061"] = lambda: prism([(0, 0), (60, 0), (60, 6), (6, 6), (6, 40), (0, 40)], 250)
    p["WD_062"] = lambda: cut(cz(50, 0, 80), span(20, 30, -30, 30, -1, 81), span(-30, -20, -30, 30, -1, 81))
    p["WD_063"] = lambda: cut(hexbar(40, 20), cz(22, -1, 21))
    p["WD_064"] = lambda: cut(box(20, 20, 100, z=50), cx(6, -20, 20, 0, 15), cx(6, -20, 20, 0, 85))
    p["WD_065"] = lambda: cut(box(80, 40, 50, z=25), cy(30, -30, 30, 0, 30), *holes(9, [(-28, 0), (28, 0)]))
    p["WD_066"] = lambda: cut(on_edges(cz(60, 0, 8), "%CIRCLE", "fillet", 2), cz(20, -1, 9))
    p["WD_067"] = lambda: tube(48.3, 48.3 - 6.4, 0, 500)
    p["WD_068"] = lambda: cut(box(60, 60, 60, z=30), cz(16, -1, 61), cz(30, 50, 61))
    p["WD_069"] = lambda: cut(
        on_edges(box(200, 150, 12), "|Z", "fillet", 15), cz(60, -10, 10), *holes(14, corners(170, 120))
    )
    p["WD_070"] = lambda: cut(box(100, 30, 6), box(30, 10, 10), cz(10, -5, 5, -15), cz(10, -5, 5, 15))
    p["WD_071"] = lambda: cq.Solid.makeSphere(22.5, angleDegrees1=-90, angleDegrees2=90)
    p["WD_072"] = lambda: cut(on_edges(cz(150, 0, 10), "%CIRCLE", "chamfer", 2), cz(50, -1, 11))
    p["WD_073"] = lambda: pyramid(60, 60, 45, 30, 30)
    p["WD_074"] = lambda: cq.Solid.makeTorus(40, 10)
    p["WD_075"] = lambda: prism([(0, 0), (50, 0), (0, 20)], 30)
    p["WD_076"] = lambda: cq.Solid.makeCone(40, 0, 40)
    p["WD_077"] = lambda: cq.Solid.makeCone(0, 20, 50)
    p["WD_078"] = lambda: pyramid(60, 40, 30)
    p["WD_079"] = lambda: ngon(6, 30, 20)
    p["WD_080"] = lambda: prism([(0, 0), (40, 0), (20, 40 * sqrt(3) / 2)], 100)
    p["WD_081"] = lambda: cq.Solid.makeSphere(25, angleDegrees1=-90, angleDegrees2=90).cut(
        cq.Solid.makeSphere(21, angleDegrees1=-90, angleDegrees2=90)
    )
    p["WD_082"] = lambda: box(16, 16, 300)
    p["WD_083"] = lambda: ngon(8, 30 / cos(pi / 8), 60).rotate(cq.Vector(0, 0, 0), cq.Vector(0, 0, 1), 22.5)
    p["WD_084"] = lambda: cut(box(60, 40, 200), box(54, 34, 210))
    p["WD_085"] = lambda: cut(fuse(cz(100, 0, 40), cz(40, 40, 50)), cz(20, -1, 51))
    p["WD_086"] = lambda: rack_program(2.0, 20.0, 20.0, 20.0, 10)
    p["WD_087"] = lambda: prism([(15, 0), (100, 0), (0, 100), (0, 15)], 8)
    p["WD_088"] = lambda: cut(
        fuse(box(80, 40, 8, z=4), span(10, 18, -20, 20, 8, 48), span(-18, -10, -20, 20, 8, 48)),
        *holes(9, [(-30, 0), (30, 0)]),
        cx(12, -40, 40, 0, 36),
    )
    p["WD_089"] = lambda: cut(hexbar(24, 13), cz(TAP[16], -1, 14))
    p["WD_090"] = lambda: cut(cz(10, 0, 25), cz(TAP[5], -1, 26))
    channel100 = [(-50, 0), (50, 0), (50, 50), (45, 50), (45, 5), (-45, 5), (-45, 50), (-50, 50)]
    p["WD_091"] = lambda: cut(
        cq.Workplane("YZ").polyline(channel100).close().extrude(400).val(),
        *holes(CLEAR[10], [(200 + x, y) for x in (-150, -50, 50, 150) for y in (-25, 25)]),
    )
    p["WD_092"] = lambda: cut(tube(30, 12, 0, 50), span(0, 20, -0.75, 0.75, -1, 51))
    p["WD_093"] = lambda: cut(
        fuse(cz(40, 0, 12), cz(24, 0, 12, 100), box(100, 16, 12, 50, 0, 6)), cz(20, -1, 13), cz(10, -1, 13, 100)
    )
    p["WD_094"] = lambda: cut(tube(40, 25, 0, 16), cx(TAP[6], 0, 30, 0, 8))
    p["WD_095"] = lambda: scaled(tube(0.812, 0.406, 0, 0.065), I)
    p["WD_096"] = lambda: cut(fuse(cx(42.4, -50, 50), cz(42.4, 0, 50)), cx(37.2, -51, 51), cz(37.2, 0, 51))
    p["WD_097"] = lambda: box(80, 40, 20)
    p["WD_098"] = lambda: cz(30, -30, 30)
    p["WD_099"] = lambda: cut(box(60, 60, 10), *holes(6.6, corners(44, 44)))
    p["WD_100"] = lambda: cq.Solid.makeSphere(20, angleDegrees1=-90, angleDegrees2=90)
    p["WD_101"] = lambda: tube(30, 16, 0, 3)
    p["WD_102"] = lambda: on_edges(cz(25, 0, 50), "%CIRCLE", "chamfer", 1)
    p["WD_103"] = lambda: cut(tube(120, 60, 0, 15), *holes(10, pcd(8, 95)))
    p["WD_104"] = lambda: hexbar(22, 40)
    p["WD_105"] = lambda: cut(box(50, 50, 50), cz(20, -30, 30))
    p["WD_106"] = lambda: cq.Solid.makeCone(20, 0, 50)
    p["WD_107"] = lambda: cut(span(0, 100, 0, 60, 0, 30), span(3, 97, 3, 57, 3, 31))
    p["WD_108"] = lambda: prism([(0, 0), (30, 0), (30, 3), (3, 3), (3, 30), (0, 30)], 100)
    return p


def programs_v2() -> dict[str, Callable[[], Shape]]:
    """The held-out v2 parts (heldout2.tsv)."""
    p: dict[str, Callable[[], Shape]] = {}
    p["WH2_001"] = lambda: tube(12, 6.4, 0, 15)
    p["WH2_002"] = lambda: cut(box(200, 80, 12), *holes(13.5, [(-80, 0), (80, 0)]))
    p["WH2_003"] = lambda: on_edges(cz(25, 0, 180), "%CIRCLE", "chamfer", 2)
    p["WH2_004"] = lambda: cut(
        fuse(cz(120, 0, 15), cz(60, 15, 25)), cz(40, -1, 26), *holes(CLEAR[8], pcd(6, 95), -1, 16)
    )
    p["WH2_005"] = lambda: cut(cz(8, 0, 20), cz(TAP[4], -1, 21))
    p["WH2_006"] = lambda: tube(33.7, 28.5, 0, 400)
    p["WH2_007"] = lambda: tube(37, 21, 0, 3)
    p["WH2_008"] = lambda: cut(hexbar(18, 10.8), cz(TAP[12], -1, 12))
    p["WH2_009"] = lambda: on_edges(tube(22, 16, 0, 30), R(1), "chamfer", 1)
    p["WH2_010"] = lambda: cut(box(70, 70, 3), cz(38.1, -5, 5), *holes(5, corners(47.14, 47.14)))
    p["WH2_011"] = lambda: tube(90, 82, 0, 150)
    p["WH2_012"] = lambda: cut(box(60, 40, 25), *holes(TAP[6], [(-20, 0), (20, 0)]))
    bot = 14 - 2 * 10 * tan(radians(19))
    groove = [(0, 0), (50, 0), (50, 8), (40, 15 - bot / 2), (40, 15 + bot / 2), (50, 22), (50, 30), (0, 30)]
    p["WH2_013"] = lambda: cut(revolve(groove), cz(25, -1, 31), span(0, 12.5 + 3.3, -4, 4, -1, 31))
    key = span(0, 2 * I, -0.09375 * I, 0.09375 * I, (0.375 - 0.09375) * I, I)
    p["WH2_014"] = lambda: cut(cx(0.75 * I, 0, 8 * I), key)
    p["WH2_015"] = lambda: cut(tube(2 * I, 1.5 * I, 0, I), cx(0.201 * I, 0, 2 * I, 0, 0.5 * I))
    p["WH2_016"] = lambda: hexbar(0.875 * I, 3 * I)
    p["WH2_017"] = lambda: cut(on_edges(cz(150, 0, 10), "%CIRCLE", "fillet", 2), cz(50, -1, 11))
    legs = [span(0, 60, 0, 40, 0, 5), span(0, 5, 0, 40, 0, 60)]
    bores = [cz(6.6, -1, 6, 20, 20), cz(6.6, -1, 6, 45, 20), cx(6.6, -1, 6, 20, 20), cx(6.6, -1, 6, 20, 45)]
    p["WH2_018"] = lambda: cut(fuse(*legs), *bores)
    r5 = 20 / (2 * sin(radians(36)))
    p["WH2_019"] = lambda: ngon(5, 2 * r5, 15)
    p["WH2_020"] = lambda: revolve([(0, 0), (30, 0), (15, 40), (0, 40)])
    arc = (30 * cos(pi / 4), 30 * sin(pi / 4))
    p["WH2_021"] = lambda: cq.Workplane("XY").lineTo(30, 0).threePointArc(arc, (0, 30)).close().extrude(100).val()
    p["WH2_022"] = lambda: cut(tube(25, 10, 0, 40), cx(TAP[4], 0, 20, 0, 10), cx(TAP[4], 0, 20, 0, 30))
    web = [cz(8.5, -1, 5, x, 20) for x in (20, 50, 80)]
    p["WH2_023"] = lambda: cut(span(0, 100, 0, 40, 0, 30), span(-1, 101, 4, 36, 4, 31), *web)
    p["WH2_024"] = lambda: cz(35, 0, 50)
    p["WH2_025"] = lambda: cut(hexbar(22, 60), cy(8, -20, 20, 0, 30))
    return p


def rack_program(module: float, pressure_deg: float, face: float, height: float, teeth: int) -> Shape:
    pitch = pi * module
    slope = tan(radians(pressure_deg))
    tip = pitch / 2 - 2 * module * slope
    root = pitch / 2 + 2.5 * module * slope
    base = height - 2.25 * module
    length = teeth * pitch
    pts = [(0.0, 0.0), (length, 0.0), (length, base)]
    for k in reversed(range(teeth)):
        c = (k + 0.5) * pitch
        pts += [(c + root / 2, base), (c + tip / 2, height), (c - tip / 2, height), (c - root / 2, base)]
    pts.append((0.0, base))
    return cq.Workplane("XZ").polyline(pts).close().extrude(face).val()


def measure(shape: Shape) -> tuple[list[float], float, int, bool]:
    """Tight extents, volume (OCCT's integration at a 1e-9 relative tolerance: the default
    is off by 1e-5 on holes meeting a bore), number of solids and validity."""
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps

    b = Bnd_Box()
    BRepBndLib.AddOptimal_s(shape.wrapped, b, False, False)
    x0, y0, z0, x1, y1, z1 = b.Get()
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape.wrapped, props, 1e-9, False)
    return [x1 - x0, y1 - y0, z1 - z0], float(props.Mass()), len(shape.Solids()), bool(shape.isValid())


def main(argv: list[str]) -> int:
    refs = heldout() | dev() | heldout2()
    progs = programs() | programs_v2()
    wanted = argv or sorted(refs)
    problems = 0
    worst_e = worst_v = 0.0
    for pid in wanted:
        if pid not in progs:
            print(f"{pid}: no CadQuery program")
            problems += 1
            continue
        try:
            size, vol, solids, valid = measure(progs[pid]())
        except Exception as e:  # a failing program is reported, never fatal to the others
            print(f"{pid}: the program failed: {type(e).__name__}: {e}")
            problems += 1
            continue
        ext, want = refs[pid]
        g, w = sorted(size), sorted(ext)
        de = max(abs(a - b) / b if abs(a - b) > EXTENT_SLACK else 0.0 for a, b in zip(g, w, strict=True))
        dv = abs(vol - want) / want
        worst_e, worst_v = max(worst_e, de), max(worst_v, dv)
        if solids != 1 or not valid or de > EXTENT_TOL or dv > VOLUME_TOL:
            print(
                f"{pid}: solids {solids} valid {valid} extents {[round(s, 3) for s in g]} vs {[round(s, 3) for s in w]}"
                f" volume {vol:.3f} vs {want:.3f} ({100 * dv:.3f} %)"
            )
            problems += 1
    print(
        f"cq_check: {len(wanted)} parts, largest difference extents {100 * worst_e:.4f} % volume {100 * worst_v:.4f} %,"
        f" {problems} problem(s)"
    )
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
