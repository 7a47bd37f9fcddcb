"""Reads a written scenewright package into what the judge measures.

Only `scene.xml` is read, with the official MuJoCo Python bindings: the model is reset to
its `home` keyframe and `mj_forward` places every body. From the MJCF we take:

- the room: the inner faces of the wall boxes (`wall_<side>[_k]`), else the floor plane;
  the door: the `doorway*` floor marker(s), else a wall box that does not reach the floor
  (a lintel over an opening);
- objects: world children named `<category>_<n>`; their collision geometry (geom group 3)
  and support sites (site group 5);
- robots: world children named `<model>_<n>_<link>`; their root body's collision
  geometry is the base footprint; the shoulder is found from the joints (see `_shoulder`).

Front convention (documented in sw_geom's asset frame, checked on written scenes): an
object's front is its body's local +Y axis, width along local X, depth along local Y.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import mujoco  # type: ignore[import-untyped]
import numpy as np

from judge_geometry import Arr, rect, unit

OBJECT_NAME = re.compile(r"^([a-z][a-z0-9_]*)_(\d+)$")
ROBOT_ROOT_NAME = re.compile(r"^([a-z][a-z0-9_]*?)_(\d+)_(.+)$")
WALL_NAME = re.compile(r"^wall_(north|south|east|west)(?:_\d+)?$")
COLLISION_GROUP = 3
SURFACE_GROUP = 5


class SceneError(Exception):
    """The package cannot be judged (missing file, no home keyframe, unreadable MJCF)."""


@dataclass
class Surface:
    """A support surface: a box site in group 5, its top plane at `centre[2]`."""

    name: str
    centre: Arr
    rot: Arr
    half: Arr

    def contains_xy(self, p: Arr, margin: float = 0.0) -> bool:
        """Whether a floor-plane point lies over the surface (grown by `margin`)."""
        local = self.rot.T @ np.array([p[0] - self.centre[0], p[1] - self.centre[1], 0.0])
        return bool(abs(local[0]) <= self.half[0] + margin and abs(local[1]) <= self.half[1] + margin)

    def polygon(self) -> Arr:
        """Return the surface's outline on the floor plane."""
        return rect(self.centre[:2], self.rot[:2, 0], float(self.half[0]), float(self.half[1]))


@dataclass
class Thing:
    """One object (`kind == "object"`) or robot (`kind == "robot"`) in the scene."""

    name: str
    kind: str
    category: str
    index: int
    root: int
    free: bool
    pos: Arr
    rot: Arr
    local_lo: Arr
    local_hi: Arr
    world_lo: Arr
    world_hi: Arr
    footprint: Arr
    upright: bool
    surfaces: list[Surface] = field(default_factory=list)
    shoulder: Arr | None = None
    base: Arr | None = None

    @property
    def centre(self) -> Arr:
        """Centre of the footprint on the floor plane."""
        return np.asarray(self.footprint.mean(axis=0), dtype=np.float64)

    @property
    def centre3(self) -> Arr:
        """Centre of the world bounding box."""
        return (self.world_lo + self.world_hi) / 2.0

    @property
    def bottom(self) -> float:
        """Lowest point; for a robot, its mounting plane (the root body's origin)."""
        if self.kind == "robot" and self.base is not None:
            return float(self.base[2])
        return float(self.world_lo[2])

    @property
    def top(self) -> float:
        """Highest point of the collision geometry."""
        return float(self.world_hi[2])

    @property
    def front(self) -> Arr | None:
        """Unit front direction on the floor (local +Y), None for a tilted body."""
        return unit(self.rot[:2, 1]) if self.upright else None

    @property
    def half_w(self) -> float:
        """Half the width (local X extent)."""
        return float(self.local_hi[0] - self.local_lo[0]) / 2.0

    @property
    def half_d(self) -> float:
        """Half the depth (local Y extent)."""
        return float(self.local_hi[1] - self.local_lo[1]) / 2.0

    @property
    def local_centre_xy(self) -> Arr:
        """Centre of the local box on the floor plane, in world coordinates."""
        c = (self.local_lo + self.local_hi) / 2.0
        return np.asarray(self.pos[:2] + (self.rot @ c)[:2], dtype=np.float64)

    @property
    def long_axis(self) -> Arr:
        """Unit direction of the longer horizontal side."""
        e = self.footprint[1] - self.footprint[0]
        f = self.footprint[2] - self.footprint[1]
        v = e if np.linalg.norm(e) >= np.linalg.norm(f) else f
        u = unit(v)
        return u if u is not None else np.array([1.0, 0.0])

    @property
    def oriented(self) -> bool:
        """A static, upright fixture whose front means something (not a free item)."""
        return self.kind == "object" and not self.free and self.upright


@dataclass
class Room:
    """The room's interior rectangle and door openings."""

    xmin: float
    xmax: float
    ymin: float
    ymax: float
    doors: list[Arr]
    # The top of the walls (the ceiling height), None without wall boxes.
    height: float | None = None

    @property
    def size(self) -> tuple[float, float]:
        """Interior size (east-west, north-south)."""
        return self.xmax - self.xmin, self.ymax - self.ymin

    @property
    def centre(self) -> Arr:
        """Centre of the floor."""
        return np.array([(self.xmin + self.xmax) / 2.0, (self.ymin + self.ymax) / 2.0])

    def wall_gap(self, poly: Arr, side: str) -> float:
        """Clear distance from a footprint to one wall's inner face."""
        if side == "north":
            return self.ymax - float(poly[:, 1].max())
        if side == "south":
            return float(poly[:, 1].min()) - self.ymin
        if side == "east":
            return self.xmax - float(poly[:, 0].max())
        return float(poly[:, 0].min()) - self.xmin

    @staticmethod
    def inward(side: str) -> Arr:
        """Return the unit normal of a wall pointing into the room."""
        return {
            "north": np.array([0.0, -1.0]),
            "south": np.array([0.0, 1.0]),
            "east": np.array([-1.0, 0.0]),
            "west": np.array([1.0, 0.0]),
        }[side]


@dataclass
class Scene:
    """Everything measured from one package."""

    room: Room
    objects: list[Thing]
    robots: list[Thing]

    def things(self) -> list[Thing]:
        """Objects then robots."""
        return self.objects + self.robots


def _geom_world_corners(m: mujoco.MjModel, d: mujoco.MjData, g: int) -> Arr:
    aabb = m.geom_aabb[g]
    c, h = aabb[:3], aabb[3:]
    signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], dtype=np.float64)
    local = c + signs * h
    r = d.geom_xmat[g].reshape(3, 3)
    return np.asarray(d.geom_xpos[g] + local @ r.T, dtype=np.float64)


def _collision_geoms(m: mujoco.MjModel, bodies: list[int], robot: bool) -> list[int]:
    body_set = set(bodies)
    gs = [g for g in range(m.ngeom) if int(m.geom_bodyid[g]) in body_set]
    if not robot:
        grouped = [g for g in gs if int(m.geom_group[g]) == COLLISION_GROUP]
        if grouped:
            return grouped
    return [g for g in gs if int(m.geom_contype[g]) != 0 or int(m.geom_conaffinity[g]) != 0]


def _subtree(m: mujoco.MjModel, root: int) -> list[int]:
    return [b for b in range(m.nbody) if int(m.body_rootid[b]) == root]


def _shoulder(m: mujoco.MjModel, d: mujoco.MjData, bodies: list[int]) -> Arr | None:
    """Find the arm's shoulder: the first vertical revolute axis at the height of the next joint.

    The first hinge whose world axis is vertical is the base (pan) joint; the next hinge
    below it in the kinematic tree is the shoulder (lift) joint. The shoulder point is the
    second joint's anchor projected onto the first joint's axis — the centre of the sphere
    a data sheet's reach figure describes.
    """
    body_set = set(bodies)
    hinges = [
        j for j in range(m.njnt) if int(m.jnt_bodyid[j]) in body_set and m.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE
    ]
    for k, j1 in enumerate(hinges):
        a1 = d.xaxis[j1]
        if abs(float(a1[2])) < 0.9:
            continue
        b1 = int(m.jnt_bodyid[j1])
        for j2 in hinges[k + 1 :]:
            b = int(m.jnt_bodyid[j2])
            while b not in (0, b1):
                b = int(m.body_parentid[b])
            if b == b1:
                p1, p2 = d.xanchor[j1], d.xanchor[j2]
                return np.asarray(p1 + a1 * float((p2 - p1) @ a1), dtype=np.float64)
        return None
    return None


def _surfaces(m: mujoco.MjModel, d: mujoco.MjData, bodies: list[int]) -> list[Surface]:
    body_set = set(bodies)
    out = []
    for s in range(m.nsite):
        if int(m.site_bodyid[s]) in body_set and int(m.site_group[s]) == SURFACE_GROUP:
            out.append(
                Surface(
                    name=m.site(s).name,
                    centre=np.array(d.site_xpos[s], dtype=np.float64),
                    rot=np.array(d.site_xmat[s], dtype=np.float64).reshape(3, 3),
                    half=np.array(m.site_size[s], dtype=np.float64),
                )
            )
    return out


def _thing(m: mujoco.MjModel, d: mujoco.MjData, root: int, kind: str, category: str, index: int) -> Thing:
    bodies = _subtree(m, root)
    # A robot's footprint is its base (root body); an object's is all of its bodies.
    geoms = _collision_geoms(m, [root] if kind == "robot" else bodies, robot=kind == "robot")
    pos = np.array(d.xpos[root], dtype=np.float64)
    rot = np.array(d.xmat[root], dtype=np.float64).reshape(3, 3)
    if geoms:
        corners = np.vstack([_geom_world_corners(m, d, g) for g in geoms])
    else:
        corners = pos + np.array([[sx, sy, sz] for sx in (-0.05, 0.05) for sy in (-0.05, 0.05) for sz in (0, 0.1)])
    local = (corners - pos) @ rot
    local_lo, local_hi = local.min(axis=0), local.max(axis=0)
    world_lo, world_hi = corners.min(axis=0), corners.max(axis=0)
    upright = float(rot[2, 2]) > math.cos(math.radians(5.0))
    if upright:
        c = (local_lo + local_hi) / 2.0
        fp = rect(
            pos[:2] + (rot @ c)[:2],
            rot[:2, 0],
            float(local_hi[0] - local_lo[0]) / 2.0,
            float(local_hi[1] - local_lo[1]) / 2.0,
        )
    else:
        fp = rect(
            (world_lo[:2] + world_hi[:2]) / 2.0,
            np.array([1.0, 0.0]),
            float(world_hi[0] - world_lo[0]) / 2.0,
            float(world_hi[1] - world_lo[1]) / 2.0,
        )
    free = any(int(m.jnt_bodyid[j]) == root and m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE for j in range(m.njnt))
    return Thing(
        name=m.body(root).name if kind == "object" else f"{category}_{index}",
        kind=kind,
        category=category,
        index=index,
        root=root,
        free=free,
        pos=pos,
        rot=rot,
        local_lo=local_lo,
        local_hi=local_hi,
        world_lo=world_lo,
        world_hi=world_hi,
        footprint=fp,
        upright=upright,
        surfaces=_surfaces(m, d, bodies) if kind == "object" else [],
        shoulder=_shoulder(m, d, bodies) if kind == "robot" else None,
        base=pos if kind == "robot" else None,
    )


def _room(m: mujoco.MjModel) -> Room:
    inner: dict[str, float] = {}
    tops: list[float] = []
    lintels: list[tuple[str, Arr, Arr]] = []
    doors: list[Arr] = []
    for g in range(m.ngeom):
        name = m.geom(g).name
        if int(m.geom_bodyid[g]) != 0:
            continue
        pos, size = m.geom_pos[g], m.geom_size[g]
        wm = WALL_NAME.match(name)
        if wm and m.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX:
            side = wm.group(1)
            tops.append(float(pos[2] + size[2]))
            face = {
                "north": pos[1] - size[1],
                "south": pos[1] + size[1],
                "east": pos[0] - size[0],
                "west": pos[0] + size[0],
            }[side]
            if pos[2] - size[2] > 0.3:
                lintels.append((side, pos.copy(), size.copy()))
            if side in ("north", "east"):
                inner[side] = min(inner.get(side, math.inf), float(face))
            else:
                inner[side] = max(inner.get(side, -math.inf), float(face))
        elif name.startswith("doorway") and m.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX:
            doors.append(rect(np.array(pos[:2]), np.array([1.0, 0.0]), float(size[0]), float(size[1])))
    if len(inner) < 4:
        floor = [g for g in range(m.ngeom) if m.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE]
        if not floor:
            raise SceneError("no walls (wall_north … wall_west) and no floor plane in scene.xml")
        p, s = m.geom_pos[floor[0]], m.geom_size[floor[0]]
        inner.setdefault("north", float(p[1] + s[1]))
        inner.setdefault("south", float(p[1] - s[1]))
        inner.setdefault("east", float(p[0] + s[0]))
        inner.setdefault("west", float(p[0] - s[0]))
    if not doors:
        for side, pos, size in lintels:
            depth = 0.3
            n = Room.inward(side)
            c = np.array(pos[:2]) + n * (float(size[0] if side in ("east", "west") else size[1]) + depth)
            along = np.array([1.0, 0.0]) if side in ("north", "south") else np.array([0.0, 1.0])
            half = float(size[0] if side in ("north", "south") else size[1])
            doors.append(rect(c, along, half, depth))
    return Room(inner["west"], inner["east"], inner["south"], inner["north"], doors, max(tops) if tops else None)


def load(package: Path) -> Scene:
    """Load `package/scene.xml`, reset it to the `home` keyframe and measure it."""
    xml = package / "scene.xml"
    if not xml.is_file():
        raise SceneError(f"no scene.xml in {package}")
    try:
        m = mujoco.MjModel.from_xml_path(str(xml))
    except ValueError as e:
        raise SceneError(f"{xml}: MuJoCo cannot load it: {e}") from e
    key = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_KEY, "home")
    d = mujoco.MjData(m)
    if key >= 0:
        mujoco.mj_resetDataKeyframe(m, d, key)
    elif m.nq > 0:
        raise SceneError(f"{xml}: no keyframe named 'home' and {m.nq} position coordinates")
    # else: nothing moves, the written poses are the spawn state.
    mujoco.mj_forward(m, d)
    objects, robots = [], []
    for b in range(1, m.nbody):
        if int(m.body_parentid[b]) != 0:
            continue
        name = m.body(b).name
        om = OBJECT_NAME.match(name)
        rm = ROBOT_ROOT_NAME.match(name)
        if om:
            objects.append(_thing(m, d, b, "object", om.group(1), int(om.group(2))))
        elif rm:
            robots.append(_thing(m, d, b, "robot", rm.group(1), int(rm.group(2))))
    return Scene(_room(m), objects, robots)
