"""Closed formulas for standard_100: each prompt's extents and volume worked out by hand
from its words (Steiner for filleted boxes, Pappus for revolved and swept parts, Steinmetz
for crossing pipes, the star-polygon area for gears, circle segments for keyways), written
apart from the CadQuery reference programs (standard_100.ref.py) so that the two check
each other. `None` where no closed form is at hand (lofts to a circle, shells of curved
profiles): there the program alone is the reference.

Extents are per axis as the prompt places the part where it says, else any order (the
check compares them sorted). Readings of ambiguous words are those listed at the top of
standard_100.ref.py.
"""

from __future__ import annotations

from math import cos, pi, radians, sin, sqrt

from geometry import annulus_disc_area, circle_strip, cyl_chamfer, cyl_fillet, hole_through_wall, keyway_area

R3 = sqrt(3)

Ref = tuple[tuple[float, float, float], float | None]


def hexa(r: float) -> float:
    """A regular hexagon of circumradius r."""
    return 3 * R3 / 2 * r * r


def ngon(n: int, r: float) -> float:
    return n / 2 * r * r * sin(2 * pi / n)


def star(n: int, tip: float, root: float) -> float:
    """A star polygon of n points between the tip and root radii."""
    return n * tip * root * sin(pi / n)


def steiner(a: float, b: float, c: float, r: float) -> float:
    """A box with every edge filleted r."""
    p, q, t = a - 2 * r, b - 2 * r, c - 2 * r
    return p * q * t + 2 * (p * q + q * t + p * t) * r + pi * (p + q + t) * r * r + 4 / 3 * pi * r**3


def box_chamfer(a: float, b: float, c: float, k: float) -> float:
    """A box with every edge chamfered k."""
    return a * b * c - 2 * k * k * (a + b + c) + 6 * k**3


def rounded_rect(a: float, b: float, r: float) -> float:
    """A rectangle with its four corners rounded r."""
    return a * b - (4 - pi) * r * r


def disc(d: float) -> float:
    return pi * d * d / 4


def _t3() -> dict[str, Ref]:
    t: dict[str, Ref] = {}
    # Open containers: the outer rounded rectangle times the height, less the cavity (the
    # inner corner radius is the outer one less the wall) above the 2 mm floor.
    t["T3_001"] = ((60, 40, 30), rounded_rect(60, 40, 5) * 30 - rounded_rect(56, 36, 3) * 28)
    t["T3_002"] = ((80, 50, 25), rounded_rect(80, 50, 8) * 25 - rounded_rect(76, 46, 6) * 23 - 4 * disc(3.2) * 2)
    tray = rounded_rect(70, 50, 4) * 30 - rounded_rect(66, 46, 2) * 28
    t["T3_003"] = ((70, 50, 30), tray + 4 * disc(8) * 28 - 4 * disc(3) * 30)
    # The pulley: Pappus on the profile (a 24 x 20 rectangle from r = 6 less the V notch,
    # a triangle of area 50 whose centroid is at r = 80 / 3).
    moment = 24 * 20 * 18 - 50 * 80 / 3
    t["T3_004"] = ((60, 60, 20), 2 * pi * moment - keyway_area(6, 4, 8.5) * 20)
    t["T3_005"] = ((50, 50, 50), disc(50) * 10 + disc(30) * 40 - disc(20) * 50 - 4 * disc(6) * 10)
    t["T3_006"] = ((56, 56, 65), None)
    t["T3_007"] = ((70, 50, 63), None)
    # Gears: a star polygon of n tips has a tip on the Y axis when n is a multiple of 4
    # (20, 24, 16 here), so both plan extents are the tip diameter.
    shaft = disc(15) * 40 + disc(20) * 15
    gear = star(20, 22, 18) * 15 - disc(20) * 15
    t["T3_008"] = ((44, 44, 55), shaft + gear - disc(8) * 55 - keyway_area(4, 3, 7) * 15)
    g1 = star(24, 27, 22) * 10 - disc(16) * 10
    g2 = star(14, 16, 13) * 10 - disc(16) * 10
    t["T3_009"] = ((54, 54, 40), disc(16) * 40 + g1 + g2 - disc(8) * 40)
    gears = sum(star(n, a, b) * 8 - disc(14) * 8 for n, a, b in ((24, 27, 22), (18, 21, 17), (12, 15, 12)))
    t["T3_010"] = ((54, 54, 55), disc(14) * 55 + gears - disc(6) * 55 - keyway_area(3, 3, 5) * 55)
    body = star(20, 24, 20) * 10 + disc(16) * 20 - disc(10) * 30 - keyway_area(5, 4, 7.5) * 30
    # The set-screw hole through both walls of the hub (r 5 to 8); on +X the keyway has
    # already opened the wall up to the plane x = 7.5.
    screw = hole_through_wall(4, 5, 8) + hole_through_wall(4, 7.5, 8, inner_is_plane=True)
    t["T3_011"] = ((48, 48, 30), body - screw)
    t["T3_012"] = (
        (60, 60, 40),
        60 * 60 * 5
        + disc(20) * 13
        + disc(14) * 22
        + star(16, 20, 16) * 8
        - disc(20) * 8
        - disc(8) * 40
        - 4 * disc(6) * 5,
    )
    # Swept pipes: Pappus, the annulus times the centreline's length.
    ring = disc(20) - disc(16)
    t["T3_013"] = ((50, 20, 50), ring * pi / 2 * 40)
    t["T3_014"] = ((90, 20, 45), ring * pi * 35)
    # 45 degrees: the end face's centre at (40 - 40 cos 45, 40 sin 45), tilted 45 degrees.
    h = sqrt(0.5)
    t["T3_016"] = ((10 + 40 * (1 - h) + 10 * h, 20, 40 * h + 10 * h), ring * pi / 4 * 40)
    # Tee: the branch's part inside the run is half a Steinmetz solid (8 r^3 / 3).
    outer = disc(30) * 100 + disc(30) * 50 - 8 * 15**3 / 3
    inner = disc(24) * 100 + disc(24) * 50 - 8 * 12**3 / 3
    t["T3_015"] = ((100, 30, 65), outer - inner)
    outer = 2 * disc(30) * 100 - 16 * 15**3 / 3
    inner = 2 * disc(24) * 100 - 16 * 12**3 / 3
    t["T3_017"] = ((100, 30, 100), outer - inner)
    # Drone frames, 3 mm thick: plan areas. A mount centred on its arm's end covers half
    # of the arm's strip of it.
    mount = disc(18) - circle_strip(9, 5) / 2
    plus = 30 * 30 + 4 * 45 * 10 + 4 * mount - 4 * disc(5) - 4 * disc(3.2)
    t["T3_018"] = ((138, 138, 3), plus * 3)
    arm = 10 * 73 - circle_strip(18, 5) / 2  # an arm from the hub's rim out to 73 mm
    xframe = disc(36) + 4 * arm + 4 * mount - 4 * disc(5) - 4 * disc(3.2)
    e = 2 * (73 * h + 9)
    t["T3_019"] = ((e, e, 3), xframe * 3)
    plate = 2 * 160 * 12 + 50 * 72 - 2 * 50 * 12 + 4 * (disc(22) - circle_strip(11, 6) / 2) - 4 * disc(5)
    t["T3_020"] = ((182, 82, 3), (plate - 4 * disc(3.2)) * 3)
    groove = (disc(50) - disc(38)) * 2
    overlap = 6 * annulus_disc_area(19, 25, 27.5, 4.5) * 2  # the bolt holes cross the groove
    t["T3_021"] = ((80, 80, 16), (disc(80) - disc(32)) * 16 - 6 * disc(9) * 16 - groove + overlap)
    spokes = 4 * 8 * (circle_strip(44, 4) - circle_strip(15, 4)) / 2
    t["T3_022"] = ((100, 100, 12), disc(30) * 12 + (disc(100) - disc(88)) * 8 + spokes - disc(14) * 12)
    t["T3_023"] = ((80, 50, 15), 80 * 50 * 3 + 6 * disc(8) * 12 - 6 * disc(3.2) * 15)
    t["T3_024"] = ((120, 120, 30), disc(120) * 20 + disc(40) * 10 - 6 * disc(22) * 20 - disc(16) * 30)
    t["T3_025"] = (
        (50, 50, 60),
        2 * disc(50) * 10 + disc(28) * 40 - 6 * disc(6.5) * 20 - disc(14) * 60 - keyway_area(7, 5, 9.5) * 60,
    )
    return t


def table() -> dict[str, Ref]:
    """Every prompt's (extents, volume) by id."""
    t: dict[str, Ref] = {
        "T1_001": ((50, 30, 20), 50 * 30 * 20),
        "T1_002": ((25, 25, 40), disc(25) * 40),
        "T1_003": ((30, 30, 30), 4 / 3 * pi * 15**3),
        "T1_004": ((30, 30, 45), disc(30) * 45 / 3),
        "T1_005": ((40, 40, 40), 40**3),
        "T1_006": ((100, 60, 3), 100 * 60 * 3),
        "T1_007": ((20, 10 * R3, 35), hexa(10) * 35),
        "T1_008": ((50, 50, 25), 2 / 3 * pi * 25**3),
        "T1_009": ((50, 50, 2), disc(50) * 2),
        "T1_010": ((8, 8, 150), disc(8) * 150),
        "T1_011": ((200, 10, 10), 20000),
        "T1_012": ((15 * R3, 22.5, 50), 3 * R3 / 4 * 225 * 50),
        "T1_013": ((60, 20, 8), (40 * 20 + disc(20)) * 8),
        "T1_014": ((40, 40, 15), ngon(8, 20) * 15),
        "T1_015": ((40, 40, 30), pi * 30 / 3 * (400 + 200 + 100)),
        "T1_016": ((40, 20, 25), pi * 20 * 10 * 25),
        "T1_017": ((80, 80, 5), 80 * 80 * 5),
        "T1_018": ((12.5 * (1 + cos(radians(36))), 25 * sin(radians(72)), 40), ngon(5, 12.5) * 40),
        "T1_019": ((120, 45, 15), 120 * 45 * 15),
        "T1_020": ((36, 36, 60), disc(36) * 60),
        "T1_021": ((60, 30, 25), 0.5 * 30 * 25 * 60),
        "T1_022": ((10, 10, 10), 1000),
        "T1_023": ((50, 25, 15), rounded_rect(50, 25, 3) * 15),
        "T1_024": ((30, 30, 30), box_chamfer(30, 30, 30, 2)),
        "T1_025": ((50, 50, 4), (disc(50) - disc(25)) * 4),
        "T1_026": ((30, 30, 80), (disc(30) - disc(24)) * 80),
        "T1_027": ((70, 40, 25), steiner(70, 40, 25, 5)),
        "T1_028": ((40, 40, 23), disc(40) * 3 + 2 / 3 * pi * 20**3),
        "T1_029": ((20, 30, 40), 0.5 * 20 * 30 * 40),
        "T1_030": ((12, 12, 100), cyl_chamfer(6, 100, 1)),
        "T1_031": ((50, 30, 40), 40 / 6 * (50 * 30 + 4 * 40 * 22.5 + 30 * 15)),
        "T1_032": ((35, 35, 20), 3 * 17.5**2 * 20),
        "T1_033": ((50, 50, 10), 3 * 25**2 * 10),
        "T1_034": ((20, 20, 20), cyl_fillet(10, 20, 2)),
        "T1_035": ((35, 35, 50), 35 * 35 * 50),
        "T1_036": ((80, 80, 1), disc(80) * 1),
        "T1_037": ((40, 40, 50), 1600 * 50 / 3),
        "T1_038": ((120, 15, 7.5 * R3), hexa(7.5) * 120),
        "T1_039": ((25, 15, 10), box_chamfer(25, 15, 10, 1)),
        "T1_040": ((38, 38, 3), cyl_fillet(19, 3, 0.5)),
        "T1_041": ((40, 40, 12), (disc(40) - disc(30)) * 12),
        "T1_042": ((90, 20, 8), rounded_rect(20, 8, 2) * 90),
        "T1_043": ((30, 30, 80), disc(30) * 50 + 4 / 3 * pi * 15**3),
        "T1_044": ((60, 2, 80), 60 * 2 * 80),
        "T1_045": ((50, 70, 25), (disc(50) - disc(44)) / 2 * 70),
        "T1_046": ((20, 20, 20), steiner(20, 20, 20, 3)),
        "T1_047": ((60, 60, 35), pi * 35 / 3 * (900 + 600 + 400)),
        "T1_048": ((150, 50, 30), 150 * 50 * 30),
        "T1_049": ((40, 40, 10), disc(40) * 10),
        "T1_050": ((40, 20, 60), rounded_rect(40, 20, 4) * 60),
        "T2_001": ((20, 20, 2), (disc(20) - disc(10.5)) * 2),
        "T2_002": ((19.6, 9.8 * R3, 8), (hexa(9.8) - disc(10)) * 8),
        "T2_003": ((19.6, 9.8 * R3, 37), disc(10) * 30 + hexa(9.8) * 7),
        "T2_004": ((13, 13, 33), disc(8) * 25 + disc(13) * 8 - hexa(6.93 / 2) * 4),
        "T2_005": ((100, 20, 40), (2 * 20 * 3 + 34 * 2) * 100),
        # The base 40 deep from the inside corner, the 3 mm wall behind it: 43 in Y.
        "T2_006": ((40, 43, 50), 40 * 40 * 3 + 40 * 3 * 50),
        "T2_007": ((80, 40, 30), (40 * 30 - 34 * 27) * 80),
        "T2_008": ((80, 60, 5), 80 * 60 * 5 - 4 * disc(4.2) * 5),
        "T2_009": ((30, 30, 33), disc(30) * 3 + disc(20) * 30 - disc(10) * 33),
        "T2_010": ((25, 25, 12), (disc(25) - disc(15)) * 12 - hole_through_wall(5, 7.5, 12.5)),
        "T2_011": ((8, 8, 40), cyl_chamfer(4, 40, 1)),
        "T2_012": ((60, 40, 8), 60 * 40 * 8 - 4 * (disc(5.5) * 5 + disc(10) * 3)),
        "T2_013": ((60, 60, 8), (disc(60) - disc(20)) * 8 - 6 * disc(5.5) * 8),
        "T2_014": ((80, 30, 40), (30 * 40 - 26 * 36) * 80),
        # The keyway's flat at x = 7 leaves the circle's widest point at y = +-3.
        "T2_015": ((10 + sqrt(91), 20, 60), disc(20) * 60 - (circle_strip(10, 3) / 2 - 7 * 6) * 60),
        "T2_016": ((14, 14, 35), disc(6) * 10 + disc(10) * 20 + disc(14) * 5),
        "T2_017": ((80, 30, 40), (3 * 37 + 30 * 3) * 80),
        "T2_018": ((40, 40, 8), (star(16, 20, 16) - disc(10)) * 8),
        # The pin hole runs along X through both 10 mm prongs.
        "T2_019": ((30, 20, 25), 30 * 20 * 25 - 10 * 20 * 15 - disc(6) * 20),
        "T2_020": ((60, 40, 34), 60 * 40 * 4 + 40 * 30 * 4 - 2 * disc(6) * 4 - 2 * disc(5) * 4),
        "T2_021": ((60, 40, 18), 60 * 40 * 3 + 5 * 2 * 40 * 15),
        "T2_022": ((24, 24, 3), 24 * 24 * 3 - disc(10.5) * 3),
        "T2_023": ((60, 25, 26), 2 * 30 * 25 * 3 + 3 * 25 * 26 - 2 * 1.5 * 25 * 3),
        "T2_024": ((45, 45, 20), star(16, 22.5, 16.875) * 8 + disc(16) * 12 - disc(8) * 20),
        "T2_025": ((40, 40, 55), disc(40) * 5 + disc(20) * 50 - 4 * disc(6) * 5),
    }
    t.update(_t3())
    return t
