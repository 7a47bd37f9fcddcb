"""Checks a dataset directory without trusting the manifest writer (issue 14's 10,000-scene
target): counts the packages on disk, checks that the manifest lists each exactly once,
that the packages are distinct (the bytes of scene.xml, and independently the objects'
positions rounded to 1 cm with the asset files' contents), and loads a random sample in the
MuJoCo Python bindings — reset to `home`, no contact deeper than 1 mm between different
bodies at t = 0, no free body moving 1 cm over a 2 s settle.

    .cache/venv/bin/python bench/python/check_dataset.py DIR [--expect N] [--sample 200]

Exits 1 when a check fails.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import random
import sys
from pathlib import Path

import mujoco
import numpy as np


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def structure(pkg: Path) -> tuple:
    """Objects at 1 cm and the assets' contents: two scenes with the same key are the same."""
    layout = json.loads((pkg / "layout.json").read_text(encoding="utf-8"))
    objects = sorted(
        (o["name"], tuple(round(float(x), 2) for x in o["pos"]))
        for o in layout["objects"]
    )
    assets = pkg / "assets"
    files = sorted(sha(f) for f in assets.iterdir()) if assets.is_dir() else []
    return (tuple(objects), tuple(files))


def settle(path: Path) -> list[str]:
    """What is wrong with the scene in MuJoCo (empty: nothing)."""
    m = mujoco.MjModel.from_xml_path(str(path))
    d = mujoco.MjData(m)
    key = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_KEY, "home")
    if key >= 0:
        mujoco.mj_resetDataKeyframe(m, d, key)
    mujoco.mj_forward(m, d)
    wrong = []
    for i in range(d.ncon):
        c = d.contact[i]
        b1, b2 = m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]
        if b1 != b2 and -c.dist > 0.001:
            wrong.append(
                f"{m.body(b1).name}-{m.body(b2).name} {-c.dist * 1000:.1f} mm deep"
            )
    free = [
        m.jnt_bodyid[j]
        for j in range(m.njnt)
        if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE
    ]
    start = d.xpos[free].copy()
    mujoco.mj_step(m, d, nstep=round(2.0 / m.opt.timestep))
    if free:
        moved = float(np.linalg.norm(d.xpos[free] - start, axis=1).max())
        if not np.isfinite(moved) or moved > 0.01:
            wrong.append(f"a free body moved {moved * 100:.1f} cm")
    return wrong


def main() -> int:
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("dir", type=Path)
    ap.add_argument("--expect", type=int)
    ap.add_argument("--sample", type=int, default=200)
    args = ap.parse_args()
    scenes = args.dir / "scenes"
    on_disk = sorted(p for p in scenes.iterdir())
    hidden = [p.name for p in on_disk if p.name.startswith(".")]
    pkgs = [p for p in on_disk if not p.name.startswith(".")]
    text = (args.dir / "manifest.jsonl").read_text(encoding="utf-8")
    lines = [json.loads(line) for line in text.splitlines()]
    listed = [e["dir"] for e in lines]
    problems = []
    if not text.endswith("\n"):
        problems.append("the manifest ends in a torn line")
    if hidden or (args.dir / ".work").exists():
        problems.append(f"half-made packages left: {hidden[:5]}")
    if len(set(listed)) != len(listed):
        problems.append(f"{len(listed) - len(set(listed))} packages listed twice")
    if sorted(listed) != [f"scenes/{p.name}" for p in pkgs]:
        problems.append("the manifest and scenes/ disagree")
    incomplete = [
        p.name
        for p in pkgs
        if not (p / "scene.xml").is_file() or not (p / "layout.json").is_file()
    ]
    if incomplete:
        problems.append(f"{len(incomplete)} packages without scene.xml or layout.json")
    xml = {sha(p / "scene.xml") for p in pkgs}
    keys = {structure(p) for p in pkgs}
    if args.expect is not None and len(pkgs) != args.expect:
        problems.append(f"{len(pkgs)} packages, not {args.expect}")
    if len(xml) != len(pkgs) or len(keys) != len(pkgs):
        problems.append(
            f"duplicates: {len(xml)} distinct scene.xml, {len(keys)} distinct layouts+assets"
        )
    rng = random.Random(14)
    sample = rng.sample(pkgs, min(args.sample, len(pkgs)))
    bad = {p.name: w for p in sample if (w := settle(p / "scene.xml"))}
    if bad:
        problems.append(
            f"{len(bad)} of the sample fail in MuJoCo: {dict(list(bad.items())[:3])}"
        )
    print(
        json.dumps(
            {
                "packages": len(pkgs),
                "manifest_lines": len(lines),
                "distinct_scene_xml": len(xml),
                "distinct_layout_and_assets": len(keys),
                "sample_loaded_and_settled": len(sample) - len(bad),
                "sample": len(sample),
                "mujoco": mujoco.__version__,
                "problems": problems,
            },
            indent=2,
        )
    )
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
