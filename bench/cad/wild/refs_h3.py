"""References for v3 of the wild part corpus (bench/cad/wild/dev3.tsv; written as held-out v3,
retired to development on 2026-11-27 late night).

Every `make` row gets its bounding box and volume by two routes that never touch the project's
feature language, and they must agree:
- closed formulas written from the description's words (refs.py's functions and conventions:
  prisms and solids of revolution, Pappus for chamfers and V-grooves on circular edges, the
  frustum formula, a keyway's plan area in a bore);
- a small hand-written CadQuery program per part, measured exactly (OCCT's tight box and its
  volume integrated at a 1e-9 relative tolerance), one valid solid each.
The table written (refs_h3.tsv) holds the formulas' numbers; the run fails when the CadQuery
build disagrees (extents 0.1 % + 0.01 mm, volume 0.1 %), is not one valid solid, or when a
refusal row's `refuse_words` are not in its description.

Shorthand is read as README.md says: M<n> clearance is ISO 273 medium (M5 5.5), a tapped hole
is its ISO coarse tap drill (M4 3.3, M5 4.2, M6 5.0), blind holes are flat-bottomed, C x 45°
removes a right isosceles triangle of legs C, R<r> corners on a plate are its vertical edges,
PCD is a diameter, "n from edges" with 4 holes is at the corners, an inch is 25.4 mm, a
polygonal bar lies on a flat. An L bracket's legs are given outside; its corners are sharp.

Usage, from the checkout root (CadQuery venv; the formulas alone need only the standard library):
    .cache/cad-venv/bin/python bench/cad/wild/refs_h3.py          # builds both routes, writes refs_h3.tsv
    .cache/cad-venv/bin/python bench/cad/wild/refs_h3.py --check  # the same, and compares with refs_h3.tsv
"""

from __future__ import annotations

import csv
import os
import sys
from collections.abc import Callable
from math import cos, pi, radians, tan
from typing import Any

from refs import (
    CLEAR,
    INCH,
    TAP,
    chamfer_outer,
    cyl,
    disc,
    hexagon,
    keyway_in_bore,
    square_frustum,
    stadium,
    tube,
    v_groove,
)

HERE = os.path.dirname(os.path.abspath(__file__))
SUITE = os.path.join(HERE, "dev3.tsv")
OUT = os.path.join(HERE, "refs_h3.tsv")
I = INCH  # noqa: E741 - an inch, written the way the descriptions write it

Ref = tuple[tuple[float, float, float], float]
Shape = Any  # a CadQuery solid; cadquery ships no type information


# --- route 1: closed formulas ------------------------------------------------------------


def formulas() -> dict[str, Ref]:
    t: dict[str, Ref] = {}
    t["h3-01"] = ((25, 25, 18), tube(25, 12.5, 18))
    t["h3-02"] = ((120, 80, 10), (120 * 80 - (4 - pi) * 8 * 8) * 10 - 4 * cyl(9, 10))
    t["h3-03"] = ((140, 140, 16), tube(140, 60, 16) - 2 * chamfer_outer(70, 2) - 6 * cyl(11, 16))
    t["h3-04"] = ((60, 40, 25), 60 * 40 * 25 - cyl(6.6, 25) - (disc(11) - disc(6.6)) * 6.5)
    t["h3-05"] = ((1 * I, 1 * I, 7 / 16 * I), tube(1 * I, 0.5 * I, 7 / 16 * I))
    t["h3-06"] = ((25, 8 / cos(pi / 6), 8), hexagon(8) * 25 - cyl(TAP[4], 25))
    t["h3-07"] = ((0.5 * I, 0.375 * I, 0.375 * I), tube(0.375 * I, 0.191 * I, 0.5 * I))
    plate8 = (4 * I) * (6 * I) * (0.25 * I) - cyl(1 * I, 0.25 * I) - 4 * cyl(0.25 * I, 0.25 * I)
    t["h3-08"] = ((6 * I, 4 * I, 0.25 * I), plate8)
    t["h3-09"] = ((50, 50, 40), (50 * 5 + 45 * 5) * 40 - 2 * cyl(6.5, 5))
    t["h3-10"] = ((80, 60, 8), 80 * 60 / 2 * 8)
    t["h3-11"] = ((60, 60, 20), cyl(60, 20) - cyl(15, 20) - v_groove(30, 10, 8, 40))
    t["h3-12"] = ((40, 40, 15), tube(40, 20, 15) - 2 * chamfer_outer(20, 1))
    t["h3-13"] = ((150, 30, 6), 150 * 30 * 6 - 3 * cyl(8, 6))
    t["h3-14"] = ((200, 50, 25), (50 * 3 + 2 * 3 * 22) * 200 - 4 * cyl(6.6, 3))
    # four top edges chamfered 1 x 45°: the edge prisms less their overlaps at the corners (k³/3 each)
    t["h3-15"] = ((80, 50, 20), 80 * 50 * 20 - 2 * cyl(TAP[6], 20) - (1 * 1 / 2 * 2 * (80 + 50) - 4 * 1**3 / 3))
    t["h3-16"] = ((40, 40, 30), square_frustum(40, 20, 30))
    plate17 = (3 * I) ** 2 * (0.25 * I) - cyl(1.050 * I, 0.25 * I) - 4 * cyl(0.266 * I, 0.25 * I)
    t["h3-17"] = ((3 * I, 3 * I, 0.25 * I), plate17)
    bar18 = cyl(1.25 * I, 3 * I) - 2 * chamfer_outer(0.625 * I, I / 16)
    t["h3-18"] = ((3 * I, 1.25 * I, 1.25 * I), bar18)
    t["h3-19"] = ((30, 10, 10), cyl(10, 30) - 2 * cyl(TAP[5], 8))
    t["h3-20"] = ((40, 40, 25), cyl(40, 5) + cyl(25, 20) - cyl(16, 25))
    t["h3-21"] = ((100, 100, 4), cyl(100, 4) - cyl(30, 4) - 4 * cyl(5.5, 4))
    t["h3-22"] = ((60, 40, 30), (40 * 3 + 27 * 3) * 60 - 4 * cyl(CLEAR[5], 3))
    t["h3-23"] = ((100, 25, 25), 25 * 25 * 100 - cyl(10, 100))
    t["h3-24"] = ((100, 60, 8), 100 * 60 * 8 - stadium(30, 10) * 8 - 4 * cyl(6.6, 8))
    t["h3-25"] = ((50, 50, 12), cyl(50, 12) - (disc(20) + keyway_in_bore(10, 6, 2.8)) * 12)
    return t


# --- route 2: CadQuery -------------------------------------------------------------------


def builders() -> dict[str, Callable[[], Shape]]:
    import cadquery as cq

    def wp() -> Shape:
        return cq.Workplane("XY")

    def cz(d: float, z0: float, z1: float, x: float = 0, y: float = 0) -> Shape:
        return cq.Solid.makeCylinder(d / 2, z1 - z0, cq.Vector(x, y, z0), cq.Vector(0, 0, 1))

    def cx(d: float, x0: float, x1: float, y: float = 0, z: float = 0) -> Shape:
        return cq.Solid.makeCylinder(d / 2, x1 - x0, cq.Vector(x0, y, z), cq.Vector(1, 0, 0))

    def span(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float) -> Shape:
        return cq.Solid.makeBox(x1 - x0, y1 - y0, z1 - z0, cq.Vector(x0, y0, z0))

    def revolve(profile: list[tuple[float, float]]) -> Shape:
        """A closed (r, z) profile turned about Z."""
        return cq.Workplane("XZ").polyline(profile).close().revolve(360, (0, 0, 0), (0, 1, 0)).val()

    def cut(shape: Shape, *tools: Shape) -> Shape:
        for tool in tools:
            shape = shape.cut(tool)
        return shape

    def holes(d: float, pts: list[tuple[float, float]], z0: float, z1: float) -> list[Shape]:
        return [cz(d, z0, z1, x, y) for x, y in pts]

    def corners(a: float, b: float) -> list[tuple[float, float]]:
        return [(sx * a, sy * b) for sx in (-1, 1) for sy in (-1, 1)]

    def pcd(n: int, diameter: float) -> list[tuple[float, float]]:
        from math import sin

        return [(diameter / 2 * cos(2 * pi * k / n), diameter / 2 * sin(2 * pi * k / n)) for k in range(n)]

    def p01() -> Shape:
        return cut(cz(25, 0, 18), cz(12.5, 0, 18))

    def p02() -> Shape:
        plate = wp().box(120, 80, 10).edges("|Z").fillet(8).val()
        return cut(plate, *holes(9, corners(50, 30), -5, 5))

    def p03() -> Shape:
        body = revolve([(30, 0), (68, 0), (70, 2), (70, 14), (68, 16), (30, 16)])
        return cut(body, *holes(11, pcd(6, 110), 0, 16))

    def p04() -> Shape:
        return cut(span(-30, 30, -20, 20, 0, 25), cz(6.6, 0, 25), cz(11, 25 - 6.5, 25))

    def p05() -> Shape:
        return cut(cz(1 * I, 0, 7 / 16 * I), cz(0.5 * I, 0, 7 / 16 * I))

    def p06() -> Shape:
        hexbar = wp().polygon(6, 8 / cos(pi / 6)).extrude(25).val()
        return cut(hexbar, cz(TAP[4], 0, 25))

    def p07() -> Shape:
        return cut(cz(0.375 * I, 0, 0.5 * I), cz(0.191 * I, 0, 0.5 * I))

    def p08() -> Shape:
        plate = span(-3 * I, 3 * I, -2 * I, 2 * I, 0, 0.25 * I)
        return cut(plate, cz(1 * I, 0, 0.25 * I), *holes(0.25 * I, corners(2.5 * I, 1.5 * I), 0, 0.25 * I))

    def p09() -> Shape:
        bracket = span(0, 50, 0, 40, 0, 5).fuse(span(0, 5, 0, 40, 0, 50))
        return cut(bracket, cz(6.5, 0, 5, 27.5, 20), cx(6.5, 0, 5, 20, 27.5))

    def p10() -> Shape:
        return wp().polyline([(0, 0), (80, 0), (0, 60)]).close().extrude(8).val()

    def p11() -> Shape:
        bottom = 10 - 2 * 8 * tan(radians(20))
        return revolve(
            [(7.5, 0), (30, 0), (30, 5), (22, 10 - bottom / 2), (22, 10 + bottom / 2), (30, 15), (30, 20), (7.5, 20)]
        )

    def p12() -> Shape:
        return revolve([(10, 0), (19, 0), (20, 1), (20, 14), (19, 15), (10, 15)])

    def p13() -> Shape:
        return cut(span(-75, 75, -15, 15, 0, 6), *holes(8, [(-50, 0), (0, 0), (50, 0)], 0, 6))

    def p14() -> Shape:
        channel = span(0, 200, -25, 25, 0, 3).fuse(span(0, 200, -25, -22, 0, 25)).fuse(span(0, 200, 22, 25, 0, 25))
        return cut(channel, *holes(6.6, [(100 + x, 0) for x in (-60, -20, 20, 60)], 0, 3))

    def p15() -> Shape:
        blk = wp().box(80, 50, 20).faces(">Z").edges().chamfer(1).val()
        return cut(blk, *holes(TAP[6], [(-15, 0), (15, 0)], -10, 10))

    def p16() -> Shape:
        return wp().rect(40, 40).workplane(offset=30).rect(20, 20).loft().val()

    def p17() -> Shape:
        plate = span(-1.5 * I, 1.5 * I, -1.5 * I, 1.5 * I, 0, 0.25 * I)
        square = corners(1.125 * I, 1.125 * I)
        return cut(plate, cz(1.050 * I, 0, 0.25 * I), *holes(0.266 * I, square, 0, 0.25 * I))

    def p18() -> Shape:
        r, c, h = 0.625 * I, I / 16, 3 * I
        return revolve([(0, 0), (r - c, 0), (r, c), (r, h - c), (r - c, h), (0, h)])

    def p19() -> Shape:
        return cut(cz(10, 0, 30), cz(TAP[5], 0, 8), cz(TAP[5], 22, 30))

    def p20() -> Shape:
        return cut(cz(40, 20, 25).fuse(cz(25, 0, 20)), cz(16, 0, 25))

    def p21() -> Shape:
        return cut(cz(100, 0, 4), cz(30, 0, 4), *holes(5.5, pcd(4, 84), 0, 4))

    def p22() -> Shape:
        bracket = span(0, 40, 0, 60, 0, 3).fuse(span(0, 3, 0, 60, 0, 30))
        tools = [cz(CLEAR[5], 0, 3, 21.5, y) for y in (12, 48)]
        tools += [cx(CLEAR[5], 0, 3, y, 16.5) for y in (12, 48)]
        return cut(bracket, *tools)

    def p23() -> Shape:
        return cut(span(-12.5, 12.5, -12.5, 12.5, 0, 100), cz(10, 0, 100))

    def p24() -> Shape:
        slot = wp().slot2D(30, 10).extrude(8).val()
        return cut(span(-50, 50, -30, 30, 0, 8), slot, *holes(6.6, corners(42, 22), 0, 8))

    def p25() -> Shape:
        return cut(cz(50, 0, 12), cz(20, 0, 12), span(-3, 3, 0, 10 + 2.8, 0, 12))

    return {f"h3-{k:02d}": f for k, f in enumerate(
        [p01, p02, p03, p04, p05, p06, p07, p08, p09, p10, p11, p12, p13,
         p14, p15, p16, p17, p18, p19, p20, p21, p22, p23, p24, p25], 1)}  # fmt: skip


def measure(shape: Shape) -> tuple[list[float], float, int, bool]:
    """Tight extents, volume at a 1e-9 relative tolerance, number of solids, validity."""
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


# --- the table ---------------------------------------------------------------------------


def suite_rows(suite: str) -> list[dict[str, str]]:
    with open(suite, encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines, delimiter="\t", quoting=csv.QUOTE_NONE))


def table(
    suite: str, refs: dict[str, Ref], builds: dict[str, Callable[[], Shape]], cad: bool = True
) -> tuple[list[tuple[str, str, str]], list[str]]:
    """Both routes for every row of a suite: (id, bbox, volume) and the problems found."""
    out: list[tuple[str, str, str]] = []
    problems: list[str] = []
    seen: set[str] = set()
    for row in suite_rows(suite):
        pid = row["id"]
        seen.add(pid)
        if row["expected"] == "refuse":
            if pid in refs or pid in builds:
                problems.append(f"{pid}: expected refuse but has a reference")
            if not row["refuse_words"] or row["refuse_words"] not in row["description"]:
                problems.append(f"{pid}: refuse_words must quote the description")
            out.append((pid, "refuse", "refuse"))
            continue
        if pid not in refs:
            problems.append(f"{pid}: no reference")
            continue
        ext, vol = refs[pid]
        if vol <= 0 or min(ext) <= 0:
            problems.append(f"{pid}: non-positive reference")
        if cad:
            if pid not in builds:
                problems.append(f"{pid}: no CadQuery build")
            else:
                got_ext, got_vol, solids, valid = measure(builds[pid]())
                want = sorted(ext, reverse=True)
                got = sorted(got_ext, reverse=True)
                if solids != 1 or not valid:
                    problems.append(f"{pid}: CadQuery build is {solids} solids, valid={valid}")
                if any(abs(g - w) > 1e-3 * w + 0.01 for g, w in zip(got, want, strict=True)):
                    problems.append(f"{pid}: extents formula {want} CadQuery {[round(g, 4) for g in got]}")
                if abs(got_vol - vol) > 1e-3 * vol:
                    problems.append(f"{pid}: volume formula {vol:.3f} CadQuery {got_vol:.3f}")
        box = ",".join(f"{v:.4f}" for v in sorted(ext, reverse=True))
        out.append((pid, box, f"{vol:.3f}"))
    problems += [f"{pid}: reference for an id the suite lacks" for pid in refs if pid not in seen]
    return out, problems


HEADER = (
    "# Written by refs_h3.py (closed formulas, confirmed by CadQuery builds); do not edit by hand."
    " bbox_mm sorted descending. v3 (dev3.tsv, was heldout3.tsv).\n"
)


def render(rows: list[tuple[str, str, str]], header: str = HEADER) -> str:
    lines = [header, "id\tbbox_mm\tvolume_mm3\n"]
    lines += [f"{pid}\t{box}\t{vol}\n" for pid, box, vol in rows]
    return "".join(lines)


def run(
    argv: list[str],
    suite: str,
    out: str,
    header: str,
    formulas_of: Callable[[], dict[str, Ref]],
    builders_of: Callable[[], dict[str, Callable[[], Shape]]],
) -> int:
    """Writes (or with --check compares) a suite's reference table from both routes."""
    cad = "--no-cad" not in argv
    name = os.path.basename(out)
    rows, problems = table(suite, formulas_of(), builders_of() if cad else {}, cad)
    if problems:
        print(f"{name}: " + "; ".join(problems), file=sys.stderr)
        return 1
    text = render(rows, header)
    if "--check" in argv:
        try:
            with open(out, encoding="utf-8") as f:
                stored = f.read()
        except FileNotFoundError:
            print(f"--check: {name} is missing; write it first", file=sys.stderr)
            return 1
        if stored != text:
            print(f"--check: {name} differs from the formulas", file=sys.stderr)
            return 1
        print(f"{name} matches the formulas and the CadQuery builds ({len(rows)} rows)")
        return 0
    with open(out, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"wrote {out} ({len(rows)} rows; formulas and CadQuery agree)")
    return 0


def main(argv: list[str]) -> int:
    return run(argv, SUITE, OUT, HEADER, formulas, builders)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
