"""A random policy in freshly generated scenes: the loop a training script starts from.

Run from a checkout, after `pip install './python[gym]'`:

    python python/examples/train_loop.py --prompt "a lab with a UR5e on a workbench and three bins"

Each episode resets into a new variant of the prompt's scene (a new seed: another layout,
other asset proportions and colours); the reward here is the negative distance of the
robot's tool point (its gripper's TCP site) from the first free object, to show where a task plugs in.
"""

from __future__ import annotations

import argparse

import gymnasium as gym
import mujoco
import numpy as np

import scenewright.env  # noqa: F401  (registers scenewright/Scene-v0)


def tool_site(model: mujoco.MjModel) -> int:
    """The robot's tool point: its gripper's TCP site, else its flange's (`<robot>_tool0`)."""
    names = [mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_SITE, i) or "" for i in range(model.nsite)]
    for suffix in ("_gripper_tcp", "_tcp", "_tool0"):
        for i, n in enumerate(names):
            if n.endswith(suffix):
                return i
    raise ValueError("the scene's robot has no tool site (…_tcp or …_tool0)")


def reach_reward(model: mujoco.MjModel, data: mujoco.MjData) -> float:
    """Negative distance from the robot's tool point to the first free object (0 without one)."""
    free = [model.jnt_bodyid[j] for j in range(model.njnt) if int(model.jnt_type[j]) == int(mujoco.mjtJoint.mjJNT_FREE)]
    if not free:
        return 0.0
    return -float(np.linalg.norm(data.site_xpos[tool_site(model)] - data.xpos[free[0]]))


def main() -> None:
    """Run a few episodes of a random policy and print their returns."""
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--prompt", default="a lab with a UR5e on a workbench and three bins on the bench")
    ap.add_argument("--episodes", type=int, default=3)
    ap.add_argument("--steps", type=int, default=50)
    args = ap.parse_args()
    env = gym.make("scenewright/Scene-v0", prompt=args.prompt, reward_fn=reach_reward)
    for episode in range(args.episodes):
        _obs, info = env.reset(seed=episode)
        total = 0.0
        for _ in range(args.steps):
            _obs, reward, terminated, truncated, _info = env.step(env.action_space.sample())
            total += float(reward)
            if terminated or truncated:
                break
        print(f"episode {episode}: scene {info['package']} (seed {info['seed']}), return {total:.2f}")
    env.close()


if __name__ == "__main__":
    main()
