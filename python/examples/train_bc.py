r"""Behaviour cloning on a `scenewright demos` dataset, against a random policy.

Make demonstrations, then train and evaluate (needs `pyarrow`; the network is NumPy):

    scenewright demos --prompt "a Panda on a table that puts the red cube in the bowl" \\
        --episodes 200 --out out/pick
    python python/examples/train_bc.py out/pick --holdout 20

The policy maps an observation (the robot's joint positions, where its tool centre point is,
where the task's objects and targets are and how far each is from the tool, the episode's
progress) to the action (the actuator controls held for one frame), as the expert recorded
them; a joint's target as its step from the joint's position. The observations are read
from MuJoCo while the recorded actions are replayed, the same way the rollouts read them,
and in the robot's own frame: every episode is a new layout. It is trained on all but the
last `--holdout` episodes and rolled out from the start of each held-out episode's scene (a
layout it has not seen) in plain MuJoCo; success is the task's predicates
(`scenewright.tasks`) at the end. A random policy (controls drawn within the recorded
ranges) is rolled out from the same starts.
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

Policy = Callable[[np.ndarray], np.ndarray]


@dataclass
class Observer:
    """Reads a policy's input from an episode's scene: what its task is about, by id."""

    qadr: list[int]
    base: int
    tcp: int
    bodies: list[int]
    horizon: int

    @staticmethod
    def of(ep: DemoEpisode, model: mujoco.MjModel, horizon: int) -> Observer:
        """The observer of one episode (its own robot, tool site, objects and targets)."""
        names = ep.info["features"]["observation.state"]["names"]
        qadr = [int(model.jnt_qposadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, n)]) for n in names]
        tcp = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, ep.task["gripper"]["tcp_site"])
        # The robot's own frame: the top body of the chain its first joint moves.
        first = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, names[0])
        base = int(model.body_rootid[model.jnt_bodyid[first]])
        wanted: list[str] = []
        for goal in ep.task["goals"]:
            for key in ("object", "target"):
                v = goal.get(key)
                wanted += v if isinstance(v, list) else [v] if v else []
        bodies = [mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, n) for n in dict.fromkeys(wanted)]
        return Observer(qadr, base, tcp, [b for b in bodies if b >= 0], horizon)

    def __call__(self, data: mujoco.MjData, t: int) -> np.ndarray:
        """Read the input at frame t.

        Joint positions; in the robot's own frame (each episode stands it somewhere else) the
        tool's position and each body's position and offset from the tool; the progress.
        """
        origin, rot = data.xpos[self.base], data.xmat[self.base].reshape(3, 3)
        tool = (data.site_xpos[self.tcp] - origin) @ rot
        where = [((data.xpos[b] - origin) @ rot, (data.xpos[b] - origin) @ rot - tool) for b in self.bodies]
        return np.concatenate([data.qpos[self.qadr], tool, *(np.concatenate(w) for w in where), [t / self.horizon]])


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


def substeps(ep: DemoEpisode, model: mujoco.MjModel) -> int:
    """Physics steps per frame: each action is held for 1/fps."""
    fps, dt = int(ep.info["fps"]), float(model.opt.timestep)
    return round(1.0 / (fps * dt))


def demonstrations(ep: DemoEpisode, horizon: int) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """(observation, action) per frame, read in MuJoCo while the recorded actions replay."""
    model, data = ep.load()
    observe, n = Observer.of(ep, model, horizon), substeps(ep, model)
    xs, ys = [], []
    for t, action in enumerate(ep.frames()["action"]):
        xs.append(observe(data, t))
        ys.append(action)
        data.ctrl[:] = action
        mujoco.mj_step(model, data, nstep=n)
    return xs, ys


def rollout(ep: DemoEpisode, policy: Policy, horizon: int) -> bool:
    """Runs the policy from the episode's start for `horizon` frames; True when its task holds then."""
    model, data = ep.load()
    observe, n = Observer.of(ep, model, horizon), substeps(ep, model)
    for t in range(horizon):
        data.ctrl[:] = policy(observe(data, t))
        mujoco.mj_step(model, data, nstep=n)
    mujoco.mj_forward(model, data)
    return holds(ep.task, model, data)


def main() -> None:
    """Train on the dataset, roll out on the held-out starts, print both success rates."""
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dataset")
    ap.add_argument("--holdout", type=int, default=5)
    ap.add_argument("--epochs", type=int, default=150)
    ap.add_argument("--hidden", type=int, default=256)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    demos = Demos(args.dataset)
    eps = list(demos.episodes())
    if len(eps) <= args.holdout:
        raise SystemExit(f"{len(eps)} episodes: need more than --holdout {args.holdout}")
    train, test = eps[: -args.holdout], eps[-args.holdout :]
    # Long enough for the slowest demonstration, with a margin for a policy a little slower.
    horizon = int(1.2 * max(len(ep.frames()["action"]) for ep in train))
    xs: list[np.ndarray] = []
    ys: list[np.ndarray] = []
    for ep in train:
        x_ep, y_ep = demonstrations(ep, horizon)
        xs += x_ep
        ys += y_ep
    x, y = np.asarray(xs), np.asarray(ys)
    # A joint's target is learnt as its step from where the joint is (the observation's first
    # entries are the joint positions, in the state's order): one reach looks alike wherever
    # the arm starts, and an error does not throw the arm across the room.
    state = eps[0].info["features"]["observation.state"]["names"]
    steps = [(a, state.index(n)) for a, n in enumerate(eps[0].info["features"]["action"]["names"]) if n in state]
    rel = np.zeros((x.shape[1], y.shape[1]))
    for a, q in steps:
        rel[q, a] = 1.0
    mlp = Mlp.new(x.shape[1], y.shape[1], args.hidden, rng)
    loss = mlp.fit(x, y - x @ rel, args.epochs, rng)
    lo, hi = y.min(0), y.max(0)
    bc = sum(rollout(ep, lambda o: mlp(o) + o @ rel, horizon) for ep in test)
    rand = sum(rollout(ep, lambda _o: rng.uniform(lo, hi), horizon) for ep in test)
    print(f"trained on {len(train)} episodes ({len(x)} frames), final loss {loss:.4f}")
    print(f"behaviour cloning: {bc}/{len(test)} held-out episodes solved ({100 * bc / len(test):.0f} %)")
    print(f"random policy:     {rand}/{len(test)} ({100 * rand / len(test):.0f} %)")


if __name__ == "__main__":
    main()
