"""The Gymnasium environment with a task: end-effector actions, object poses, reward and
success from the task's predicates, camera rendering; mixed-robot datasets refused at
`make`; temporary folders removed."""

from __future__ import annotations

import gc
import glob
import os
import tempfile

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import scenewright
import scenewright.env

PROMPT = "a Panda on a table with a red cube and a bowl"
TASK = "put the red cube in the bowl"


@pytest.fixture(scope="module")
def env(tmp_path_factory: pytest.TempPathFactory) -> scenewright.env.SceneEnv:
    e = scenewright.env.SceneEnv(
        prompt=PROMPT,
        task=TASK,
        action_type="ee_delta",
        reward_type="dense",
        render_mode="rgb_array",
        width=96,
        height=96,
        cache_dir=tmp_path_factory.mktemp("task-variants"),
    )
    yield e
    e.close()


def test_the_task_env_passes_gymnasiums_checker(env) -> None:
    check_env(env, skip_render_check=True)
    assert env.action_space.shape == (4,)
    # 9 joint positions and velocities (7 arm, 2 fingers), 2 bodies' poses, the tool.
    assert env.observation_space.shape == (9 + 9 + 2 * 7 + 3,)


def test_ee_delta_moves_the_tool_and_closes_the_gripper(env) -> None:
    obs, info = env.reset(seed=3)
    assert info["task"] == TASK and info["is_success"] is False
    tool0 = obs[-3:].copy()
    for _ in range(60):
        obs, reward, terminated, _, info = env.step(np.array([0.0, 0.0, 1.0, 1.0]))
    # Straight up (the servos lag the commanded 3 cm a step), the gripper closed.
    assert obs[-1] > tool0[2] + 0.1, (tool0, obs[-3:])
    assert np.hypot(*(obs[-3:-1] - tool0[:2])) < 0.03, (tool0, obs[-3:])
    assert reward < 0 and not terminated and info["is_success"] is False
    model, data = env.unwrapped.model, env.unwrapped.data
    grip = env.unwrapped._grip_act
    assert data.ctrl[grip] == pytest.approx(env.unwrapped._grip[1])
    frame = env.render()
    assert frame.shape == (96, 96, 3) and frame.std() > 5
    assert model.camera("front").id >= 0


def test_sparse_reward_is_one_exactly_when_the_task_holds(tmp_path) -> None:
    import mujoco

    e = scenewright.env.SceneEnv(prompt=PROMPT, task=TASK, reward_type="sparse", cache_dir=tmp_path)
    e.reset(seed=1)
    _, r, term, _, info = e.step(e.action_space.low * 0 + e.unwrapped.data.ctrl[e.unwrapped._act])
    assert r == 0.0 and not term and not info["is_success"]
    # Put the cube in the bowl by hand (teleport), let it settle: the task holds.
    m, d = e.model, e.data
    cube, bowl = m.body("cube_1"), m.body("bowl_1")
    adr = m.jnt_qposadr[cube.jntadr[0]]
    d.qpos[adr : adr + 3] = d.xpos[bowl.id] + np.array([0, 0, 0.03])
    d.qvel[:] = 0
    mujoco.mj_forward(m, d)
    for _ in range(40):
        _, r, term, _, info = e.step(d.ctrl[e.unwrapped._act].copy())
        if term:
            break
    assert info["is_success"] and r == 1.0 and term
    e.close()


def test_a_dataset_that_mixes_robots_is_refused_at_make(tmp_path) -> None:
    prompts = ["a table with two mugs and a UR5e", "a table with two mugs and a Panda"]
    scenewright.dataset(tmp_path / "mixed", prompts=prompts, count=1, progress=False)
    with pytest.raises(ValueError, match="mixes robots"):
        gym.make("scenewright/Scene-v0", dataset=tmp_path / "mixed")
    e = scenewright.env.SceneEnv(dataset=tmp_path / "mixed", robot="panda")
    for s in range(4):
        e.reset(seed=s)
        assert [r.model for r in e.package.layout.robots] == ["panda"]
    e.close()


def test_temporary_folders_are_removed(tmp_path) -> None:
    pattern = os.path.join(tempfile.gettempdir(), "scenewright-*")
    before = set(glob.glob(pattern))
    pkg = scenewright.generate("a table with a mug", seed=1)
    made = set(glob.glob(pattern)) - before
    assert len(made) == 1 and pkg.path.is_dir()
    del pkg
    gc.collect()
    assert not (set(glob.glob(pattern)) - before), "generate() left its temporary folder"
    # The environment's cache keeps at most max_cached variants, and goes on close().
    e = scenewright.env.SceneEnv(prompt="a lab with a UR5e on a workbench", max_cached=2)
    cache = e.cache_dir
    for s in range(4):
        e.reset(seed=s)
    assert len(list(cache.glob("seed-*"))) <= 2
    e.close()
    assert not cache.exists()
