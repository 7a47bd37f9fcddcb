"""What every relation check shares: the parsed relation, name resolution, verdicts.

A subject or target is a key: a catalog category (`shelf`), a robot model (`ur5e`), the
aliases `arm` (a robot with a shoulder and a fixed base) and `mobile` (a robot whose root
moves freely), or alternatives joined by `|` (`shelf|pallet_rack`): every instance of
any alternative present in the scene.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from judge_scene import Scene, Thing

ROBOT_ALIASES = ("arm", "mobile")


class LineError(Exception):
    """A suite line the judge cannot use (unknown relation, missing field)."""


@dataclass
class Relation:
    """One expected relation from a suite line."""

    subject: str
    relation: str
    target: str | None = None
    target2: str | None = None
    wall: str | None = None
    walls: list[str] | None = None
    n: int | None = None
    stacks: int | None = None
    where: str | None = None
    gap_m: tuple[float, float] | None = None
    parallel: bool = False
    implied: bool = False
    m: int | None = None
    end: str | None = None
    long: bool = False
    dims: dict[str, tuple[float, float]] | None = None

    @staticmethod
    def parse(raw: dict[str, Any]) -> Relation:
        """Read one entry of a suite line's `relations`."""
        try:
            subject, relation = str(raw["subject"]), str(raw["relation"])
        except KeyError as e:
            raise LineError(f"a relation lacks {e.args[0]!r}: {raw}") from e
        gap = raw.get("gap_m")
        if gap is not None and (not isinstance(gap, list) or len(gap) != 2):
            raise LineError(f"gap_m must be [min, max]: {raw}")
        wall = raw.get("wall")
        if wall is not None and wall not in ("north", "south", "east", "west"):
            raise LineError(f"unknown wall {wall!r}: {raw}")
        end = raw.get("end")
        if end is not None and end not in ("start", "end", "both"):
            raise LineError(f"end must be start, end or both: {raw}")
        dims = _dims(raw)
        return Relation(
            subject=subject,
            relation=relation,
            target=raw.get("target"),
            target2=raw.get("target2"),
            wall=wall,
            walls=raw.get("walls"),
            n=raw.get("n"),
            stacks=raw.get("stacks"),
            where=raw.get("where"),
            gap_m=(float(gap[0]), float(gap[1])) if gap is not None else None,
            parallel=bool(raw.get("parallel", False)),
            implied=bool(raw.get("implied", False)),
            m=raw.get("m"),
            end=end,
            long=bool(raw.get("long", False)),
            dims=dims,
        )


SIZE_DIMS = ("length", "width", "depth", "height", "diameter")


def _dims(raw: dict[str, Any]) -> dict[str, tuple[float, float]] | None:
    """Read a `size` relation's `dims`: {name: [min, max]} in metres."""
    dims = raw.get("dims")
    if dims is None:
        return None
    if not isinstance(dims, dict) or not dims:
        raise LineError(f"dims must be an object of [min, max] ranges: {raw}")
    out = {}
    for k, v in dims.items():
        if k not in SIZE_DIMS:
            raise LineError(f"unknown dimension {k!r} (known: {', '.join(SIZE_DIMS)}): {raw}")
        if not isinstance(v, list) or len(v) != 2 or not all(isinstance(x, (int, float)) for x in v) or v[0] > v[1]:
            raise LineError(f"dims.{k} must be [min, max] in metres: {raw}")
        out[k] = (float(v[0]), float(v[1]))
    return out


@dataclass
class Verdict:
    """Whether one relation held, with what was measured and, when not, why."""

    held: bool
    measured: dict[str, Any] = field(default_factory=dict)
    why: str = ""

    @staticmethod
    def fail(why: str, **measured: Any) -> Verdict:
        """Make the verdict of a relation that does not hold."""
        return Verdict(False, _rounded(measured), why)

    @staticmethod
    def of(held: bool, why: str, **measured: Any) -> Verdict:
        """Make a verdict; `why` is kept only when it did not hold."""
        return Verdict(held, _rounded(measured), "" if held else why)


def _rounded(x: Any) -> Any:
    if isinstance(x, float):
        return round(x, 3) + 0.0
    if isinstance(x, dict):
        return {k: _rounded(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_rounded(v) for v in x]
    return x


def robot_is(t: Thing, alias: str) -> bool:
    """Whether a robot is an `arm` (has a shoulder, fixed base) or `mobile` (free root)."""
    if t.kind != "robot":
        return False
    if alias == "mobile":
        return t.free
    return t.shoulder is not None and not t.free


def matches(t: Thing, key: str) -> bool:
    """Whether a thing is an instance of a key."""
    for alt in key.split("|"):
        if alt in ROBOT_ALIASES:
            if robot_is(t, alt):
                return True
        elif t.category == alt:
            return True
    return False


def resolve(scene: Scene, key: str | None) -> list[Thing]:
    """Every instance of a key in the scene, objects first, in name order."""
    if key is None:
        return []
    found = [t for t in scene.things() if matches(t, key)]
    return sorted(found, key=lambda t: (t.kind, t.category, t.index))


def names(things: list[Thing]) -> list[str]:
    """Return the body names of some things."""
    return [t.name for t in things]
