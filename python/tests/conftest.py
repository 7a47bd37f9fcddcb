"""Shared fixtures: the binary under test, and scenes made once per session.

The tests run the `scenewright` binary of this checkout: `SCENEWRIGHT_BIN` when set
(scripts/test.sh sets it to the debug build `cargo test` made), else target/debug.
"""

from __future__ import annotations

import os
from pathlib import Path

# Offscreen rendering in the tests: MuJoCo's EGL backend, chosen before mujoco is imported.
os.environ.setdefault("MUJOCO_GL", "egl")

import mujoco
import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]

if "SCENEWRIGHT_BIN" not in os.environ:
    for profile in ("debug", "release"):
        candidate = ROOT / "target" / profile / "scenewright"
        if candidate.is_file():
            os.environ["SCENEWRIGHT_BIN"] = str(candidate)
            break

import scenewright  # noqa: E402

LAB = "a robotics lab with a workbench, a UR5e on the bench, three bins on the bench and a chair next to the workbench"


def settle(model: mujoco.MjModel, data: mujoco.MjData, seconds: float = 2.0) -> float:
    """Step `seconds` from the current state; the largest displacement of a free body, m."""
    free = [model.jnt_bodyid[j] for j in range(model.njnt) if int(model.jnt_type[j]) == int(mujoco.mjtJoint.mjJNT_FREE)]
    start = data.xpos[free].copy()
    mujoco.mj_step(model, data, nstep=round(seconds / model.opt.timestep))
    assert np.isfinite(data.qpos).all()
    if not free:
        return 0.0
    return float(np.linalg.norm(data.xpos[free] - start, axis=1).max())


@pytest.fixture(scope="session")
def lab(tmp_path_factory: pytest.TempPathFactory) -> scenewright.Package:
    return scenewright.generate(LAB, seed=3, out=tmp_path_factory.mktemp("lab") / "pkg")
