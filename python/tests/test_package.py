"""generate → Package: paths, plan, layout, report as Python objects, and load()."""

from __future__ import annotations

import json
import os
import stat

import mujoco
import numpy as np
import pytest
from conftest import LAB, settle

import scenewright


def test_generate_returns_the_package_as_python_objects(lab: scenewright.Package) -> None:
    assert lab.scene_xml.is_file() and lab.scene_only_xml.is_file()
    assert lab.verified and lab.report.status == "verified" and lab.report.failures == []
    assert lab.report.seed == 3 and lab.layout.seed == 3
    assert lab.plan.room_kind == "lab"
    assert {g.category for g in lab.plan.objects} == {"workbench", "bin", "chair"}
    assert lab.plan.robots == ["ur5e"]
    assert sorted(o.category for o in lab.layout.objects) == ["bin", "bin", "bin", "chair", "workbench"]
    assert [r.model for r in lab.layout.robots] == ["ur5e"]
    # The Python objects are the JSON documents, read field by field.
    raw = json.loads((lab.path / "layout.json").read_text())
    assert [o.name for o in lab.layout.objects] == [o["name"] for o in raw["objects"]]
    assert "total_ms" in lab.timings
    assert {p.name for p in lab.files()} >= {"scene.xml", "plan.json", "layout.json", "report.json"}


def test_load_is_at_home_where_the_layout_says(lab: scenewright.Package) -> None:
    model, data = lab.load()
    key = model.key("home")
    np.testing.assert_allclose(data.qpos, key.qpos)
    # Second route: every object body stands where layout.json put it (MuJoCo's own
    # forward kinematics of the loaded file against the layout's numbers).
    for o in lab.layout.objects:
        body = model.body(o.name).id
        assert np.linalg.norm(data.xpos[body][:2] - np.array(o.pos[:2])) < 0.05, o.name
    # Every scene a test makes is settled in MuJoCo.
    assert settle(model, data) < 0.01
    model2, _ = lab.load(robots=False)
    assert model2.nu == 0 and model.nu == 7  # six arm servos and the gripper's


def test_same_prompt_and_seed_give_the_same_scene(lab: scenewright.Package, tmp_path) -> None:
    again = scenewright.generate(LAB, seed=3, out=tmp_path / "again")
    assert again.scene_xml.read_bytes() == lab.scene_xml.read_bytes()
    other = scenewright.generate(LAB, seed=4, out=tmp_path / "other", robot="panda")
    assert [r.model for r in other.layout.robots] == ["panda"]
    model, data = other.load()
    assert settle(model, data) < 0.01


def test_bad_input_is_a_clear_error(tmp_path) -> None:
    with pytest.raises(scenewright.BadInput, match="unknown robot 'r2d2'"):
        scenewright.generate(LAB, robot="r2d2", out=tmp_path / "x")
    with pytest.raises(scenewright.BadInput):
        scenewright.generate("   ", out=tmp_path / "y")
    taken = tmp_path / "taken"
    taken.mkdir()
    (taken / "keep.txt").write_text("mine")
    with pytest.raises(scenewright.BadInput, match="not empty"):
        scenewright.generate(LAB, out=taken)
    assert (taken / "keep.txt").read_text() == "mine"
    with pytest.raises(scenewright.BadInput, match="not a scene package"):
        scenewright.Package(tmp_path)
    a_file = tmp_path / "a_file"
    a_file.write_text("")
    with pytest.raises(scenewright.BadInput, match="cannot write"):
        scenewright.generate(LAB, out=a_file / "pkg")
    with pytest.raises(ValueError, match="physics"):
        scenewright.generate(LAB, physics="bullet")


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes anywhere")
def test_unwritable_output_is_bad_input(tmp_path) -> None:
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(stat.S_IRUSR | stat.S_IXUSR)
    with pytest.raises(scenewright.BadInput, match="cannot write"):
        scenewright.generate(LAB, out=ro / "pkg")


def test_a_missing_engine_is_named(monkeypatch, tmp_path) -> None:
    monkeypatch.setenv("SCENEWRIGHT_BIN", str(tmp_path / "nope"))
    with pytest.raises(scenewright.EngineNotFound, match="SCENEWRIGHT_BIN"):
        scenewright.generate(LAB)


def test_no_verify_is_unverified(tmp_path) -> None:
    pkg = scenewright.generate("a kitchen with a table and two mugs on the table", out=tmp_path / "k", verify=False)
    assert pkg.report.status == "unverified" and not pkg.verified
    model, data = pkg.load()
    assert settle(model, data) < 0.01
    assert mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "mug_1") >= 0
