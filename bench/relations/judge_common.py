"""What every relation check shares: the parsed relation, name resolution, verdicts.

A subject or target is a key: a catalog category (`shelf`), a robot model (`ur5e`), the
aliases `arm` (a robot with a shoulder and a fixed base) and `mobile` (a robot whose root
moves freely), or alternatives joined by `|` (`shelf|pallet_rack`): every instance of
any alternative present in the scene.

With a vocabulary (the catalog's own names, from `scenewright assets list --json`), a key
also names an object whose category is spelt the same but for spaces or one letter
("bandsaw" for `band_saw`, "dock_leveler" for `dock_leveller`), or that the catalog says is
a kind of it (`is_a`: a `stock_pot` is a "pot") — unless the same suite line names that
category itself. The catalog's synonyms are not used: they are its own claims of likeness
(a close substitute is listed as a synonym), and a judge that took them would let the
catalog grade itself. Without a vocabulary, a key names its categories exactly
(`--vocabulary none`).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
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


def _snake(words: str) -> str:
    return "_".join(words.lower().replace("-", " ").split())


@dataclass
class Vocabulary:
    """Per catalog category, the keys that name it: its names and its kinds (not its synonyms)."""

    names: dict[str, frozenset[str]]

    @staticmethod
    def read(path: Path) -> Vocabulary:
        """Read `scenewright assets list --json` output."""
        rows = json.loads(path.read_text())
        names = {}
        for row in rows:
            words = [row["name"], row.get("display", ""), *row.get("is_a", [])]
            names[row["name"]] = frozenset(_snake(w) for w in words if w)
        return Vocabulary(names)


VOCABULARY: Vocabulary | None = None
# The categories the suite line being judged names itself: never matched through a word.
_NAMED: frozenset[str] = frozenset()


def use_vocabulary(path: Path | None) -> None:
    """Match keys through the catalog's names (a path) or exactly (None)."""
    global VOCABULARY
    VOCABULARY = Vocabulary.read(path) if path else None


def line_keys(line: dict[str, Any]) -> set[str]:
    """Every key alternative a suite line mentions (counts, relations, allowed extras)."""
    keys = {a for f in ("counts", "min_counts") for k in line.get(f, {}) for a in k.split("|")}
    for r in line.get("relations", []):
        for f in ("subject", "target", "target2"):
            keys.update(a for a in str(r.get(f) or "").split("|") if a)
    keys.update(line.get("allow_extra", []))
    return keys


def bind_line(line: dict[str, Any]) -> None:
    """Judge the next package against this line (its own category names win over words)."""
    global _NAMED
    _NAMED = frozenset(line_keys(line))


def spelt_alike(a: str, b: str) -> bool:
    """Tell whether two names are one word spelt two ways.

    The same but for spaces, or (7 letters or more) for one letter added, dropped or changed.
    """
    a, b = a.replace("_", ""), b.replace("_", "")
    if a == b:
        return True
    if min(len(a), len(b)) < 7 or abs(len(a) - len(b)) > 1:
        return False
    if len(a) > len(b):
        a, b = b, a
    i = 0
    while i < len(a) and a[i] == b[i]:
        i += 1
    return a[i + (len(a) == len(b)) :] == b[i + 1 :]


def names_category(category: str, alt: str) -> bool:
    """Whether a key alternative names a catalog category, exactly or through the vocabulary."""
    if category == alt:
        return True
    if VOCABULARY is None or category in _NAMED:
        return False
    # A key that is itself a catalog category names only that one (a pallet jack is no pallet rack).
    if alt in VOCABULARY.names:
        return alt in VOCABULARY.names[category] if category in VOCABULARY.names else False
    return spelt_alike(category, alt) or alt in VOCABULARY.names.get(category, frozenset())


def matches(t: Thing, key: str) -> bool:
    """Whether a thing is an instance of a key."""
    for alt in key.split("|"):
        if alt in ROBOT_ALIASES:
            if robot_is(t, alt):
                return True
        elif t.kind == "robot":
            if t.category == alt:
                return True
        elif names_category(t.category, alt):
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
