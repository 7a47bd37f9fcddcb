"""References for the session-6 dev rows of the wild part corpus (bench/cad/wild/dev6.tsv).

Two routes that never touch the project's feature language, and they must agree (the same
machinery as refs_h3.py): closed formulas written from the words, and a small hand-written
CadQuery program per part measured exactly. Conventions as README.md says (tapped holes at
the ISO coarse tap drill, flat-bottomed blind holes, angle legs outside to outside with sharp
corners, an inch is 25.4 mm, a polygonal bar lies on a flat); a number written with no unit
as a binary fraction ("5/8") or with no digit before its point (".500") is in inches.

    .cache/cad-venv/bin/python bench/cad/wild/refs_d6.py          # writes refs_d6.tsv
    .cache/cad-venv/bin/python bench/cad/wild/refs_d6.py --check  # compares with refs_d6.tsv
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from math import cos, pi

from refs_h3 import Ref, Shape, run

from refs import INCH, TAP, cyl, hexagon, tube

HERE = os.path.dirname(os.path.abspath(__file__))
SUITE = os.path.join(HERE, "dev6.tsv")
OUT = os.path.join(HERE, "refs_d6.tsv")
I = INCH  # noqa: E741 - an inch
HEADER = (
    "# Written by refs_d6.py (closed formulas, confirmed by CadQuery builds); do not edit by hand."
    " bbox_mm sorted descending. Session-6 dev rows (dev6.tsv).\n"
)


def formulas() -> dict[str, Ref]:
    t: dict[str, Ref] = {}
    t["WD6_01"] = ((40, 8, 8), cyl(8, 40) - 2 * cyl(TAP[4], 10))
    t["WD6_02"] = ((60, 12, 12), cyl(12, 60) - 2 * cyl(5, 12))
    t["WD6_03"] = ((80, 20, 20), 20 * 20 * 80 - cyl(6, 80))
    t["WD6_04"] = ((50, 19 / cos(pi / 6), 19), hexagon(19) * 50 - cyl(8, 50))
    t["WD6_05"] = ((0.75 * I, 0.625 * I, 0.625 * I), tube(0.625 * I, 0.375 * I, 0.75 * I))
    t["WD6_06"] = ((0.5 * I, 0.5 * I, 0.25 * I), tube(0.5 * I, 0.257 * I, 0.25 * I))
    t["WD6_07"] = ((30, 30, 16), cyl(30, 4) + cyl(20, 12) - cyl(10, 16))
    t["WD6_08"] = ((60, 60, 18), cyl(60, 8) + cyl(30, 10))
    t["WD6_09"] = ((60, 40, 25), (60 * 6 + 34 * 6) * 25)
    t["WD6_10"] = ((100, 70, 6), 100 * 70 / 2 * 6)
    t["WD6_11"] = ((150, 40, 40), (40 * 4 + 36 * 4) * 150)
    t["WD6_12"] = ((30, 30, 25), tube(30, 20, 25))
    return t


def builders() -> dict[str, Callable[[], Shape]]:
    import cadquery as cq

    def cz(d: float, z0: float, z1: float) -> Shape:
        return cq.Solid.makeCylinder(d / 2, z1 - z0, cq.Vector(0, 0, z0), cq.Vector(0, 0, 1))

    def box(x: float, y: float, z: float) -> Shape:
        return cq.Solid.makeBox(x, y, z, cq.Vector(-x / 2, -y / 2, 0))

    def prism(pts: list[tuple[float, float]], length: float) -> Shape:
        return cq.Workplane("XY").polyline(pts).close().extrude(length).val()

    def hex_bar(af: float, length: float) -> Shape:
        return cq.Workplane("XY").polygon(6, af / cos(pi / 6)).extrude(length).val()

    return {
        "WD6_01": lambda: cz(8, 0, 40).cut(cz(TAP[4], 0, 10)).cut(cz(TAP[4], 30, 40)),
        "WD6_02": lambda: cz(12, 0, 60).cut(cz(5, 0, 12)).cut(cz(5, 48, 60)),
        "WD6_03": lambda: box(20, 20, 80).cut(cz(6, 0, 80)),
        "WD6_04": lambda: hex_bar(19, 50).cut(cz(8, 0, 50)),
        "WD6_05": lambda: cz(0.625 * I, 0, 0.75 * I).cut(cz(0.375 * I, 0, 0.75 * I)),
        "WD6_06": lambda: cz(0.5 * I, 0, 0.25 * I).cut(cz(0.257 * I, 0, 0.25 * I)),
        "WD6_07": lambda: cz(20, 0, 12).fuse(cz(30, 12, 16)).cut(cz(10, 0, 16)),
        "WD6_08": lambda: cz(60, 0, 8).fuse(cz(30, 8, 18)),
        "WD6_09": lambda: prism([(0, 0), (60, 0), (60, 6), (6, 6), (6, 40), (0, 40)], 25),
        "WD6_10": lambda: prism([(0, 0), (100, 0), (0, 70)], 6),
        "WD6_11": lambda: prism([(0, 0), (40, 0), (40, 4), (4, 4), (4, 40), (0, 40)], 150),
        "WD6_12": lambda: cz(30, 0, 25).cut(cz(20, 0, 25)),
    }


def main(argv: list[str]) -> int:
    return run(argv, SUITE, OUT, HEADER, formulas, builders)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
