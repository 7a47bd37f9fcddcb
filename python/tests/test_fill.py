"""generate(fill=...): furnished and cluttered rooms, marked added, verified."""

from __future__ import annotations

import json

import mujoco
import pytest
from conftest import settle

import scenewright


def test_a_cluttered_bedroom_is_verified_and_marks_what_it_added(tmp_path) -> None:
    pkg = scenewright.generate("a bedroom with a desk", seed=1, out=tmp_path / "room", fill="cluttered")
    assert pkg.verified, pkg.report.failures
    raw = json.loads((pkg.path / "layout.json").read_text())
    added = [o for o in raw["objects"] if o.get("added")]
    stated = [o for o in raw["objects"] if not o.get("added")]
    assert [o["category"] for o in stated] == ["desk"]
    assert any(o["category"] == "bed" for o in added)
    assert len(added) > 10
    # Second route: the official bindings load the scene and its free bodies stay put.
    model, data = pkg.load()
    assert settle(model, data) < 0.01
    assert model.nbody > len(raw["objects"])
    assert isinstance(model, mujoco.MjModel)


def test_fill_is_checked_before_the_engine_runs() -> None:
    with pytest.raises(ValueError):
        scenewright.generate("a bedroom", fill="crowded")
