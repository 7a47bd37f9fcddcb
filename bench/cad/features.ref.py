# features reference parts: one CadQuery program per prompt of features.tsv, written by hand
# from the prompt's words alone, apart from the synthesizer (nothing here comes from it).
# Format as standard_100.ref.py: sections "# ref: ID", a "_prelude" put in front of each.
#
# Readings: F_034 "spaced 8mm apart" is the fins' pitch (a gap of 8 would put the outer fins
# past the 50mm base); F_043's arms are as thick as the hub they leave (5mm) and run from
# inside it to 50mm from the centre; F_047's posts stand on the plate.

# ref: _prelude
import math

import cadquery as cq


def cyl(d, z0, z1, x=0.0, y=0.0):
    return cq.Workplane("XY").workplane(offset=z0).center(x, y).circle(d / 2).extrude(z1 - z0)


def slab(x0, x1, y0, y1, z0, z1):
    return cq.Workplane("XY").box(x1 - x0, y1 - y0, z1 - z0).translate(((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2))


def xcyl(d, x0, x1, y=0.0, z=0.0):
    return cq.Workplane("YZ").workplane(offset=x0).center(y, z).circle(d / 2).extrude(x1 - x0)


# ref: F_001
result = cq.Workplane("XY").box(40, 25, 10)

# ref: F_002
result = xcyl(12, 0, 80)

# ref: F_003
result = cyl(42, 0, 150).cut(cyl(36, 0, 150))

# ref: F_004
result = cq.Workplane("XY").polygon(6, 19 / math.cos(math.radians(30))).extrude(60)

# ref: F_005
result = cq.Workplane("XY").add(cq.Solid.makeCone(20, 0, 60))

# ref: F_006
result = cq.Workplane("XY").add(cq.Solid.makeCone(25, 15, 25))

# ref: F_007
result = cq.Workplane("XY").sphere(25.4 / 2)

# ref: F_008
result = cq.Workplane("XY").add(cq.Solid.makeTorus(25, 5))

# ref: F_009
result = cq.Workplane("XY").ellipse(30, 15).extrude(5)

# ref: F_010
result = slab(-25, 25, -15, 15, 0, 6).union(cyl(30, 0, 6, -25)).union(cyl(30, 0, 6, 25))

# ref: F_011
result = cq.Workplane("XY").polygon(8, 30).extrude(12)

# ref: F_012
result = cq.Workplane("XY").rect(30, 30).workplane(offset=45).rect(0.001, 0.001).loft()

# ref: F_013
result = cq.Workplane("XY").sphere(20).intersect(slab(-25, 25, -25, 25, 0, 25))

# ref: F_014
result = cq.Workplane("XY").box(50.8, 25.4, 12.7)

# ref: F_015
result = slab(0, 200, -20, 20, 0, 5).union(slab(0, 200, -20, 20, 55, 60)).union(slab(0, 200, -2, 2, 5, 55))

# ref: F_016
result = slab(0, 120, -25, 25, 0, 25).cut(slab(0, 120, -21, 21, 4, 25))

# ref: F_017
result = slab(0, 250, -20, 20, -20, 20).cut(slab(0, 250, -17, 17, -17, 17))

# ref: F_018
result = slab(-25, 25, 0, 40, 0, 5).union(slab(-25, 25, -5, 0, 0, 60))

# ref: F_019
result = cq.Workplane("XY").box(40, 40, 40).translate((0, 0, 20)).cut(cyl(10, 25, 40))

# ref: F_020
result = slab(-25, 25, -25, 25, 0, 20).cut(cyl(8, 0, 20)).cut(cyl(14, 14, 20))

# ref: F_021
result = slab(-30, 30, -20, 20, 0, 6)
for x in (-24, 24):
    for y in (-14, 14):
        hole = cyl(4, 0, 6, x, y)
        sink = cq.Workplane("XY").add(cq.Solid.makeCone(2, 4, 2, cq.Vector(x, y, 4)))
        result = result.cut(hole).cut(sink)

# ref: F_022
slot = slab(-11, 11, -4, 4, 0, 5).union(cyl(8, 0, 5, -11)).union(cyl(8, 0, 5, 11))
result = slab(-40, 40, -25, 25, 0, 5).cut(slot)

# ref: F_023
result = cyl(25, 0, 80).cut(slab(8.5, 14, -4, 4, 0, 80))

# ref: F_024
result = cyl(20, 0, 60).cut(cyl(22, 28.5, 31.5).cut(cyl(17, 28.5, 31.5)))

# ref: F_025
result = slab(-30, 30, -20, 20, 0, 20).cut(slab(-15, 15, -10, 10, 12, 20))

# ref: F_026
hexagon = cq.Workplane("XY").workplane(offset=9).polygon(6, 8 / math.cos(math.radians(30))).extrude(6)
result = cyl(20, 0, 15).cut(hexagon)

# ref: F_027
result = cyl(25.4, 0, 2.54).cut(cyl(12.7, 0, 2.54))

# ref: F_028
result = slab(-50, 50, -30, 30, 0, 8)
for x in (-30, 0, 30):
    for y in (-12.5, 12.5):
        result = result.cut(cyl(6, 0, 8, x, y))

# ref: F_029
result = cyl(80, 0, 10)
for k in range(8):
    a = math.radians(45 * k)
    result = result.cut(cyl(6, 0, 10, 30 * math.cos(a), 30 * math.sin(a)))

# ref: F_030
result = slab(-60, 60, -40, 40, 0, 10)
for x in (-50, 50):
    for y in (-30, 30):
        result = result.cut(cyl(10, 0, 10, x, y))

# ref: F_031
result = slab(-100, 100, -15, 15, 0, 10)
for x in (-80, -40, 0, 40, 80):
    result = result.cut(cyl(8, 0, 10, x, 0))

# ref: F_032
result = slab(-50, 50, -25, 25, -3, 3).cut(cyl(12, -3, 3, 30, 0)).cut(cyl(6, -3, 3, -30, 10))

# ref: F_033
result = cyl(100, 0, 6)
for deg in (90, 210, 330):
    a = math.radians(deg)
    result = result.cut(cyl(10, 0, 6, 35 * math.cos(a), 35 * math.sin(a)))

# ref: F_034
result = slab(-25, 25, -20, 20, 0, 4)
for k in range(6):
    x = -20 + 8 * k
    result = result.union(slab(x - 1, x + 1, -20, 20, 4, 24))

# ref: F_035
result = cq.Workplane("XY").box(30, 20, 10).edges().fillet(2)

# ref: F_036
result = cq.Workplane("XY").box(50, 50, 50).faces(">Z").edges().chamfer(3)

# ref: F_037
result = cq.Workplane("XY").box(100, 60, 40).faces(">Z").shell(-3)

# ref: F_038
result = cyl(30, 0, 50).faces(">Z or <Z").edges().fillet(2)

# ref: F_039
result = cq.Workplane("XY").box(90, 50, 10).edges("|Z").fillet(6).cut(cyl(20, -5, 5))

# ref: F_040
# Centre of the bend at (50, 0, 0); from the origin heading +Z to (50, 0, 50) heading +X.
start, mid, end = cq.Vector(0, 0, 0), cq.Vector(50 - 50 * math.cos(math.radians(45)), 0, 50 * math.sin(math.radians(45))), cq.Vector(50, 0, 50)
path = cq.Workplane("XY").add(cq.Wire.assembleEdges([cq.Edge.makeThreePointArc(start, mid, end)]))
outer = cq.Workplane("XY").circle(12.5).sweep(path)
inner = cq.Workplane("XY").circle(10).sweep(path)
result = outer.cut(inner)

# ref: F_041
result = cq.Workplane("XY").rect(40, 40).workplane(offset=30).circle(10).loft()

# ref: F_042
result = cq.Workplane("XZ").polyline([(0, 0), (15, 0), (15, 10), (8, 14), (8, 25), (0, 25)]).close().revolve(360, (0, 0, 0), (0, 1, 0))

# ref: F_043
result = cyl(20, 0, 5)
for deg in (0, 120, 240):
    result = result.union(slab(0, 50, -4, 4, 0, 5).rotate((0, 0, 0), (0, 0, 1), deg))

# ref: F_044
result = cyl(30, 0, 20).union(cyl(20, 20, 60)).union(cyl(12, 60, 75))

# ref: F_045
result = cyl(20, 0, 100).union(cyl(60, 20, 28))

# ref: F_046
outer = xcyl(40, -60, 60).union(cyl(40, 0, 60))
inner = xcyl(32, -60, 60).union(cyl(32, 0, 60))
result = outer.cut(inner)

# ref: F_047
result = slab(-40, 40, -40, 40, 0, 6)
for x in (-30, 30):
    for y in (-30, 30):
        result = result.union(cyl(10, 6, 36, x, y))
for x in (-30, 30):
    for y in (-30, 30):
        result = result.cut(cyl(4, 0, 36, x, y))

# ref: F_048
teeth = []
for k in range(24):
    a = math.pi * k / 12
    r = 18 if k % 2 == 0 else 14
    teeth.append((r * math.cos(a), r * math.sin(a)))
gear = cq.Workplane("XY").polyline(teeth).close().extrude(6)
result = gear.union(cyl(12, 0, 16)).cut(cyl(8, 0, 16))

# ref: F_049
result = cyl(50, 0, 20)
for k in range(4):
    a = math.radians(90 * k)
    result = result.cut(cyl(5, 0, 20, 17.5 * math.cos(a), 17.5 * math.sin(a)))

# ref: F_050
result = slab(-40, 40, -20, 20, 0, 30).cut(slab(-25, 25, -10, 10, 20, 30))

# ref: F_051
result = cyl(30, 0, 50).cut(cyl(20, 0, 50))

# ref: F_052
result = slab(0, 100, -15, 15, 0, 4).union(slab(0, 100, -15, 15, 46, 50)).union(slab(0, 100, -1.5, 1.5, 4, 46))

# ref: F_053
result = cq.Workplane("XY").sphere(20)

# ref: F_054
result = cq.Workplane("XY").polygon(6, 10 / math.cos(math.radians(30))).extrude(5).cut(cyl(6, 0, 5))

# ref: F_055
result = slab(-100, 100, -50, 50, 0, 10).cut(cyl(12, 0, 10, -25, 0)).cut(cyl(12, 0, 10, 25, 0))

# ref: F_056
result = cq.Workplane("XY").box(25, 25, 25).cut(xcyl(10, -12.5, 12.5))

# ref: F_057
result = cyl(100, 0, 10).union(cyl(40, 10, 25))

# ref: F_058
result = cyl(120, 0, 12).cut(cyl(60, 0, 12))
for k in range(8):
    a = math.radians(45 * k)
    result = result.cut(cyl(10, 0, 12, 47.5 * math.cos(a), 47.5 * math.sin(a)))

# ref: F_059
result = cq.Workplane("XY").add(cq.Solid.makeCone(15, 0, 50))

# ref: F_060
result = cq.Workplane("XY").box(100, 100, 8).edges("|Z").fillet(2).cut(cyl(30, -4, 4))

# ref: F_061
result = cyl(25.4, 0, 304.8).cut(cyl(25.4 - 2 * 25.4 / 16, 0, 304.8))

# ref: F_062
result = cyl(50, 0, 100).cut(cyl(40, 0, 100))

# ref: F_063
result = cyl(80, 0, 10).cut(cq.Workplane("XY").box(30, 30, 10, centered=(True, True, False)))

# ref: F_064
result = cq.Workplane("XY").box(30, 30, 30, centered=(True, True, False)).cut(cyl(10, 0, 5))

# ref: F_065
result = slab(0, 150, -25, 25, 35, 40).union(slab(0, 150, -2, 2, 0, 35))

# ref: F_066
result = slab(-50, 50, -30, 30, 0, 5).union(slab(-50, 50, -2.5, 2.5, 5, 25))

# ref: F_067
result = slab(-40, 40, -40, 40, 0, 10)
for gx in (-20, 0, 20):
    for gy in (-20, 0, 20):
        result = result.cut(cyl(5, 0, 10, gx, gy))

# ref: F_068
# A point on +X (the direction is not said; extents are compared sorted).
pts = [((30 if k % 2 == 0 else 12.5) * math.cos(math.pi * k / 5), (30 if k % 2 == 0 else 12.5) * math.sin(math.pi * k / 5)) for k in range(10)]
result = cq.Workplane("XY").polyline(pts).close().extrude(8)
