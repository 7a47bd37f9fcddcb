"""Physics targets in the simulators they are for: MuJoCo XLA (JAX, on CPU) loads, steps
and settles `physics="mjx"` scenes like native MuJoCo does; MuJoCo Warp (on CPU) loads the
default scenes and matches native MuJoCo after 200 steps.

JIT compiling a scene for MJX on CPU takes tens of seconds, so this runs a small sample
that covers what the rewrite touches: a robot arm's cylinders on a bench with free bins,
object cylinders (a round table, mugs), and a scene with no joint at all. The whole bench
suite runs in the benchmark (bench/gpu/targets.py, BENCHMARKS.md).
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from conftest import settle

import scenewright

SAMPLE = [
    "a robotics lab with a workbench, a UR5e on the bench, three bins on the bench and a chair next to the workbench",
    "a kitchen with a round table, two chairs around it and two mugs on the table",
    "a warehouse with four pallet racks against the north wall",
]


def free_bodies(model: mujoco.MjModel) -> np.ndarray:
    return np.array(
        [model.jnt_bodyid[j] for j in range(model.njnt) if int(model.jnt_type[j]) == int(mujoco.mjtJoint.mjJNT_FREE)],
        dtype=np.int64,
    )


@pytest.mark.mjx
@pytest.mark.parametrize("prompt", SAMPLE)
def test_mjx_loads_steps_and_settles_like_native(prompt: str, tmp_path) -> None:
    jax = pytest.importorskip("jax")
    from mujoco import mjx

    native = scenewright.generate(prompt, seed=1, out=tmp_path / "native")
    pkg = scenewright.generate(prompt, seed=1, out=tmp_path / "mjx", physics="mjx")
    assert pkg.verified
    # The default scene of a cylinder prompt is what MJX refuses; the mjx one it takes.
    model, data = pkg.load()
    nmodel, _ = native.load()
    cylinders = any(int(t) == int(mujoco.mjtGeom.mjGEOM_CYLINDER) for t in nmodel.geom_type[nmodel.geom_contype > 0])
    if cylinders:
        with pytest.raises(NotImplementedError, match="collisions not implemented"):
            mjx.put_model(nmodel)
    mx = mjx.put_model(model)
    dx = mjx.put_data(model, data)
    steps = round(2.0 / model.opt.timestep)
    settle_jit = jax.jit(lambda d: jax.lax.fori_loop(0, steps, lambda _, x: mjx.step(mx, x), d))
    out = settle_jit(dx)
    qpos = np.asarray(out.qpos)
    assert np.isfinite(qpos).all()
    free = free_bodies(model)
    mjx_disp = np.linalg.norm(np.asarray(out.xpos)[free] - data.xpos[free], axis=1) if len(free) else np.zeros(1)
    # Native MuJoCo on the same file, the same 2 s.
    native_disp = settle(model, data)
    assert mjx_disp.max() < 0.01, f"MJX moved a free body {mjx_disp.max():.4f} m"
    assert native_disp < 0.01
    assert abs(float(mjx_disp.max()) - native_disp) < 0.005


@pytest.mark.warp
def test_warp_loads_default_scenes_and_matches_native(tmp_path) -> None:
    wp = pytest.importorskip("warp")
    mjw = pytest.importorskip("mujoco_warp")
    wp.config.quiet = True
    for i, prompt in enumerate(SAMPLE):
        pkg = scenewright.generate(prompt, seed=1, out=tmp_path / f"s{i}")
        model, data = pkg.load()
        with wp.ScopedDevice("cpu"):
            mw = mjw.put_model(model)
            dw = mjw.put_data(model, data, nconmax=1024, njmax=8192)
            for _ in range(200):
                mjw.step(mw, dw)
            qpos = dw.qpos.numpy()[0]
        mujoco.mj_step(model, data, nstep=200)
        err = float(np.abs(qpos - data.qpos).max(initial=0.0))
        assert err < 1e-4, f"{prompt}: Warp and native differ by {err:.2e} after 200 steps"


@pytest.mark.warp
def test_load_warp_sizes_the_scene_so_nothing_drifts(tmp_path) -> None:
    wp = pytest.importorskip("warp")
    mjw = pytest.importorskip("mujoco_warp")
    wp.config.quiet = True
    pkg = scenewright.generate("a table with a red cube and a bowl and a Panda", seed=2, out=tmp_path / "p")
    sizes = pkg.warp_sizes()
    assert sizes["nconmax"] >= 2 * sizes["ncon"] and sizes["njmax"] >= 2 * sizes["nefc"]
    assert (pkg.path / "warp.json").is_file()
    with wp.ScopedDevice("cpu"):
        mw, dw = pkg.load_warp()
        for _ in range(100):
            mjw.step(mw, dw)
        qpos = dw.qpos.numpy()[0]
    model, data = pkg.load()
    mujoco.mj_step(model, data, nstep=100)
    err = float(np.abs(qpos - data.qpos).max(initial=0.0))
    assert err < 1e-3, f"Warp and native differ by {err:.2e} after 100 steps"
