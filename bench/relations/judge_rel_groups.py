"""Relations of groups: in a row, in rows, in aisles, facing each other, around.

Rows are found without knowing how the layout built them: for every candidate direction
(the room's axes, each member's long axis, the group's principal axis and the direction
between every pair of members) the members' centres are sorted across that direction and
split wherever two neighbours are more than 0.6 m apart; a direction whose pieces meet the
relation's definition makes it hold. Thresholds are in README.md.
"""

from __future__ import annotations

import math
from itertools import pairwise
from typing import Any

import numpy as np

from judge_common import Relation, Verdict, resolve
from judge_geometry import (
    Arr,
    angle_deg,
    axis_angle_deg,
    interval_overlap,
    perp,
    point_in_convex,
    point_segment_distance,
    poly_distance,
    principal_axis,
    project,
    unit,
)
from judge_scene import Scene, Thing

ROW_SPLIT_M = 0.6
ROW_SPREAD_M = 0.4
ROW_GAP_M = 2.5
FRONT_TOL_DEG = 30.0
SIDE_BY_SIDE_DEG = 70.0
BACK_TO_BACK_M = 0.3
AISLE_M = (1.5, 3.5)
AISLE_OVERLAP = 0.5
FACING_TOL_DEG = 15.0
FACING_MEMBER_TOL_DEG = 20.0
FACING_GAP_M = (0.0, 3.5)
FACING_OVERLAP = 0.5
AROUND_SIDES = 3
AROUND_SIDE_SHARE = 0.25
AROUND_OPENING_M = 0.6
BARRIER_HEIGHT_M = 1.2
AROUND_MAX_M = 3.0


def _missing(key: str | None) -> Verdict:
    return Verdict.fail(f"no {key} in the scene")


def _directions(things: list[Thing]) -> list[Arr]:
    cands = [np.array([1.0, 0.0]), np.array([0.0, 1.0])]
    cs = np.array([t.centre for t in things])
    cands.append(principal_axis(cs))
    cands += [t.long_axis for t in things]
    for i in range(len(things)):
        for j in range(i + 1, len(things)):
            u = unit(cs[j] - cs[i])
            if u is not None:
                cands.append(u)
    out: list[Arr] = []
    for c in cands:
        if all(axis_angle_deg(c, o) > 0.5 for o in out):
            out.append(c)
    return out


def _split(things: list[Thing], d: Arr, split: float) -> list[list[Thing]]:
    n = perp(d)
    ordered = sorted(things, key=lambda t: float(t.centre @ n))
    rows: list[list[Thing]] = [[ordered[0]]]
    for t in ordered[1:]:
        if float(t.centre @ n) - float(rows[-1][-1].centre @ n) > split:
            rows.append([t])
        else:
            rows[-1].append(t)
    return rows


def _spread(row: list[Thing], d: Arr) -> float:
    v = [float(t.centre @ perp(d)) for t in row]
    return max(v) - min(v)


def _max_gap(row: list[Thing], d: Arr) -> float:
    ordered = sorted(row, key=lambda t: float(t.centre @ d))
    gaps = [project(b.footprint, d)[0] - project(a.footprint, d)[1] for a, b in pairwise(ordered)]
    return max(gaps, default=0.0)


def _orientation_problem(row: list[Thing], d: Arr) -> str | None:
    """Fixtures in a row stand side by side facing one way (fronts across the row)."""
    fixtures = [t for t in row if t.oriented and t.front is not None]
    if not fixtures:
        return None
    fronts = [t.front for t in fixtures if t.front is not None]
    if any(axis_angle_deg(f, d) < SIDE_BY_SIDE_DEG for f in fronts):
        return "fronts along the row (one behind another, not side by side)"
    mean = unit(np.sum(fronts, axis=0))
    if mean is None or any(angle_deg(f, mean) > FRONT_TOL_DEG for f in fronts):
        return "members of a row face different ways"
    return None


def _row_problems(row: list[Thing], d: Arr, min_size: int) -> list[str]:
    out = []
    if len(row) < min_size:
        out.append(f"a row of {len(row)}")
    if _spread(row, d) > ROW_SPREAD_M:
        out.append(f"centres {_spread(row, d):.2f} m off one line")
    if _max_gap(row, d) > ROW_GAP_M:
        out.append(f"a {_max_gap(row, d):.2f} m gap in the row")
    o = _orientation_problem(row, d)
    if o:
        out.append(o)
    return out


def _best(things: list[Thing], check: Any) -> tuple[list[str], dict[str, Any]]:
    """Return the candidate direction with the fewest problems: (problems, measured)."""
    best: tuple[list[str], dict[str, Any]] | None = None
    for d in _directions(things):
        probs, meas = check(d)
        if best is None or len(probs) < len(best[0]):
            best = (probs, meas)
        if not probs:
            break
    assert best is not None
    return best


def in_row(rel: Relation, scene: Scene) -> Verdict:
    """Judge `in_row`.

    All instances (at least two) on one line: centres within 0.4 m across it, clear gaps
    along it at most 2.5 m; fixtures side by side facing one way.
    """
    subs = resolve(scene, rel.subject)
    if len(subs) < 2:
        return Verdict.fail(f"{len(subs)} {rel.subject}: a row needs two")

    def check(d: Arr) -> tuple[list[str], dict[str, Any]]:
        return _row_problems(subs, d, 2), {
            "direction": [float(d[0]), float(d[1])],
            "spread_m": _spread(subs, d),
            "max_gap_m": _max_gap(subs, d),
        }

    probs, meas = _best(subs, check)
    return Verdict.of(not probs, "; ".join(probs), **meas)


def _rows_check(subs: list[Thing], d: Arr, n: int | None, m: int | None = None) -> tuple[list[str], dict[str, Any]]:
    rows = _split(subs, d, ROW_SPLIT_M)
    probs = []
    if (n is not None and len(rows) != n) or (n is None and len(rows) < 2):
        probs.append(f"{len(rows)} rows")
    sizes = [len(r) for r in rows]
    if n is not None and max(sizes) - min(sizes) > 1:
        probs.append(f"uneven rows {sizes}")
    # "rows of four": every row holds m, one may be shorter when the count is not a multiple.
    if m is not None and (sum(1 for k in sizes if k != m) > int(len(subs) % m != 0) or max(sizes) > m):
        probs.append(f"rows of {sizes}, asked {m} each")
    for r in rows:
        probs += _row_problems(r, d, 2)
    return probs, {
        "direction": [float(d[0]), float(d[1])],
        "row_sizes": [len(r) for r in rows],
        "spread_m": [_spread(r, d) for r in rows],
        "max_gap_m": [_max_gap(r, d) for r in rows],
    }


def in_rows(rel: Relation, scene: Scene) -> Verdict:
    """Judge `in_rows`: `n` parallel rows of (nearly) equal length (of `m` each when given), each a row as above."""
    subs = resolve(scene, rel.subject)
    if len(subs) < 2:
        return Verdict.fail(f"{len(subs)} {rel.subject}: rows need more")
    probs, meas = _best(subs, lambda d: _rows_check(subs, d, rel.n, rel.m))
    return Verdict.of(not probs, "; ".join(probs), **meas)


def _aisles_check(subs: list[Thing], d: Arr) -> tuple[list[str], dict[str, Any]]:
    rows = _split(subs, d, ROW_SPLIT_M)
    n = perp(d)
    probs = []
    if len(rows) < 2:
        probs.append("one row: no aisle")
    for r in rows:
        if _spread(r, d) > ROW_SPREAD_M:
            probs.append(f"centres {_spread(r, d):.2f} m off one line")
        o = _orientation_problem(r, d)
        if o:
            probs.append(o)
    corridors, overlaps = [], []
    for a, b in pairwise(rows):
        gap = min(project(t.footprint, n)[0] for t in b) - max(project(t.footprint, n)[1] for t in a)
        sa = (min(project(t.footprint, d)[0] for t in a), max(project(t.footprint, d)[1] for t in a))
        sb = (min(project(t.footprint, d)[0] for t in b), max(project(t.footprint, d)[1] for t in b))
        share = interval_overlap(sa, sb) / max(1e-9, min(sa[1] - sa[0], sb[1] - sb[0]))
        corridors.append(gap)
        overlaps.append(share)
        if gap <= BACK_TO_BACK_M:
            continue
        if not AISLE_M[0] <= gap <= AISLE_M[1]:
            probs.append(f"a {gap:.2f} m gap between rows")
        elif share < AISLE_OVERLAP:
            probs.append(f"rows overlap {share:.0%} along the aisle")
    if len(rows) >= 2 and not any(AISLE_M[0] <= g <= AISLE_M[1] for g in corridors):
        probs.append("no corridor of 1.5–3.5 m")
    return probs, {
        "direction": [float(d[0]), float(d[1])],
        "row_sizes": [len(r) for r in rows],
        "corridor_m": corridors,
        "along_overlap": overlaps,
    }


def in_aisles(rel: Relation, scene: Scene) -> Verdict:
    """Judge `in_aisles`.

    Parallel rows with corridors of 1.5–3.5 m between neighbours (or back to back, ≤ 0.3 m),
    neighbouring rows overlapping at least half along the corridor.
    """
    subs = resolve(scene, rel.subject)
    if len(subs) < 2:
        return Verdict.fail(f"{len(subs)} {rel.subject}: aisles need two rows")
    probs, meas = _best(subs, lambda d: _aisles_check(subs, d))
    return Verdict.of(not probs, "; ".join(probs), **meas)


def _two_groups(subs: list[Thing]) -> tuple[list[Thing], list[Thing]] | None:
    fronts = [t.front for t in subs]
    if len(subs) < 2 or any(f is None for f in fronts):
        return None
    fs = [f for f in fronts if f is not None]
    i, j = max(
        ((i, j) for i in range(len(fs)) for j in range(i + 1, len(fs))), key=lambda p: angle_deg(fs[p[0]], fs[p[1]])
    )
    a = [t for t, f in zip(subs, fs, strict=True) if angle_deg(f, fs[i]) <= angle_deg(f, fs[j])]
    b = [t for t in subs if t not in a]
    return (a, b) if b else None


def facing_each_other(rel: Relation, scene: Scene) -> Verdict:
    """Judge `facing_each_other`.

    Two groups (two members, two rows, or subject and target) whose fronts are
    anti-parallel within 15°, point towards each other, across a clear gap in range
    (default 0–3.5 m), the two groups opposite each other (≥ 50 % lateral overlap).
    """
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    if rel.target:
        tgts = resolve(scene, rel.target)
        if not tgts:
            return _missing(rel.target)
        groups: tuple[list[Thing], list[Thing]] | None = (subs, tgts)
    else:
        groups = _two_groups(subs)
    if groups is None:
        return Verdict.fail("fewer than two members, all facing one way, or one without an upright front")
    a, b = groups
    fa = unit(np.sum([t.front for t in a if t.front is not None], axis=0))
    fb = unit(np.sum([t.front for t in b if t.front is not None], axis=0))
    if fa is None or fb is None:
        return Verdict.fail("a group's fronts cancel out")
    anti = angle_deg(fa, -fb)
    spread = max(
        [angle_deg(t.front, fa) for t in a if t.front is not None]
        + [angle_deg(t.front, fb) for t in b if t.front is not None]
    )
    ca, cb = np.mean([t.centre for t in a], axis=0), np.mean([t.centre for t in b], axis=0)
    towards = float((cb - ca) @ fa) > 0 and float((ca - cb) @ fb) > 0
    gap = min(project(t.footprint, fa)[0] for t in b) - max(project(t.footprint, fa)[1] for t in a)
    side = perp(fa)
    la = (min(project(t.footprint, side)[0] for t in a), max(project(t.footprint, side)[1] for t in a))
    lb = (min(project(t.footprint, side)[0] for t in b), max(project(t.footprint, side)[1] for t in b))
    lateral = interval_overlap(la, lb) / max(1e-9, min(la[1] - la[0], lb[1] - lb[0]))
    lo, hi = rel.gap_m or FACING_GAP_M
    probs = []
    if anti > FACING_TOL_DEG or spread > FACING_MEMBER_TOL_DEG:
        probs.append(f"fronts {anti:.0f}° from opposite (members within {spread:.0f}°)")
    if not towards:
        probs.append("fronts point away from each other")
    if not lo - 0.02 <= gap <= hi:
        probs.append(f"gap {gap:.2f} m not in {lo}–{hi} m")
    if lateral < FACING_OVERLAP:
        probs.append(f"only {lateral:.0%} opposite each other")
    return Verdict.of(
        not probs,
        "; ".join(probs),
        groups=[len(a), len(b)],
        anti_parallel_deg=anti,
        member_spread_deg=spread,
        gap_m=gap,
        lateral_overlap=lateral,
    )


def _bins(a: float, b: float) -> list[int]:
    """Return the whole-degree bins an angular interval [a, b] (degrees, b >= a) covers."""
    if b - a >= 360.0:
        return list(range(360))
    return [k % 360 for k in range(math.floor(a), math.ceil(b))]


def _largest_gap(covered: list[bool]) -> tuple[int, int]:
    """Return the longest circular run of uncovered bins: (length, first bin)."""
    if not any(covered):
        return 360, 0
    start = next(k for k in range(360) if covered[k])
    best, best_at, run = 0, 0, 0
    for k in range(start, start + 360):
        if covered[k % 360]:
            run = 0
        else:
            run += 1
            if run > best:
                best, best_at = run, (k - run + 1) % 360
    return best, best_at


def _distance_from(p: Arr, poly: Arr) -> float:
    """Return the distance from a point to a convex polygon (0 inside)."""
    if point_in_convex(p, poly):
        return 0.0
    return min(point_segment_distance(p, poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly)))


def around(rel: Relation, scene: Scene) -> Verdict:
    """Judge `around`.

    Pieces on at least three sides of the target, each within 3 m of it; barriers (pieces
    1.2 m tall or more: screens, fences) leave an opening at least 0.6 m wide. Seen from
    the target's centre in its own frame, the sides are the four sectors cut by the
    diagonals of its footprint grown by 0.5 m; a side is taken when the pieces cover at
    least a quarter of its sector.
    """
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    centroid = np.mean([s.centre for s in subs], axis=0)
    t = min(tgts, key=lambda x: float(np.linalg.norm(x.centre - centroid)))
    tc = t.centre if t.kind == "object" else np.asarray(t.pos[:2], dtype=np.float64)
    ax = unit(t.rot[:2, 0])
    if ax is None:
        ax = np.array([1.0, 0.0])
    yaw = math.degrees(math.atan2(ax[1], ax[0]))
    covered = [False] * 360
    owner: list[Thing | None] = [None] * 360
    gaps = []
    for s in subs:
        v = s.centre - tc
        theta = math.degrees(math.atan2(v[1], v[0])) - yaw
        deltas = []
        for p in s.footprint:
            q = p - tc
            dd = math.degrees(math.atan2(q[1], q[0])) - yaw - theta
            deltas.append((dd + 180.0) % 360.0 - 180.0)
        for k in _bins(theta + min(deltas), theta + max(deltas)):
            covered[k] = True
            owner[k] = s
        gaps.append(poly_distance(s.footprint, t.footprint))
    diag = math.degrees(math.atan2(t.half_d + 0.5, t.half_w + 0.5))
    sectors = {
        "+x": _bins(-diag, diag),
        "+y": _bins(diag, 180.0 - diag),
        "-x": _bins(180.0 - diag, 180.0 + diag),
        "-y": _bins(180.0 + diag, 360.0 - diag),
    }
    share = {k: sum(covered[b] for b in v) / max(1, len(v)) for k, v in sectors.items()}
    sides = sorted(k for k, f in share.items() if f >= AROUND_SIDE_SHARE)
    gap_deg, gap_at = _largest_gap(covered)
    # The opening: the two pieces flanking the widest angular gap, the larger of their clear
    # distance and the chord the gap spans at the nearer piece's distance from the centre.
    left, right = owner[(gap_at - 1) % 360], owner[(gap_at + gap_deg) % 360]
    if gap_deg == 0:
        opening = 0.0
    elif gap_deg >= 360 or left is None or right is None or left is right:
        opening = math.inf
    else:
        r = min(_distance_from(tc, left.footprint), _distance_from(tc, right.footprint))
        chord = 2.0 * r * math.sin(math.radians(min(gap_deg, 180)) / 2.0)
        opening = max(poly_distance(left.footprint, right.footprint), chord)
    barriers = all(s.top - s.bottom >= BARRIER_HEIGHT_M for s in subs)
    probs = []
    if len(sides) < AROUND_SIDES:
        probs.append(f"on {len(sides)} side(s) of {t.name}")
    if barriers and opening < AROUND_OPENING_M:
        probs.append(f"closed: the widest opening is {opening:.2f} m")
    if max(gaps) > AROUND_MAX_M:
        probs.append(f"a piece {max(gaps):.2f} m away")
    return Verdict.of(
        not probs,
        "; ".join(probs),
        target=t.name,
        sides=sides,
        side_cover=share,
        largest_opening_deg=gap_deg,
        opening_m=opening if math.isfinite(opening) else None,
        barriers=barriers,
        max_gap_m=max(gaps),
    )
