"""Relations of place.

Walls, corners, the door, the room's ends and middle, proximity, between, in front of /
behind, and at the end of a row. Thresholds are in README.md.
"""

from __future__ import annotations

import math

import numpy as np

from judge_common import Relation, Verdict, names, resolve
from judge_geometry import (
    Arr,
    angle_deg,
    axis_angle_deg,
    convex_hull,
    overlap_depth,
    perp,
    point_in_convex,
    poly_distance,
    principal_axis,
    project,
    shrink,
    unit,
)
from judge_scene import Room, Scene, Thing

WALL_GAP_M = 0.15
FRONT_TOL_DEG = 30.0
NEXT_TO_M = 0.6
NEAR_M = 1.5
CORNER_M = 0.5
DOOR_M = 2.0
END_FRACTION = 1.0 / 3.0
MIDDLE_FRACTION = 1.0 / 6.0
FRONT_MAX_M = 2.5
FRONT_TUCK_M = 0.25
LATERAL_SLACK_M = 0.3
PARALLEL_TOL_DEG = 20.0
ROW_END_GAP_M = 1.5
ROW_END_OFFSET_M = 0.5
SIDES = ("north", "south", "east", "west")


def _missing(key: str | None) -> Verdict:
    return Verdict.fail(f"no {key} in the scene")


def wall_contact(room: Room, t: Thing, side: str | None = None) -> tuple[str, float, float | None, bool]:
    """Find the wall a thing stands against: (side, clear gap, front angle to the inward normal, ok).

    A thing is against a wall when its footprint is within 15 cm of the wall's inner face
    and, for an oriented fixture, its front points into the room within 30 degrees (its back
    is to the wall).
    """
    rows = []
    for s in [side] if side else list(SIDES):
        gap = room.wall_gap(t.footprint, s)
        front = t.front
        ang = angle_deg(front, Room.inward(s)) if front is not None and t.oriented else None
        ok = gap <= WALL_GAP_M and (ang is None or ang <= FRONT_TOL_DEG)
        rows.append((s, gap, ang, ok))
    # In a corner two walls are near: the one its back is to.
    return min(rows, key=lambda r: (not r[3], r[1]))


def against_wall(rel: Relation, scene: Scene) -> Verdict:
    """Every instance against the named wall (or any wall)."""
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    rows = [wall_contact(scene.room, s, rel.wall) for s in subs]
    bad = [s.name for s, r in zip(subs, rows, strict=True) if not r[3]]
    return Verdict.of(
        not bad,
        f"not against {('the ' + rel.wall + ' wall') if rel.wall else 'a wall'}: {', '.join(bad)}",
        walls=[r[0] for r in rows],
        gap_m=[r[1] for r in rows],
        front_angle_deg=[r[2] for r in rows],
    )


def on_two_walls(rel: Relation, scene: Scene) -> Verdict:
    """Every instance against a wall, the group spread over exactly two walls."""
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    rows = [wall_contact(scene.room, s) for s in subs]
    bad = [s.name for s, r in zip(subs, rows, strict=True) if not r[3]]
    walls = sorted({r[0] for s, r in zip(subs, rows, strict=True) if r[3]})
    want = sorted(rel.walls) if rel.walls else None
    ok = not bad and len(walls) == 2 and (want is None or walls == want)
    why = f"not against a wall: {', '.join(bad)}" if bad else f"on {len(walls)} walls ({', '.join(walls)})"
    return Verdict.of(ok, why, walls=walls, gap_m=[r[1] for r in rows])


def _proximity(rel: Relation, scene: Scene, limit: float) -> Verdict:
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    gaps = []
    for s in subs:
        others = [t for t in tgts if t is not s]
        gaps.append(min((poly_distance(s.footprint, t.footprint) for t in others), default=math.inf))
    bad = [s.name for s, g in zip(subs, gaps, strict=True) if g > limit]
    return Verdict.of(not bad, f"farther than {limit} m: {', '.join(bad)}", gap_m=gaps, limit_m=limit)


def next_to(rel: Relation, scene: Scene) -> Verdict:
    """Every instance within 0.6 m (clear gap) of an instance of the target."""
    return _proximity(rel, scene, NEXT_TO_M)


def near(rel: Relation, scene: Scene) -> Verdict:
    """Every instance within 1.5 m (clear gap) of an instance of the target."""
    return _proximity(rel, scene, NEAR_M)


def _between_pair(s: Thing, a: Thing, b: Thing) -> bool:
    hull = convex_hull(np.vstack([a.footprint, b.footprint]))
    c = s.centre
    if not point_in_convex(c, hull, margin=-0.01):
        return False
    inner = shrink(s.footprint, 0.02)
    return overlap_depth(inner, a.footprint) <= 0.0 and overlap_depth(inner, b.footprint) <= 0.0


def between(rel: Relation, scene: Scene) -> Verdict:
    """Judge `between`.

    Every instance inside the hull of a pair (A and B, or two members of one group),
    its centre outside both and its footprint not overlapping either.
    """
    subs = resolve(scene, rel.subject)
    first = resolve(scene, rel.target)
    second = resolve(scene, rel.target2) if rel.target2 else first
    if not subs:
        return _missing(rel.subject)
    if not first or not second:
        return _missing(rel.target if not first else rel.target2)
    found: list[list[str] | None] = []
    for s in subs:
        pair = next(
            ([a.name, b.name] for a in first for b in second if a is not b and _between_pair(s, a, b)),
            None,
        )
        found.append(pair)
    bad = [s.name for s, p in zip(subs, found, strict=True) if p is None]
    return Verdict.of(not bad, f"not between two {rel.target}: {', '.join(bad)}", pairs=found)


def _long_axis_room(room: Room) -> tuple[int, float, float]:
    lx, ly = room.size
    return (0, lx, ly) if lx >= ly else (1, ly, lx)


def at_end(rel: Relation, scene: Scene) -> Verdict:
    """Every instance's centre in the outer third of the room's long axis, all at one end."""
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    room = scene.room
    axis, length, _ = _long_axis_room(room)
    lo, hi = (room.xmin, room.xmax) if axis == 0 else (room.ymin, room.ymax)
    ends, dists = [], []
    for s in subs:
        c = float(s.centre[axis])
        ends.append("low" if c - lo <= hi - c else "high")
        dists.append(min(c - lo, hi - c))
    limit = length * END_FRACTION
    ok = len(set(ends)) == 1 and all(x <= limit for x in dists)
    return Verdict.of(
        ok,
        f"centre to the nearer end wall {max(dists):.2f} m (limit {limit:.2f}) or split between ends",
        end_distance_m=dists,
        limit_m=limit,
        ends=ends,
    )


def in_middle(rel: Relation, scene: Scene) -> Verdict:
    """Judge `in_middle`.

    One object: its centre in the central third of the room both ways. A group ("down the
    middle"): every centre in the central third across the long axis, the group's mean in
    the central third along it.
    """
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    room = scene.room
    axis, length, width = _long_axis_room(room)
    rc = room.centre
    along = [abs(float(s.centre[axis] - rc[axis])) for s in subs]
    across = [abs(float(s.centre[1 - axis] - rc[1 - axis])) for s in subs]
    mean_along = abs(float(np.mean([s.centre[axis] for s in subs]) - rc[axis]))
    ok = all(a <= width * MIDDLE_FRACTION for a in across) and mean_along <= length * MIDDLE_FRACTION
    if len(subs) == 1:
        ok = ok and along[0] <= length * MIDDLE_FRACTION
    return Verdict.of(
        ok,
        "off the middle of the room",
        off_centre_across_m=across,
        off_centre_along_m=along,
        limit_across_m=width * MIDDLE_FRACTION,
        limit_along_m=length * MIDDLE_FRACTION,
    )


def in_corner(rel: Relation, scene: Scene) -> Verdict:
    """Every instance within 0.5 m of two perpendicular walls."""
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    room = scene.room
    corners, bad = [], []
    for s in subs:
        ew = min(("east", "west"), key=lambda w: room.wall_gap(s.footprint, w))
        ns = min(("north", "south"), key=lambda w: room.wall_gap(s.footprint, w))
        g1, g2 = room.wall_gap(s.footprint, ew), room.wall_gap(s.footprint, ns)
        corners.append({"corner": f"{ns}-{ew}", "gaps_m": [g2, g1]})
        if max(g1, g2) > CORNER_M:
            bad.append(s.name)
    return Verdict.of(not bad, f"not within {CORNER_M} m of two walls: {', '.join(bad)}", corners=corners)


def near_door(rel: Relation, scene: Scene) -> Verdict:
    """Every instance within 2 m of a doorway's floor area and not standing in it."""
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    doors = scene.room.doors
    if not doors:
        return Verdict.fail("the scene has no door")
    gaps, blocking = [], []
    for s in subs:
        gaps.append(min(poly_distance(s.footprint, d) for d in doors))
        if any(overlap_depth(s.footprint, d) > 0.02 for d in doors):
            blocking.append(s.name)
    bad = [s.name for s, g in zip(subs, gaps, strict=True) if g > DOOR_M]
    why = f"farther than {DOOR_M} m from the door: {', '.join(bad)}" if bad else f"in the doorway: {blocking}"
    return Verdict.of(not bad and not blocking, why, door_gap_m=gaps)


def _frame(group: list[Thing], back: bool) -> tuple[Arr, float, tuple[float, float]] | None:
    """Return a group's common facing direction, its front (or back) plane and lateral extent."""
    fronts = [t.front for t in group]
    if any(f is None for f in fronts):
        return None
    fs = [f for f in fronts if f is not None]
    mean = unit(np.sum(fs, axis=0))
    if mean is None or any(angle_deg(f, mean) > FRONT_TOL_DEG for f in fs):
        return None
    f = -mean if back else mean
    side = perp(f)
    plane = max(project(t.footprint, f)[1] for t in group)
    lat = (min(project(t.footprint, side)[0] for t in group), max(project(t.footprint, side)[1] for t in group))
    return f, plane, lat


def ahead(s: Thing, group: list[Thing], back: bool) -> tuple[float, float] | None:
    """(distance of s's centre beyond the face, lateral excess) or None without a front."""
    fr = _frame(group, back)
    if fr is None:
        return None
    f, plane, lat = fr
    c = s.centre
    a = float(c @ f) - plane
    lc = float(c @ perp(f))
    excess = max(0.0, lat[0] - lc, lc - lat[1])
    return a, excess


def _in_front(rel: Relation, scene: Scene, back: bool) -> Verdict:
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    side = "behind" if back else "in front of"
    dists, laterals, parallels, bad = [], [], [], []
    for s in subs:
        # The group as a row first, then each member alone; the first that holds, else the
        # one that misses least.
        options = [tgts] + [[t] for t in tgts] if len(tgts) > 1 else [tgts]
        scored = []
        for g in options:
            r = ahead(s, g, back)
            if r is not None:
                miss = r[1] + max(0.0, -FRONT_TUCK_M - r[0]) + max(0.0, r[0] - FRONT_MAX_M)
                scored.append((miss, r[0], r[1], g))
        if not scored:
            return Verdict.fail(f"{rel.target} has no upright front to be {side}")
        best = min(scored, key=lambda x: x[0])
        _, a, ex, g = best
        par = None
        if rel.parallel:
            row = principal_axis(np.array([t.centre for t in g])) if len(g) > 1 else g[0].long_axis
            par = axis_angle_deg(s.long_axis, row)
        dists.append(a)
        laterals.append(ex)
        parallels.append(par)
        ok = -FRONT_TUCK_M <= a <= FRONT_MAX_M and ex <= LATERAL_SLACK_M
        if par is not None and par > PARALLEL_TOL_DEG:
            ok = False
        if not ok:
            bad.append(s.name)
    measured: dict[str, list[float] | list[float | None]] = {"beyond_face_m": dists, "lateral_excess_m": laterals}
    if rel.parallel:
        measured["axis_angle_deg"] = parallels
    return Verdict.of(not bad, f"not {side} {rel.target}: {', '.join(bad)}", **measured)


def in_front_of(rel: Relation, scene: Scene) -> Verdict:
    """Judge `in_front_of`.

    Every instance's centre 0–2.5 m beyond the target's front face (up to 25 cm tucked in),
    within its width (± 30 cm); a target group facing one way counts as one row.
    """
    return _in_front(rel, scene, back=False)


def behind(rel: Relation, scene: Scene) -> Verdict:
    """As `in_front_of`, beyond the back face."""
    return _in_front(rel, scene, back=True)


def at_end_of_row(rel: Relation, scene: Scene) -> Verdict:
    """Judge `at_end_of_row`.

    Every instance beyond an end of the target row (a single target: its long axis), the
    clear gap to the row's end at most 1.5 m, centred on the row's line within 0.5 m plus
    the row's half depth.
    """
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    d = principal_axis(np.array([t.centre for t in tgts])) if len(tgts) > 1 else tgts[0].long_axis
    n = perp(d)
    span = (min(project(t.footprint, d)[0] for t in tgts), max(project(t.footprint, d)[1] for t in tgts))
    line = float(np.mean([t.centre @ n for t in tgts]))
    half_depth = max((project(t.footprint, n)[1] - project(t.footprint, n)[0]) / 2.0 for t in tgts)
    gaps, offsets, bad = [], [], []
    for s in subs:
        lo, hi = project(s.footprint, d)
        gap = max(lo - span[1], span[0] - hi)
        off = abs(float(s.centre @ n) - line)
        gaps.append(gap)
        offsets.append(off)
        if not (-0.05 <= gap <= ROW_END_GAP_M and off <= half_depth + ROW_END_OFFSET_M):
            bad.append(s.name)
    return Verdict.of(
        not bad,
        f"not at an end of the {rel.target} row: {', '.join(bad)}",
        end_gap_m=gaps,
        line_offset_m=offsets,
        row=names(tgts),
    )
