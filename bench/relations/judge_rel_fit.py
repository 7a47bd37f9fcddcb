"""Relations of fit: inside, set into, on the edge of, and stated sizes.

Inside: resting on an interior support of the target (a support surface at least 2 cm
below its top: a shelf or cabinet level, a drawer, a bin's floor) with its centre inside
the target. Set into: a sink or hob in a counter run, either within the counter's top or
standing in its run as a base unit of its own. On the edge of: resting on the target near
an edge of the surface it rests on. Sizes are measured on the collision geometry's box in
the object's own frame. Thresholds are in README.md.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from judge_common import Relation, Verdict, resolve
from judge_geometry import Arr, angle_deg, point_in_convex, project
from judge_rel_support import OPEN_DEPTH_M, rests_on
from judge_scene import Room, Scene, Surface, Thing

SET_INTO_SLACK_M = 0.02
SET_INTO_TOP_M = 0.05
RUN_FACING_DEG = 10.0
RUN_GAP_M = (-0.02, 0.05)
RUN_FRONT_M = 0.05
EDGE_M = 0.2
ROOM_SIZE_TOL = 0.05


def _missing(key: str | None) -> Verdict:
    return Verdict.fail(f"no {key} in the scene")


def _surface(t: Thing, name: str) -> Surface | None:
    return next((s for s in t.surfaces if s.name == name), None)


def inside(rel: Relation, scene: Scene) -> Verdict:
    """Judge `inside`.

    Every instance rests on an interior support of a target instance (a support surface
    at least 2 cm below the target's top) with its centre inside the target's footprint.
    """
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    where: dict[str, str | None] = {}
    for s in subs:
        where[s.name] = None
        for t in tgts:
            name = rests_on(s, t)
            surf = _surface(t, name) if name else None
            if surf is None:
                continue
            interior = t.top - float(surf.centre[2]) >= OPEN_DEPTH_M
            if interior and point_in_convex(s.centre, t.footprint):
                where[s.name] = f"{t.name}:{name}"
                break
    bad = [n for n, w in where.items() if w is None]
    return Verdict.of(not bad, f"not inside {rel.target}: {', '.join(bad)}", inside=where)


def _work_top(t: Thing) -> float:
    """Return the height of a thing's highest support surface (its worktop), else its top."""
    return max((float(s.centre[2]) for s in t.surfaces), default=t.top)


def _within_top(s: Thing, t: Thing) -> tuple[bool, float]:
    """Whether s's footprint lies within a top surface of t and its top is level with it."""
    best = np.inf
    for surf in t.surfaces:
        if not all(surf.contains_xy(p, SET_INTO_SLACK_M) for p in s.footprint):
            continue
        d = abs(_work_top(s) - float(surf.centre[2]))
        best = min(best, d)
    return bool(best <= SET_INTO_TOP_M), float(best)


def _in_run(s: Thing, t: Thing) -> tuple[bool, dict[str, float]]:
    """Whether s stands in t's run: same facing, abutting an end of it, fronts flush, tops level."""
    if s.front is None or t.front is None:
        return False, {}
    facing = angle_deg(s.front, t.front)
    ax = t.rot[:2, 0]
    lo_s, hi_s = project(s.footprint, ax)
    lo_t, hi_t = project(t.footprint, ax)
    gap = max(lo_s - hi_t, lo_t - hi_s)
    f = t.front
    front = abs(project(s.footprint, f)[1] - project(t.footprint, f)[1])
    top = abs(_work_top(s) - _work_top(t))
    ok = (
        facing <= RUN_FACING_DEG
        and RUN_GAP_M[0] <= gap <= RUN_GAP_M[1]
        and front <= RUN_FRONT_M
        and top <= SET_INTO_TOP_M
    )
    return ok, {"facing_deg": facing, "end_gap_m": gap, "front_offset_m": front, "top_offset_m": top}


def set_into(rel: Relation, scene: Scene) -> Verdict:
    """Judge `set_into`.

    Every instance is set into a target instance: its footprint within the target's top
    surface (2 cm slack) with its own worktop within 5 cm of it, or, a base unit of its
    own (a sink unit, a range), standing in the target's run — facing the same way
    (within 10°), abutting an end of the target (−2…5 cm), fronts flush (5 cm), worktops
    level (5 cm).
    """
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    modes: dict[str, str | None] = {}
    misses: list[dict[str, Any]] = []
    for s in subs:
        modes[s.name] = None
        for t in tgts:
            ok, _ = _within_top(s, t)
            if ok:
                modes[s.name] = f"in the top of {t.name}"
                break
            ok, m = _in_run(s, t)
            if ok:
                modes[s.name] = f"in the run of {t.name}"
                break
            misses.append({"subject": s.name, "target": t.name, **m})
    bad = [n for n, m in modes.items() if m is None]
    return Verdict.of(
        not bad,
        f"not set into {rel.target}: {', '.join(bad)}",
        modes=modes,
        misses=misses if bad else [],
    )


def _edge_distance(s: Thing, surf: Surface) -> float:
    """Return the distance from s's footprint centre to the nearest edge of a surface."""
    c = s.centre
    local = surf.rot.T @ np.array([c[0] - surf.centre[0], c[1] - surf.centre[1], 0.0])
    return float(min(surf.half[0] - abs(local[0]), surf.half[1] - abs(local[1])))


def on_edge_of(rel: Relation, scene: Scene) -> Verdict:
    """Judge `on_edge_of`: resting on the target, footprint centre within 0.2 m of an edge of its surface."""
    subs, tgts = resolve(scene, rel.subject), resolve(scene, rel.target)
    if not subs:
        return _missing(rel.subject)
    if not tgts:
        return _missing(rel.target)
    dists: list[float | None] = []
    bad = []
    for s in subs:
        best: float | None = None
        for t in tgts:
            name = rests_on(s, t)
            surf = _surface(t, name) if name else None
            if surf is not None:
                d = _edge_distance(s, surf)
                best = d if best is None else min(best, d)
        dists.append(best)
        if best is None or best > EDGE_M:
            bad.append(s.name)
    return Verdict.of(not bad, f"not on an edge of {rel.target}: {', '.join(bad)}", edge_distance_m=dists)


def measured_size(t: Thing) -> dict[str, float]:
    """Return a thing's extents in its own frame: width (X, across the front), depth (Y), height."""
    ext = t.local_hi - t.local_lo
    return {"x": float(ext[0]), "y": float(ext[1]), "height": float(ext[2])}


def _dim_values(name: str, ext: dict[str, float], with_length: bool) -> list[float]:
    """Return the measured values a stated dimension may match (any one suffices)."""
    long_side, short_side = max(ext["x"], ext["y"]), min(ext["x"], ext["y"])
    if name == "length":
        return [long_side]
    if name == "width":
        # "2 m long and 90 cm wide": the shorter side. "a 1.8 m wide wardrobe": across its
        # front. Both readings are English; without a length either may be meant.
        return [short_side] if with_length else [short_side, ext["x"]]
    if name == "depth":
        return [ext["y"], short_side]
    if name == "diameter":
        return [long_side]
    return [ext["height"]]


def size(rel: Relation, scene: Scene) -> Verdict:
    """Judge `size`: every instance's stated dimensions (`dims`, [min, max] m) on its collision box."""
    subs = resolve(scene, rel.subject)
    if not subs:
        return _missing(rel.subject)
    if not rel.dims:
        return Verdict.fail("size needs dims")
    rows, bad = [], []
    with_length = "length" in rel.dims
    for s in subs:
        ext = measured_size(s)
        row: dict[str, Any] = {"name": s.name}
        ok = True
        for name, (lo, hi) in rel.dims.items():
            vals = _dim_values(name, ext, with_length)
            hit = next((v for v in vals if lo <= v <= hi), None)
            row[name] = hit if hit is not None else vals[0]
            ok &= hit is not None
        rows.append(row)
        if not ok:
            bad.append(s.name)
    return Verdict.of(not bad, f"outside the stated size: {', '.join(bad)}", sizes=rows, dims=rel.dims)


def room_size(room: Room, want: list[float], height: float | None) -> dict[str, Any]:
    """Judge a line's `room_size_m` ([a, b], either orientation, 5 %) and `room_height_m`."""
    got = sorted(room.size)
    probs = []
    if want:
        exp = sorted(float(x) for x in want)
        if any(abs(g - e) > ROOM_SIZE_TOL * e for g, e in zip(got, exp, strict=True)):
            probs.append(f"room {got[0]:.2f} × {got[1]:.2f} m, asked {exp[0]:g} × {exp[1]:g}")
    if height is not None:
        if room.height is None or abs(room.height - height) > ROOM_SIZE_TOL * height:
            probs.append(f"ceiling {room.height} m, asked {height:g}")
    return {
        "held": not probs,
        "measured": {"size_m": [round(g, 3) for g in got], "height_m": room.height},
        **({"why": "; ".join(probs)} if probs else {}),
    }


def front_of(t: Thing) -> Arr | None:
    """Return the direction a thing faces: an object's local +Y, a robot's working +X."""
    if t.kind == "robot":
        v = t.rot[:2, 0]
        n = float(np.linalg.norm(v))
        return v / n if n > 1e-9 else None
    return t.front
