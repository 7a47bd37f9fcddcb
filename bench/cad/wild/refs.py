"""Independent references for the wild part corpus (bench/cad/wild/dev.tsv, heldout.tsv and heldout2.tsv).

Every part a description asks for gets its bounding box and volume here, worked out by hand
from the description's words as closed formulas: prisms and solids of revolution, Pappus for
edge chamfers, fillets and grooves, circle strips and segments for flats, keyways and slits,
and one-dimensional integrals (Simpson) for holes crossing curved walls. Nothing here reads,
imports or runs the project's feature language; cq_check.py builds a subset of the parts
again in CadQuery as a third route.

Shorthand conventions (README.md says why):
- a metric clearance hole "M<n> clearance" / "M<n> clr" is ISO 273 medium series (M6 -> 6.6);
- a tapped hole is modelled at its ISO coarse tap drill (M6 -> 5.0), flat-bottomed;
- a blind hole is flat-bottomed (no drill point) unless a point is stated;
- a keyway's depth in a bore is measured from the bore's surface on the keyway's centreline
  (DIN 6885 t2); on a shaft, from the shaft's surface on its centreline (t1);
- a chamfer "C x 45°" removes a right isosceles triangle of legs C along the edge;
- an inch is 25.4 mm; 16 SWG is 0.064 in;
- a polygonal bar lies on a flat: its extents are across flats by across corners (a hexagon)
  or across flats both ways (an octagon).

Usage, from the checkout root:
    .cache/cad-venv/bin/python bench/cad/wild/refs.py          # writes refs.tsv
    .cache/cad-venv/bin/python bench/cad/wild/refs.py --check  # recomputes and compares
(any Python 3.11 does: only the standard library is used).
"""

from __future__ import annotations

import csv
import os
import sys
from collections.abc import Callable
from math import acos, asin, cos, pi, radians, sin, sqrt, tan

HERE = os.path.dirname(os.path.abspath(__file__))
SUITES = ("heldout.tsv", "dev.tsv", "heldout2.tsv")
OUT = os.path.join(HERE, "refs.tsv")

INCH = 25.4
SWG16 = 0.064 * INCH
# ISO 273 clearance holes, medium series.
CLEAR = {3: 3.4, 4: 4.5, 5: 5.5, 6: 6.6, 8: 9.0, 10: 11.0, 12: 13.5, 16: 17.5, 20: 22.0}
# ISO coarse threads, tap drill = nominal - pitch.
TAP = {3: 2.5, 4: 3.3, 5: 4.2, 6: 5.0, 8: 6.8, 10: 8.5, 12: 10.2, 16: 14.0}

Ref = tuple[tuple[float, float, float], float]


# --- plane areas -------------------------------------------------------------------------


def disc(d: float) -> float:
    return pi * d * d / 4


def hexagon(af: float) -> float:
    """A regular hexagon given across flats."""
    return sqrt(3) / 2 * af * af


def across_corners(af: float, n: int = 6) -> float:
    return af / cos(pi / n)


def ngon_af(n: int, af: float) -> float:
    """A regular n-gon given across flats (twice its inradius)."""
    return n * (af / 2) ** 2 * tan(pi / n)


def ngon_ac(n: int, ac: float) -> float:
    """A regular n-gon given across corners (twice its circumradius)."""
    return n / 2 * (ac / 2) ** 2 * sin(2 * pi / n)


def strip(r: float, h: float) -> float:
    """The part of a circle of radius r with |y| <= h."""
    h = min(h, r)
    return 2 * (h * sqrt(r * r - h * h) + r * r * asin(h / r))


def segment(r: float, depth: float) -> float:
    """A circle segment of the given depth (sagitta): what a flat that deep takes away."""
    d = r - depth
    return r * r * acos(d / r) - d * sqrt(r * r - d * d)


def rounded_rect(a: float, b: float, r: float) -> float:
    return a * b - (4 - pi) * r * r


def keyway_in_bore(r: float, width: float, depth: float) -> float:
    """The plan area of a keyway cut from a bore of radius r, depth from the bore surface on
    the keyway's centreline."""
    return width * (r + depth) - strip(r, width / 2) / 2


def keyway_on_shaft(r: float, width: float, depth: float) -> float:
    """The section of a flat-bottomed keyway in a shaft of radius r."""
    return strip(r, width / 2) / 2 - width * (r - depth)


def stadium(length: float, width: float) -> float:
    """A slot or link outline: `length` overall, `width` across, fully rounded ends."""
    return (length - width) * width + disc(width)


# --- solids ------------------------------------------------------------------------------


def cyl(d: float, h: float) -> float:
    return disc(d) * h


def tube(od: float, id_: float, h: float) -> float:
    return (disc(od) - disc(id_)) * h


def cone(d: float, h: float) -> float:
    return disc(d) * h / 3


def sphere(d: float) -> float:
    return pi * d**3 / 6


def torus(major: float, minor: float) -> float:
    return 2 * pi * pi * major * minor * minor


def square_frustum(a: float, b: float, h: float) -> float:
    """A frustum of a square pyramid, a square below and b square above."""
    return h / 3 * (a * a + b * b + a * b)


def steiner(a: float, b: float, c: float, r: float) -> float:
    """A box with all twelve edges filleted r (Steiner's formula for the parallel body)."""
    p, q, t = a - 2 * r, b - 2 * r, c - 2 * r
    return p * q * t + 2 * r * (p * q + q * t + p * t) + pi * r * r * (p + q + t) + 4 / 3 * pi * r**3


def box_chamfer(a: float, b: float, c: float, k: float) -> float:
    """A box with all twelve edges chamfered k x 45°, the three chamfer planes meeting in a
    point at each corner: the edge prisms (k²/2 per unit length) less their pairwise overlaps
    at the corners (k³/3 each, three per corner) plus the triple overlap (k³/4 per corner).
    (OCCT closes each corner with a small triangular face instead, k³/12 more per corner.)"""
    return a * b * c - 2 * k * k * (a + b + c) + 8 * (k**3 - k**3 / 4)


def end_edge_chamfers(side: float, k: float) -> float:
    """What a k x 45° chamfer on the four edges of both square ends of a square bar removes."""
    return 8 * (k * k / 2 * side) - 8 * k**3 / 3


# --- Pappus: rings cut from circular edges -----------------------------------------------


def chamfer_outer(r: float, c: float) -> float:
    """A C x 45° chamfer on one circular outside edge of radius r."""
    return 2 * pi * (r - c / 3) * c * c / 2


def chamfer_bore(r: float, c: float) -> float:
    """A C x 45° chamfer on one edge of a bore of radius r."""
    return 2 * pi * (r + c / 3) * c * c / 2


def fillet_outer(r: float, f: float) -> float:
    """A fillet of radius f on one circular outside edge of radius r."""
    area = f * f * (1 - pi / 4)
    offset = f * (5 / 6 - pi / 4) / (1 - pi / 4)
    return 2 * pi * (r - offset) * area


def v_groove(r_out: float, top: float, depth: float, angle_deg: float) -> float:
    """A symmetric V groove of included angle `angle_deg`, `top` wide at radius r_out."""
    bottom = top - 2 * depth * tan(radians(angle_deg / 2))
    area = (top + bottom) / 2 * depth
    from_top = depth * (top + 2 * bottom) / (3 * (top + bottom))
    return 2 * pi * (r_out - from_top) * area


# --- holes crossing curved walls ---------------------------------------------------------


def simpson(f: Callable[[float], float], lo: float, hi: float, n: int = 2000) -> float:
    step = (hi - lo) / n
    total = f(lo) + f(hi)
    for i in range(1, n):
        total += (4 if i % 2 else 2) * f(lo + i * step)
    return total * step / 3


def across_disc(a: float, g: Callable[[float], float]) -> float:
    """The integral over a disc of radius a of g(y) dx dy, i.e. the integral of
    2 sqrt(a² - y²) g(y) over -a..a, taken with y = a sin t so that the integrand is smooth."""
    return simpson(lambda t: 2 * a * a * cos(t) ** 2 * g(a * sin(t)), -pi / 2, pi / 2)


def cross_hole(d: float, shaft: float) -> float:
    """A hole of diameter d drilled right across a round shaft through its axis: over the
    hole's section, the chord of the shaft (the shaft's axis along the section's x)."""
    r = shaft / 2
    return across_disc(d / 2, lambda y: 2 * sqrt(r * r - y * y))


def radial_hole(d: float, r_in: float, r_out: float) -> float:
    """A radial hole of diameter d through one wall, from the bore r_in to the outside r_out."""
    return across_disc(d / 2, lambda y: sqrt(r_out * r_out - y * y) - sqrt(r_in * r_in - y * y))


def equal_tee(od: float, wall: float, run: float, reach: float) -> float:
    """An equal pipe tee: the run, and a branch from the run's axis out to `reach`, bores
    open into each other. A branch cylinder of radius R inside a run of the same radius is
    half a Steinmetz bicylinder, 8R³/3."""
    big, small = od / 2, od / 2 - wall
    solid = pi * big * big * (run + reach) - 8 * big**3 / 3
    bore = pi * small * small * (run + reach) - 8 * small**3 / 3
    return solid - bore


def inch(ext: tuple[float, float, float], vol_in3: float) -> Ref:
    e = (ext[0] * INCH, ext[1] * INCH, ext[2] * INCH)
    return e, vol_in3 * INCH**3


# --- the parts ---------------------------------------------------------------------------


def heldout() -> dict[str, Ref]:
    t: dict[str, Ref] = {}
    t["WH_001"] = ((75, 38, 38), tube(38, 30, 75))
    t["WH_002"] = ((60, 16, 16), cyl(16, 60) - 2 * chamfer_outer(8, 1))
    t["WH_003"] = ((120, 80, 8), 120 * 80 * 8 - 4 * cyl(9, 8))
    t["WH_004"] = ((110, 110, 14), tube(110, 50, 14) - 6 * cyl(11, 14) - 2 * chamfer_outer(55, 1))
    t["WH_005"] = ((25, 25, 12), tube(25, 10.5, 12))
    t["WH_006"] = ((80, 50, 30), 80 * 50 * 30 - cyl(22, 50) - 2 * cyl(8.5, 30))
    t["WH_007"] = ((24, 24, 2.5), tube(24, 13, 2.5))
    t["WH_008"] = ((25, across_corners(7), 7), hexagon(7) * 25 - cyl(TAP[4], 25))
    t["WH_009"] = ((36, 36, 14), tube(36, 20, 14) - radial_hole(TAP[6], 10, 18))
    t["WH_010"] = ((76, 76, 22), 76 * 76 * 12 + cyl(50, 10) - cyl(30, 22) - 4 * cyl(CLEAR[10], 12))
    t["WH_011"] = ((150, 25, 25), 25 * 25 * 150)
    t["WH_012"] = ((15, 8, 8), cyl(8, 15) - cyl(TAP[3], 15))
    t["WH_013"] = ((40, 40, 25), tube(30, 20, 22) + tube(40, 20, 3))
    t["WH_014"] = ((60, 60, 8), tube(60, 50, 8))
    t["WH_015"] = ((40, 40, 40), 40**3 - cyl(20, 40))
    t["WH_016"] = ((100, 100, 6), 100 * 100 * 6 - cyl(38.1, 6) - 4 * cyl(CLEAR[5], 6) - 4 * cyl(CLEAR[6], 6))
    t["WH_017"] = ((50, 50, 20), cyl(50, 20) - cyl(44, 17))
    # The arm: both bosses, the 12 wide web between the centres less the parts of it inside
    # the bosses (half a circle strip each), less the bores.
    arm = disc(30) + disc(20) + 12 * 80 - strip(15, 6) / 2 - strip(10, 6) / 2 - disc(12) - disc(8)
    t["WH_018"] = ((105, 30, 10), arm * 10)
    t["WH_019"] = ((40, 40, 12), cyl(40, 12) - cyl(8, 12) - 3 * cyl(CLEAR[5], 12))
    t["WH_020"] = ((150, 25, 25), 25 * 25 * 150 - 4 * (1 - pi / 4) * 3 * 3 * 150)
    t["WH_021"] = ((60, 40, 20), 60 * 40 * 20 - 4 * cyl(CLEAR[6], 20))
    hub = cyl(60, 20) - cyl(20, 20) - keyway_in_bore(10, 6, 2.8) * 20 - 4 * cyl(TAP[6], 12)
    t["WH_022"] = ((60, 60, 20), hub)
    t["WH_023"] = ((80, 25, 25), cyl(25, 80) - 2 * chamfer_outer(12.5, 1) - keyway_on_shaft(12.5, 8, 4) * 40)
    t["WH_024"] = ((50, across_corners(24), 24), hexagon(24) * 50)
    t["WH_025"] = inch((3, 2, 0.25), 2 * 3 * 0.25 - 4 * cyl(0.25, 0.25))
    t["WH_026"] = inch((6, 1.5, 1.5), tube(1.5, 1.25, 6))
    t["WH_027"] = inch((6, 2, 0.5), 0.5 * 2 * 6 - 2 * cyl(0.375, 0.5))
    t["WH_028"] = inch((0.75, 0.75, 0.75), sphere(0.75))
    t["WH_029"] = inch((6, 6, 0.875), tube(6, 2.38, 0.875) - 4 * cyl(0.75, 0.875))
    t["WH_030"] = inch((4, 1, 1), cyl(1, 4) - 2 * chamfer_outer(0.5, 1 / 16))
    t["WH_031"] = ((100, 30, 27), (disc(30) - segment(15, 3)) * 100)
    t["WH_032"] = ((200, 40, 40), (40 * 5 + 35 * 5) * 200)
    t["WH_033"] = ((60, 40, 20), 60 * 40 * 20 - cyl(12, 20))
    t["WH_034"] = ((80, 80, 10), tube(80, 25, 10) - 2 * chamfer_bore(12.5, 1))
    t["WH_035"] = ((150, 100, 10), 150 * 100 * 10 - cyl(40, 10) - 4 * cyl(9, 10))
    t["WH_036"] = ((50, 50, 30), cyl(30, 20) + cyl(50, 10) - cyl(10, 30))
    t["WH_037"] = ((40, 40, 30), square_frustum(40, 20, 30))
    t["WH_038"] = ((72, 72, 12), torus(30, 6))
    t["WH_039"] = ((40, 30, 15), 30 * 40 / 2 * 15)
    t["WH_040"] = ((60, 50, 50), cone(50, 60))
    t["WH_041"] = ((50, 50, 40), 50 * 50 * 40 / 3)
    t["WH_042"] = ((250, 40, 40), (40 * 40 - 34 * 34) * 250)
    t["WH_043"] = ((80, 80, 20), tube(80, 15, 20) - v_groove(40, 10, 8, 40))
    t["WH_044"] = ((80, 60, 6), 80 * 60 / 2 * 6 - 2 * cyl(8.5, 6))
    # The clevis: the block less the slot (16 x 30 x 35) less the cross hole through the two
    # 12 thick cheeks.
    t["WH_045"] = ((50, 40, 30), 40 * 30 * 50 - 16 * 30 * 35 - cyl(10, 2 * 12))
    t["WH_046"] = ((60, 42.5, 25), equal_tee(25, 2, 60, 30))
    t["WH_047"] = ((across_corners(17), 17, 8), hexagon(17) * 8 - cyl(TAP[10], 8))
    t["WH_048"] = ((300, 50, 25), (50 * 3 + 2 * 22 * 3) * 300 - 5 * cyl(CLEAR[6], 3))
    t["WH_049"] = ((40, 25, 25), cyl(25, 40) - cyl(8, 20) - cyl(0.25 * INCH, 20))
    t["WH_050"] = ((50, 50, 50), 50.0**3)
    t["WH_051"] = ((200, 60, 60), tube(60, 50, 200))
    t["WH_052"] = ((100, 60, 5), 100 * 60 * 5 - cyl(10, 5))
    t["WH_053"] = ((40, 40, 20), cyl(40, 20))
    t["WH_054"] = ((50, 40, 30), (50 * 4 + 36 * 4) * 30 - 2 * cyl(CLEAR[6], 4))
    return t


def dev() -> dict[str, Ref]:
    t: dict[str, Ref] = {}
    t["WD_001"] = ((100, 50, 50), tube(50, 40, 100))
    t["WD_002"] = ((50, 20, 20), cyl(20, 50) - 2 * chamfer_outer(10, 1))
    t["WD_003"] = ((120, 42, 42), tube(42, 36, 120))
    t["WD_004"] = ((150, 100, 10), 150 * 100 * 10 - 4 * cyl(11, 10))
    t["WD_005"] = ((80, 80, 30), cyl(50, 22) + cyl(80, 8) - cyl(20, 30) - 4 * cyl(CLEAR[6], 8))
    t["WD_006"] = ((60, 40, 40), 40 * 40 * 60 - cyl(16, 25))
    t["WD_007"] = ((100, 100, 6), tube(100, 40, 6) - 2 * fillet_outer(50, 2))
    t["WD_008"] = ((80, 60, 50), 80 * 50 * 6 + 80 * 6 * 54 - 4 * cyl(9, 6))
    t["WD_009"] = ((120, 30, 30), cyl(30, 120) - 2 * chamfer_outer(15, 1) - cross_hole(10, 30))
    t["WD_010"] = ((30, 30, 3), tube(30, 13, 3))
    t["WD_011"] = ((100, 20, 20), box_chamfer(20, 20, 100, 1))
    t["WD_012"] = ((200, 120, 5), rounded_rect(200, 120, 10) * 5 - 6 * cyl(5.5, 5))
    t["WD_013"] = ((16, 16, 1.6), tube(16, 8.4, 1.6))
    t["WD_014"] = ((across_corners(13), 13, 6.8), hexagon(13) * 6.8 - cyl(TAP[8], 6.8))
    t["WD_015"] = ((25, 25, 10), tube(25, 12, 10) - radial_hole(TAP[5], 6, 12.5))
    t["WD_016"] = ((10, 10, 8), tube(10, 5.3, 8))
    t["WD_017"] = ((30, across_corners(5.5), 5.5), hexagon(5.5) * 30 - cyl(TAP[3], 30))
    # The pillow block: base, plus the boss less the segment of it inside the base (its
    # centre 17.3 above the base's top, so a segment 12.7 deep), less the bore and bolt holes.
    boss = (disc(60) - segment(30, 30 - (33.3 - 16))) * 38
    t["WD_018"] = ((127, 63.3, 38), 127 * 38 * 16 + boss - cyl(40, 38) - 2 * cyl(14, 16))
    t["WD_019"] = ((300, 50, 10), 50 * 10 * 300)
    t["WD_020"] = ((500, INCH, INCH), tube(INCH, INCH - 2 * SWG16, 500))
    t["WD_021"] = ((90, 90, 40), cyl(90, 14) + cyl(45, 26) - cyl(25, 40) - 4 * cyl(CLEAR[8], 14))
    t["WD_022"] = ((50, 12, 12), cyl(12, 50) - cross_hole(4, 12))
    t["WD_023"] = ((1000, 50, 50), (50 * 6 + 44 * 6) * 1000)
    t["WD_024"] = ((42.3, 42.3, 5), 42.3 * 42.3 * 5 - cyl(22, 5) - 4 * cyl(CLEAR[3], 5))
    t["WD_025"] = ((70, 50, 50), tube(50, 45, 70))
    t["WD_026"] = ((60, 60, 60), steiner(60, 60, 60, 5))
    t["WD_027"] = ((30, 30, 15), cyl(30, 15) - cyl(6, 10))
    t["WD_028"] = ((120, 20, 8), (stadium(120, 20) - 2 * disc(8) - disc(6)) * 8)
    t["WD_029"] = ((100, across_corners(20), 20), hexagon(20) * 100 - cyl(10, 100))
    t["WD_030"] = ((170, 120, 120), cyl(120, 20) + cyl(30, 150) - cyl(10, 170))
    t["WD_031"] = ((25, 25, 25), sphere(25))
    t["WD_032"] = ((80, 60, 40), 80 * 60 * 40 - 76 * 56 * 38)
    t["WD_033"] = ((700, 40, 40), square_frustum(40, 25, 700) - cyl(TAP[8], 20))
    t["WD_034"] = ((100, 100, 3), tube(100, 60, 3) - 8 * cyl(9, 3))
    t["WD_035"] = ((80, 50, 10), 80 * 50 * 10 - 30 * 20 * 10)
    t["WD_036"] = ((60, 60, 30), sphere(60) / 2)
    t["WD_037"] = ((30, 30, 12), tube(30, 10, 12) - 2 * chamfer_outer(15, 1))
    t["WD_038"] = ((100, 50, 10), rounded_rect(100, 50, 5) * 10 - 2 * cyl(8, 10))
    boss = tube(50, 25, 25) - (disc(35) - disc(25)) * 5 - 3 * cyl(TAP[4], 8)
    t["WD_039"] = ((50, 50, 25), boss)
    t["WD_040"] = ((80, 30, 30), 30 * 30 * 80 - cyl(12, 20) - end_edge_chamfers(30, 0.5))
    t["WD_041"] = ((200, 40, 40), cyl(40, 200))
    t["WD_042"] = ((60, 20, 20), cyl(20, 60) - cross_hole(5, 20) - 2 * chamfer_outer(10, 0.5))
    blk = 100 * 60 * 25 - 60 * 30 * 10 - 4 * cyl(CLEAR[6], 25) - 2 * cyl(8, 12)
    t["WD_043"] = ((100, 60, 25), blk)
    t["WD_044"] = ((100, 100, 8), cyl(100, 8) - 6 * cyl(8.5, 8))
    t["WD_045"] = ((30, across_corners(17), 17), hexagon(17) * 30)
    t["WD_046"] = ((100, 16, 16), cyl(16, 100) - segment(8, 2) * 30)
    cbores = 4 * (cyl(9, 12) + (disc(15) - disc(9)) * 9)
    t["WD_047"] = ((80, 80, 12), 80 * 80 * 12 - cyl(30, 12) - cbores)
    blank = tube(60, 20, 40) - keyway_in_bore(10, 6, 2.8) * 40 - 2 * radial_hole(TAP[6], 10, 30)
    t["WD_048"] = ((60, 60, 40), blank)
    t["WD_049"] = inch((4, 2, 1), 4 * 2 * 1)
    t["WD_050"] = inch((6, 4, 0.75), 6 * 4 * 0.75 - cyl(1, 0.75))
    t["WD_051"] = inch((3, 2, 2), cyl(2, 3))
    t["WD_052"] = inch((0.625, 0.625, 0.5), tube(0.625, 0.375, 0.5))
    t["WD_053"] = inch((3, 3, 0.5), 3 * 3 * 0.5 - 4 * cyl(0.5, 0.5))
    t["WD_054"] = inch((2.5, 1.5, 1), 2.5 * 1.5 * 1 - cyl(0.75, 1.5) - 2 * cyl(0.201, 1))
    t["WD_055"] = inch((12, 1, 1), tube(1, 1 - 2 * 0.065, 12))
    t["WD_056"] = inch((1.5, 1.5, 1.5), sphere(1.5))
    t["WD_057"] = inch((4, 4, 0.5), cyl(4, 0.5) - 6 * cyl(0.375, 0.5))
    t["WD_058"] = inch((3, 2, 2), (3 * 0.25 + 1.75 * 0.25) * 2 - 2 * cyl(0.375, 0.25))
    t["WD_059"] = inch((5, 1, 1), box_chamfer(1, 1, 5, 0.125))
    t["WD_060"] = inch((2, 1.25, 1.25), cyl(1.25, 2) - cross_hole(0.25, 1.25))
    t["WD_061"] = ((250, 60, 40), (60 * 6 + 34 * 6) * 250)
    t["WD_062"] = ((80, 50, 40), (disc(50) - 2 * segment(25, 5)) * 80)
    t["WD_063"] = ((across_corners(40), 40, 20), hexagon(40) * 20 - cyl(22, 20))
    t["WD_064"] = ((100, 20, 20), 20 * 20 * 100 - 2 * cyl(6, 20))
    t["WD_065"] = ((80, 50, 40), 80 * 40 * 50 - cyl(30, 40) - 2 * cyl(9, 50))
    t["WD_066"] = ((60, 60, 8), tube(60, 20, 8) - 2 * fillet_outer(30, 2))
    t["WD_067"] = ((500, 48.3, 48.3), tube(48.3, 48.3 - 2 * 3.2, 500))
    t["WD_068"] = ((60, 60, 60), 60.0**3 - cyl(16, 60) - (disc(30) - disc(16)) * 10)
    t["WD_069"] = ((200, 150, 12), rounded_rect(200, 150, 15) * 12 - cyl(60, 12) - 4 * cyl(14, 12))
    t["WD_070"] = ((100, 30, 6), 100 * 30 * 6 - stadium(40, 10) * 6)
    t["WD_071"] = ((45, 45, 45), sphere(45))
    t["WD_072"] = ((150, 150, 10), tube(150, 50, 10) - 2 * chamfer_outer(75, 2))
    t["WD_073"] = ((60, 60, 45), square_frustum(60, 30, 45))
    t["WD_074"] = ((100, 100, 20), torus(40, 10))
    t["WD_075"] = ((50, 30, 20), 50 * 20 / 2 * 30)
    t["WD_076"] = ((80, 80, 40), cone(80, 40))
    t["WD_077"] = ((50, 40, 40), cone(40, 50))
    t["WD_078"] = ((60, 40, 30), 60 * 40 * 30 / 3)
    t["WD_079"] = ((30, 30 * cos(pi / 6), 20), ngon_ac(6, 30) * 20)
    t["WD_080"] = ((100, 40, 40 * sqrt(3) / 2), sqrt(3) / 4 * 40 * 40 * 100)
    t["WD_081"] = ((50, 50, 50), sphere(50) - sphere(42))
    t["WD_082"] = ((300, 16, 16), 16 * 16 * 300)
    t["WD_083"] = ((60, 30, 30), ngon_af(8, 30) * 60)
    t["WD_084"] = ((200, 60, 40), (60 * 40 - 54 * 34) * 200)
    t["WD_085"] = ((100, 100, 50), cyl(100, 40) + cyl(40, 10) - cyl(20, 50))
    t["WD_086"] = rack(module=2.0, pressure_deg=20.0, face=20.0, height=20.0, teeth=10)
    t["WD_087"] = ((100, 100, 8), (100 * 100 / 2 - 15 * 15 / 2) * 8)
    t["WD_088"] = ((80, 48, 40), 80 * 40 * 8 + 2 * 8 * 40 * 40 - 2 * cyl(9, 8) - 2 * cyl(12, 8))
    t["WD_089"] = ((across_corners(24), 24, 13), hexagon(24) * 13 - cyl(TAP[16], 13))
    t["WD_090"] = ((25, 10, 10), cyl(10, 25) - cyl(TAP[5], 25))
    t["WD_091"] = ((400, 100, 50), (100 * 5 + 2 * 45 * 5) * 400 - 8 * cyl(CLEAR[10], 5))
    slit = (strip(15, 0.75) - strip(6, 0.75)) / 2
    # The slit takes the outside's extreme point on its side: that extent is 15 + the half-chord.
    t["WD_092"] = ((50, 30, 15 + sqrt(15 * 15 - 0.75 * 0.75)), tube(30, 12, 50) - slit * 50)
    arm = disc(40) + disc(24) + 16 * 100 - strip(20, 8) / 2 - strip(12, 8) / 2 - disc(20) - disc(10)
    t["WD_093"] = ((132, 40, 12), arm * 12)
    t["WD_094"] = ((40, 40, 16), tube(40, 25, 16) - radial_hole(TAP[6], 12.5, 20))
    t["WD_095"] = inch((0.812, 0.812, 0.065), tube(0.812, 0.406, 0.065))
    t["WD_096"] = ((100, 50 + 21.2, 42.4), equal_tee(42.4, 2.6, 100, 50))
    t["WD_097"] = ((80, 40, 20), 80 * 40 * 20)
    t["WD_098"] = ((60, 30, 30), cyl(30, 60))
    t["WD_099"] = ((60, 60, 10), 60 * 60 * 10 - 4 * cyl(6.6, 10))
    t["WD_100"] = ((40, 40, 40), sphere(40))
    t["WD_101"] = ((30, 30, 3), tube(30, 16, 3))
    t["WD_102"] = ((50, 25, 25), cyl(25, 50) - 2 * chamfer_outer(12.5, 1))
    t["WD_103"] = ((120, 120, 15), tube(120, 60, 15) - 8 * cyl(10, 15))
    t["WD_104"] = ((40, across_corners(22), 22), hexagon(22) * 40)
    t["WD_105"] = ((50, 50, 50), 50.0**3 - cyl(20, 50))
    t["WD_106"] = ((50, 40, 40), cone(40, 50))
    t["WD_107"] = ((100, 60, 30), 100 * 60 * 30 - 94 * 54 * 27)
    t["WD_108"] = ((100, 30, 30), (30 * 3 + 27 * 3) * 100)
    # Session 4: patterns and restatements near the limits the contradiction checks draw.
    t["WD_139"] = ((80, 80, 10), cyl(80, 10) - 8 * cyl(8, 10))
    t["WD_140"] = ((100, 50, 10), 100 * 50 * 10 - 2 * cyl(12, 10))
    t["WD_141"] = inch((4, 2, 2), cyl(2, 4))
    t["WD_142"] = ((100, 100, 12), tube(100, 40, 12) - 4 * cyl(10, 12))
    t["WD_143"] = ((150, 100, 6), 150 * 100 * 6 - 4 * cyl(9, 6))
    t["WD_144"] = ((50, across_corners(20), 20), hexagon(20) * 50)
    # Session 5: part families, their shorthand, standards' defaults and parts of objects
    # (written before the reader's family layer; WD_177, WD_179, WD_181, WD_191 are refusals).
    t["WD_145"] = ((45, 45, 14), tube(45, 25, 14))
    t["WD_146"] = ((20, 12, 12), tube(12, 6.4, 20))
    t["WD_147"] = ((120, 120, 12), tube(120, 40, 12) - 6 * cyl(11, 12))
    t["WD_148"] = ((100, 60, 8), 100 * 60 * 8 - 4 * cyl(6.6, 8))
    t["WD_149"] = ((30, 30, 25), tube(30, 20, 25))
    t["WD_150"] = inch((1.5, 0.5, 0.5), tube(0.5, 0.25, 1.5))
    t["WD_151"] = inch((2, 2, 1 / 16), 2 * 2 / 16)
    t["WD_152"] = ((40, 8, 7), 8 * 7 * 40)
    t["WD_153"] = ((30, 6, 6), cyl(6, 30))
    t["WD_154"] = ((46.4, across_corners(16), 16), hexagon(16) * 6.4 + cyl(10, 40))
    t["WD_155"] = ((across_corners(13), 13, 6.5), hexagon(13) * 6.5 - cyl(TAP[8], 6.5))
    # Angles, channels, beams and tees: sharp corners (no root radii), legs outside to outside.
    t["WD_156"] = ((50, 50, 30), (50 * 5 + 45 * 5) * 30)
    t["WD_157"] = ((60, 40, 25), (60 * 6 + 34 * 6) * 25)
    t["WD_158"] = ((250, 40, 20), (40 * 20 - 34 * 17) * 250)
    t["WD_159"] = ((300, 100, 50), (2 * 50 * 8 + 84 * 5) * 300)
    t["WD_160"] = ((200, 50, 50), (50 * 6 + 44 * 6) * 200)
    t["WD_161"] = ((60, 60, 25), tube(60, 12, 25))
    # The boss (r 20, axis 25 up) dips 5 into the 10 thick base: a segment of depth 5 is shared.
    block = 80 * 30 * 10 + cyl(40, 30) - segment(20, 5) * 30 - cyl(20, 30) - 2 * cyl(CLEAR[8], 10)
    t["WD_162"] = ((80, 45, 30), block)
    t["WD_163"] = ((80, 60, 6), 80 * 60 / 2 * 6)
    t["WD_164"] = ((20, across_corners(7), 7), hexagon(7) * 20 - cyl(TAP[4], 20))
    t["WD_165"] = ((15, 8, 8), cyl(8, 15) - cyl(TAP[3], 15))
    t["WD_166"] = ((150, 150, 16), cyl(150, 16) - 8 * cyl(18, 16))
    t["WD_167"] = inch((1.125, 1.125, 0.5), tube(1.125, 0.5, 0.5))
    t["WD_168"] = ((32, 32, 20), tube(22, 16, 17) + tube(32, 16, 3))
    t["WD_169"] = inch((0.75, 0.75, 0.5), tube(0.75, 0.375, 0.5))
    t["WD_170"] = ((35, 8, 8), cyl(8, 35) - 2 * chamfer_outer(4, 0.5))
    t["WD_171"] = inch((1.5, 0.25, 0.25), 0.25 * 0.25 * 1.5)
    t["WD_172"] = ((300, 80, 40), (80 * 4 + 2 * 36 * 4) * 300 - 3 * cyl(9, 4))
    t["WD_173"] = ((200, 30, 6), 30 * 6 * 200 - 5 * cyl(6.6, 6))
    # ISO 7089 M12: d1 13, d2 24, h 2.5. ISO 4032 M10: s 16, m 8.4 (max), tapped at 8.5.
    t["WD_174"] = ((24, 24, 2.5), tube(24, 13, 2.5))
    t["WD_175"] = ((across_corners(16), 16, 8.4), hexagon(16) * 8.4 - cyl(TAP[10], 8.4))
    t["WD_176"] = ((720, 40, 40), 40 * 40 * 720)
    t["WD_178"] = ((450, 30, 30), cyl(30, 450))
    t["WD_180"] = ((800, 250, 18), 800 * 250 * 18)
    t["WD_182"] = ((100, 100, 10), tube(100, 30, 10) - 4 * cyl(9, 10))
    t["WD_183"] = inch((4, 4, 0.5), tube(4, 1, 0.5) - 4 * cyl(0.375, 0.5))
    t["WD_184"] = ((80, 80, 32), cyl(80, 20) + cyl(30, 12) - cyl(10, 32))
    t["WD_185"] = ((300, 25.4, 25.4), tube(25.4, 22.2, 300))
    t["WD_186"] = ((40, 20, 10), 40 * 20 * 10 - cyl(5.5, 10 - 5.5) - cyl(10, 5.5))
    t["WD_187"] = ((120, 80, 6), rounded_rect(120, 80, 10) * 6 - 4 * cyl(6.6, 6))
    t["WD_188"] = ((80, 30, 30), cyl(30, 80) - 2 * chamfer_outer(15, 2))
    t["WD_189"] = ((60, 40, 20), 60 * 40 * 20 - 4 * 2 * 2 / 2 * 20)
    t["WD_190"] = inch((1, 1, 1), tube(1, 0.75, 1))
    t["WD_192"] = ((1200, 600, 25), 1200 * 600 * 25)
    return t


def heldout2() -> dict[str, Ref]:
    """The held-out v2 parts (frozen 2026-11-27)."""
    t: dict[str, Ref] = {}
    t["WH2_001"] = ((15, 12, 12), tube(12, 6.4, 15))
    t["WH2_002"] = ((200, 80, 12), 200 * 80 * 12 - 2 * cyl(13.5, 12))
    t["WH2_003"] = ((180, 25, 25), cyl(25, 180) - 2 * chamfer_outer(12.5, 2))
    t["WH2_004"] = ((120, 120, 25), cyl(120, 15) + cyl(60, 10) - cyl(40, 25) - 6 * cyl(CLEAR[8], 15))
    t["WH2_005"] = ((20, 8, 8), cyl(8, 20) - cyl(TAP[4], 20))
    t["WH2_006"] = ((400, 33.7, 33.7), tube(33.7, 33.7 - 2 * 2.6, 400))
    t["WH2_007"] = ((37, 37, 3), tube(37, 21, 3))
    t["WH2_008"] = ((across_corners(18), 18, 10.8), hexagon(18) * 10.8 - cyl(TAP[12], 10.8))
    t["WH2_009"] = ((30, 22, 22), tube(22, 16, 30) - 2 * chamfer_outer(11, 1))
    t["WH2_010"] = ((70, 70, 3), 70 * 70 * 3 - cyl(38.1, 3) - 4 * cyl(5, 3))
    t["WH2_011"] = ((150, 90, 90), tube(90, 82, 150))
    t["WH2_012"] = ((60, 40, 25), 60 * 40 * 25 - 2 * cyl(TAP[6], 25))
    blank = cyl(100, 30) - cyl(25, 30) - keyway_in_bore(12.5, 8, 3.3) * 30 - v_groove(50, 14, 10, 38)
    t["WH2_013"] = ((100, 100, 30), blank)
    # A 3/16 x 3/32 keyway 2 in long on a 3/4 in shaft (depth from the shaft's surface, t1).
    t["WH2_014"] = inch((8, 0.75, 0.75), cyl(0.75, 8) - keyway_on_shaft(0.375, 0.1875, 0.09375) * 2)
    t["WH2_015"] = inch((2, 2, 1), tube(2, 1.5, 1) - radial_hole(0.201, 0.75, 1.0))
    t["WH2_016"] = inch((3, across_corners(0.875), 0.875), hexagon(0.875) * 3)
    t["WH2_017"] = ((150, 150, 10), tube(150, 50, 10) - 2 * fillet_outer(75, 2))
    # Two 60 x 40 legs of 5 mm plate sharing the 5 x 5 corner, less two holes in each leg.
    t["WH2_018"] = ((60, 60, 40), 40 * 5 * (60 + 60 - 5) - 4 * cyl(6.6, 5))
    # A regular pentagon of side s lying on a side: circumradius R = s / (2 sin 36°), width
    # corner to corner 2R sin 72°, height R (1 + cos 36°).
    r5 = 20 / (2 * sin(radians(36)))
    t["WH2_019"] = ((2 * r5 * sin(radians(72)), r5 * (1 + cos(radians(36))), 15), ngon_ac(5, 2 * r5) * 15)
    t["WH2_020"] = ((60, 60, 40), pi * 40 * (30 * 30 + 30 * 15 + 15 * 15) / 3)
    t["WH2_021"] = ((100, 30, 30), disc(60) / 4 * 100)
    t["WH2_022"] = ((40, 25, 25), tube(25, 10, 40) - 2 * radial_hole(TAP[4], 5, 12.5))
    t["WH2_023"] = ((100, 40, 30), (40 * 30 - 32 * 26) * 100 - 3 * cyl(8.5, 4))
    t["WH2_024"] = ((50, 35, 35), cyl(35, 50))
    # The cross hole runs between two parallel flats, 22 apart: a plain cylinder.
    t["WH2_025"] = ((60, across_corners(22), 22), hexagon(22) * 60 - cyl(8, 22))
    return t


def rack(module: float, pressure_deg: float, face: float, height: float, teeth: int) -> Ref:
    """A straight-sided rack: every tooth a trapezoid (addendum 1 m, dedendum 1.25 m, flanks
    at the pressure angle, thickness half a pitch on the pitch line), centred in its pitch,
    on a bar up to the root line."""
    pitch = pi * module
    slope = tan(radians(pressure_deg))
    tip = pitch / 2 - 2 * module * slope
    root = pitch / 2 + 2 * 1.25 * module * slope
    depth = 2.25 * module
    length = teeth * pitch
    area = length * (height - depth) + teeth * (tip + root) / 2 * depth
    return (length, face, height), area * face


# --- tables ------------------------------------------------------------------------------


def suite_rows() -> list[dict[str, str]]:
    rows: list[dict[str, str]] = []
    for name in SUITES:
        with open(os.path.join(HERE, name), encoding="utf-8") as f:
            lines = [line for line in f if not line.startswith("#")]
        rows.extend(csv.DictReader(lines, delimiter="\t", quoting=csv.QUOTE_NONE))
    return rows


def table() -> list[tuple[str, str, str]]:
    """(id, bbox, volume) for every description, in file order; refusals carry no numbers."""
    refs = heldout() | dev() | heldout2()
    out: list[tuple[str, str, str]] = []
    problems: list[str] = []
    seen: set[str] = set()
    for row in suite_rows():
        pid = row["id"]
        seen.add(pid)
        if row["expected"] == "refuse":
            if pid in refs:
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
        box = ",".join(f"{v:.4f}" for v in sorted(ext, reverse=True))
        out.append((pid, box, f"{vol:.3f}"))
    problems += [f"{pid}: reference for an id no suite has" for pid in refs if pid not in seen]
    if problems:
        raise SystemExit("refs.py: " + "; ".join(problems))
    return out


HEADER = "# Written by refs.py (closed formulas, no CadQuery); do not edit by hand. bbox_mm sorted descending.\n"


def render(rows: list[tuple[str, str, str]]) -> str:
    lines = [HEADER, "id\tbbox_mm\tvolume_mm3\n"]
    lines += [f"{pid}\t{box}\t{vol}\n" for pid, box, vol in rows]
    return "".join(lines)


def main(argv: list[str]) -> int:
    text = render(table())
    if "--check" in argv:
        try:
            with open(OUT, encoding="utf-8") as f:
                stored = f.read()
        except FileNotFoundError:
            print("refs.py --check: refs.tsv is missing; run refs.py", file=sys.stderr)
            return 1
        if stored != text:
            old = set(stored.splitlines())
            diff = [line for line in text.splitlines() if line not in old]
            print("refs.py --check: refs.tsv differs from the formulas: " + "; ".join(diff[:5]), file=sys.stderr)
            return 1
        print(f"refs.tsv matches the formulas ({text.count(chr(10)) - 2} rows)")
        return 0
    with open(OUT, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"wrote {OUT} ({text.count(chr(10)) - 2} rows)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
