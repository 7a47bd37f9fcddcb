"""Writes standard_100.refs.tsv: the reference extents and volumes of standard_100's T1 and
T2 prompts, computed by hand from each prompt's text (independent of the synthesizer).
Run: python3 bench/cad/refs.py (from the checkout root)."""
from math import pi, sqrt, sin, radians
import os

R3 = sqrt(3)


def hexa(R):  # regular hexagon, circumradius R
    return 3 * R3 / 2 * R * R


def ngon(n, R):
    return n / 2 * R * R * sin(2 * pi / n)


def star(n, R, r):  # star polygon of n points between radii R and r
    return n * R * r * sin(pi / n)


def steiner(a, b, c, r):  # box with every edge filleted r
    p, q, t = a - 2 * r, b - 2 * r, c - 2 * r
    return p * q * t + 2 * (p * q + q * t + p * t) * r + pi * (p + q + t) * r * r + 4 / 3 * pi * r**3


def cyl_chamfer(R, h, k):  # both circular edges chamfered k (Pappus)
    return pi * R * R * h - 2 * 2 * pi * (R - k / 3) * (k * k / 2)


def cyl_fillet(R, h, f):  # both circular edges filleted f (Pappus)
    A = f * f * (1 - pi / 4)
    xb = f * (5 / 6 - pi / 4) / (1 - pi / 4)
    return pi * R * R * h - 2 * 2 * pi * (R - xb) * A


def box_chamfer(a, b, c, k):  # every edge chamfered k
    return a * b * c - 2 * k * k * (a + b + c) + 6 * k**3


ROWS = [
    ("T1_001", (50, 30, 20), 50 * 30 * 20),
    ("T1_002", (25, 25, 40), pi * 12.5**2 * 40),
    ("T1_003", (30, 30, 30), 4 / 3 * pi * 15**3),
    ("T1_004", (30, 30, 45), pi * 15**2 * 45 / 3),
    ("T1_005", (40, 40, 40), 40**3),
    ("T1_006", (100, 60, 3), 100 * 60 * 3),
    ("T1_007", (20, 10 * R3, 35), hexa(10) * 35),
    ("T1_008", (50, 50, 25), 2 / 3 * pi * 25**3),
    ("T1_009", (50, 50, 2), pi * 625 * 2),
    ("T1_010", (8, 8, 150), pi * 16 * 150),
    ("T1_011", (200, 10, 10), 20000),
    ("T1_012", (15 * R3, 22.5, 50), 3 * R3 / 4 * 225 * 50),
    ("T1_013", (60, 20, 8), ((60 - 20) * 20 + pi * 100) * 8),
    ("T1_014", (40, 40, 15), ngon(8, 20) * 15),
    ("T1_015", (40, 40, 30), pi * 30 / 3 * (400 + 200 + 100)),
    ("T1_016", (40, 20, 25), pi * 20 * 10 * 25),
    ("T1_017", (80, 80, 5), 80 * 80 * 5),
    ("T1_018", (12.5 * (1 + 0.80901699), 25 * sin(radians(72)), 40), ngon(5, 12.5) * 40),
    ("T1_019", (120, 45, 15), 120 * 45 * 15),
    ("T1_020", (36, 36, 60), pi * 18**2 * 60),
    ("T1_021", (60, 30, 25), 0.5 * 30 * 25 * 60),
    ("T1_022", (10, 10, 10), 1000),
    ("T1_023", (50, 25, 15), (50 * 25 - (4 - pi) * 9) * 15),
    ("T1_024", (30, 30, 30), box_chamfer(30, 30, 30, 2)),
    ("T1_025", (50, 50, 4), pi * (625 - 156.25) * 4),
    ("T1_026", (30, 30, 80), pi * (225 - 144) * 80),
    ("T1_027", (70, 40, 25), steiner(70, 40, 25, 5)),
    ("T1_028", (40, 40, 23), pi * 400 * 3 + 2 / 3 * pi * 8000),
    ("T1_029", (20, 30, 40), 0.5 * 20 * 30 * 40),
    ("T1_030", (12, 12, 100), cyl_chamfer(6, 100, 1)),
    ("T1_031", (50, 30, 40), 40 / 6 * (50 * 30 + 4 * 40 * 22.5 + 30 * 15)),
    ("T1_032", (35, 35, 20), 3 * 17.5**2 * 20),
    ("T1_033", (50, 50, 10), 3 * 25**2 * 10),
    ("T1_034", (20, 20, 20), cyl_fillet(10, 20, 2)),
    ("T1_035", (35, 35, 50), 35 * 35 * 50),
    ("T1_036", (80, 80, 1), pi * 1600 * 1),
    ("T1_037", (40, 40, 50), 1600 * 50 / 3),
    ("T1_038", (15, 7.5 * R3, 120), hexa(7.5) * 120),
    ("T1_039", (25, 15, 10), box_chamfer(25, 15, 10, 1)),
    ("T1_040", (38, 38, 3), cyl_fillet(19, 3, 0.5)),
    ("T1_041", (40, 40, 12), pi * (400 - 225) * 12),
    ("T1_042", (90, 20, 8), (20 * 8 - (4 - pi) * 4) * 90),
    ("T1_043", (30, 30, 80), pi * 225 * 50 + 4 / 3 * pi * 15**3),
    ("T1_044", (60, 2, 80), 60 * 2 * 80),
    ("T1_045", (50, 70, 25), pi * (625 - 484) / 2 * 70),
    ("T1_046", (20, 20, 20), steiner(20, 20, 20, 3)),
    ("T1_047", (60, 60, 35), pi * 35 / 3 * (900 + 600 + 400)),
    ("T1_048", (150, 50, 30), 150 * 50 * 30),
    ("T1_049", (40, 40, 10), pi * 400 * 10),
    ("T1_050", (40, 20, 60), (40 * 20 - (4 - pi) * 16) * 60),
    ("T2_001", (20, 20, 2), pi * (100 - 5.25**2) * 2),
    ("T2_002", (19.6, 9.8 * R3, 8), (hexa(9.8) - pi * 25) * 8),
    ("T2_003", (19.6, 9.8 * R3, 37), pi * 25 * 30 + hexa(9.8) * 7),
    ("T2_004", (13, 13, 33), pi * 16 * 25 + pi * 6.5**2 * 8 - hexa(6.93 / 2) * 4),
    ("T2_005", (100, 20, 40), (2 * 20 * 3 + 34 * 2) * 100),
    ("T2_006", (40, 40, 50), 40 * 40 * 3 + 40 * 3 * 50 - 40 * 3 * 3),
    ("T2_007", (80, 40, 30), (40 * 30 - 34 * 27) * 80),
    ("T2_008", (80, 60, 5), 80 * 60 * 5 - 4 * pi * 2.1**2 * 5),
    ("T2_009", (30, 30, 33), pi * (225 * 3 + 100 * 30 - 25 * 33)),
    ("T2_010", (25, 25, 12), None),
    ("T2_011", (8, 8, 40), cyl_chamfer(4, 40, 1)),
    ("T2_012", (60, 40, 8), 60 * 40 * 8 - 4 * (pi * 2.75**2 * 5 + pi * 25 * 3)),
    ("T2_013", (60, 60, 8), pi * (900 - 100) * 8 - 6 * pi * 2.75**2 * 8),
    ("T2_014", (80, 30, 40), (30 * 40 - 26 * 36) * 80),
    ("T2_015", (10 + sqrt(91), 20, 60), None),
    ("T2_016", (14, 14, 35), pi * (9 * 10 + 25 * 20 + 49 * 5)),
    ("T2_017", (80, 30, 40), (3 * 37 + 30 * 3) * 80),
    ("T2_018", (40, 40, 8), (star(16, 20, 16) - pi * 25) * 8),
    ("T2_019", (30, 20, 25), 30 * 20 * 25 - 10 * 20 * 15 - pi * 9 * 10),
    ("T2_020", (60, 40, 30), None),
    ("T2_021", (60, 40, 18), 60 * 40 * 3 + 5 * 2 * 40 * 15),
    ("T2_022", (24, 24, 3), 24 * 24 * 3 - pi * 5.25**2 * 3),
    ("T2_023", (60, 25, 26), 2250 + 2250 + 3 * 25 * 26 - 2 * 1.5 * 25 * 3),
    ("T2_024", (45, 45, 20), star(16, 22.5, 16.875) * 8 + pi * 64 * 12 - pi * 16 * 20),
    ("T2_025", (40, 40, 55), pi * 400 * 5 + pi * 100 * 50 - 4 * pi * 9 * 5),
]

HEADER = """# Reference extents and volumes for standard_100 T1 and T2, computed by hand from each
# prompt's text by bench/cad/refs.py (independent of the synthesizer's reading).
# Columns: id<TAB>size_x_mm<TAB>size_y_mm<TAB>size_z_mm<TAB>volume_mm3 (- unknown)<TAB>reference mesh (- none).
# Extents are compared sorted (any orientation). Readings of ambiguous prompts: T1_043 caps are added
# to the 50 mm cylinder (80 mm overall); T2_006 wall and base share the corner (40 x 40 x 50).
"""

if __name__ == "__main__":
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "standard_100.refs.tsv")
    with open(out, "w") as f:
        f.write(HEADER)
        for id_, s, v in ROWS:
            vol = "-" if v is None else f"{v:.3f}"
            f.write(f"{id_}\t{s[0]:.4f}\t{s[1]:.4f}\t{s[2]:.4f}\t{vol}\t-\n")
