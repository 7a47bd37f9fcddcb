"""A scene package on disk and what it holds, as Python objects.

A package is a directory: `scene.xml` (robots merged), `scene_only.xml`, `assets/`,
`plan.json`, `layout.json`, `report.json`, `timings.json`. [`Package`][] reads the JSON
documents lazily into the dataclasses below (each keeps the whole document in `raw`) and
loads the scene into MuJoCo at its `home` keyframe.
"""

from __future__ import annotations

import contextlib
import json
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Any

from . import _engine
from .errors import BadInput

if TYPE_CHECKING:
    import mujoco

Vec3 = tuple[float, float, float]


def _vec3(v: Any) -> Vec3:
    return (float(v[0]), float(v[1]), float(v[2]))


@dataclass(frozen=True)
class PlannedGroup:
    """One object group of the plan: `count` instances of a catalog `category`."""

    id: str
    category: str
    count: int
    phrase: str


@dataclass(frozen=True)
class Plan:
    """What the prompt was read as (`plan.json`)."""

    prompt: str
    room_kind: str
    room_size: Vec3
    objects: list[PlannedGroup]
    robots: list[str]
    rules_profile: str
    raw: dict[str, Any] = field(repr=False)

    @staticmethod
    def from_json(doc: dict[str, Any]) -> Plan:
        """Read a `plan.json` document."""
        room = doc.get("room", {})
        size = room.get("size", {})
        return Plan(
            prompt=str(doc.get("prompt", "")),
            room_kind=str(room.get("kind", "")),
            room_size=(
                float(size.get("width", 0)),
                float(size.get("depth", 0)),
                float(size.get("height", 0)),
            ),
            objects=[
                PlannedGroup(str(o["id"]), str(o["category"]), int(o["count"]), str(o.get("phrase", "")))
                for o in doc.get("objects", [])
            ],
            robots=[str(r["model"]) for r in doc.get("robots", []) for _ in range(int(r.get("count", 1)))],
            rules_profile=str(doc.get("rules_profile", "")),
            raw=doc,
        )


@dataclass(frozen=True)
class PlacedObject:
    """One object instance as laid out: its MJCF body is named `name`."""

    name: str
    category: str
    label: str
    group: str
    pos: Vec3
    yaw: float
    size: Vec3
    movable: bool
    mass: float | None
    support: dict[str, Any]


@dataclass(frozen=True)
class PlacedRobot:
    """One robot instance: every MJCF name it brings is prefixed with `name + "_"`."""

    name: str
    model: str
    pos: Vec3
    yaw: float
    mount: str
    mounted_on: str | None


@dataclass(frozen=True)
class Layout:
    """Poses, supports, anomaly labels and rule violations (`layout.json`)."""

    seed: int
    room_kind: str
    room_size: Vec3
    objects: list[PlacedObject]
    robots: list[PlacedRobot]
    anomalies: list[dict[str, Any]]
    violations: list[dict[str, Any]]
    raw: dict[str, Any] = field(repr=False)

    @staticmethod
    def from_json(doc: dict[str, Any]) -> Layout:
        """Read a `layout.json` document."""
        room = doc.get("room", {})
        size = room.get("size", {})
        return Layout(
            seed=int(doc.get("seed", 0)),
            room_kind=str(room.get("kind", "")),
            room_size=(
                float(size.get("width", 0)),
                float(size.get("depth", 0)),
                float(size.get("height", 0)),
            ),
            objects=[
                PlacedObject(
                    name=str(o["name"]),
                    category=str(o["category"]),
                    label=str(o.get("label", "")),
                    group=str(o.get("group", "")),
                    pos=_vec3(o["pos"]),
                    yaw=float(o.get("yaw", 0.0)),
                    size=_vec3(o.get("size", (0, 0, 0))),
                    movable=bool(o.get("movable", False)),
                    mass=None if o.get("mass") is None else float(o["mass"]),
                    support=dict(o.get("support", {})),
                )
                for o in doc.get("objects", [])
            ],
            robots=[
                PlacedRobot(
                    name=str(r["name"]),
                    model=str(r["model"]),
                    pos=_vec3(r["pos"]),
                    yaw=float(r.get("yaw", 0.0)),
                    mount=str(r.get("mount", "")),
                    mounted_on=r.get("mounted_on"),
                )
                for r in doc.get("robots", [])
            ],
            anomalies=list(doc.get("anomalies", [])),
            violations=list(doc.get("violations", [])),
            raw=doc,
        )


@dataclass(frozen=True)
class Report:
    """MuJoCo's verification and everything the run noted (`report.json`)."""

    prompt: str
    seed: int
    status: str
    failures: list[str]
    warnings: list[dict[str, Any]]
    violations: list[dict[str, Any]]
    relations: list[dict[str, Any]]
    verification: dict[str, Any] | None
    raw: dict[str, Any] = field(repr=False)

    @property
    def verified(self) -> bool:
        """True when MuJoCo compiled and settled the scene within every threshold."""
        return self.status == "verified"

    @staticmethod
    def from_json(doc: dict[str, Any]) -> Report:
        """Read a `report.json` document (relations are read when the report has them)."""
        ver = doc.get("verification")
        return Report(
            prompt=str(doc.get("prompt", "")),
            seed=int(doc.get("seed", 0)),
            status=str(doc.get("status", "")),
            failures=list(ver.get("failures", [])) if isinstance(ver, dict) else [],
            warnings=list(doc.get("warnings", [])),
            violations=list(doc.get("violations", [])),
            relations=list(doc.get("relations", [])),
            verification=ver if isinstance(ver, dict) else None,
            raw=doc,
        )


def _read_json(path: Path) -> dict[str, Any]:
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError as e:
        raise BadInput(f"'{path}' is missing") from e
    except (OSError, ValueError) as e:
        raise BadInput(f"'{path}' cannot be read: {e}") from e
    if not isinstance(doc, dict):
        raise BadInput(f"'{path}' is not a JSON object")
    return doc


class Package:
    """A scene package directory.

    >>> pkg = Package("out/aisle")            # doctest: +SKIP
    >>> model, data = pkg.load()              # doctest: +SKIP
    """

    def __init__(self, path: str | Path) -> None:
        """Open the package at `path`; raises `BadInput` when it holds no `scene.xml`."""
        self.path = Path(path)
        if not self.scene_xml.is_file():
            raise BadInput(f"'{self.path}' is not a scene package (no scene.xml)")

    def __repr__(self) -> str:
        return f"Package({str(self.path)!r})"

    @property
    def scene_xml(self) -> Path:
        """The scene with its robots merged."""
        return self.path / "scene.xml"

    @property
    def scene_only_xml(self) -> Path:
        """The same scene without robots."""
        return self.path / "scene_only.xml"

    @cached_property
    def plan(self) -> Plan:
        """What the prompt was read as."""
        return Plan.from_json(_read_json(self.path / "plan.json"))

    @cached_property
    def layout(self) -> Layout:
        """Poses and supports of every object and robot."""
        return Layout.from_json(_read_json(self.path / "layout.json"))

    @cached_property
    def report(self) -> Report:
        """MuJoCo's verification, warnings, violations and relations."""
        return Report.from_json(_read_json(self.path / "report.json"))

    @cached_property
    def timings(self) -> dict[str, Any]:
        """Wall-clock time per stage (`timings.json`)."""
        return _read_json(self.path / "timings.json")

    @property
    def verified(self) -> bool:
        """True when the package passed MuJoCo's verification."""
        return self.report.verified

    def files(self) -> list[Path]:
        """Every file of the package, sorted."""
        return sorted(p for p in self.path.rglob("*") if p.is_file())

    def load(self, robots: bool = True) -> tuple[mujoco.MjModel, mujoco.MjData]:
        """Load the scene into MuJoCo and reset it to its `home` keyframe (the spawn state).

        With `robots=False`, `scene_only.xml` is loaded instead.
        """
        import mujoco

        model = mujoco.MjModel.from_xml_path(str(self.scene_xml if robots else self.scene_only_xml))
        data = mujoco.MjData(model)
        key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, "home")
        if key >= 0:
            mujoco.mj_resetDataKeyframe(model, data, key)
        mujoco.mj_forward(model, data)
        return model, data

    def load_mjx(self) -> tuple[Any, Any]:
        """The scene in MuJoCo XLA (`mujoco.mjx`): `(mjx.Model, mjx.Data)` at `home`.

        The package must have been generated with `physics="mjx"` when its objects use
        collision pairs MJX lacks (cylinders against boxes); `mjx.put_model` says so otherwise.
        """
        from mujoco import mjx

        model, data = self.load()
        return mjx.put_model(model), mjx.put_data(model, data)

    def warp_sizes(self, seconds: float = 1.0) -> dict[str, int]:
        """The contact and constraint capacity MuJoCo Warp needs for this scene.

        Warp allocates `nconmax` contacts and `njmax` constraint rows per world up front
        (its defaults, 48 and 64 here, lose contacts: things drift through each other). The
        peaks are measured in native MuJoCo over `seconds` from `home` with the robots
        holding their pose, doubled, and rounded up to Warp's sizes; they are kept in the
        package's `warp.json` (measured once).
        """
        import mujoco

        cache = self.path / "warp.json"
        if cache.is_file():
            sizes: dict[str, int] = json.loads(cache.read_text())
            return sizes
        model, data = self.load()
        peak_con, peak_efc = data.ncon, data.nefc
        for _ in range(max(1, round(seconds / model.opt.timestep))):
            mujoco.mj_step(model, data)
            peak_con, peak_efc = max(peak_con, data.ncon), max(peak_efc, data.nefc)
        valid = [(2 + (k % 2)) * 2 ** (k // 2 + 3) for k in range(40)]  # 16, 24, 32, 48, ...

        def size(n: int, floor: int) -> int:
            return int(next(v for v in valid if v >= max(floor, 2 * n)))

        sizes = {
            "nconmax": size(peak_con, 64),
            "njmax": size(peak_efc, 256),
            "ncon": int(peak_con),
            "nefc": int(peak_efc),
        }
        with contextlib.suppress(OSError):
            cache.write_text(json.dumps(sizes) + "\n")
        return sizes

    def load_warp(self, nworld: int = 1) -> tuple[Any, Any]:
        """The scene in MuJoCo Warp (`mujoco_warp`): `(Model, Data)` at `home`.

        The contact and constraint arrays are sized by [`warp_sizes`][], so that no contact
        is dropped.
        """
        import mujoco_warp as mjw

        sizes = self.warp_sizes()
        model, data = self.load()
        return mjw.put_model(model), mjw.put_data(
            model, data, nworld=nworld, nconmax=sizes["nconmax"], njmax=sizes["njmax"]
        )

    def export_usd(self, out: str | Path) -> Path:
        """Convert the package to USD (`scenewright export DIR --format usd`); the stage's path."""
        res = _engine.run(["export", str(self.path), "--format", "usd", "--out", str(out), "--json"])
        doc = res.document if isinstance(res.document, dict) else {}
        return Path(str(doc.get("stage", out)))
