"""The package's entry points: [`generate`][] one scene, [`dataset`][] many."""

from __future__ import annotations

import shutil
import tempfile
import weakref
from collections.abc import Sequence
from pathlib import Path

from . import _engine
from .dataset import Dataset
from .errors import ScenewrightError
from .package import Package

PHYSICS = ("native", "mjx")
FILLS = ("none", "furnished", "cluttered")


def _robot_list(robot: str | Sequence[str] | None) -> str | None:
    if robot is None:
        return None
    names = [robot] if isinstance(robot, str) else list(robot)
    return ",".join(n.strip() for n in names) or "none"


def generate(
    prompt: str,
    seed: int = 0,
    robot: str | Sequence[str] | None = None,
    out: str | Path | None = None,
    physics: str = "native",
    verify: bool = True,
    timeout: float | None = 600.0,
    fill: str | None = None,
    task: str | None = None,
) -> Package:
    """Generate a scene from a plain-English prompt and return its package.

    Args:
        prompt: What the workspace holds, e.g. "a lab with a UR5e on a workbench".
        seed: Layout and asset variation; the same prompt and seed give the same scene.
        robot: Registry robots to use instead of the prompt's (`"ur5e"`, `["ur5e",
            "turtlebot3"]`, `"none"` for none).
        out: The package directory (new or empty); a new temporary directory by default.
        physics: `"native"` (MuJoCo, MuJoCo Warp) or `"mjx"` (MuJoCo XLA's collision pairs).
        verify: Compile and settle the scene in MuJoCo (on by default).
        timeout: Seconds before the run is abandoned.
        fill: `"none"`, `"furnished"` (the furniture the room's kind is used with) or
            `"cluttered"` (furnished, with small things on its surfaces), added after the
            stated objects without moving them; `None` follows the prompt's own words
            ("a cluttered kitchen"), else no fill.
        task: What the scene's robot is to do ("put the red cube in the bowl"): bound to the
            scene and written to the package's `task.json`.

    Returns:
        The package (without `out`, in a temporary directory removed when the package
        object is collected or the interpreter exits). A scene that failed verification is returned too: check
        `package.verified` and `package.report.failures`.

    Raises:
        BadInput: The prompt or an option was unusable (the message says which).
        ScenewrightError: The engine failed.
    """
    if physics not in PHYSICS:
        raise ValueError(f"physics must be one of {PHYSICS}, not {physics!r}")
    if fill is not None and fill not in FILLS:
        raise ValueError(f"fill must be one of {FILLS}, not {fill!r}")
    tmp = None if out is not None else tempfile.mkdtemp(prefix="scenewright-")
    target = Path(out) if out is not None else Path(str(tmp)) / "package"
    args = [
        "generate",
        prompt,
        "--out",
        str(target),
        "--seed",
        str(int(seed)),
        "--physics",
        physics,
        "--json",
    ]
    robots = _robot_list(robot)
    if robots is not None:
        args += ["--robot", robots]
    if not verify:
        args.append("--no-verify")
    if fill is not None:
        args += ["--fill", fill]
    if task is not None:
        args += ["--task", task]
    try:
        res = _engine.run(args, timeout=timeout)
        doc = res.document if isinstance(res.document, dict) else {}
        path = Path(str(doc.get("out_dir", target)))
        if not (path / "scene.xml").is_file():
            raise ScenewrightError(f"generate wrote no package at {path}", res.exit_code)
    except BaseException:
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)
        raise
    pkg = Package(path)
    if tmp is not None:
        weakref.finalize(pkg, shutil.rmtree, tmp, True)
    return pkg


def dataset(
    out: str | Path,
    prompt: str | None = None,
    prompts: Sequence[str] | str | Path | None = None,
    count: int | None = None,
    jobs: int | None = None,
    physics: str = "native",
    robots: Sequence[str] | None = None,
    anomaly: Sequence[str] | None = None,
    anomaly_rate: float = 0.2,
    seed: int = 0,
    progress: bool = True,
) -> Dataset:
    """Make (or resume) a dataset of `count` scenes per prompt, and return it to iterate.

    With `count=None`, the dataset already at `out` is opened without generating.

    Args:
        out: The dataset directory (new, empty, or this dataset to resume or extend).
        prompt: One prompt.
        prompts: Several prompts (a list), or a file of prompts (one per line).
        count: Scenes per prompt.
        jobs: Scenes made at once (default: every core).
        physics: `"native"` or `"mjx"`.
        robots: Draw each scene's robot from these (`"none"` for no robot).
        anomaly: Inject labelled anomalies (`"overlap"`, `"scale"`, `"misplacement"`,
            `"floating"`, `"rule-violation"`, `"all"`).
        anomaly_rate: Share of eligible objects to corrupt.
        seed: The first seed of each prompt's seed stream.
        progress: Pass the engine's progress lines on to stderr.

    Returns:
        The dataset; its `summary` holds the run's figures (scenes/s, failures by reason).
    """
    out = Path(out)
    if count is None:
        return Dataset(out)
    if physics not in PHYSICS:
        raise ValueError(f"physics must be one of {PHYSICS}, not {physics!r}")
    args = [
        "dataset",
        "--out",
        str(out),
        "--count",
        str(int(count)),
        "--physics",
        physics,
        "--seed",
        str(seed),
    ]
    tmp: tempfile.TemporaryDirectory[str] | None = None
    if prompt is not None:
        args += ["--prompt", prompt]
    elif isinstance(prompts, (str, Path)):
        args += ["--prompts", str(prompts)]
    elif prompts is not None:
        tmp = tempfile.TemporaryDirectory(prefix="scenewright-prompts-")
        file = Path(tmp.name) / "prompts.txt"
        lines = []
        for p in prompts:
            if "\n" in p:
                raise ValueError(f"a prompt may not span lines: {p!r}")
            lines.append(p)
        file.write_text("\n".join(lines) + "\n", encoding="utf-8")
        args += ["--prompts", str(file)]
    else:
        raise ValueError("give prompt= or prompts=")
    if jobs is not None:
        args += ["--jobs", str(int(jobs))]
    if robots is not None:
        args += ["--robots", ",".join(robots)]
    if anomaly is not None:
        args += ["--anomaly", ",".join(anomaly), "--anomaly-rate", str(anomaly_rate)]
    args.append("--json")
    try:
        res = _engine.stream(args, echo=progress)
    finally:
        if tmp is not None:
            tmp.cleanup()
    summary = res.document if isinstance(res.document, dict) else None
    if res.exit_code not in (0, 1):
        raise ScenewrightError(f"the dataset run stopped (exit code {res.exit_code})", res.exit_code)
    return Dataset(out, summary)
