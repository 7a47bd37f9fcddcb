"""Reading a `scenewright demos` dataset (LeRobot v3.0) and replaying its episodes.

```python
from scenewright.demos import Demos
demos = Demos("out/demos")
for ep in demos.episodes():
    result = ep.replay()          # the recorded actions in a fresh MuJoCo, then the task judged
    print(ep.index, ep.task["instruction"], result.success, result.max_state_error)
```

Reading the parquet files needs `pyarrow`. Replaying needs only `mujoco`: each episode's
scene (`scenes/episode_NNNNNN/scene.xml`) starts at its `home` keyframe, and each recorded
action (the actuator controls) is held for one frame (`substeps` physics steps).
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from .tasks import judge


@dataclass(frozen=True)
class ReplayResult:
    """What a replay found."""

    success: bool
    #: Largest difference between a recorded and a replayed joint position, rad or m.
    max_state_error: float
    frames: int
    verdicts: list[Any]


@dataclass
class DemoEpisode:
    """One episode of a demos dataset."""

    root: Path
    index: int
    info: dict[str, Any]

    @property
    def scene_dir(self) -> Path:
        """The episode's scene directory (`scenes/episode_NNNNNN`)."""
        return self.root / "scenes" / f"episode_{self.index:06d}"

    @property
    def task(self) -> dict[str, Any]:
        """The episode's `task.json`."""
        task: dict[str, Any] = json.loads((self.scene_dir / "task.json").read_text())
        return task

    @property
    def record(self) -> dict[str, Any]:
        """The episode's `episode.json` (seed, randomisation, verdicts, effort)."""
        rec: dict[str, Any] = json.loads((self.scene_dir / "episode.json").read_text())
        return rec

    def frames(self) -> dict[str, np.ndarray]:
        """The episode's data file as arrays (needs pyarrow)."""
        import pyarrow.parquet as pq

        chunk, file = divmod(self.index, int(self.info["chunks_size"]))
        table = pq.read_table(self.root / "data" / f"chunk-{chunk:03d}" / f"file-{file:03d}.parquet")
        out: dict[str, np.ndarray] = {}
        for name in table.column_names:
            col = table.column(name).to_pylist()
            out[name] = np.asarray(col, dtype=np.float64)
        return out

    def load(self) -> tuple[mujoco.MjModel, mujoco.MjData]:
        """The episode's scene at its start (keyframe `home`)."""
        model = mujoco.MjModel.from_xml_path(str(self.scene_dir / "scene.xml"))
        data = mujoco.MjData(model)
        mujoco.mj_resetDataKeyframe(model, data, mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, "home"))
        mujoco.mj_forward(model, data)
        return model, data

    def replay(self) -> ReplayResult:
        """Replays the recorded actions from the start and judges the task at the end."""
        f = self.frames()
        model, data = self.load()
        fps = int(self.info["fps"])
        substeps = round(1.0 / (fps * model.opt.timestep))
        names = self.info["features"]["observation.state"]["names"]
        qadr = [int(model.jnt_qposadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, n)]) for n in names]
        worst = 0.0
        actions, states = f["action"], f["observation.state"]
        for a, s in zip(actions, states, strict=True):
            worst = max(worst, float(np.max(np.abs(data.qpos[qadr] - s))))
            data.ctrl[:] = a
            mujoco.mj_step(model, data, nstep=substeps)
        mujoco.mj_forward(model, data)
        verdicts = judge(self.task, model, data)
        return ReplayResult(all(v.held for v in verdicts), worst, len(actions), verdicts)


class Demos:
    """A demos dataset directory."""

    def __init__(self, path: str | Path) -> None:
        self.root = Path(path)
        self.info: dict[str, Any] = json.loads((self.root / "meta" / "info.json").read_text())

    def __len__(self) -> int:
        return int(self.info["total_episodes"])

    def episodes(self) -> Iterator[DemoEpisode]:
        """Every episode, in order."""
        for i in range(len(self)):
            yield DemoEpisode(self.root, i, self.info)

    def episode(self, index: int) -> DemoEpisode:
        """Episode `index`."""
        if not 0 <= index < len(self):
            raise IndexError(f"episode {index} of {len(self)}")
        return DemoEpisode(self.root, index, self.info)
