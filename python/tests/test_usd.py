"""`scenewright export --format usd`, opened with usd-core's `pxr` (another OpenUSD build
than the converter's own), and compared with the scene MuJoCo compiles."""

from __future__ import annotations

import json
import os
from pathlib import Path

import mujoco
import pytest
from conftest import ROOT

import scenewright

pytestmark = pytest.mark.usd

USD_PYTHON = ROOT / ".cache" / "usd-venv" / "bin" / "python"


@pytest.fixture(autouse=True)
def _converter() -> None:
    if not USD_PYTHON.is_file() and "SCENEWRIGHT_USD_PYTHON" not in os.environ:
        pytest.skip("the USD exporter is not set up (scripts/setup.sh --usd)")
    os.environ.setdefault("SCENEWRIGHT_USD_PYTHON", str(USD_PYTHON))


def test_usd_export_opens_with_pxr_and_holds_the_scene(lab: scenewright.Package, tmp_path: Path) -> None:
    pxr = pytest.importorskip("pxr")
    from pxr import Usd, UsdGeom, UsdPhysics

    assert pxr is not None
    stage_path = lab.export_usd(tmp_path / "usd")
    assert stage_path == tmp_path / "usd" / "scenewright.usda" and stage_path.is_file()
    record = json.loads((tmp_path / "usd" / "export.json").read_text())
    # What the converter drops, said: keyframes (the home pose), cameras, lights.
    dropped = " ".join(record["dropped"])
    for word in ("keys", "cameras", "lights"):
        assert word in dropped, record["dropped"]

    stage = Usd.Stage.Open(str(stage_path))
    assert stage is not None and stage.GetDefaultPrim().IsValid()
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
    prims = list(stage.Traverse())
    rigid = [p for p in prims if p.HasAPI(UsdPhysics.RigidBodyAPI)]
    colliders = [p for p in prims if p.HasAPI(UsdPhysics.CollisionAPI)]
    revolute = [p for p in prims if p.IsA(UsdPhysics.RevoluteJoint)]
    meshes = [p for p in prims if p.IsA(UsdGeom.Mesh)]

    model, _ = lab.load()
    colliding = sum(1 for g in range(model.ngeom) if model.geom_contype[g] or model.geom_conaffinity[g])
    hinges = sum(1 for j in range(model.njnt) if int(model.jnt_type[j]) == int(mujoco.mjtJoint.mjJNT_HINGE))
    assert len(rigid) == model.nbody - 1  # every body but the world
    assert len(colliders) == colliding
    assert len(revolute) == hinges == 6  # the UR5e's joints
    assert len(meshes) >= model.nmesh
    names = {p.GetName() for p in prims}
    for o in lab.layout.objects:
        assert o.name in names, o.name
    # Where the layout put a static object is where USD has it (metres, Z up).
    cache = UsdGeom.XformCache()
    bench = next(p for p in prims if p.GetName() == "workbench_1")
    t = cache.GetLocalToWorldTransform(bench).ExtractTranslation()
    placed = next(o for o in lab.layout.objects if o.name == "workbench_1")
    assert max(abs(t[i] - placed.pos[i]) for i in range(3)) < 1e-4


def test_export_refuses_what_it_cannot_do(lab: scenewright.Package, tmp_path: Path) -> None:
    from scenewright import _engine

    with pytest.raises(scenewright.BadInput, match="unknown export format"):
        _engine.run(["export", str(lab.path), "--format", "fbx", "--out", str(tmp_path / "x")])
    with pytest.raises(scenewright.BadInput, match="not a scene package"):
        _engine.run(["export", str(tmp_path), "--format", "usd"])
    taken = tmp_path / "taken"
    taken.mkdir()
    (taken / "a").write_text("mine")
    with pytest.raises(scenewright.BadInput, match="not empty"):
        lab.export_usd(taken)
    assert (taken / "a").read_text() == "mine"
