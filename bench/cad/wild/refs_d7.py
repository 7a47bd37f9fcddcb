"""References for the session-8 dev rows of the wild part corpus (bench/cad/wild/dev7.tsv).

Two routes that never touch the project's feature language, and they must agree (the same
machinery as refs_h3.py): closed formulas written from the words, and a small hand-written
CadQuery program per part measured exactly. Conventions as README.md says (tapped holes at
the ISO coarse tap drill, flat-bottomed blind holes, sections outside to outside with sharp
corners in the standard's order, an inch is 25.4 mm, a polygonal bar lies on a flat, a
straight-sided rack as refs.rack); "OD a / ID b" is a ring's two diameters; a set screw in a
collar is one radial tapped hole through one wall at mid-width; an L bracket "a x b x t
thick, w wide" has legs a and b outside.

    .cache/cad-venv/bin/python bench/cad/wild/refs_d7.py          # writes refs_d7.tsv
    .cache/cad-venv/bin/python bench/cad/wild/refs_d7.py --check  # compares with refs_d7.tsv
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from math import cos, pi, radians, tan

from refs_h3 import Ref, Shape, run

from refs import (
    INCH,
    TAP,
    across_corners,
    chamfer_outer,
    cone,
    cross_hole,
    cyl,
    hexagon,
    inch,
    rack,
    radial_hole,
    rounded_rect,
    segment,
    square_frustum,
    tube,
)

HERE = os.path.dirname(os.path.abspath(__file__))
SUITE = os.path.join(HERE, "dev7.tsv")
OUT = os.path.join(HERE, "refs_d7.tsv")
I = INCH  # noqa: E741 - an inch
HEADER = (
    "# Written by refs_d7.py (closed formulas, confirmed by CadQuery builds); do not edit by hand."
    " bbox_mm sorted descending. Session-8 dev rows (dev7.tsv).\n"
)
HEX_AF_30_AC = 30 * cos(pi / 6)  # a hexagon 30 across corners is this across flats


def formulas() -> dict[str, Ref]:
    t: dict[str, Ref] = {}
    t["WD7_01"] = ((50, 40, 30), (50 * 5 + 25 * 5) * 40)
    t["WD7_02"] = ((24, 24, 20), cyl(24, 3) + cyl(18, 17) - cyl(12, 20))
    t["WD7_03"] = ((140, 140, 12), tube(140, 60, 12) - 4 * cyl(14, 12))
    t["WD7_04"] = inch((3, 3, 0.375), tube(3, 1.05, 0.375))
    t["WD7_05"] = ((40, 40, 40), 40**3 - cyl(10, 40))
    t["WD7_06"] = ((80, 40, 10), 80 * 40 * 10 - 2 * cyl(TAP[6], 10))
    t["WD7_07"] = ((60, 40, 30), 60 * 40 * 30 - cyl(8, 15))
    t["WD7_08"] = ((200, 60, 40), (60 * 6 + 34 * 6) * 200)
    t["WD7_09"] = ((36, 36, 12), tube(36, 20, 12))
    t["WD7_10"] = ((25, across_corners(8), 8), hexagon(8) * 25 - cyl(TAP[4], 25))
    t["WD7_11"] = ((300, 50, 25), (50 * 3 + 2 * 22 * 3) * 300 - 5 * cyl(6.5, 3))
    t["WD7_12"] = ((80, 80, 8), 80 * 80 / 2 * 8)
    t["WD7_13"] = ((80, 80, 25), tube(80, 12, 25))
    t["WD7_14"] = rack(1.5, 20, 15, 15, 12)
    t["WD7_15"] = inch((6, 1.5, 1.5), 1.5 * 1.5 * 6)
    t["WD7_16"] = ((120, 120, 10), tube(120, 25, 10))
    t["WD7_17"] = ((60, 50, 50), cone(50, 60))
    t["WD7_18"] = ((40, 30, HEX_AF_30_AC), hexagon(HEX_AF_30_AC) * 40)
    t["WD7_19"] = ((15, 10, 10), tube(10, 5.3, 15))
    t["WD7_20"] = ((50, 50, 20), cyl(50, 20) - 2 * chamfer_outer(25, 1))
    t["WD7_21"] = ((150, 100, 12), rounded_rect(150, 100, 10) * 12 - 4 * cyl(10, 12))
    t["WD7_22"] = ((60, 30, 30), cyl(30, 60))
    t["WD7_23"] = ((100, 50, 20), 100 * 50 * 20 - 4 * cyl(8, 20))
    # The boss (axis 30 up, radius 25) dips 7 into the 12-thick base: that segment counts once.
    t["WD7_24"] = (
        (100, 55, 35),
        100 * 35 * 12 + cyl(50, 35) - segment(25, 7) * 35 - cyl(25, 35) - 2 * cyl(11, 12),
    )
    t["WD7_25"] = inch((4, 2.5, 0.5), 4 * 2.5 * 0.5)
    t["WD7_26"] = inch((1.5, 1.25, 1.25), tube(1.25, 0.75, 1.5))
    t["WD7_27"] = ((100, 25, 25), cyl(25, 100) - 2 * chamfer_outer(12.5, 1))
    t["WD7_28"] = ((60, 40, 40), cyl(40, 60) - cross_hole(6, 40))
    t["WD7_29"] = ((30, 30, 3), tube(30, 17, 3))
    t["WD7_30"] = ((100, 50, 50), (50 * 6 + 44 * 6) * 100)
    t["WD7_31"] = ((40, 40, 25), cyl(40, 5) + cyl(25, 20) - cyl(16, 25))
    t["WD7_32"] = ((50, 50, 25), 50 * 50 * 25 - cyl(20, 25))
    t["WD7_33"] = ((50, 50, 15), tube(50, 30, 15) - radial_hole(TAP[6], 15, 25))
    t["WD7_34"] = inch((10, 2, 2), tube(2, 1.75, 10))
    t["WD7_35"] = ((60, 60, 40), square_frustum(60, 30, 40))
    t["WD7_36"] = ((70, 50, 20), 70 * 50 * 20 - cyl(12, 8))
    return t


def builders() -> dict[str, Callable[[], Shape]]:
    import cadquery as cq

    def cz(d: float, z0: float, z1: float) -> Shape:
        return cq.Solid.makeCylinder(d / 2, z1 - z0, cq.Vector(0, 0, z0), cq.Vector(0, 0, 1))

    def cx(d: float, x0: float, x1: float, y: float = 0, z: float = 0) -> Shape:
        return cq.Solid.makeCylinder(d / 2, x1 - x0, cq.Vector(x0, y, z), cq.Vector(1, 0, 0))

    def cy(d: float, y0: float, y1: float, x: float = 0, z: float = 0) -> Shape:
        return cq.Solid.makeCylinder(d / 2, y1 - y0, cq.Vector(x, y0, z), cq.Vector(0, 1, 0))

    def box(x: float, y: float, z: float, z0: float = 0) -> Shape:
        return cq.Solid.makeBox(x, y, z, cq.Vector(-x / 2, -y / 2, z0))

    def prism(pts: list[tuple[float, float]], length: float) -> Shape:
        return cq.Workplane("XY").polyline(pts).close().extrude(length).val()

    def hex_bar(af: float, length: float) -> Shape:
        return cq.Workplane("XY").polygon(6, af / cos(pi / 6)).extrude(length).val()

    def holes(body: Shape, d: float, pts: list[tuple[float, float]], z0: float, z1: float) -> Shape:
        for x, y in pts:
            body = body.cut(cq.Solid.makeCylinder(d / 2, z1 - z0, cq.Vector(x, y, z0), cq.Vector(0, 0, 1)))
        return body

    def chamfered_disc(d: float, h: float, c: float) -> Shape:
        return cq.Workplane("XY").circle(d / 2).extrude(h).edges().chamfer(c).val()

    def rack_solid() -> Shape:
        m, face, height, teeth = 1.5, 15.0, 15.0, 12
        pitch, slope = pi * m, tan(radians(20))
        tip, root, depth = pitch / 2 - 2 * m * slope, pitch / 2 + 2 * 1.25 * m * slope, 2.25 * m
        base = height - depth
        pts: list[tuple[float, float]] = [(0, 0), (teeth * pitch, 0), (teeth * pitch, base)]
        for k in reversed(range(teeth)):
            c = (k + 0.5) * pitch
            pts += [(c + root / 2, base), (c + tip / 2, height), (c - tip / 2, height), (c - root / 2, base)]
        pts.append((0, base))
        return prism(pts, face)

    def pillow_block() -> Shape:
        base = box(100, 35, 12)
        boss = cy(50, -17.5, 17.5, 0, 30)
        body = base.fuse(boss).cut(cy(25, -17.5, 17.5, 0, 30))
        return holes(body, 11, [(-38, 0), (38, 0)], 0, 12)

    def collar_set_screw() -> Shape:
        ring = cz(50, 0, 15).cut(cz(30, 0, 15))
        return ring.cut(cx(TAP[6], 0, 30, 0, 7.5))

    def channel_with_holes() -> Shape:
        # The web lies in y 0..3; the holes cross it along y, 50 apart about mid-length.
        body = prism([(0, 0), (50, 0), (50, 25), (47, 25), (47, 3), (3, 3), (3, 25), (0, 25)], 300)
        for k in (-2, -1, 0, 1, 2):
            body = body.cut(cy(6.5, 0, 3, 25, 150 + k * 50))
        return body

    return {
        "WD7_01": lambda: prism([(0, 0), (50, 0), (50, 5), (5, 5), (5, 30), (0, 30)], 40),
        "WD7_02": lambda: cz(18, 0, 17).fuse(cz(24, 17, 20)).cut(cz(12, 0, 20)),
        "WD7_03": lambda: holes(cz(140, 0, 12).cut(cz(60, 0, 12)), 14, [(50, 0), (0, 50), (-50, 0), (0, -50)], 0, 12),
        "WD7_04": lambda: cz(3 * I, 0, 0.375 * I).cut(cz(1.05 * I, 0, 0.375 * I)),
        "WD7_05": lambda: box(40, 40, 40).cut(cz(10, 0, 40)),
        "WD7_06": lambda: holes(box(80, 40, 10), TAP[6], [(-20, 0), (20, 0)], 0, 10),
        "WD7_07": lambda: box(60, 40, 30).cut(cz(8, 15, 30)),
        "WD7_08": lambda: prism([(-30, 40), (30, 40), (30, 34), (3, 34), (3, 0), (-3, 0), (-3, 34), (-30, 34)], 200),
        "WD7_09": lambda: cz(36, 0, 12).cut(cz(20, 0, 12)),
        "WD7_10": lambda: hex_bar(8, 25).cut(cz(TAP[4], 0, 25)),
        "WD7_11": channel_with_holes,
        "WD7_12": lambda: prism([(0, 0), (80, 0), (0, 80)], 8),
        "WD7_13": lambda: cz(80, 0, 25).cut(cz(12, 0, 25)),
        "WD7_14": rack_solid,
        "WD7_15": lambda: box(1.5 * I, 1.5 * I, 6 * I),
        "WD7_16": lambda: cz(120, 0, 10).cut(cz(25, 0, 10)),
        "WD7_17": lambda: cq.Solid.makeCone(25, 0, 60),
        "WD7_18": lambda: hex_bar(HEX_AF_30_AC, 40),
        "WD7_19": lambda: cz(10, 0, 15).cut(cz(5.3, 0, 15)),
        "WD7_20": lambda: chamfered_disc(50, 20, 1),
        "WD7_21": lambda: holes(
            cq.Workplane("XY").box(150, 100, 12, centered=(True, True, False)).edges("|Z").fillet(10).val(),
            10,
            [(60, 35), (-60, 35), (60, -35), (-60, -35)],
            0,
            12,
        ),
        "WD7_22": lambda: cz(30, 0, 60),
        "WD7_23": lambda: holes(box(100, 50, 20), 8, [(40, 15), (-40, 15), (40, -15), (-40, -15)], 0, 20),
        "WD7_24": pillow_block,
        "WD7_25": lambda: box(4 * I, 2.5 * I, 0.5 * I),
        "WD7_26": lambda: cz(1.25 * I, 0, 1.5 * I).cut(cz(0.75 * I, 0, 1.5 * I)),
        "WD7_27": lambda: chamfered_disc(25, 100, 1),
        "WD7_28": lambda: cz(40, 0, 60).cut(cx(6, -20, 20, 0, 15)),
        "WD7_29": lambda: cz(30, 0, 3).cut(cz(17, 0, 3)),
        "WD7_30": lambda: prism([(0, 0), (50, 0), (50, 6), (6, 6), (6, 50), (0, 50)], 100),
        "WD7_31": lambda: cz(25, 0, 20).fuse(cz(40, 20, 25)).cut(cz(16, 0, 25)),
        "WD7_32": lambda: box(50, 50, 25).cut(cz(20, 0, 25)),
        "WD7_33": collar_set_screw,
        "WD7_34": lambda: cz(2 * I, 0, 10 * I).cut(cz(1.75 * I, 0, 10 * I)),
        "WD7_35": lambda: cq.Solid.makeLoft(
            [
                cq.Wire.makePolygon(
                    [cq.Vector(x * 30, y * 30, 0) for x, y in ((-1, -1), (1, -1), (1, 1), (-1, 1))], close=True
                ),
                cq.Wire.makePolygon(
                    [cq.Vector(x * 15, y * 15, 40) for x, y in ((-1, -1), (1, -1), (1, 1), (-1, 1))], close=True
                ),
            ],
            True,
        ),
        "WD7_36": lambda: box(70, 50, 20).cut(cz(12, 12, 20)),
    }


def main(argv: list[str]) -> int:
    return run(argv, SUITE, OUT, HEADER, formulas, builders)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
