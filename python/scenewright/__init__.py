"""scenewright: plain-English descriptions in, verified MuJoCo scenes out — from Python.

```python
import scenewright

pkg = scenewright.generate("a lab with a UR5e on a workbench and three bins", seed=3)
model, data = pkg.load()                 # mujoco.MjModel + MjData at the `home` keyframe
print(pkg.report.status, [o.name for o in pkg.layout.objects])

ds = scenewright.dataset("out/bins", prompt="a table with four mugs", count=100)
for rec in ds:                           # the manifest, one record per verified scene
    model, data = rec.package.load()
```

The engine is the `scenewright` binary (see `scenewright._engine` for how it is found);
this package needs no network. The Gymnasium environment is in `scenewright.env`.
"""

import os as _os
import sys as _sys

# Offscreen rendering (the environment's `render()`) on a machine without a display needs
# MuJoCo's EGL backend, chosen before `mujoco` is first imported.
if _sys.platform.startswith("linux") and not _os.environ.get("DISPLAY"):
    _os.environ.setdefault("MUJOCO_GL", "egl")

from .api import dataset, generate
from .dataset import Dataset, SceneRecord
from .errors import BadInput, EngineNotFound, ScenewrightError
from .package import Layout, Package, PlacedObject, PlacedRobot, Plan, PlannedGroup, Report

__version__ = "0.1.0"

__all__ = [
    "BadInput",
    "Dataset",
    "EngineNotFound",
    "Layout",
    "Package",
    "PlacedObject",
    "PlacedRobot",
    "Plan",
    "PlannedGroup",
    "Report",
    "SceneRecord",
    "ScenewrightError",
    "__version__",
    "dataset",
    "generate",
]
