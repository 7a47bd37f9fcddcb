"""Datasets: many scenes of a few prompts, and the manifest a training script reads.

A dataset directory (made by `scenewright dataset`) holds `dataset.json`, the packages
under `scenes/<id>/` and `manifest.jsonl`, one line per finished scene. [`Dataset`][]
iterates the manifest as [`SceneRecord`][]s; a record's `package` opens the scene.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import BadInput
from .package import Package


@dataclass(frozen=True)
class SceneRecord:
    """One line of `manifest.jsonl`: a finished, verified scene of the dataset."""

    id: str
    dir: Path
    prompt_index: int
    prompt: str
    seed: int
    fingerprint: str
    physics: str
    objects_by_category: dict[str, int]
    robots: list[str]
    relations_held: tuple[int, int] | None
    """`(held, total)` when the report measures relations, else None."""
    anomalies: list[dict[str, Any]]
    violations: list[dict[str, Any]]
    verification: dict[str, Any]
    timings_ms: dict[str, float]
    files: list[dict[str, Any]]
    raw: dict[str, Any] = field(repr=False)

    @property
    def package(self) -> Package:
        """The scene's package."""
        return Package(self.dir)

    @staticmethod
    def from_json(root: Path, doc: dict[str, Any]) -> SceneRecord:
        """Read one manifest line of the dataset at `root`."""
        rel = doc.get("relations")
        return SceneRecord(
            id=str(doc["id"]),
            dir=root / str(doc["dir"]),
            prompt_index=int(doc.get("prompt_index", 0)),
            prompt=str(doc.get("prompt", "")),
            seed=int(doc.get("seed", 0)),
            fingerprint=str(doc.get("fingerprint", "")),
            physics=str(doc.get("physics", "native")),
            objects_by_category={str(k): int(v) for k, v in doc.get("objects", {}).get("by_category", {}).items()},
            robots=[str(r) for r in doc.get("robots", [])],
            relations_held=(int(rel["held"]), int(rel["total"])) if isinstance(rel, dict) else None,
            anomalies=list(doc.get("anomalies", [])),
            violations=list(doc.get("violations", [])),
            verification=dict(doc.get("verification", {})),
            timings_ms={str(k): float(v) for k, v in doc.get("timings_ms", {}).items()},
            files=list(doc.get("files", [])),
            raw=doc,
        )


class Dataset:
    """A dataset directory; iterating it yields its scenes in id order.

    >>> ds = Dataset("out/shelves")               # doctest: +SKIP
    >>> for rec in ds:                            # doctest: +SKIP
    ...     model, data = rec.package.load()
    """

    def __init__(self, path: str | Path, summary: dict[str, Any] | None = None) -> None:
        """Open the dataset at `path` (it must hold `dataset.json`)."""
        self.path = Path(path)
        spec = self.path / "dataset.json"
        try:
            self.spec: dict[str, Any] = json.loads(spec.read_text(encoding="utf-8"))
        except FileNotFoundError as e:
            raise BadInput(f"'{self.path}' is not a scenewright dataset (no dataset.json)") from e
        except (OSError, ValueError) as e:
            raise BadInput(f"'{spec}' cannot be read: {e}") from e
        self.summary = summary
        """The run's summary when this object came from [`scenewright.dataset`][]."""

    def __repr__(self) -> str:
        return f"Dataset({str(self.path)!r}, {len(self)} scenes)"

    @property
    def prompts(self) -> list[str]:
        """The dataset's prompts."""
        return [str(p) for p in self.spec.get("prompts", [])]

    def records(self) -> list[SceneRecord]:
        """Every listed scene, sorted by id (a line cut short by a kill is skipped)."""
        out: list[SceneRecord] = []
        manifest = self.path / "manifest.jsonl"
        if not manifest.is_file():
            return out
        for line in manifest.read_text(encoding="utf-8").splitlines():
            if not line.strip():
                continue
            try:
                doc = json.loads(line)
            except ValueError:
                continue
            out.append(SceneRecord.from_json(self.path, doc))
        out.sort(key=lambda r: r.id)
        return out

    def __iter__(self) -> Iterator[SceneRecord]:
        return iter(self.records())

    def __len__(self) -> int:
        return len(self.records())
