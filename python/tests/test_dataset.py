"""dataset → manifest: distinct verified scenes, hashes that match, resume and refusal."""

from __future__ import annotations

import hashlib
import json
from itertools import combinations

import numpy as np
import pytest
from conftest import settle

import scenewright

SHELF = "a storage room with a shelf and four boxes on the shelf"
TABLE = "a kitchen with a table and two mugs on the table"


def structurally_different(a: scenewright.Package, b: scenewright.Package) -> bool:
    """An independent reading of 'different': an object or robot moved by 1 cm or more,
    another asset, or another colour (not the engine's fingerprint)."""
    la, lb = a.layout, b.layout
    pa = {o.name: o for o in la.objects}
    pb = {o.name: o for o in lb.objects}
    if pa.keys() != pb.keys() or la.room_size != lb.room_size:
        return True
    for name, o in pa.items():
        if (
            np.linalg.norm(np.subtract(o.pos, pb[name].pos)) >= 0.01
            or np.abs(np.subtract(o.size, pb[name].size)).max() >= 0.001
        ):
            return True
    for ra, rb in zip(la.robots, lb.robots, strict=False):
        if ra.model != rb.model or np.linalg.norm(np.subtract(ra.pos, rb.pos)) >= 0.01:
            return True
    meshes = lambda p: sorted(f.name for f in (p.path / "assets").iterdir() if f.is_file())  # noqa: E731
    return meshes(a) != meshes(b)


def test_dataset_of_two_prompts_lists_distinct_verified_scenes(tmp_path) -> None:
    out = tmp_path / "ds"
    ds = scenewright.dataset(out, prompts=[SHELF, TABLE], count=3, jobs=2, robots=["none", "ur5e"], progress=False)
    assert ds.summary is not None and ds.summary["made"] == 6 and ds.summary["scenes_listed"] == 6
    records = list(ds)
    assert [r.id for r in records] == [
        "0000-000000",
        "0000-000001",
        "0000-000002",
        "0001-000000",
        "0001-000001",
        "0001-000002",
    ]
    assert len({r.fingerprint for r in records}) == 6
    for r in records:
        pkg = r.package
        assert r.verification["status"] == "verified" and pkg.verified
        assert r.prompt == ds.prompts[r.prompt_index] == pkg.report.prompt
        assert r.seed == pkg.report.seed
        # Counts by category, read again from the layout.
        counts: dict[str, int] = {}
        for o in pkg.layout.objects:
            counts[o.category] = counts.get(o.category, 0) + 1
        assert r.objects_by_category == counts
        assert r.robots == [x.model for x in pkg.layout.robots]
        assert r.raw["variation"]["robot"] in ("none", "ur5e")
        assert "robot" in r.raw["variation"]["kinds"]
        # Every file listed with its size and SHA-256, as hashlib reads them.
        listed = {f["path"]: f for f in r.files}
        on_disk = sorted(p.relative_to(pkg.path).as_posix() for p in pkg.files())
        assert sorted(listed) == on_disk
        for rel, f in listed.items():
            data = (pkg.path / rel).read_bytes()
            assert f["bytes"] == len(data) and f["sha256"] == hashlib.sha256(data).hexdigest()
        model, data = pkg.load()
        assert settle(model, data) < 0.01
    for a, b in combinations(records, 2):
        if a.prompt_index == b.prompt_index:
            assert structurally_different(a.package, b.package), (a.id, b.id)


def test_resume_extends_without_redoing(tmp_path) -> None:
    out = tmp_path / "ds"
    scenewright.dataset(out, prompt=TABLE, count=2, progress=False)
    before = {r.id: (r.dir / "scene.xml").stat().st_ino for r in scenewright.Dataset(out)}
    ds = scenewright.dataset(out, prompt=TABLE, count=4, progress=False)
    assert ds.summary is not None and ds.summary["made"] == 2 and ds.summary["resumed"]["listed"] == 2
    after = {r.id: (r.dir / "scene.xml").stat().st_ino for r in ds}
    assert len(after) == 4 and all(after[k] == v for k, v in before.items())
    # Asking again for what is there makes nothing.
    again = scenewright.dataset(out, prompt=TABLE, count=4, progress=False)
    assert again.summary is not None and again.summary["made"] == 0 and len(again) == 4
    spec = json.loads((out / "dataset.json").read_text())
    assert spec["format"] == "scenewright-dataset" and spec["count"] == 4


def test_foreign_and_mismatched_directories_are_refused(tmp_path) -> None:
    foreign = tmp_path / "mine"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("keep me")
    with pytest.raises(scenewright.BadInput, match="not a scenewright dataset"):
        scenewright.dataset(foreign, prompt=TABLE, count=1, progress=False)
    assert (foreign / "notes.txt").read_text() == "keep me" and len(list(foreign.iterdir())) == 1
    ds = tmp_path / "ds"
    scenewright.dataset(ds, prompt=TABLE, count=1, progress=False)
    with pytest.raises(scenewright.BadInput, match="other prompts"):
        scenewright.dataset(ds, prompt=SHELF, count=1, progress=False)
    with pytest.raises(scenewright.BadInput, match="other physics"):
        scenewright.dataset(ds, prompt=TABLE, count=1, physics="mjx", progress=False)
    assert len(scenewright.Dataset(ds)) == 1


def test_a_bad_prompt_line_names_the_line(tmp_path) -> None:
    prompts = tmp_path / "prompts.txt"
    prompts.write_bytes(b"# two prompts\n" + TABLE.encode() + b"\n\n\xff\xfe broken\n")
    with pytest.raises(scenewright.BadInput, match="line 4 is not UTF-8"):
        scenewright.dataset(tmp_path / "ds", prompts=prompts, count=1, progress=False)
    assert not (tmp_path / "ds").exists()
