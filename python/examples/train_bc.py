r"""Behaviour cloning on a `scenewright demos` dataset, against a random policy.

Make demonstrations, then train and evaluate (needs `pyarrow`; the network is NumPy):

    scenewright demos --prompt "a Panda on a table that puts the red cube in the bowl" \\
        --episodes 60 --out out/pick
    python python/examples/train_bc.py out/pick --holdout 10

The policy maps an observation (the robot's joint positions, the moved thing's pose, the
episode's progress) to the action (the actuator controls held for one frame), as the
expert recorded them. It is trained on all but the last `--holdout` episodes and rolled
out from the start of each held-out episode's scene (a layout it has not seen) in plain
MuJoCo; success is the task's predicates (`scenewright.tasks`) at the end. A random policy
(controls drawn within the recorded ranges) is rolled out from the same starts.
"""

from __future__ import annotations

import argparse
import itertools
from collections.abc import Callable
from dataclasses import dataclass

import mujoco
import numpy as np

from scenewright.demos import DemoEpisode, Demos
from scenewright.tasks import holds

Policy = Callable[[np.ndarray, np.ndarray, int], np.ndarray]


def features(state: np.ndarray, env: np.ndarray, progress: float) -> np.ndarray:
    """The policy's input: joint positions, the moved things' poses, the episode's progress."""
    return np.concatenate([state, env, [progress]])


@dataclass
class Mlp:
    """Two hidden layers, tanh, trained by Adam on the mean squared error."""

    w: list[np.ndarray]
    b: list[np.ndarray]
    mu: np.ndarray
    sd: np.ndarray
    amu: np.ndarray
    asd: np.ndarray

    @staticmethod
    def new(n_in: int, n_out: int, hidden: int, rng: np.random.Generator) -> Mlp:
        """A network with random weights."""
        sizes = [n_in, hidden, hidden, n_out]
        w = [rng.normal(0, 1 / np.sqrt(a), (a, b)) for a, b in itertools.pairwise(sizes)]
        b = [np.zeros(s) for s in sizes[1:]]
        return Mlp(w, b, np.zeros(n_in), np.ones(n_in), np.zeros(n_out), np.ones(n_out))

    def forward(self, x: np.ndarray) -> tuple[np.ndarray, list[np.ndarray]]:
        """The normalised output and every layer's activation."""
        h = [(x - self.mu) / self.sd]
        for i, (w, b) in enumerate(zip(self.w, self.b, strict=True)):
            z = h[-1] @ w + b
            h.append(np.tanh(z) if i < len(self.w) - 1 else z)
        return h[-1], h

    def __call__(self, x: np.ndarray) -> np.ndarray:
        """The action for one input."""
        y, _ = self.forward(x[None])
        return np.asarray(y[0] * self.asd + self.amu)

    def fit(self, x: np.ndarray, y: np.ndarray, epochs: int, rng: np.random.Generator) -> float:
        """Trains on (x, y); the last batch's loss."""
        self.mu, self.sd = x.mean(0), x.std(0) + 1e-6
        self.amu, self.asd = y.mean(0), y.std(0) + 1e-6
        yn = (y - self.amu) / self.asd
        params = self.w + self.b
        m = [np.zeros_like(p) for p in params]
        v = [np.zeros_like(p) for p in params]
        step, lr, loss = 0, 1e-3, 0.0
        for _ in range(epochs):
            order = rng.permutation(len(x))
            for k in range(0, len(x), 256):
                idx = order[k : k + 256]
                out, h = self.forward(x[idx])
                err = out - yn[idx]
                loss = float((err**2).mean())
                grad = 2 * err / err.size
                gw, gb = [], []
                for i in reversed(range(len(self.w))):
                    gw.insert(0, h[i].T @ grad)
                    gb.insert(0, grad.sum(0))
                    if i > 0:
                        grad = (grad @ self.w[i].T) * (1 - h[i] ** 2)
                step += 1
                for j, (p, g) in enumerate(zip(params, gw + gb, strict=True)):
                    m[j] = 0.9 * m[j] + 0.1 * g
                    v[j] = 0.999 * v[j] + 0.001 * g * g
                    p -= lr * (m[j] / (1 - 0.9**step)) / (np.sqrt(v[j] / (1 - 0.999**step)) + 1e-8)
        return loss


def rollout(ep: DemoEpisode, policy: Policy, horizon: int) -> bool:
    """Runs `policy(obs, t)` from the episode's start; True when its task holds at the end."""
    model, data = ep.load()
    names = ep.info["features"]["observation.state"]["names"]
    qadr = [int(model.jnt_qposadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, n)]) for n in names]
    env_names = ep.info["features"].get("observation.environment_state", {}).get("names", [])
    bodies = []
    for n in env_names[::7]:
        bodies.append(mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, n.split(".")[0]))
    substeps = round(1.0 / (int(ep.info["fps"]) * model.opt.timestep))
    for t in range(horizon):
        env = np.concatenate([np.concatenate([data.xpos[b], data.xquat[b]]) for b in bodies]) if bodies else np.zeros(0)
        data.ctrl[:] = policy(data.qpos[qadr], env, t)
        mujoco.mj_step(model, data, nstep=substeps)
    mujoco.mj_forward(model, data)
    return holds(ep.task, model, data)


def main() -> None:
    """Train on the dataset, roll out on the held-out starts, print both success rates."""
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dataset")
    ap.add_argument("--holdout", type=int, default=5)
    ap.add_argument("--epochs", type=int, default=60)
    ap.add_argument("--hidden", type=int, default=256)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    demos = Demos(args.dataset)
    eps = list(demos.episodes())
    if len(eps) <= args.holdout:
        raise SystemExit(f"{len(eps)} episodes: need more than --holdout {args.holdout}")
    train, test = eps[: -args.holdout], eps[-args.holdout :]
    xs, ys, lengths = [], [], []
    for ep in train:
        f = ep.frames()
        n = len(f["action"])
        lengths.append(n)
        env = f.get("observation.environment_state", np.zeros((n, 0)))
        for t in range(n):
            xs.append(features(f["observation.state"][t], env[t], t / n))
            ys.append(f["action"][t])
    x, y = np.asarray(xs), np.asarray(ys)
    mlp = Mlp.new(x.shape[1], y.shape[1], args.hidden, rng)
    loss = mlp.fit(x, y, args.epochs, rng)
    horizon = int(np.mean(lengths))
    lo, hi = y.min(0), y.max(0)
    bc = sum(rollout(ep, lambda s, e, t: mlp(features(s, e, t / horizon)), horizon) for ep in test)
    rand = sum(rollout(ep, lambda s, e, t: rng.uniform(lo, hi), horizon) for ep in test)
    print(f"trained on {len(train)} episodes ({len(x)} frames), final loss {loss:.4f}")
    print(f"behaviour cloning: {bc}/{len(test)} held-out episodes solved ({100 * bc / len(test):.0f} %)")
    print(f"random policy:     {rand}/{len(test)} ({100 * rand / len(test):.0f} %)")


if __name__ == "__main__":
    main()
