"""A Gymnasium environment: every `reset()` draws a new variant of a prompt's scene.

```python
import gymnasium as gym
import scenewright.env  # registers scenewright/Scene-v0
env = gym.make("scenewright/Scene-v0", prompt="a lab with a UR5e on a workbench and three bins")
obs, info = env.reset(seed=1)          # info["package"] is the scene's directory
obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
```

Actions are the robot's actuator controls (their `ctrlrange`); observations are the
robot's joint positions then velocities. The reward is 0 unless a `reward_fn(model, data)`
is given: the environment is a scene, the task is yours. A variant is a scene generated
with a seed drawn from the environment's random generator (kept under `cache_dir`, so a
seed is generated once), or a scene drawn from an existing `dataset`.
"""

from __future__ import annotations

import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

import gymnasium as gym
import mujoco
import numpy as np
from gymnasium import spaces

from .api import generate
from .dataset import Dataset
from .errors import ScenewrightError
from .package import Package

RewardFn = Callable[[mujoco.MjModel, mujoco.MjData], float]

# Seeds tried for one variant before reset() gives up (a seed's scene may fail verification).
_TRIES = 5


class SceneEnv(gym.Env[np.ndarray, np.ndarray]):
    """A robot in a generated scene; `reset()` loads a new variant at its `home` keyframe."""

    metadata: dict[str, Any] = {"render_modes": []}  # noqa: RUF012 - Gymnasium's class attribute

    def __init__(
        self,
        prompt: str | None = None,
        robot: str | None = None,
        physics: str = "native",
        dataset: str | Path | None = None,
        cache_dir: str | Path | None = None,
        frame_skip: int = 5,
        reward_fn: RewardFn | None = None,
    ) -> None:
        """Create the environment.

        Args:
            prompt: The scene to vary (needed unless `dataset` is given).
            robot: The registry robot to put in every variant (default: the prompt's).
            physics: `"native"` or `"mjx"` collision geometry.
            dataset: Draw variants from this dataset directory instead of generating.
            cache_dir: Where generated variants are kept (default: a temporary directory).
            frame_skip: Simulation steps per `step()`.
            reward_fn: `reward_fn(model, data) -> float` after each step (default 0).
        """
        super().__init__()
        if prompt is None and dataset is None:
            raise ValueError("give a prompt or a dataset")
        if frame_skip < 1:
            raise ValueError("frame_skip must be at least 1")
        self.prompt = prompt
        self.robot = robot
        self.physics = physics
        self.frame_skip = frame_skip
        self.reward_fn = reward_fn
        self._dataset = Dataset(dataset).records() if dataset is not None else None
        if self._dataset is not None and not self._dataset:
            raise ValueError(f"the dataset at {dataset} lists no scenes")
        self._tmp: tempfile.TemporaryDirectory[str] | None = None
        if cache_dir is None:
            self._tmp = tempfile.TemporaryDirectory(prefix="scenewright-env-")
            cache_dir = self._tmp.name
        self.cache_dir = Path(cache_dir)
        self.model: mujoco.MjModel | None = None
        self.data: mujoco.MjData | None = None
        self.package: Package | None = None
        self._qpos: np.ndarray = np.zeros(0, dtype=np.int64)
        self._qvel: np.ndarray = np.zeros(0, dtype=np.int64)
        self._act: np.ndarray = np.zeros(0, dtype=np.int64)
        # The spaces come from a first variant (seed 0): every variant has the same robot.
        self._load(self._variant(0))
        assert self.model is not None
        bounds = self._ctrl_bounds()
        self._low: np.ndarray = bounds[0]
        self._high: np.ndarray = bounds[1]
        self.action_space = spaces.Box(low=self._low, high=self._high, dtype=np.float64)
        n = len(self._qpos) + len(self._qvel)
        self.observation_space = spaces.Box(low=-np.inf, high=np.inf, shape=(n,), dtype=np.float64)

    # ---- variants

    def _variant(self, seed: int) -> Package:
        if self._dataset is not None:
            return self._dataset[seed % len(self._dataset)].package
        assert self.prompt is not None
        last: Exception | None = None
        for k in range(_TRIES):
            s = seed + k
            path = self.cache_dir / f"seed-{s}"
            if (path / "report.json").is_file():
                pkg = Package(path)
            else:
                try:
                    pkg = generate(self.prompt, seed=s, robot=self.robot, out=path, physics=self.physics)
                except ScenewrightError as e:
                    last = e
                    continue
            if pkg.verified:
                return pkg
        raise ScenewrightError(f"no verified variant of {self.prompt!r} near seed {seed}: {last}")

    def _load(self, pkg: Package) -> None:
        model, data = pkg.load()
        robots = [r.name for r in pkg.layout.robots]
        if not robots:
            raise ValueError(f"the scene {pkg.path} has no robot to act with; pass robot=")
        prefixes = tuple(f"{r}_" for r in robots)
        joints = [
            j
            for j in range(model.njnt)
            if int(model.jnt_type[j]) in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
            and mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, j).startswith(prefixes)
        ]
        acts = [
            a
            for a in range(model.nu)
            if (mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, a) or "").startswith(prefixes)
        ]
        qpos = np.array([model.jnt_qposadr[j] for j in joints], dtype=np.int64)
        qvel = np.array([model.jnt_dofadr[j] for j in joints], dtype=np.int64)
        act = np.array(acts, dtype=np.int64)
        if self.model is not None and (len(qpos) != len(self._qpos) or len(act) != len(self._act)):
            raise ScenewrightError(
                f"the variant {pkg.path} has another robot ({len(act)} actuators, not {len(self._act)})"
            )
        self.model, self.data, self.package = model, data, pkg
        self._qpos, self._qvel, self._act = qpos, qvel, act

    def _ctrl_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        assert self.model is not None
        m = self.model
        low = np.full(len(self._act), -np.inf)
        high = np.full(len(self._act), np.inf)
        for i, a in enumerate(self._act):
            if m.actuator_ctrllimited[a]:
                low[i], high[i] = m.actuator_ctrlrange[a]
        return low, high

    def _obs(self) -> np.ndarray:
        assert self.data is not None
        return np.concatenate([self.data.qpos[self._qpos], self.data.qvel[self._qvel]]).astype(np.float64)

    # ---- Gymnasium API

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[np.ndarray, dict[str, Any]]:
        """Draw a new variant (or `options={"variant": N}` for scene seed N) at `home`."""
        super().reset(seed=seed)
        if options is not None and "variant" in options:
            variant = int(options["variant"])
        else:
            variant = int(self.np_random.integers(0, 2**31 - 1))
        self._load(self._variant(variant))
        assert self.package is not None
        return self._obs(), {"package": str(self.package.path), "seed": self.package.report.seed}

    def step(self, action: np.ndarray) -> tuple[np.ndarray, float, bool, bool, dict[str, Any]]:
        """Apply `action` to the robot's actuators for `frame_skip` steps."""
        assert self.model is not None and self.data is not None
        a = np.asarray(action, dtype=np.float64).reshape(-1)
        if a.shape != (len(self._act),):
            raise ValueError(f"the action has {a.size} values; the robot has {len(self._act)} actuators")
        self.data.ctrl[self._act] = np.clip(a, self._low, self._high)
        mujoco.mj_step(self.model, self.data, nstep=self.frame_skip)
        obs = self._obs()
        reward = float(self.reward_fn(self.model, self.data)) if self.reward_fn is not None else 0.0
        # A diverged simulation ends the episode.
        terminated = not bool(np.isfinite(self.data.qpos).all())
        return obs, reward, terminated, False, {"time": float(self.data.time)}

    def close(self) -> None:
        """Remove the temporary variant cache, if this environment made one."""
        if self._tmp is not None:
            self._tmp.cleanup()
            self._tmp = None


gym.register(id="scenewright/Scene-v0", entry_point="scenewright.env:SceneEnv", max_episode_steps=1000)
