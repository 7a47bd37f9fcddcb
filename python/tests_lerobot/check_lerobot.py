"""The opt-in check that LeRobot itself reads a `scenewright demos` dataset (issue 23).

    scripts/setup.sh --lerobot            # lerobot 0.6.1 (with PyTorch) in .cache/lerobot-venv
    scripts/test_lerobot.sh               # makes a small dataset with cameras and runs this

Loads DIR with `lerobot.datasets.LeRobotDataset` (offline, from disk), checks its counts
against `meta/info.json`, reads every frame of the first and last episode (decoding the
videos with LeRobot's own decoder), and checks that each item's action, state, timestamps
and images have the shapes and values the parquet files hold.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
from lerobot.datasets.lerobot_dataset import LeRobotDataset


def main(root: Path) -> None:
    info = json.loads((root / "meta" / "info.json").read_text())
    ds = LeRobotDataset("scenewright/demos", root=root)
    assert ds.meta.total_episodes == info["total_episodes"], (ds.meta.total_episodes, info["total_episodes"])
    assert len(ds) == info["total_frames"], (len(ds), info["total_frames"])
    cams = [k for k, f in info["features"].items() if f["dtype"] == "video"]
    last = info["total_episodes"] - 1
    for ep in sorted({0, last}):
        table = pq.read_table(root / "data" / "chunk-000" / f"file-{ep:03d}.parquet").to_pydict()
        first = int(table["index"][0])
        for k in range(len(table["index"])):
            item = ds[first + k]
            assert int(item["episode_index"]) == ep and int(item["frame_index"]) == k
            np.testing.assert_allclose(item["action"].numpy(), np.asarray(table["action"][k]), atol=1e-6)
            np.testing.assert_allclose(
                item["observation.state"].numpy(), np.asarray(table["observation.state"][k]), atol=1e-6
            )
            for c in cams:
                img = item[c]
                h, w, _ = info["features"][c]["shape"]
                assert tuple(img.shape) == (3, h, w), (c, img.shape)
                assert float(img.std()) > 0.01, f"{c} frame {k} of episode {ep} is blank"
    task = ds[0]["task"]
    expected = pq.read_table(root / "meta" / "tasks.parquet").to_pandas().index[0]
    assert task == expected, (task, expected)
    print(f"lerobot read {len(ds)} frames of {ds.meta.total_episodes} episodes ({', '.join(cams) or 'no cameras'}); task {task!r}")


if __name__ == "__main__":
    main(Path(sys.argv[1]))
