"""Scores `scenewright assets generate` on a wild corpus file, the way README.md says.

Each description is run through the binary; a part it makes is measured here, from the mesh it
writes (part.stl, metres), never from its own report: sorted extents against refs.tsv (1 %),
the mesh's enclosed volume (2 %) and whether every edge joins exactly two triangles, once each
way (watertight and consistently oriented). A `make` row is exact, refused (exit 2) or wrong;
a `refuse` row is refused quoting its words, refused with other words, or wrong (a part made).
Anything else (a crash, a timeout, exit 1) is an error.

    python3 bench/cad/wild/score.py bench/cad/wild/dev.tsv [--bin target/release/scenewright] [--json OUT]

Score heldout.tsv only at the end of a session. Standard library only.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
from collections import Counter, defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
EXTENT_TOL, VOLUME_TOL = 0.01, 0.02
TIMEOUT_S = 120
STOP = {"a", "an", "the", "with", "of", "and", "on", "in", "x", "mm", "to", "at", "is", "it", "its"}

Vec = tuple[float, float, float]


def read_rows(path: str) -> list[dict[str, str]]:
    with open(path, encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines, delimiter="\t", quoting=csv.QUOTE_NONE))


def read_refs() -> dict[str, tuple[list[float], float]]:
    """Every reference table: refs.tsv (rebuilt by refs.py) and refs_<set>.tsv beside it
    (sets frozen with builders of their own, e.g. refs_h3.tsv by refs_h3.py)."""
    refs: dict[str, tuple[list[float], float]] = {}
    tables = ["refs.tsv", *sorted(f for f in os.listdir(HERE) if f.startswith("refs_") and f.endswith(".tsv"))]
    rows = [row for t in tables for row in read_rows(os.path.join(HERE, t))]
    for row in rows:
        if row["bbox_mm"] != "refuse":
            refs[row["id"]] = ([float(v) for v in row["bbox_mm"].split(",")], float(row["volume_mm3"]))
    return refs


def read_stl(path: str) -> list[tuple[Vec, Vec, Vec]]:
    """The triangles of a binary or ASCII STL."""
    with open(path, "rb") as f:
        data = f.read()
    if len(data) >= 84:
        (n,) = struct.unpack_from("<I", data, 80)
        if 84 + 50 * n == len(data):
            tris = []
            for i in range(n):
                v = struct.unpack_from("<12f", data, 84 + 50 * i)
                tris.append(((v[3], v[4], v[5]), (v[6], v[7], v[8]), (v[9], v[10], v[11])))
            return tris
    pts = [tuple(float(x) for x in m.groups()) for m in re.finditer(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)]
    return [(pts[i], pts[i + 1], pts[i + 2]) for i in range(0, len(pts) - 2, 3)]  # type: ignore[misc]


def measure(tris: list[tuple[Vec, Vec, Vec]], scale: float) -> tuple[list[float], float, bool]:
    """Sorted extents and enclosed volume (scaled to mm), and watertightness."""
    lo = [min(t[k][i] for t in tris for k in range(3)) for i in range(3)]
    hi = [max(t[k][i] for t in tris for k in range(3)) for i in range(3)]
    vol = 0.0
    directed: Counter[tuple[Vec, Vec]] = Counter()
    for a, b, c in tris:
        vol += (
            a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
        ) / 6
        directed.update([(a, b), (b, c), (c, a)])
    watertight = all(n == 1 and directed.get((q, p), 0) == 1 for (p, q), n in directed.items())
    ext = sorted(((h - lo_) * scale for lo_, h in zip(lo, hi, strict=True)), reverse=True)
    return ext, abs(vol) * scale**3, watertight


def tokens(text: str) -> set[str]:
    return {t for t in re.findall(r"\d+(?:\.\d+)?|[a-zø']+", text.lower()) if t not in STOP}


def judge(row: dict[str, str], rc: int, stderr: str, out: str, refs: dict[str, tuple[list[float], float]]) -> str:
    if rc == 2:
        if row["expected"] == "make":
            return "refused"
        quoted = " ".join(re.findall(r'"([^"]*)"', stderr))
        return "refused_quoting" if tokens(quoted) & tokens(row["refuse_words"]) else "refused_other"
    if rc != 0:
        return "error"
    if row["expected"] == "refuse":
        return "wrong"
    stl = os.path.join(out, "part.stl")
    if not os.path.exists(stl):
        return "wrong"
    ext, vol, watertight = measure(read_stl(stl), 1000.0)
    want_ext, want_vol = refs[row["id"]]
    box_ok = all(abs(g - w) <= EXTENT_TOL * w for g, w in zip(ext, want_ext, strict=True))
    vol_ok = abs(vol - want_vol) <= VOLUME_TOL * want_vol
    return "exact" if box_ok and vol_ok and watertight else "wrong"


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("suite")
    ap.add_argument("--bin", default=None, help="the scenewright binary (default: target/release, else target/debug)")
    ap.add_argument("--json", default=None, help="write every row's outcome here")
    ap.add_argument("--summary", action="store_true", help="no per-part lines (for a held-out set)")
    args = ap.parse_args(argv)
    binary = args.bin or next(
        (
            p
            for p in (os.path.join(ROOT, "target", d, "scenewright") for d in ("release", "debug"))
            if os.path.exists(p)
        ),
        "scenewright",
    )
    refs = read_refs()
    rows = read_rows(args.suite)
    outcomes: list[dict[str, str]] = []
    with tempfile.TemporaryDirectory(prefix="wild-score-") as tmp:
        for row in rows:
            out = os.path.join(tmp, row["id"])
            cmd = [binary, "assets", "generate", row["description"], "--out", out, "--no-preview", "--no-store"]
            try:
                p = subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT_S, check=False)
                rc, err = p.returncode, p.stderr.strip()
            except subprocess.TimeoutExpired:
                rc, err = -1, "timeout"
            outcome = judge(row, rc, err, out, refs)
            outcomes.append(
                {"id": row["id"], "style": row["style"], "level": row["level"], "outcome": outcome, "stderr": err[:300]}
            )
    by: dict[str, Counter[str]] = defaultdict(Counter)
    for o in outcomes:
        for key in ("all", o["style"], o["level"]):
            by[key][o["outcome"]] += 1
    kinds = ["exact", "refused", "refused_quoting", "refused_other", "wrong", "error"]
    print(f"{os.path.basename(args.suite)}: " + ", ".join(f"{k} {by['all'][k]}" for k in kinds))
    for key in sorted(k for k in by if k != "all"):
        print(f"  {key:11s} " + " ".join(f"{k} {by[key][k]}" for k in kinds if by[key][k]))
    for o in [] if args.summary else outcomes:
        if o["outcome"] in ("wrong", "error"):
            print(f"  {o['outcome']}: {o['id']} {o['stderr'][:120]}")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(outcomes, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
