"""Tasks (`task.json`) judged on a MuJoCo state, written apart from the engine's Rust judge.

A package made with a task (`scenewright demos`, or `generate --task`) holds `task.json`:
the goal as predicates over named bodies. `judge(task, model, data)` measures each
predicate on the state with the definitions of the relation report — world boxes around
each top-level body's collision geoms (group 3), support surfaces as the `sw_surface`
sites (group 5), a body resting on a surface when its bottom is within 2 cm of it and its
centre over it — and is what the replay check and the Gymnasium environment's reward use.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

REST = 0.02
EDGE = 0.01
FLOOR_SLACK = 0.01
_COLLISION_GROUP = 3
_SURFACE_GROUP = 5


@dataclass(frozen=True)
class Box:
    """An axis-aligned world box."""

    lo: np.ndarray
    hi: np.ndarray

    @property
    def center(self) -> np.ndarray:
        """The box's centre."""
        return np.asarray((self.lo + self.hi) / 2)

    def covers_xy(self, p: np.ndarray) -> bool:
        """Whether `p`'s footprint is strictly inside the box's."""
        return bool(self.lo[0] < p[0] < self.hi[0] and self.lo[1] < p[1] < self.hi[1])


@dataclass(frozen=True)
class Surface:
    """A support surface: its height and world rectangle (x0, y0, x1, y1)."""

    z: float
    rect: tuple[float, float, float, float]


@dataclass(frozen=True)
class Verdict:
    """One goal's verdict."""

    predicate: str
    held: bool
    measured: float | None
    why: str | None


def load_task(path: str | Path) -> dict[str, Any]:
    """Read a `task.json` (a package directory or the file)."""
    p = Path(path)
    if p.is_dir():
        p = p / "task.json"
    task: dict[str, Any] = json.loads(p.read_text())
    return task


def _name(model: mujoco.MjModel, kind: mujoco.mjtObj, i: int) -> str:
    return mujoco.mj_id2name(model, kind, i) or ""


def bodies(model: mujoco.MjModel, data: mujoco.MjData) -> dict[str, tuple[Box, list[Surface]]]:
    """Every named top-level body: its collision box and support surfaces, world frame."""
    boxes: dict[int, tuple[np.ndarray, np.ndarray]] = {}
    for g in range(model.ngeom):
        b = int(model.geom_bodyid[g])
        if b == 0 or int(model.geom_group[g]) != _COLLISION_GROUP:
            continue
        root = int(model.body_rootid[b])
        aabb = model.geom_aabb[g]
        rot = data.geom_xmat[g].reshape(3, 3)
        center = data.geom_xpos[g] + rot @ aabb[:3]
        half = np.abs(rot) @ aabb[3:]
        lo, hi = center - half, center + half
        if root in boxes:
            boxes[root] = (np.minimum(boxes[root][0], lo), np.maximum(boxes[root][1], hi))
        else:
            boxes[root] = (lo, hi)
    surfaces: dict[int, list[Surface]] = {}
    for s in range(model.nsite):
        if int(model.site_group[s]) != _SURFACE_GROUP:
            continue
        root = int(model.body_rootid[int(model.site_bodyid[s])])
        p = data.site_xpos[s]
        rot = data.site_xmat[s].reshape(3, 3)
        size = model.site_size[s]
        hx = abs(rot[0, 0] * size[0]) + abs(rot[0, 1] * size[1])
        hy = abs(rot[1, 0] * size[0]) + abs(rot[1, 1] * size[1])
        surfaces.setdefault(root, []).append(Surface(float(p[2]), (p[0] - hx, p[1] - hy, p[0] + hx, p[1] + hy)))
    out: dict[str, tuple[Box, list[Surface]]] = {}
    for b, (lo, hi) in boxes.items():
        name = _name(model, mujoco.mjtObj.mjOBJ_BODY, b)
        if name:
            out[name] = (Box(lo, hi), surfaces.get(b, []))
    return out


def _rests_on(me: Box, host: tuple[Box, list[Surface]]) -> bool:
    c = me.center
    for s in host[1]:
        x0, y0, x1, y1 = s.rect
        if abs(me.lo[2] - s.z) <= REST and x0 - EDGE <= c[0] <= x1 + EDGE and y0 - EDGE <= c[1] <= y1 + EDGE:
            return True
    return _on_top(me, host[0])


def _on_top(me: Box, host: Box) -> bool:
    return bool(abs(me.lo[2] - host.hi[2]) <= REST and host.covers_xy(me.center))


def _within(me: Box, host: Box) -> bool:
    return bool(host.covers_xy(me.center) and host.lo[2] - FLOOR_SLACK <= me.lo[2] < host.hi[2])


def _gap(a: Box, b: Box) -> float:
    dx = max(b.lo[0] - a.hi[0], a.lo[0] - b.hi[0])
    dy = max(b.lo[1] - a.hi[1], a.lo[1] - b.hi[1])
    if dx < 0 and dy < 0:
        return float(max(dx, dy))
    return float(np.hypot(max(dx, 0.0), max(dy, 0.0)))


def judge(task: dict[str, Any], model: mujoco.MjModel, data: mujoco.MjData) -> list[Verdict]:
    """Each goal of `task` measured on the state (call `mj_forward` or step first)."""
    world = bodies(model, data)
    out: list[Verdict] = []
    for g in task["goals"]:
        kind = g["predicate"]
        obj = g.get("object")
        me = world[obj][0] if obj in world else None
        if kind in ("on", "inside"):
            targets = [world[t] for t in g["target"] if t in world]
            if me is None or not targets:
                out.append(Verdict(kind, False, None, "a named body is missing"))
                continue
            ok = any(_within(me, t[0]) if kind == "inside" else _rests_on(me, t) for t in targets)
            out.append(Verdict(kind, ok, float(me.lo[2]), None if ok else f"{obj} is not {kind} {g['target']}"))
        elif kind == "stacked_on":
            host = world.get(g["target"])
            if me is None or host is None:
                out.append(Verdict(kind, False, None, "a named body is missing"))
                continue
            ok = _on_top(me, host[0])
            out.append(Verdict(kind, ok, float(me.lo[2] - host[0].hi[2]), None if ok else f"{obj} is not on top"))
        elif kind == "near":
            host = world.get(g["target"])
            if me is None or host is None:
                out.append(Verdict(kind, False, None, "a named body is missing"))
                continue
            gap = _gap(me, host[0])
            out.append(Verdict(kind, gap <= g["within"], gap, None if gap <= g["within"] else f"{gap:.3f} m apart"))
        elif kind == "in_region":
            if me is None:
                out.append(Verdict(kind, False, None, "a named body is missing"))
                continue
            c = me.center
            ok = bool(g["min"][0] <= c[0] <= g["max"][0] and g["min"][1] <= c[1] <= g["max"][1])
            out.append(Verdict(kind, ok, None, None if ok else "outside the region"))
        elif kind == "at_pose":
            if me is None:
                out.append(Verdict(kind, False, None, "a named body is missing"))
                continue
            d = float(np.linalg.norm(me.center - np.asarray(g["pos"])))
            out.append(Verdict(kind, d <= g["tolerance"], d, None if d <= g["tolerance"] else f"{d:.3f} m away"))
        elif kind in ("open", "closed"):
            j = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, g["joint"])
            if j < 0:
                out.append(Verdict(kind, False, None, f"no joint {g['joint']}"))
                continue
            lo, hi = model.jnt_range[j]
            q = data.qpos[model.jnt_qposadr[j]]
            f = float((q - lo) / (hi - lo)) if hi > lo else 0.0
            ok = f >= 0.8 if kind == "open" else f <= 0.1
            out.append(Verdict(kind, ok, f, None if ok else f"{100 * f:.0f} % open"))
        elif kind == "navigate_to":
            host = world.get(g["target"])
            base = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, f"{g['robot']}_base")
            if host is None or base < 0:
                out.append(Verdict(kind, False, None, "a named body is missing"))
                continue
            p = data.xpos[base].copy()
            gap = _gap(Box(p, p), host[0])
            out.append(Verdict(kind, gap <= g["within"], gap, None if gap <= g["within"] else f"{gap:.2f} m away"))
        else:
            out.append(Verdict(kind, False, None, f"unknown predicate {kind}"))
    return out


def holds(task: dict[str, Any], model: mujoco.MjModel, data: mujoco.MjData) -> bool:
    """True when every goal of `task` holds on the state."""
    return all(v.held for v in judge(task, model, data))


def distance_to_goal(task: dict[str, Any], model: mujoco.MjModel, data: mujoco.MjData) -> float:
    """A dense measure of how far the task is from holding.

    The summed distance from each moved thing to where its goal wants it (the centre of the
    target's top, the region's centre, the pose); 0 for goals that hold.
    """
    world = bodies(model, data)
    total = 0.0
    for g, v in zip(task["goals"], judge(task, model, data), strict=True):
        if v.held or g.get("object") not in world:
            continue
        me = world[g["object"]][0]
        kind = g["predicate"]
        if kind in ("on", "inside", "stacked_on", "near"):
            names = g["target"] if isinstance(g["target"], list) else [g["target"]]
            goals = [world[t][0] for t in names if t in world]
            if not goals:
                continue
            dists = [
                float(np.linalg.norm(me.center[:2] - t.center[:2])) + abs(float(me.lo[2] - t.hi[2])) for t in goals
            ]
            total += min(dists)
        elif kind == "in_region":
            c = (np.asarray(g["min"]) + np.asarray(g["max"])) / 2
            total += float(np.linalg.norm(me.center[:2] - c))
        elif kind == "at_pose":
            total += float(np.linalg.norm(me.center - np.asarray(g["pos"])))
    return total
