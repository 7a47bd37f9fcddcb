"""A Gymnasium environment: every `reset()` draws a new variant of a prompt's scene.

```python
import gymnasium as gym
import scenewright.env  # registers scenewright/Scene-v0
env = gym.make("scenewright/Scene-v0", prompt="a Panda on a table with a red cube and a bowl",
               task="put the red cube in the bowl", action_type="ee_delta", reward_type="dense",
               render_mode="rgb_array")
obs, info = env.reset(seed=1)          # info["package"] is the scene's directory
obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
frame = env.render()                   # the scene's `front` camera
```

Actions: `action_type="joint"` (default) is the robot's actuator controls (their
`ctrlrange`); `"ee_delta"` is a move of the tool centre point (x, y, z in [-1, 1], scaled by
`ee_step` metres; the tool keeps pointing as at the start, solved by damped least squares on
MuJoCo's Jacobian) and the gripper in [-1 open, 1 closed]. Observations are the robot's joint
positions and velocities, then (with a task) the position and orientation of every body the
task names and the tool centre point's position.

With a `task` ("put the red cube in the bowl", bound to every variant by the engine and kept
in its `task.json`), the reward is `sparse` (1 when the task holds) or `dense` (minus the
distance of the tool to the thing to move and of the thing to its goal, plus 1 when it holds),
and an episode terminates when the task holds (`info["is_success"]`). Without one, the reward
is `reward_fn(model, data)` or 0: the environment is a scene, the task is yours.

A variant is a scene generated with a seed drawn from the environment's random generator
(kept under `cache_dir`, at most `max_cached` of them in a temporary cache), or a scene
drawn from an existing `dataset` (one robot: a dataset that mixes robots is refused at
`make` unless `robot=` picks one).
"""

from __future__ import annotations

import json
import shutil
import tempfile
import weakref
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
from .tasks import distance_to_goal, holds

RewardFn = Callable[[mujoco.MjModel, mujoco.MjData], float]

# Seeds tried for one variant before reset() gives up (a seed's scene may fail verification).
_TRIES = 5
_ACTIONS = ("joint", "ee_delta")
_REWARDS = ("sparse", "dense")


def _name(model: mujoco.MjModel, kind: mujoco.mjtObj, i: int) -> str:
    return mujoco.mj_id2name(model, kind, i) or ""


class SceneEnv(gym.Env[np.ndarray, np.ndarray]):
    """A robot in a generated scene; `reset()` loads a new variant at its `home` keyframe."""

    metadata: dict[str, Any] = {"render_modes": ["rgb_array", "depth_array"], "render_fps": 20}  # noqa: RUF012

    def __init__(
        self,
        prompt: str | None = None,
        robot: str | None = None,
        physics: str = "native",
        dataset: str | Path | None = None,
        cache_dir: str | Path | None = None,
        frame_skip: int = 5,
        reward_fn: RewardFn | None = None,
        task: str | None = None,
        action_type: str = "joint",
        reward_type: str = "sparse",
        ee_step: float = 0.03,
        render_mode: str | None = None,
        camera: str = "front",
        width: int = 224,
        height: int = 224,
        max_cached: int = 16,
    ) -> None:
        """Create the environment.

        Args:
            prompt: The scene to vary (needed unless `dataset` is given).
            robot: The registry robot to put in every variant (default: the prompt's); with a
                `dataset`, the robot whose scenes to use.
            physics: `"native"` or `"mjx"` collision geometry.
            dataset: Draw variants from this dataset directory instead of generating.
            cache_dir: Where generated variants are kept (default: a temporary directory).
            frame_skip: Simulation steps per `step()`.
            reward_fn: `reward_fn(model, data) -> float` after each step, without a task.
            task: What the robot is to do ("put the red cube in the bowl").
            action_type: `"joint"` (actuator controls) or `"ee_delta"` (tool moves + gripper).
            reward_type: With a task: `"sparse"` or `"dense"`.
            ee_step: Metres of tool motion for an `ee_delta` action of 1.
            render_mode: `"rgb_array"` or `"depth_array"` from `camera`.
            camera: The scene's camera to render (`front`, `overview`, `<robot>_wrist`).
            width: Rendered image width.
            height: Rendered image height.
            max_cached: Variants kept in the temporary cache (older ones are removed).
        """
        super().__init__()
        if prompt is None and dataset is None:
            raise ValueError("give a prompt or a dataset")
        if frame_skip < 1:
            raise ValueError("frame_skip must be at least 1")
        if action_type not in _ACTIONS:
            raise ValueError(f"action_type must be one of {_ACTIONS}, not {action_type!r}")
        if reward_type not in _REWARDS:
            raise ValueError(f"reward_type must be one of {_REWARDS}, not {reward_type!r}")
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode must be one of {self.metadata['render_modes']}, not {render_mode!r}")
        if action_type == "ee_delta" and task is None:
            raise ValueError("action_type='ee_delta' needs a task (it names the gripper to drive)")
        self.prompt = prompt
        self.robot = robot
        self.physics = physics
        self.frame_skip = frame_skip
        self.reward_fn = reward_fn
        self.task_words = task
        self.action_type = action_type
        self.reward_type = reward_type
        self.ee_step = float(ee_step)
        self.render_mode = render_mode
        self.camera = camera
        self.width, self.height = int(width), int(height)
        self.max_cached = max(1, int(max_cached))
        self._dataset = self._dataset_records(dataset, robot) if dataset is not None else None
        self._tmp: str | None = None
        if cache_dir is None:
            self._tmp = tempfile.mkdtemp(prefix="scenewright-env-")
            cache_dir = self._tmp
            # The temporary cache goes with the environment (close(), or when it is collected).
            self._finalizer = weakref.finalize(self, shutil.rmtree, self._tmp, True)
        self.cache_dir = Path(cache_dir)
        self.model: mujoco.MjModel | None = None
        self.data: mujoco.MjData | None = None
        self.package: Package | None = None
        self.task: dict[str, Any] | None = None
        self._renderer: mujoco.Renderer | None = None
        self._qpos: np.ndarray = np.zeros(0, dtype=np.int64)
        self._qvel: np.ndarray = np.zeros(0, dtype=np.int64)
        self._act: np.ndarray = np.zeros(0, dtype=np.int64)
        self._tracked: list[int] = []
        # The spaces come from a first variant (seed 0): every variant has the same robot.
        self._load(self._variant(0))
        assert self.model is not None
        bounds = self._ctrl_bounds()
        self._low: np.ndarray = bounds[0]
        self._high: np.ndarray = bounds[1]
        if action_type == "ee_delta":
            self.action_space = spaces.Box(low=-1.0, high=1.0, shape=(4,), dtype=np.float64)
        else:
            self.action_space = spaces.Box(low=self._low, high=self._high, dtype=np.float64)
        n = len(self._obs())
        self.observation_space = spaces.Box(low=-np.inf, high=np.inf, shape=(n,), dtype=np.float64)

    # ---- variants

    @staticmethod
    def _dataset_records(path: str | Path, robot: str | None) -> list[Any]:
        records = Dataset(path).records()
        if not records:
            raise ValueError(f"the dataset at {path} lists no scenes")
        groups: dict[str, list[Any]] = {}
        for r in records:
            key = ",".join(sorted(x.model for x in r.package.layout.robots)) or "none"
            groups.setdefault(key, []).append(r)
        if robot is not None:
            chosen = groups.get(robot)
            if not chosen:
                raise ValueError(f"the dataset at {path} has no scenes with robot {robot!r} (it has {sorted(groups)})")
            return chosen
        if len(groups) > 1:
            counts = ", ".join(f"{k}: {len(v)} scenes" for k, v in sorted(groups.items()))
            raise ValueError(
                f"the dataset at {path} mixes robots ({counts}); an environment acts with one robot: "
                f"pass robot= to use the scenes of one"
            )
        return records

    def _variant(self, seed: int) -> Package:
        if self._dataset is not None:
            pkg: Package = self._dataset[seed % len(self._dataset)].package
            return pkg
        assert self.prompt is not None
        last: Exception | None = None
        for k in range(_TRIES):
            s = seed + k
            path = self.cache_dir / f"seed-{s}"
            if (path / "report.json").is_file() and (self.task_words is None or (path / "task.json").is_file()):
                pkg = Package(path)
            else:
                if path.exists():
                    shutil.rmtree(path, ignore_errors=True)
                self._trim_cache()
                try:
                    pkg = generate(
                        self.prompt, seed=s, robot=self.robot, out=path, physics=self.physics, task=self.task_words
                    )
                except ScenewrightError as e:
                    last = e
                    continue
            if pkg.verified:
                return pkg
        raise ScenewrightError(f"no verified variant of {self.prompt!r} near seed {seed}: {last}")

    def _trim_cache(self) -> None:
        """Keeps the temporary cache to `max_cached` variants (the least recently made go)."""
        if self._tmp is None:
            return
        variants = sorted((p for p in self.cache_dir.glob("seed-*") if p.is_dir()), key=lambda p: p.stat().st_mtime)
        for p in variants[: max(0, len(variants) - self.max_cached + 1)]:
            if self.package is not None and p == self.package.path:
                continue
            shutil.rmtree(p, ignore_errors=True)

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
            and _name(model, mujoco.mjtObj.mjOBJ_JOINT, j).startswith(prefixes)
        ]
        acts = [a for a in range(model.nu) if _name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, a).startswith(prefixes)]
        qpos = np.array([model.jnt_qposadr[j] for j in joints], dtype=np.int64)
        qvel = np.array([model.jnt_dofadr[j] for j in joints], dtype=np.int64)
        act = np.array(acts, dtype=np.int64)
        if self.model is not None and (len(qpos) != len(self._qpos) or len(act) != len(self._act)):
            raise ScenewrightError(
                f"the variant {pkg.path} has another robot ({len(act)} actuators, not {len(self._act)})"
            )
        task: dict[str, Any] | None = None
        if self.task_words is not None:
            task = json.loads((pkg.path / "task.json").read_text())
        self.model, self.data, self.package, self.task = model, data, pkg, task
        self._qpos, self._qvel, self._act = qpos, qvel, act
        self._tracked = []
        if task is not None:
            names: list[str] = []
            for g in task["goals"]:
                for key in ("object", "target"):
                    v = g.get(key)
                    for n in v if isinstance(v, list) else [v] if v else []:
                        if n not in names:
                            names.append(n)
            self._tracked = [mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, n) for n in names]
            self._setup_ee(task)
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None

    def _setup_ee(self, task: dict[str, Any]) -> None:
        """The arm's joints from its base to the tool centre point, their servos, the gripper."""
        m = self.model
        assert m is not None
        g = task.get("gripper")
        if g is None:
            raise ScenewrightError(f"the task's robot {task['robot']} has no gripper to drive")
        self._tcp = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SITE, g["tcp_site"])
        self._grip_act = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_ACTUATOR, g["actuator"])
        self._grip = (float(g["open"]), float(g["closed"]))
        chain: list[int] = []
        b = int(m.site_bodyid[self._tcp])
        while b > 0:
            for j in range(int(m.body_jntadr[b]), int(m.body_jntadr[b]) + int(m.body_jntnum[b])):
                if int(m.jnt_type[j]) in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE)):
                    chain.append(j)
            b = int(m.body_parentid[b])
        chain.reverse()
        servo = {int(m.actuator_trnid[a, 0]): a for a in range(m.nu) if int(m.actuator_trntype[a]) == 0}
        self._arm = [j for j in chain if j in servo]
        self._arm_act = np.array([servo[j] for j in self._arm], dtype=np.int64)
        self._arm_dof = np.array([m.jnt_dofadr[j] for j in self._arm], dtype=np.int64)
        self._arm_qpos = np.array([m.jnt_qposadr[j] for j in self._arm], dtype=np.int64)
        self._scratch = mujoco.MjData(m)

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
        parts = [self.data.qpos[self._qpos], self.data.qvel[self._qvel]]
        for b in self._tracked:
            parts += [self.data.xpos[b], self.data.xquat[b]]
        if self.task is not None:
            parts.append(self.data.site_xpos[self._tcp])
        return np.concatenate(parts).astype(np.float64)

    # ---- end-effector control

    def _ee_targets(self, a: np.ndarray) -> None:
        """Sets the arm's servos so that the tool moves by `a[:3]·ee_step`, and the gripper."""
        m, d, s = self.model, self.data, self._scratch
        assert m is not None and d is not None
        target = d.site_xpos[self._tcp] + self.ee_step * np.clip(a[:3], -1, 1)
        s.qpos[:] = d.qpos
        q = d.ctrl[self._arm_act].copy()
        s.qpos[self._arm_qpos] = q
        jacp = np.zeros((3, m.nv))
        jacr = np.zeros((3, m.nv))
        for _ in range(8):
            mujoco.mj_kinematics(m, s)
            mujoco.mj_comPos(m, s)
            err_p = target - s.site_xpos[self._tcp]
            rot = s.site_xmat[self._tcp].reshape(3, 3)
            err_r = 0.5 * np.cross(rot[:, 2], self._tool_axis[:, 2]) + 0.5 * np.cross(rot[:, 1], self._tool_axis[:, 1])
            if np.linalg.norm(err_p) < 1e-4 and np.linalg.norm(err_r) < 1e-3:
                break
            mujoco.mj_jacSite(m, s, jacp, jacr, self._tcp)
            jac = np.vstack([jacp[:, self._arm_dof], 0.5 * jacr[:, self._arm_dof]])
            err = np.concatenate([err_p, 0.5 * err_r])
            dq = jac.T @ np.linalg.solve(jac @ jac.T + 0.05**2 * np.eye(6), err)
            q = q + np.clip(dq, -0.2, 0.2)
            lo, hi = m.actuator_ctrlrange[self._arm_act].T
            q = np.clip(q, lo, hi)
            s.qpos[self._arm_qpos] = q
        d.ctrl[self._arm_act] = q
        g = (float(np.clip(a[3], -1, 1)) + 1) / 2
        d.ctrl[self._grip_act] = self._grip[0] + g * (self._grip[1] - self._grip[0])

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
        assert self.package is not None and self.data is not None
        if self.task is not None:
            self._tool_axis = self.data.site_xmat[self._tcp].reshape(3, 3).copy()
        info: dict[str, Any] = {"package": str(self.package.path), "seed": self.package.report.seed}
        if self.task is not None:
            info["task"] = self.task["instruction"]
            info["is_success"] = False
        return self._obs(), info

    def step(self, action: np.ndarray) -> tuple[np.ndarray, float, bool, bool, dict[str, Any]]:
        """Apply `action` for `frame_skip` steps."""
        assert self.model is not None and self.data is not None
        a = np.asarray(action, dtype=np.float64).reshape(-1)
        if self.action_type == "ee_delta":
            if a.shape != (4,):
                raise ValueError(f"the action has {a.size} values; ee_delta takes 4 (dx, dy, dz, gripper)")
            self._ee_targets(a)
        else:
            if a.shape != (len(self._act),):
                raise ValueError(f"the action has {a.size} values; the robot has {len(self._act)} actuators")
            self.data.ctrl[self._act] = np.clip(a, self._low, self._high)
        mujoco.mj_step(self.model, self.data, nstep=self.frame_skip)
        obs = self._obs()
        info: dict[str, Any] = {"time": float(self.data.time)}
        diverged = not bool(np.isfinite(self.data.qpos).all())
        if self.task is None:
            reward = float(self.reward_fn(self.model, self.data)) if self.reward_fn is not None else 0.0
            return obs, reward, diverged, False, info
        success = not diverged and holds(self.task, self.model, self.data)
        info["is_success"] = success
        reward = float(success) if self.reward_type == "sparse" else float(success) - self._distance()
        return obs, reward, success or diverged, False, info

    def _distance(self) -> float:
        """Tool to the first thing to move, plus each thing to its goal."""
        assert self.model is not None and self.data is not None and self.task is not None
        goal = distance_to_goal(self.task, self.model, self.data)
        first = self._tracked[0] if self._tracked else -1
        reach = float(np.linalg.norm(self.data.site_xpos[self._tcp] - self.data.xpos[first])) if first >= 0 else 0.0
        return reach + goal

    def render(self) -> np.ndarray | None:
        """The `camera`'s image (RGB, or depth in metres), per `render_mode`."""
        if self.render_mode is None:
            return None
        assert self.model is not None and self.data is not None
        if self._renderer is None:
            self._renderer = mujoco.Renderer(self.model, self.height, self.width)
        if self.render_mode == "depth_array":
            self._renderer.enable_depth_rendering()
        self._renderer.update_scene(self.data, camera=self.camera)
        return np.asarray(self._renderer.render())

    def close(self) -> None:
        """Remove the temporary variant cache, if this environment made one."""
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None
        if self._tmp is not None:
            self._finalizer()
            self._tmp = None


gym.register(id="scenewright/Scene-v0", entry_point="scenewright.env:SceneEnv", max_episode_steps=1000)
