#!/usr/bin/env python3
"""Measures a robot for the registry with the official MuJoCo Python bindings.

    scenewright robots show NAME --mjcf > /tmp/robot.xml
    .cache/venv/bin/python crates/sw_robots/tools/measure.py /tmp/robot.xml

Loads the robot alone (base at the origin), resets to the `home` keyframe and prints:
contacts between different bodies at home (there should be none), the box around every
body's collision geometry (meshes from their vertices), the keep-out boxes the registry
uses (a column over the base and the rest, 1 cm margin, rounded outwards to the cm), the
footprint radius, height and base radius, and the largest drift of a limited joint while
the robot holds its home controls for 2 s (1000 steps of 2 ms, implicitfast).
"""
import math
import sys

import mujoco
import numpy as np

COLUMN = 0.12
MARGIN = 0.01


def body_boxes(m, d):
    lo = np.full((m.nbody, 3), np.inf)
    hi = np.full((m.nbody, 3), -np.inf)
    for g in range(m.ngeom):
        if m.geom_contype[g] == 0 and m.geom_conaffinity[g] == 0:
            continue
        b = m.geom_bodyid[g]
        R = d.geom_xmat[g].reshape(3, 3)
        if m.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH:
            mid = m.geom_dataid[g]
            v = m.mesh_vert[m.mesh_vertadr[mid]: m.mesh_vertadr[mid] + m.mesh_vertnum[mid]]
            pts = d.geom_xpos[g] + v @ R.T
        else:
            c, h = m.geom_aabb[g][:3], m.geom_aabb[g][3:]
            corners = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) * h + c
            pts = d.geom_xpos[g] + corners @ R.T
        lo[b] = np.minimum(lo[b], pts.min(axis=0))
        hi[b] = np.maximum(hi[b], pts.max(axis=0))
    return lo, hi


def main(path):
    m = mujoco.MjModel.from_xml_path(path)
    d = mujoco.MjData(m)
    key = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_KEY, "home")
    if key >= 0:
        mujoco.mj_resetDataKeyframe(m, d, key)
    mujoco.mj_forward(m, d)
    for c in d.contact[: d.ncon]:
        b1, b2 = m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]
        if b1 != b2:
            print(f"contact at home: {m.body(b1).name} - {m.body(b2).name} {-c.dist * 1000:.2f} mm")
    lo, hi = body_boxes(m, d)
    free_root = any(m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE for j in range(m.njnt))
    arm = not free_root and "--base" not in sys.argv
    column = [np.full(3, np.inf), np.full(3, -np.inf)]
    rest = [np.full(3, np.inf), np.full(3, -np.inf)]
    for b in range(1, m.nbody):
        if not np.all(lo[b] <= hi[b]):
            continue
        c = (lo[b][:2] + hi[b][:2]) / 2
        into = column if (not arm or math.hypot(*c) <= COLUMN or m.body_parentid[b] == 0) else rest
        into[0] = np.minimum(into[0], lo[b])
        into[1] = np.maximum(into[1], hi[b])
        print(f"body {m.body(b).name:<40} {np.round(lo[b], 3)} {np.round(hi[b], 3)}")
    boxes = []
    for lo_, hi_ in (column, rest):
        if np.all(lo_ <= hi_):
            a = np.floor((lo_ - MARGIN) * 100) / 100
            b = np.ceil((hi_ + MARGIN) * 100) / 100
            a[2] = max(a[2], 0.0)
            boxes.append((a, b))
    for a, b in boxes:
        print(f"keepout ([{a[0]:.2f}, {a[1]:.2f}, {a[2]:.2f}], [{b[0]:.2f}, {b[1]:.2f}, {b[2]:.2f}])")
    fp = max(math.hypot(x, y) for a, b in boxes for x in (a[0], b[0]) for y in (a[1], b[1]))
    print(f"footprint_radius {fp:.2f}  height {max(b[2] for _, b in boxes):.2f}  lowest {min(lo[1:, 2]):.4f}")
    # The base: bodies whose collision geometry reaches down to the mount plane.
    low = [b for b in range(1, m.nbody) if np.all(lo[b] <= hi[b]) and lo[b][2] < 0.02]
    br = max((max(abs(lo[b][0]), abs(hi[b][0]), abs(lo[b][1]), abs(hi[b][1])) for b in low), default=0.0)
    print(f"base_radius {br:.3f}")
    limited = [j for j in range(m.njnt) if m.jnt_limited[j] and m.jnt_type[j] != mujoco.mjtJoint.mjJNT_FREE]
    q0 = d.qpos.copy()
    drift = 0.0
    worst = ""
    for step in range(1000):
        mujoco.mj_step(m, d)
        for j in limited:
            a = m.jnt_qposadr[j]
            if abs(d.qpos[a] - q0[a]) > drift:
                drift, worst = abs(d.qpos[a] - q0[a]), m.joint(j).name
    print(f"max drift of a limited joint in 2 s: {drift:.5f} ({worst})  warnings {[w.number for w in d.warning if w.number]}")


if __name__ == "__main__":
    main(sys.argv[1])
