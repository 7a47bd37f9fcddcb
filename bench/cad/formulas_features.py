"""Closed formulas for the features suite (features.tsv): each prompt's extents and volume
worked out by hand from its words, apart from the CadQuery programs in features.ref.py, so
that the two check each other (bench/cad/refs.py). `None` where no closed form is at hand."""

from __future__ import annotations

from math import cos, pi, radians, sin, sqrt

from formulas_standard_100 import rounded_rect, star, steiner
from geometry import circle_strip, cyl_fillet

Ref = tuple[tuple[float, float, float], float | None]


def disc(d: float) -> float:
    return pi * d * d / 4


def table() -> dict[str, Ref]:
    hexd = 19 / cos(radians(30))
    oct_area = 8 / 2 * 15**2 * sin(2 * pi / 8)
    t: dict[str, Ref] = {
        "F_001": ((40, 25, 10), 40 * 25 * 10),
        "F_002": ((80, 12, 12), disc(12) * 80),
        "F_003": ((42, 42, 150), (disc(42) - disc(36)) * 150),
        "F_004": ((hexd, 19, 60), 3 * sqrt(3) / 2 * (hexd / 2) ** 2 * 60),
        "F_005": ((40, 40, 60), disc(40) * 60 / 3),
        "F_006": ((50, 50, 25), pi * 25 / 3 * (25**2 + 25 * 15 + 15**2)),
        "F_007": ((25.4, 25.4, 25.4), pi * 25.4**3 / 6),
        "F_008": ((60, 60, 10), 2 * pi * pi * 25 * 5**2),
        "F_009": ((60, 30, 5), pi * 30 * 15 * 5),
        "F_010": ((80, 30, 6), (50 * 30 + disc(30)) * 6),
        "F_011": ((30, 30, 12), oct_area * 12),
        "F_012": ((30, 30, 45), 30 * 30 * 45 / 3),
        "F_013": ((40, 40, 20), 2 / 3 * pi * 20**3),
        "F_014": ((50.8, 25.4, 12.7), 50.8 * 25.4 * 12.7),
        "F_015": ((200, 40, 60), (2 * 40 * 5 + 4 * 50) * 200),
        "F_016": ((120, 50, 25), (50 * 25 - 42 * 21) * 120),
        "F_017": ((250, 40, 40), (40 * 40 - 34 * 34) * 250),
        # The base 40 deep from the inside corner, the wall behind it: 45 in Y.
        "F_018": ((50, 45, 60), 50 * 40 * 5 + 50 * 5 * 60),
        "F_019": ((40, 40, 40), 40**3 - disc(10) * 15),
        "F_020": ((50, 50, 20), 50 * 50 * 20 - disc(8) * 14 - disc(14) * 6),
        # Countersink 90 degrees from 4 to 8 mm: 2 mm deep, a frustum over the hole.
        "F_021": ((60, 40, 6), 60 * 40 * 6 - 4 * (disc(4) * 4 + pi * 2 / 3 * (2**2 + 2 * 4 + 4**2))),
        "F_022": ((80, 50, 5), 80 * 50 * 5 - (22 * 8 + disc(8)) * 5),
        "F_023": ((12.5 + sqrt(12.5**2 - 16), 25, 80), disc(25) * 80 - (circle_strip(12.5, 4) / 2 - 8.5 * 8) * 80),
        "F_024": ((20, 20, 60), disc(20) * 60 - (disc(20) - disc(17)) * 3),
        "F_025": ((60, 40, 20), 60 * 40 * 20 - 30 * 20 * 8),
        "F_026": ((20, 20, 15), disc(20) * 15 - 3 * sqrt(3) / 2 * (8 / sqrt(3)) ** 2 * 6),
        "F_027": ((25.4, 25.4, 2.54), (disc(25.4) - disc(12.7)) * 2.54),
        "F_028": ((100, 60, 8), 100 * 60 * 8 - 6 * disc(6) * 8),
        "F_029": ((80, 80, 10), (disc(80) - 8 * disc(6)) * 10),
        "F_030": ((120, 80, 10), (120 * 80 - 4 * disc(10)) * 10),
        "F_031": ((200, 30, 10), (200 * 30 - 5 * disc(8)) * 10),
        "F_032": ((100, 50, 6), (100 * 50 - disc(12) - disc(6)) * 6),
        "F_033": ((100, 100, 6), (disc(100) - 3 * disc(10)) * 6),
        "F_034": ((50, 40, 24), 50 * 40 * 4 + 6 * 2 * 40 * 20),
        "F_035": ((30, 20, 10), steiner(30, 20, 10, 2)),
        # Four edges of the top face chamfered 3: four prisms of 3 x 3 / 2, corners overlapping.
        "F_036": ((50, 50, 50), None),
        "F_037": ((100, 60, 40), 100 * 60 * 40 - 94 * 54 * 37),
        "F_038": ((30, 30, 50), cyl_fillet(15, 50, 2)),
        "F_039": ((90, 50, 10), (rounded_rect(90, 50, 6) - disc(20)) * 10),
        "F_040": ((62.5, 25, 62.5), (disc(25) - disc(20)) * pi / 2 * 50),
        "F_041": ((40, 40, 30), None),
        # Pappus on the knob's profile.
        "F_042": ((30, 30, 25), None),
        "F_044": ((30, 30, 75), disc(30) * 20 + disc(20) * 40 + disc(12) * 15),
        "F_045": ((60, 60, 100), disc(20) * 100 + (disc(60) - disc(20)) * 8),
        "F_046": (
            (120, 40, 80),
            disc(40) * 120 + disc(40) * 60 - 8 * 20**3 / 3 - (disc(32) * 120 + disc(32) * 60 - 8 * 16**3 / 3),
        ),
        "F_047": ((80, 80, 36), 80 * 80 * 6 + 4 * disc(10) * 30 - 4 * disc(4) * 36),
        "F_048": ((36, 36, 16), star(12, 18, 14) * 6 + disc(12) * 10 - disc(8) * 16),
    }
    t["F_049"] = ((50, 50, 20), (disc(50) - 4 * disc(5)) * 20)
    t["F_050"] = ((80, 40, 30), 80 * 40 * 30 - 50 * 20 * 10)
    t["F_051"] = ((30, 30, 50), (disc(30) - disc(20)) * 50)
    t["F_052"] = ((100, 30, 50), (2 * 30 * 4 + 42 * 3) * 100)
    t["F_053"] = ((40, 40, 40), 4 / 3 * pi * 20**3)
    af = 10 / cos(radians(30))
    t["F_054"] = ((af, 10, 5), (3 * sqrt(3) / 2 * (af / 2) ** 2 - disc(6)) * 5)
    t["F_055"] = ((200, 100, 10), (200 * 100 - 2 * disc(12)) * 10)
    t["F_056"] = ((25, 25, 25), 25**3 - disc(10) * 25)
    t["F_057"] = ((100, 100, 25), disc(100) * 10 + disc(40) * 15)
    t["F_058"] = ((120, 120, 12), (disc(120) - disc(60) - 8 * disc(10)) * 12)
    t["F_059"] = ((30, 30, 50), disc(30) * 50 / 3)
    t["F_060"] = ((100, 100, 8), (rounded_rect(100, 100, 2) - disc(30)) * 8)
    t["F_061"] = ((25.4, 25.4, 304.8), (disc(25.4) - disc(25.4 - 2 * 25.4 / 16)) * 304.8)
    t["F_062"] = ((50, 50, 100), (disc(50) - disc(40)) * 100)
    t["F_063"] = ((80, 80, 10), (disc(80) - 30 * 30) * 10)
    t["F_064"] = ((30, 30, 30), 30**3 - disc(10) * 5)
    t["F_065"] = ((150, 50, 40), (50 * 5 + 4 * 35) * 150)
    t["F_066"] = ((100, 60, 25), 100 * 60 * 5 + 100 * 5 * 20)
    t["F_067"] = ((80, 80, 10), (80 * 80 - 9 * disc(5)) * 10)
    # Points at 0, 72 … 288 degrees: X from the point at 0 to those at 144 and 216, Y between
    # the points at 72 and 288.
    t["F_068"] = ((30 + 30 * cos(radians(36)), 2 * 30 * sin(radians(72)), 8), star(5, 30, 12.5) * 8)
    # The knob: a 15 x 10 cylinder, a frustum from r 15 to 8 over 4 mm, an 8 x 11 cylinder.
    knob = disc(30) * 10 + pi * 4 / 3 * (15**2 + 15 * 8 + 8**2) + disc(16) * 11
    t["F_042"] = ((30, 30, 25), knob)
    # Three arms from the hub to 50 mm: the hub, and each arm's part outside it.
    arm = 8 * 50 - circle_strip(10, 4) / 2
    # Extents: +X to 50 (the 0-degree arm's end); -X to the 120/240 arms' corners at
    # 50 cos 120 - 4 sin 120; Y to the 120-degree arm's outer corner 50 sin 120 + 4 cos 120.
    x_min = 50 * cos(radians(120)) - 4 * sin(radians(120))
    y_max = 50 * sin(radians(120)) + 4 * abs(cos(radians(120)))
    t["F_043"] = ((50 - x_min, 2 * y_max, 5), (disc(20) + 3 * arm) * 5)
    return t
