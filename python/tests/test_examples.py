"""The examples' own pieces, on a real scene: what a user copies must measure what it says."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import LAB

import scenewright

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _example(name: str):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_loops_reward_is_measured_from_the_tool_point(tmp_path: Path) -> None:
    pytest.importorskip("gymnasium")
    loop = _example("train_loop")
    pkg = scenewright.generate(LAB, out=tmp_path / "lab", seed=3)
    model, data = pkg.load()
    tcp = loop.tool_site(model)
    assert mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_SITE, tcp).endswith("_gripper_tcp")
    free = next(
        model.jnt_bodyid[j] for j in range(model.njnt) if int(model.jnt_type[j]) == int(mujoco.mjtJoint.mjJNT_FREE)
    )
    want = -float(np.linalg.norm(data.site_xpos[tcp] - data.xpos[free]))
    assert loop.reach_reward(model, data) == pytest.approx(want)
    # The last body (what the example used to read) is not the tool point.
    assert (
        abs(loop.reach_reward(model, data) + float(np.linalg.norm(data.xpos[model.nbody - 1] - data.xpos[free]))) > 1e-3
    )
