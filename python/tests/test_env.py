"""The Gymnasium environment: variants on reset, actions on the robot's actuators."""

from __future__ import annotations

import gymnasium as gym
import numpy as np
import pytest
from conftest import settle
from gymnasium.utils.env_checker import check_env

import scenewright
import scenewright.env

PROMPT = "a lab with a workbench, a UR5e on the bench and two bins on the bench"


@pytest.fixture(scope="module")
def env(tmp_path_factory: pytest.TempPathFactory) -> scenewright.env.SceneEnv:
    e = gym.make("scenewright/Scene-v0", prompt=PROMPT, cache_dir=tmp_path_factory.mktemp("variants"))
    yield e
    e.close()


def test_spaces_are_the_robots(env) -> None:
    inner = env.unwrapped
    assert env.action_space.shape == (7,)  # the UR5e's six servos and its gripper's
    # The arm's six joints and the gripper's two fingers: positions, then velocities.
    assert env.observation_space.shape == (16,)
    model = inner.model
    np.testing.assert_allclose(env.action_space.low, model.actuator_ctrlrange[:, 0])
    np.testing.assert_allclose(env.action_space.high, model.actuator_ctrlrange[:, 1])


def test_reset_draws_a_new_variant_and_steps_move_the_robot(env) -> None:
    obs, info = env.reset(seed=1)
    first = info["package"]
    assert obs.shape == (16,)
    # At home: the observation is the robot's home pose from the keyframe.
    model = env.unwrapped.model
    home = model.key("home")
    np.testing.assert_allclose(obs[:8], home.qpos[env.unwrapped._qpos], atol=1e-9)
    _, info2 = env.reset(seed=2)
    assert info2["package"] != first
    # Same seed, same variant.
    _, info3 = env.reset(seed=1)
    assert info3["package"] == first
    # Drive the shoulder pan to +0.5 rad from home and see it follow.
    target = home.ctrl.copy()
    target[0] += 0.5
    for _ in range(200):
        obs, reward, terminated, _truncated, _ = env.step(target)
        assert reward == 0.0 and not terminated
    assert abs(obs[0] - (home.qpos[env.unwrapped._qpos][0] + 0.5)) < 0.05
    with pytest.raises(ValueError, match="7 actuators"):
        env.step(np.zeros(3))


def test_variants_are_verified_scenes_that_settle(env) -> None:
    for s in (5, 6):
        _, info = env.reset(seed=s)
        pkg = scenewright.Package(info["package"])
        assert pkg.verified
        model, data = pkg.load()
        assert settle(model, data) < 0.01


def test_gymnasium_checker_passes(tmp_path) -> None:
    e = scenewright.env.SceneEnv(prompt=PROMPT, cache_dir=tmp_path)
    check_env(e, skip_render_check=True)
    e.close()


def test_from_a_dataset_and_reward(tmp_path) -> None:
    scenewright.dataset(tmp_path / "ds", prompt=PROMPT, count=2, progress=False)
    e = scenewright.env.SceneEnv(dataset=tmp_path / "ds", reward_fn=lambda m, d: float(d.time))
    _, info = e.reset(seed=0)
    assert str(tmp_path / "ds" / "scenes") in info["package"]
    _, reward, _, _, _ = e.step(e.action_space.sample())
    assert reward == pytest.approx(5 * 0.002)


def test_a_scene_without_robot_is_refused(tmp_path) -> None:
    with pytest.raises(ValueError, match="no robot"):
        scenewright.env.SceneEnv(prompt="a kitchen with a table", cache_dir=tmp_path)
