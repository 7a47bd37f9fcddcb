"""`scenewright demos` → a LeRobot v3.0 dataset, checked by a second route: its layout read
with pyarrow, every episode replayed from its recorded actions in a fresh MuJoCo (the
official bindings) and its task judged by this package's own predicates (not the engine's).
"""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path
from typing import Any

import pytest

from scenewright.demos import Demos

PICK = "a Panda on a table that puts the red cube in the bowl"
STACK = "a UR5e on a table with a red cube and a blue cube. Stack the red cube on the blue cube"


def demos(out: Path, *args: str) -> subprocess.CompletedProcess[str]:
    cmd = [os.environ["SCENEWRIGHT_BIN"], "demos", "--out", str(out), "--json", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=900, check=False)


@pytest.fixture(scope="module")
def pick(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict]:
    out = tmp_path_factory.mktemp("demos") / "pick"
    r = demos(
        out, "--prompt", PICK, "--episodes", "3", "--jobs", "2", "--cameras", "front,wrist", "--image-size", "96x96"
    )
    assert r.returncode == 0, r.stderr
    return out, json.loads(r.stdout)


def test_the_dataset_has_lerobot_v3_layout(pick: tuple[Path, dict]) -> None:
    pa = pytest.importorskip("pyarrow.parquet")
    out, summary = pick
    assert summary["episodes"] == 3 and summary["solved"] == 3
    info = json.loads((out / "meta" / "info.json").read_text())
    assert info["codebase_version"] == "v3.0" and info["fps"] == 15 and info["total_episodes"] == 3
    feats = info["features"]
    for key in ("timestamp", "frame_index", "episode_index", "index", "task_index", "action", "observation.state"):
        assert key in feats, key
    assert feats["observation.images.front"]["dtype"] == "video"
    assert feats["observation.images.wrist"]["shape"] == [96, 96, 3]
    tasks = pa.read_table(out / "meta" / "tasks.parquet")
    # Indexed by the task string, as pandas (and so LeRobot) reads it.
    assert tasks.schema.pandas_metadata["index_columns"] == ["task"]
    assert tasks.column("task").to_pylist() == ["put the red cube in the bowl"]
    assert tasks.column("task_index").to_pylist() == [0]
    eps = pa.read_table(out / "meta" / "episodes" / "chunk-000" / "file-000.parquet").to_pydict()
    assert eps["episode_index"] == [0, 1, 2]
    total = 0
    for i in range(3):
        t = pa.read_table(out / "data" / "chunk-000" / f"file-{i:03d}.parquet").to_pydict()
        n = len(t["frame_index"])
        assert eps["length"][i] == n and eps["dataset_from_index"][i] == total
        assert t["index"] == list(range(total, total + n)) and set(t["episode_index"]) == {i}
        assert t["frame_index"] == list(range(n))
        assert abs(t["timestamp"][-1] - (n - 1) / 15) < 1e-4
        assert len(t["action"][0]) == len(feats["action"]["names"])
        total += n
        for cam in ("front", "wrist"):
            video = out / "videos" / f"observation.images.{cam}" / "chunk-000" / f"file-{i:03d}.mp4"
            assert video.stat().st_size > 1000
    assert info["total_frames"] == total
    stats = json.loads((out / "meta" / "stats.json").read_text())
    assert stats["action"]["count"] == [total]
    assert len(stats["observation.images.front"]["mean"]) == 3


def test_every_episode_replays_to_a_solved_task_in_a_fresh_mujoco(pick: tuple[Path, dict]) -> None:
    pytest.importorskip("pyarrow")
    out, _ = pick
    d = Demos(out)
    assert len(d) == 3
    for ep in d.episodes():
        r = ep.replay()
        assert r.success, (ep.index, r.verdicts)
        # The same controls give the same motion (MuJoCo 3.17 in Python, as the engine).
        assert r.max_state_error < 1e-3, (ep.index, r.max_state_error)


def test_the_initial_state_does_not_solve_the_task(pick: tuple[Path, dict]) -> None:
    import mujoco

    from scenewright.tasks import holds

    out, _ = pick
    for ep in Demos(out).episodes():
        model, data = ep.load()
        mujoco.mj_forward(model, data)
        assert not holds(ep.task, model, data)


def test_bad_input_is_one_line_and_exit_2(tmp_path: Path) -> None:
    cases = [
        ("--prompt", PICK, "--episodes", "0"),
        ("--prompt", "a Panda on a table with a red cube", "--task", "put the mug in the sink", "--episodes", "1"),
        (
            "--prompt",
            "a TurtleBot in a room with a red cube and a bowl",
            "--task",
            "put the cube in the bowl",
            "--episodes",
            "1",
        ),
        ("--prompt", PICK, "--episodes", "1", "--image-size", "99x0"),
        (
            "--prompt",
            "a Panda on a table with a red cube, a plate and a bowl",
            "--task",
            "put the cube in the bowl and put the cube on the plate",
            "--episodes",
            "1",
        ),
        ("--prompt", "a table with a cube", "--episodes", "1"),
    ]
    for args in cases:
        r = demos(tmp_path / "x", *args)
        assert r.returncode == 2, (args, r.stderr)
        assert r.stderr.count("\n") == 1 and r.stderr.startswith("error: "), r.stderr
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("mine")
    r = demos(foreign, "--prompt", PICK, "--episodes", "1")
    assert r.returncode == 2 and "not a scenewright demonstrations dataset" in r.stderr


class Replay:
    """A policy that plays recorded actions back, holding the last one."""

    def __init__(self, actions: Any) -> None:
        self.actions, self.t = actions, 0

    def __call__(self, _obs: Any) -> Any:
        a = self.actions[min(self.t, len(self.actions) - 1)]
        self.t += 1
        return a


def test_the_behaviour_cloning_example_reads_and_rolls_out_what_it_trains_on(pick: tuple[Path, dict]) -> None:
    """The BC example's own harness: its observations replayed with the recorded actions solve
    every episode (so a policy's rollout is judged the way the expert's was), they have one
    width in every episode, and a tiny training run completes."""
    pytest.importorskip("pyarrow")
    import importlib.util
    import sys

    import numpy as np

    path = Path(__file__).resolve().parent.parent / "examples" / "train_bc.py"
    spec = importlib.util.spec_from_file_location("train_bc", path)
    assert spec and spec.loader
    bc = importlib.util.module_from_spec(spec)
    sys.modules["train_bc"] = bc
    spec.loader.exec_module(bc)
    out, _ = pick
    eps = list(Demos(out).episodes())
    horizon = int(1.2 * max(len(ep.frames()["action"]) for ep in eps))
    widths = set()
    for ep in eps:
        xs, ys = bc.demonstrations(ep, horizon)
        widths.add(len(xs[0]))
        assert bc.rollout(ep, Replay(np.asarray(ys)), horizon), ep.index
    assert len(widths) == 1, widths
    xs, ys = bc.demonstrations(eps[0], horizon)
    mlp = bc.Mlp.new(len(xs[0]), len(ys[0]), 16, np.random.default_rng(0))
    assert np.isfinite(mlp.fit(np.asarray(xs), np.asarray(ys), 2, np.random.default_rng(0)))
