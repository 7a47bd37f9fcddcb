"""Relations of support and use.

On, under, stacked, loaded, full of, leaning, each with, and an arm's reach. Thresholds
are in README.md.

Resting: a thing rests on a carrier when its lowest point is within 3 cm of one of the
carrier's support surfaces (group-5 sites; a carrier without any: the top of its collision
geometry) and its footprint centre lies over that surface (2 cm slack). A robot rests
where its root body's origin (its mounting plane) is.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from judge_common import Relation, Verdict, resolve
from judge_geometry import Arr, point_in_convex, point_segment_distance, poly_distance, project
from judge_rel_place import ahead, wall_contact
from judge_scene import Scene, Surface, Thing

REST_TOL_M = 0.03
REST_XY_SLACK_M = 0.02
# A surface this far or more below a carrier's top is inside it (a tote's floor).
OPEN_DEPTH_M = 0.02
UNDER_SLACK_M = 0.01
STACK_OFFSET_M = 0.25
FULL_SHARE = 0.75
FULL_PER_LEVEL = 2
FULL_LENGTH_SHARE = 0.5
UPRIGHT_DEG = 60.0
LEAN_WALL_M = 0.10
ON_FLOOR_M = 0.05
EACH_FRONT_M = (-0.35, 1.0)
EACH_LATERAL_M = 0.2
EACH_NEAR_M = 0.8

# Published maximum reach (shoulder to flange), manufacturers' data sheets: Universal
# Robots UR5e 850 mm and UR10e 1300 mm; Franka Emika Panda 855 mm; Kinova Gen3 7-DOF
# 902 mm; KUKA LBR iiwa 7 R800 800 mm; Rethink Sawyer 1260 mm; UFactory xArm 7 700 mm;
# Kinova JACO2 900 mm. Mobile manipulators reach as far as the arm they carry.
REACH_M = {
    "ur5e": 0.85,
    "robosuite_ur5e": 0.85,
    "menagerie_ur5e": 0.85,
    "menagerie_ur5e_2f85": 0.85,
    "ur10e": 1.30,
    "panda": 0.855,
    "robosuite_panda": 0.855,
    "mobile_manipulator": 0.855,
    "robosuite_panda_omron": 0.855,
    "kinova_gen3": 0.902,
    "robosuite_kinova3": 0.902,
    "robosuite_iiwa": 0.80,
    "robosuite_sawyer": 1.26,
    "robosuite_xarm7": 0.70,
    "robosuite_jaco": 0.90,
}


def _missing(key: str | None) -> Verdict:
    return Verdict.fail(f"no {key} in the scene")


def rests_on(item: Thing, carrier: Thing) -> str | None:
    """Return the surface of `carrier` that `item` rests on, or None."""
    if item is carrier or carrier.kind != "object":
        return None
    c, b = item.centre, item.bottom
    for s in carrier.surfaces:
        if abs(b - float(s.centre[2])) <= REST_TOL_M and s.contains_xy(c, REST_XY_SLACK_M):
            return s.name
    # Its top: a carrier without surfaces, or an open tote's rim (every surface is a floor
    # well inside it; totes are stacked rim on rim). Not a plate's rim: its surface is its
    # top, and a plate two below in a stack is not what the top one rests on.
    rim = all(carrier.top - float(s.centre[2]) >= OPEN_DEPTH_M for s in carrier.surfaces)
    if rim and abs(b - carrier.top) <= REST_TOL_M and point_in_convex(c, carrier.footprint, REST_XY_SLACK_M):
        return "top"
    return None


def on(rel: Relation, scene: Scene) -> Verdict:
    """Judge `on`.

    Every instance rests on an instance of the target, directly or on a stack of its own
    kind that does.
    """
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    held = {s.name: next((f"{t.name}:{n}" for t in tgts if (n := rests_on(s, t))), None) for s in subs}
    changed = True
    while changed:  # an item on an item of its own kind that is on the target
        changed = False
        for s in subs:
            if held[s.name] is None:
                for o in subs:
                    if held[o.name] is not None and rests_on(s, o):
                        held[s.name] = f"{o.name} (stacked)"
                        changed = True
                        break
    bad = [s for s in subs if held[s.name] is None]
    heights = []
    for s in bad:
        t = min(tgts, key=lambda x: poly_distance(s.footprint, x.footprint))
        top = max((float(x.centre[2]) for x in t.surfaces), default=t.top)
        heights.append(
            {
                "name": s.name,
                "nearest": t.name,
                "bottom_minus_top_m": s.bottom - top,
                "xy_gap_m": poly_distance(s.footprint, t.footprint),
            }
        )
    return Verdict.of(
        not bad,
        f"not on {rel.target}: {', '.join(b.name for b in bad)}",
        on=held,
        misses=heights,
    )


def under(rel: Relation, scene: Scene) -> Verdict:
    """Judge `under`.

    Every instance's footprint centre inside the target's footprint and its top below
    the target's highest support surface.
    """
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    bad, clear = [], []
    for s in subs:
        ok_any, best = False, math.inf
        for t in tgts:
            top = max((float(x.centre[2]) for x in t.surfaces), default=t.top)
            inside = point_in_convex(s.centre, t.footprint)
            if inside and s.top <= top + UNDER_SLACK_M:
                ok_any = True
            best = min(best, top - s.top if inside else -poly_distance(s.footprint, t.footprint) - 10.0)
        clear.append(best)
        if not ok_any:
            bad.append(s.name)
    return Verdict.of(not bad, f"not under {rel.target}: {', '.join(bad)}", headroom_m=clear)


def stacked(rel: Relation, scene: Scene) -> Verdict:
    """Judge `stacked`.

    The instances form `stacks` columns (default: as many as `n` each needs, else one)
    of `n` each (default: all), each resting on the one below, centres within 25 cm of
    the one below.
    """
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    below: dict[str, Thing | None] = {}
    for s in subs:
        below[s.name] = next((o for o in subs if o is not s and rests_on(s, o)), None)
    above: dict[str, list[Thing]] = {s.name: [] for s in subs}
    for s in subs:
        b = below[s.name]
        if b is not None:
            above[b.name].append(s)
    stacks, offsets, branching = [], [], False
    for s in subs:
        if below[s.name] is not None:
            continue
        size, cur = 1, s
        while above[cur.name]:
            branching = branching or len(above[cur.name]) > 1
            nxt = above[cur.name][0]
            offsets.append(float(np.linalg.norm(nxt.centre - cur.centre)))
            size, cur = size + 1, nxt
        stacks.append(size)
    real = [h for h in stacks if h >= 2]
    # "stacked two high" without a count of stacks: as many columns as that takes.
    want = rel.stacks or (math.ceil(len(subs) / rel.n) if rel.n else 1)
    probs = []
    if len(real) != want:
        probs.append(f"{len(real)} stack(s)")
    if any(h == 1 for h in stacks):
        probs.append(f"{sum(1 for h in stacks if h == 1)} not in a stack")
    if rel.n is not None and any(h != rel.n for h in real):
        probs.append(f"stack heights {real}, asked {rel.n}")
    if branching:
        probs.append("more than one item on one")
    if offsets and max(offsets) > STACK_OFFSET_M:
        probs.append(f"offset {max(offsets):.2f} m between layers")
    return Verdict.of(not probs, "; ".join(probs), heights=stacks, max_offset_m=max(offsets, default=0.0))


def loaded(rel: Relation, scene: Scene) -> Verdict:
    """Every carrier has at least one item resting on it."""
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    counts = [sum(1 for i in tgts if rests_on(i, c)) for c in subs]
    bad = [c.name for c, k in zip(subs, counts, strict=True) if k < 1]
    return Verdict.of(not bad, f"empty: {', '.join(bad)}", items_per_carrier=counts)


def full_of(rel: Relation, scene: Scene) -> Verdict:
    """Judge `full_of`.

    On every carrier, at least 75 % of its levels (sites named `_level_`, else all its
    support surfaces) are filled: two or more items, or items covering at least half the
    level's length (one bin that fills a narrow shelf).
    """
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    per, cover, bad = [], [], []
    for c in subs:
        levels = [s for s in c.surfaces if "_level_" in s.name] or c.surfaces
        counts, shares, filled = [], [], 0
        for lv in levels:
            items = [i for i in tgts if rests_on(i, c) == lv.name]
            share = _length_share(lv, items)
            counts.append(len(items))
            shares.append(share)
            filled += int(len(items) >= FULL_PER_LEVEL or share >= FULL_LENGTH_SHARE)
        per.append(counts)
        cover.append(shares)
        if not levels or filled < math.ceil(FULL_SHARE * len(levels)):
            bad.append(c.name)
    return Verdict.of(not bad, f"not full: {', '.join(bad)}", items_per_level=per, length_share_per_level=cover)


def _length_share(level: Surface, items: list[Thing]) -> float:
    """Return the share of a level's length its items cover (their union along its long side)."""
    k = 0 if level.half[0] >= level.half[1] else 1
    axis = level.rot[:2, k]
    c = float(level.centre[:2] @ axis)
    spans = sorted(project(i.footprint, axis) for i in items)
    covered, end = 0.0, -math.inf
    lo_lv, hi_lv = c - float(level.half[k]), c + float(level.half[k])
    for lo, hi in spans:
        lo, hi = max(lo, lo_lv, end), min(hi, hi_lv)
        if hi > lo:
            covered += hi - lo
            end = hi
    return covered / max(1e-9, hi_lv - lo_lv)


def leaning(rel: Relation, scene: Scene) -> Verdict:
    """Judge `leaning`.

    Every instance stands on edge (its thinnest axis at least 60° from vertical), on the
    floor, within 10 cm of the (named) wall.
    """
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    rows, bad = [], []
    for s in subs:
        ext = s.local_hi - s.local_lo
        k = int(np.argmin(ext))
        thin = s.rot[:, k]
        from_vertical = math.degrees(math.acos(min(1.0, abs(float(thin[2])))))
        side, gap, _, _ = wall_contact(scene.room, s, rel.wall)
        ok = from_vertical >= UPRIGHT_DEG and gap <= LEAN_WALL_M and s.bottom <= ON_FLOOR_M
        rows.append({"name": s.name, "thin_axis_from_vertical_deg": from_vertical, "wall": side, "gap_m": gap})
        if not ok:
            bad.append(s.name)
    return Verdict.of(not bad, f"not leaning on the wall: {', '.join(bad)}", items=rows)


def _pair_ok(x: Thing, y: Thing, where: str) -> bool:
    if where == "on":
        return rests_on(y, x) is not None
    if where == "near":
        return poly_distance(x.footprint, y.footprint) <= EACH_NEAR_M
    r = ahead(y, [x], back=where == "behind")
    return r is not None and EACH_FRONT_M[0] <= r[0] <= EACH_FRONT_M[1] and r[1] <= EACH_LATERAL_M


def _matching(xs: list[Thing], ys: list[Thing], ok: list[list[bool]]) -> int:
    match_y: dict[int, int] = {}

    def augment(i: int, seen: set[int]) -> bool:
        for j in range(len(ys)):
            if ok[i][j] and j not in seen:
                seen.add(j)
                if j not in match_y or augment(match_y[j], seen):
                    match_y[j] = i
                    return True
        return False

    return sum(1 for i in range(len(xs)) if augment(i, set()))


def each_with(rel: Relation, scene: Scene) -> Verdict:
    """Judge `each_with`.

    As many Y as X, paired one to one, each Y where a person uses it: `front` (default:
    0–1 m in front of its X, up to 35 cm tucked in, within its width ± 20 cm), `behind`,
    `on` (resting on its X) or `near` (within 0.8 m).
    """
    xs, ys = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not xs:
        return _missing(rel.subject)
    where = rel.where or "front"
    ok = [[_pair_ok(x, y, where) for y in ys] for x in xs]
    paired = _matching(xs, ys, ok)
    held = len(ys) == len(xs) and paired == len(xs)
    return Verdict.of(
        held,
        f"{len(ys)} {rel.target} for {len(xs)} {rel.subject}, {paired} placed {where}",
        subjects=len(xs),
        targets=len(ys),
        paired=paired,
    )


def _nearest_on_box(p: Arr, lo: Arr, hi: Arr) -> Arr:
    return np.minimum(np.maximum(p, lo), hi)


def _reach_points(t: Thing, scene: Scene, shoulder: Arr) -> tuple[str, float]:
    """Return what of a target an arm must reach, and the largest distance to it."""
    if t.category == "conveyor":
        top = max((float(s.centre[2]) for s in t.surfaces), default=t.top)
        ax = t.long_axis
        length = max(np.linalg.norm(t.footprint[1] - t.footprint[0]), np.linalg.norm(t.footprint[2] - t.footprint[1]))
        c = np.array([t.centre[0], t.centre[1], top])
        a3 = np.array([ax[0], ax[1], 0.0]) * float(length) / 2.0
        return "centreline", point_segment_distance(shoulder, c - a3, c + a3)
    if t.free:
        return "centre", float(np.linalg.norm(t.centre3 - shoulder))
    if t.surfaces:
        items = [o for o in scene.objects if o is not t and rests_on(o, t)]
        if items:
            return f"{len(items)} items on it", max(float(np.linalg.norm(o.centre3 - shoulder)) for o in items)
        s = max(t.surfaces, key=lambda x: float(x.centre[2]))
        local = s.rot.T @ (shoulder - s.centre)
        local = np.clip(local, -s.half, s.half)
        return "nearest point of its top", float(np.linalg.norm(s.centre + s.rot @ local - shoulder))
    return "nearest point", float(np.linalg.norm(_nearest_on_box(shoulder, t.world_lo, t.world_hi) - shoulder))


def reach(rel: Relation, scene: Scene) -> Verdict:
    """Judge `reach`.

    Every target instance (a conveyor: its centreline at belt height; a surface: every
    item resting on it; an item: its centre; a machine: its nearest point) within the
    published reach of some arm of the model, measured from the shoulder, and every such
    arm reaching at least one target instance. Where several arms share a surface, each
    item on it counts on its own: within the reach of one of them.
    """
    robots, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not robots:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    table: list[dict[str, Any]] = []
    # A work surface shared by several arms: each item on it within the reach of one of
    # them (an arm at each end of a bench, bins between them).
    work: list[Thing] = []
    for t in tgts:
        items = [o for o in scene.objects if o is not t and rests_on(o, t)] if t.surfaces and not t.free else []
        work += items if items and t.category != "conveyor" and len(robots) > 1 else [t]
    reached_t = {t.name: False for t in work}
    probs = []
    for r in robots:
        limit = REACH_M.get(r.category)
        if r.shoulder is None or limit is None:
            probs.append(f"{r.name}: no arm with a published reach")
            continue
        any_ok = False
        for t in work:
            what, dist = _reach_points(t, scene, r.shoulder)
            ok = dist <= limit
            any_ok = any_ok or ok
            reached_t[t.name] = reached_t[t.name] or ok
            table.append({"robot": r.name, "target": t.name, "what": what, "distance_m": dist, "reach_m": limit})
        if not any_ok:
            probs.append(f"{r.name} reaches no {rel.target}")
    out = [n for n, ok in reached_t.items() if not ok]
    if out:
        probs.append(f"out of reach: {', '.join(out)}")
    return Verdict.of(not probs, "; ".join(probs), pairs=table)
