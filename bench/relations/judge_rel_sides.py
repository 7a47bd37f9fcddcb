"""Relations of sides and ends: at the end of, on each side of, facing, on opposite walls,
in the corners, back to back. Thresholds are in README.md.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from judge_common import Relation, Verdict, resolve
from judge_geometry import Arr, angle_deg, interval_overlap, perp, poly_distance, project, unit
from judge_rel_fit import front_of
from judge_rel_place import CORNER_M, wall_contact
from judge_scene import Scene, Thing

END_GAP_M = (-0.05, 1.5)
END_OFFSET_M = 0.5
SIDE_M = 1.5
FACING_DEG = 30.0
FACING_GAP_M = (0.3, 5.0)
OPPOSITE = {"north": "south", "south": "north", "east": "west", "west": "east"}
BACK_TO_BACK_M = 0.3
BACK_TOL_DEG = 20.0


def _missing(key: str | None) -> Verdict:
    return Verdict.fail(f"no {key} in the scene")


def _end_of(s: Thing, t: Thing, axis: Arr | None) -> tuple[str | None, float, float]:
    """Return which end of t's axis s is beyond ('start' is −axis), the clear gap and the offset from the axis line."""
    d = axis if axis is not None else t.long_axis
    n = perp(d)
    lo_t, hi_t = project(t.footprint, d)
    lo_s, hi_s = project(s.footprint, d)
    off = abs(float((s.centre - t.centre) @ n))
    half_depth = (project(t.footprint, n)[1] - project(t.footprint, n)[0]) / 2.0
    gap_end, gap_start = lo_s - hi_t, lo_t - hi_s
    end = "end" if gap_end >= gap_start else "start"
    gap = max(gap_end, gap_start)
    ok = END_GAP_M[0] <= gap <= END_GAP_M[1] and off <= half_depth + END_OFFSET_M
    return (end if ok else None), gap, off


def at_end_of(rel: Relation, scene: Scene) -> Verdict:
    """Judge `at_end_of`.

    Every instance beyond an end of a target instance's long axis (clear gap −5 cm … 1.5 m,
    centre within the target's half depth + 0.5 m of its axis line). `end`: `start` / `end`
    are the target's local −X / +X ends (a conveyor's infeed and outfeed); `both`: the group
    has instances at both ends of one target.
    """
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    local = rel.end in ("start", "end")
    rows: list[dict[str, Any]] = []
    ends_of: dict[str, set[str]] = {t.name: set() for t in tgts}
    bad = []
    for s in subs:
        best: tuple[str | None, float, float, str] | None = None
        for t in tgts:
            axis = t.rot[:2, 0] if local else None
            end, gap, off = _end_of(s, t, axis)
            good = end is not None and (not local or end == rel.end)
            cand = (end if good else None, gap, off, t.name)
            if best is None or (cand[0] is not None and best[0] is None):
                best = cand
            if good:
                break
        assert best is not None
        rows.append({"name": s.name, "target": best[3], "end": best[0], "gap_m": best[1], "offset_m": best[2]})
        if best[0] is None:
            bad.append(s.name)
        else:
            ends_of[best[3]].add(best[0])
    why = f"not at {'the ' + rel.end if local else 'an'} end of {rel.target}: {', '.join(bad)}"
    ok = not bad
    if ok and rel.end == "both" and not any(len(e) == 2 for e in ends_of.values()):
        ok, why = False, "not at both ends of one " + str(rel.target)
    return Verdict.of(ok, why, ends=rows)


def _side(s: Thing, t: Thing) -> str:
    """Return the side of t that s is on, in t's frame: front (+Y), back, right (+X) or left."""
    c = t.local_centre_xy
    local = t.rot[:2, :2].T @ (s.centre - c)
    hx, hy = max(t.half_w, 1e-6), max(t.half_d, 1e-6)
    if abs(local[0]) / hx >= abs(local[1]) / hy:
        return "right" if local[0] > 0 else "left"
    return "front" if local[1] > 0 else "back"


PAIRS = (("left", "right"), ("front", "back"))


def on_each_side_of(rel: Relation, scene: Scene) -> Verdict:
    """Judge `on_each_side_of`.

    The subjects stand on two opposite sides of target instances (left and right, or front
    and back, in the target's frame), each within 1.5 m of the target it flanks; every
    target instance that has subjects has them on both sides of one pair, and as many
    targets are flanked as there are pairs of subjects (at least one).
    """
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    per: dict[str, list[str]] = {t.name: [] for t in tgts}
    rows, far = [], []
    for s in subs:
        t = min(tgts, key=lambda x: poly_distance(s.footprint, x.footprint))
        gap = poly_distance(s.footprint, t.footprint)
        side = _side(s, t)
        per[t.name].append(side)
        rows.append({"name": s.name, "target": t.name, "side": side, "gap_m": gap})
        if gap > SIDE_M:
            far.append(s.name)
    flanked, mixed = 0, []
    for name, sides in per.items():
        if not sides:
            continue
        pair = next((p for p in PAIRS if p[0] in sides and p[1] in sides), None)
        if pair is not None and all(x in pair for x in sides):
            flanked += 1
        else:
            mixed.append(name)
    want = max(1, min(len(tgts), len(subs) // 2))
    probs = []
    if far:
        probs.append(f"farther than {SIDE_M} m: {', '.join(far)}")
    if mixed:
        probs.append(f"not on two opposite sides of {', '.join(mixed)}")
    if flanked < want:
        probs.append(f"{flanked} of {want} {rel.target} flanked")
    return Verdict.of(not probs, "; ".join(probs), sides=rows)


def facing(rel: Relation, scene: Scene) -> Verdict:
    """Judge `facing`: every instance's front within 30° of the direction to a target's centre, 0.3–5 m clear of it."""
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    rows, bad = [], []
    for s in subs:
        f = front_of(s)
        best: tuple[float, float, str] | None = None
        for t in tgts:
            if t is s:
                continue
            to = unit(t.centre - s.centre)
            ang = angle_deg(f, to) if f is not None and to is not None else 180.0
            gap = poly_distance(s.footprint, t.footprint)
            score = (ang > FACING_DEG) + (not FACING_GAP_M[0] <= gap <= FACING_GAP_M[1])
            if best is None or score < ((best[0] > FACING_DEG) + (not FACING_GAP_M[0] <= best[1] <= FACING_GAP_M[1])):
                best = (ang, gap, t.name)
        if best is None:
            return _missing(rel.target)
        rows.append({"name": s.name, "target": best[2], "angle_deg": best[0], "gap_m": best[1]})
        if best[0] > FACING_DEG or not FACING_GAP_M[0] <= best[1] <= FACING_GAP_M[1]:
            bad.append(s.name)
    return Verdict.of(not bad, f"not facing {rel.target}: {', '.join(bad)}", facing=rows)


def on_opposite_walls(rel: Relation, scene: Scene) -> Verdict:
    """Judge `on_opposite_walls`.

    Every instance against a wall (as `against_wall`), the group using two opposite walls;
    with `long`, the room's two long walls.
    """
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    rows = [wall_contact(scene.room, s) for s in subs]
    bad = [s.name for s, r in zip(subs, rows, strict=True) if not r[3]]
    walls = sorted({r[0] for r in rows if r[3]})
    lx, ly = scene.room.size
    long_walls = ["north", "south"] if lx >= ly else ["east", "west"]
    opposite = len(walls) == 2 and OPPOSITE[walls[0]] == walls[1]
    ok = not bad and opposite and (not rel.long or sorted(walls) == sorted(long_walls))
    if bad:
        why = f"not against a wall: {', '.join(bad)}"
    elif not opposite:
        why = f"on {', '.join(walls)}: not two opposite walls"
    else:
        why = f"on {', '.join(walls)}, not the long walls ({', '.join(long_walls)})"
    return Verdict.of(ok, why, walls=walls, gap_m=[r[1] for r in rows])


def in_corners(rel: Relation, scene: Scene) -> Verdict:
    """Judge `in_corners`: every instance within 0.5 m of two perpendicular walls, no two in one corner."""
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    room = scene.room
    corners: list[str | None] = []
    for s in subs:
        ew = min(("east", "west"), key=lambda w: room.wall_gap(s.footprint, w))
        ns = min(("north", "south"), key=lambda w: room.wall_gap(s.footprint, w))
        ok = max(room.wall_gap(s.footprint, ew), room.wall_gap(s.footprint, ns)) <= CORNER_M
        corners.append(f"{ns}-{ew}" if ok else None)
    bad = [s.name for s, c in zip(subs, corners, strict=True) if c is None]
    taken = [c for c in corners if c is not None]
    shared = sorted({c for c in taken if taken.count(c) > 1})
    probs = []
    if bad:
        probs.append(f"not in a corner: {', '.join(bad)}")
    if shared:
        probs.append(f"two in one corner: {', '.join(shared)}")
    return Verdict.of(not probs, "; ".join(probs), corners=corners)


def back_to_back(rel: Relation, scene: Scene) -> Verdict:
    """Judge `back_to_back`.

    The group splits by front into two sets facing opposite ways (each member within 20°
    of its set's mean, the means anti-parallel within 20°), the sets' backs towards each
    other with a clear gap of at most 0.3 m between their back planes, overlapping
    side to side.
    """
    subs = resolve(scene, rel.subject)
    if len(subs) < 2:
        return Verdict.fail(f"{len(subs)} {rel.subject}: back to back needs two")
    fronts = [front_of(s) for s in subs]
    if any(f is None for f in fronts):
        return Verdict.fail("a member has no upright front")
    f0 = fronts[0]
    assert f0 is not None
    a = [s for s, f in zip(subs, fronts, strict=True) if f is not None and float(f @ f0) >= 0.0]
    b = [s for s, f in zip(subs, fronts, strict=True) if f is not None and float(f @ f0) < 0.0]
    if not a or not b:
        return Verdict.fail("all face one way")

    def mean(group: list[Thing]) -> Arr:
        v = unit(np.sum([front_of(s) for s in group], axis=0))
        return v if v is not None else np.array([1.0, 0.0])

    fa, fb = mean(a), mean(b)
    spread = max(angle_deg(front_of(s), fa) for s in a)  # type: ignore[arg-type]
    spread = max(spread, max(angle_deg(front_of(s), fb) for s in b))  # type: ignore[arg-type]
    anti = angle_deg(fa, -fb)
    # Backs towards each other: B stands behind A (along −fa), A behind B.
    back_a = min(project(s.footprint, fa)[0] for s in a)
    back_b = max(project(s.footprint, fa)[1] for s in b)
    gap = back_a - back_b
    side = perp(fa)
    lat_a = (min(project(s.footprint, side)[0] for s in a), max(project(s.footprint, side)[1] for s in a))
    lat_b = (min(project(s.footprint, side)[0] for s in b), max(project(s.footprint, side)[1] for s in b))
    overlap = interval_overlap(lat_a, lat_b)
    probs = []
    if spread > BACK_TOL_DEG or anti > BACK_TOL_DEG:
        probs.append(f"fronts not opposite (spread {spread:.0f}°, {anti:.0f}° off anti-parallel)")
    if not -0.02 <= gap <= BACK_TO_BACK_M:
        probs.append(f"backs {gap:.2f} m apart (at most {BACK_TO_BACK_M})")
    if overlap <= 0.0:
        probs.append("not opposite each other")
    return Verdict.of(
        not probs,
        "; ".join(probs),
        back_gap_m=gap,
        anti_parallel_deg=anti,
        overlap_m=overlap,
        groups=[len(a), len(b)],
    )
