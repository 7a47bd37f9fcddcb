#!/usr/bin/env python3
"""Validate the issue-20 prompt corpus and print its coverage.

    .cache/venv/bin/python bench/relations/corpus/check.py [FILE ...]

Without arguments it checks `dev.jsonl` and `heldout.jsonl` next to this file. Every line must
be one JSON object in the judge's line format (bench/relations/README.md) plus the corpus fields
`source` and `style`; relation names and their fields are the judge's vocabulary and the names
issue 20 adds (/work/wt/VOCAB-20.md, restated in the README). Across the files, ids are unique and
no prompt appears twice. Exit 0 when every line is valid, 1 with one line per problem otherwise;
the coverage tables (styles, room kinds, relation names, sources) are printed either way.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent

# Relation name -> (target: "req" | "opt" | "no", the optional fields it may carry).
RELATIONS: dict[str, tuple[str, frozenset[str]]] = {
    "on": ("req", frozenset()),
    "under": ("req", frozenset()),
    "against_wall": ("no", frozenset({"wall"})),
    "on_two_walls": ("no", frozenset({"walls"})),
    "next_to": ("req", frozenset()),
    "near": ("req", frozenset()),
    "between": ("req", frozenset({"target2"})),
    "in_row": ("no", frozenset()),
    "in_rows": ("no", frozenset({"n", "m"})),
    "in_aisles": ("no", frozenset()),
    "facing_each_other": ("opt", frozenset({"gap_m"})),
    "around": ("req", frozenset()),
    "in_front_of": ("req", frozenset({"parallel"})),
    "behind": ("req", frozenset({"parallel"})),
    "at_end_of_row": ("req", frozenset()),
    "at_end": ("no", frozenset()),
    "in_middle": ("no", frozenset()),
    "in_corner": ("no", frozenset()),
    "near_door": ("no", frozenset()),
    "stacked": ("no", frozenset({"n", "stacks"})),
    "loaded": ("req", frozenset()),
    "full_of": ("req", frozenset()),
    "leaning": ("no", frozenset({"wall"})),
    "each_with": ("req", frozenset({"where"})),
    "reach": ("req", frozenset()),
    # issue 20
    "inside": ("req", frozenset()),
    "set_into": ("req", frozenset()),
    "at_end_of": ("req", frozenset({"end"})),
    "on_edge_of": ("req", frozenset()),
    "on_each_side_of": ("req", frozenset()),
    "facing": ("req", frozenset()),
    "on_opposite_walls": ("no", frozenset({"long"})),
    "in_corners": ("no", frozenset()),
    "back_to_back": ("opt", frozenset()),
    "size": ("no", frozenset({"dims"})),
}
COMMON_FIELDS = frozenset({"subject", "relation", "target", "implied"})
LINE_REQUIRED = ("id", "prompt", "source", "style", "counts", "robots", "relations")
LINE_OPTIONAL = frozenset({"room", "min_counts", "allow_extra", "room_size_m", "room_height_m", "notes"})
WALLS = frozenset({"north", "south", "east", "west"})
WHERE = frozenset({"front", "behind", "on", "near"})
ENDS = frozenset({"start", "end", "both"})
DIMS = frozenset({"length", "width", "height", "diameter"})
GENERIC_ROBOTS = frozenset({"arm", "mobile"})
STYLES = frozenset(
    {
        "terse",
        "list",
        "imperative",
        "narrative",
        "title",
        "british",
        "imperial",
        "metric",
        "typo",
        "run-on",
        "passive",
        "there-is",
        "reference",
        "mixed-case",
        "semicolons",
        "casual",
        "task",
        "question",
        "numbered",
        "long",
    }
)
ROOMS = {
    "kitchen": "home",
    "living room": "home",
    "bedroom": "home",
    "bathroom": "home",
    "laundry": "home",
    "dining room": "home",
    "garage": "home",
    "shop": "shop",
    "café": "shop",
    "classroom": "public",
    "hospital": "public",
    "office": "public",
    "greenhouse": "public",
    "tabletop": "tabletop",
    "loading dock": "industrial",
    "lab": "industrial",
    "factory": "industrial",
    "warehouse": "industrial",
    "workshop": "industrial",
}
KEY_RE = re.compile(r"[a-z][a-z0-9_]*(\|[a-z][a-z0-9_]*)*")


def words(prompt: str) -> int:
    """Whitespace-separated words of a prompt."""
    return len(prompt.split())


def norm(prompt: str) -> str:
    """Fold case, punctuation and spacing of a prompt, to find duplicates."""
    return " ".join(re.sub(r"[^a-z0-9 ]+", " ", prompt.lower()).split())


def check_number_map(where: str, value: Any, problems: list[str]) -> dict[str, int]:
    """Return a `{key: N}` map (counts, min_counts, robots), noting what is malformed."""
    if not isinstance(value, dict):
        problems.append(f"{where}: not an object")
        return {}
    for key, n in value.items():
        if not KEY_RE.fullmatch(key):
            problems.append(f"{where}: malformed key {key!r}")
        if not isinstance(n, int) or isinstance(n, bool) or n < 1:
            problems.append(f"{where}: {key} must be a positive integer, not {n!r}")
    return value


def check_relation(where: str, rel: Any, keys: set[str], problems: list[str]) -> None:
    """One relation: a known name, its fields, and keys the line declares."""
    if not isinstance(rel, dict):
        problems.append(f"{where}: relation is not an object")
        return
    name = rel.get("relation")
    if name not in RELATIONS:
        problems.append(f"{where}: unknown relation {name!r}")
        return
    target_rule, optional = RELATIONS[name]
    for field in rel:
        if field not in COMMON_FIELDS and field not in optional:
            problems.append(f"{where}: {name} has no field {field!r}")
    if target_rule == "req" and "target" not in rel:
        problems.append(f"{where}: {name} needs a target")
    if target_rule == "no" and "target" in rel:
        problems.append(f"{where}: {name} takes no target")
    for field in ("subject", "target", "target2"):
        if field in rel and rel[field] not in keys and rel[field] not in GENERIC_ROBOTS:
            problems.append(f"{where}: {field} {rel[field]!r} is not in counts, min_counts or robots")
    if "subject" not in rel:
        problems.append(f"{where}: no subject")
    checks: dict[str, Callable[[Any], bool]] = {
        "wall": lambda v: v in WALLS,
        "walls": lambda v: isinstance(v, list) and len(v) == 2 and set(v) <= WALLS,
        "where": lambda v: v in WHERE,
        "end": lambda v: v in ENDS,
        "n": lambda v: isinstance(v, int) and v >= 1,
        "m": lambda v: isinstance(v, int) and v >= 1,
        "stacks": lambda v: isinstance(v, int) and v >= 1,
        "implied": lambda v: v is True,
        "parallel": lambda v: isinstance(v, bool),
        "long": lambda v: isinstance(v, bool),
        "gap_m": lambda v: isinstance(v, list) and len(v) == 2 and 0 <= v[0] < v[1],
    }
    for field, ok in checks.items():
        if field in rel and not ok(rel[field]):
            problems.append(f"{where}: {name} has a bad {field}: {rel[field]!r}")
    if name == "size":
        dims = rel.get("dims")
        if not isinstance(dims, dict) or not dims:
            problems.append(f"{where}: size needs dims")
        else:
            for dim, span in dims.items():
                if dim not in DIMS:
                    problems.append(f"{where}: size has no dimension {dim!r}")
                elif not (isinstance(span, list) and len(span) == 2 and 0 < span[0] < span[1]):
                    problems.append(f"{where}: size {dim} must be [min, max] metres, not {span!r}")


def check_line(where: str, line: dict[str, Any], problems: list[str]) -> None:
    """Every field of one line, and the arithmetic a careful reader of it would check."""
    for field in LINE_REQUIRED:
        if field not in line:
            problems.append(f"{where}: missing {field}")
    for field in line:
        if field not in LINE_REQUIRED and field not in LINE_OPTIONAL:
            problems.append(f"{where}: unknown field {field!r}")
    if not isinstance(line.get("prompt"), str) or not line.get("prompt", "").strip():
        problems.append(f"{where}: empty prompt")
    if not isinstance(line.get("source"), str) or not line.get("source", "").strip():
        problems.append(f"{where}: empty source")
    styles = line.get("style")
    styles = [styles] if isinstance(styles, str) else styles
    if not isinstance(styles, list) or not styles or any(s not in STYLES for s in styles):
        problems.append(f"{where}: style must be one or more of {sorted(STYLES)}, not {line.get('style')!r}")
    if "room" in line and line["room"] not in ROOMS:
        problems.append(f"{where}: unknown room kind {line['room']!r}")
    counts = check_number_map(f"{where} counts", line.get("counts", {}), problems)
    mins = check_number_map(f"{where} min_counts", line.get("min_counts", {}), problems)
    robots = check_number_map(f"{where} robots", line.get("robots", {}), problems)
    keys = set(counts) | set(mins) | set(robots)
    seen: dict[str, str] = {}
    for key in [*counts, *mins, *robots]:
        if key in counts and key in mins:
            problems.append(f"{where}: {key} is in both counts and min_counts")
        for category in key.split("|"):
            if category in seen and seen[category] != key:
                problems.append(f"{where}: category {category!r} is in two keys ({seen[category]}, {key})")
            seen[category] = key
    for extra in line.get("allow_extra", []):
        if not KEY_RE.fullmatch(extra) or "|" in extra:
            problems.append(f"{where}: allow_extra entry {extra!r} is not one category")
        elif extra in seen:
            problems.append(f"{where}: allow_extra {extra!r} is already counted")
    for field in ("room_size_m",):
        if field in line:
            size = line[field]
            if not (
                isinstance(size, list) and len(size) == 2 and all(isinstance(v, int | float) and v > 0 for v in size)
            ):
                problems.append(f"{where}: {field} must be [a, b] metres")
    if "room_height_m" in line and not (isinstance(line["room_height_m"], int | float) and line["room_height_m"] > 0):
        problems.append(f"{where}: room_height_m must be a positive number of metres")
    rels = line.get("relations")
    if not isinstance(rels, list):
        problems.append(f"{where}: relations must be a list")
        return
    exact = {**counts, **robots}
    for i, rel in enumerate(rels):
        check_relation(f"{where} relation {i}", rel, keys, problems)
        if isinstance(rel, dict):
            check_arithmetic(where, rel, exact, problems)


def check_arithmetic(where: str, rel: dict[str, Any], exact: dict[str, int], problems: list[str]) -> None:
    """Check that what a relation says about numbers agrees with the exact counts."""
    subject = rel.get("subject")
    name = rel.get("relation")
    if subject not in exact:
        return
    count = exact[subject]
    target = rel.get("target")
    if name == "each_with" and target in exact and count != exact[target]:
        problems.append(f"{where}: each_with pairs {count} {subject} with {exact[target]} {target}")
    if name == "stacked" and "n" in rel and rel["n"] * rel.get("stacks", 1) != count:
        problems.append(f"{where}: {rel.get('stacks', 1)} stacks of {rel['n']} is not {count} {subject}")
    if name == "in_rows" and "n" in rel and "m" in rel and rel["n"] * rel["m"] != count:
        problems.append(f"{where}: {rel['n']} rows of {rel['m']} is not {count} {subject}")
    if name == "in_corners" and count > 4:
        problems.append(f"{where}: {count} {subject} cannot be in distinct corners")
    pairs = ("facing_each_other", "back_to_back", "in_row", "on_each_side_of", "on_opposite_walls", "in_rows")
    if name in pairs and count < 2:
        problems.append(f"{where}: {name} needs at least two {subject}")


def load(path: Path, problems: list[str]) -> list[dict[str, Any]]:
    """Parse every line of one file."""
    lines = []
    for number, text in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        where = f"{path.name}:{number}"
        if not text.strip():
            problems.append(f"{where}: blank line")
            continue
        try:
            line = json.loads(text)
        except json.JSONDecodeError as err:
            problems.append(f"{where}: not JSON ({err})")
            continue
        if not isinstance(line, dict):
            problems.append(f"{where}: not a JSON object")
            continue
        check_line(f"{where} ({line.get('id', '?')})", line, problems)
        lines.append(line)
    return lines


def table(title: str, counter: Counter[str], total: int) -> None:
    """Print one coverage table, most frequent first."""
    print(f"  {title}:")
    for name, n in sorted(counter.items(), key=lambda kv: (-kv[1], kv[0])):
        print(f"    {name:<22} {n:>4}  {100 * n / max(total, 1):5.1f} %")


def report(path: Path, lines: list[dict[str, Any]]) -> None:
    """Coverage of one file: styles, rooms, relation names, sources, lengths, robots."""
    n = len(lines)
    adapted = [ln for ln in lines if not str(ln.get("source", "")).startswith("written:")]
    robots = [ln for ln in lines if ln.get("robots")]
    lengths = sorted(words(ln.get("prompt", "")) for ln in lines)
    print(f"{path.name}: {n} prompts, {len(adapted)} adapted from named sources, {len(robots)} with robots")
    if lengths:
        print(f"  words per prompt: min {lengths[0]}, median {lengths[n // 2]}, max {lengths[-1]}")
    styles: Counter[str] = Counter()
    for ln in lines:
        style = ln.get("style", [])
        styles.update([style] if isinstance(style, str) else style)
    table("style", styles, n)
    table("room kind", Counter(str(ln.get("room", "?")) for ln in lines), n)
    table("room group", Counter(ROOMS.get(str(ln.get("room")), "?") for ln in lines), n)
    rels: Counter[str] = Counter()
    implied = 0
    for ln in lines:
        for rel in ln.get("relations", []):
            if isinstance(rel, dict):
                rels[str(rel.get("relation"))] += 1
                implied += bool(rel.get("implied"))
    total = sum(rels.values())
    print(f"  relations: {total} ({implied} implied), per prompt {total / max(n, 1):.1f}")
    table("relation", rels, total)
    sources = Counter(re.split(r"[,:(]", str(ln["source"]))[0].strip() for ln in adapted)
    table("adapted from", sources, len(adapted))


def main() -> int:
    """Check the files named (default: dev and held-out) and print their coverage."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path)
    args = parser.parse_args()
    files = args.files or [HERE / "dev.jsonl", HERE / "heldout.jsonl"]
    problems: list[str] = []
    ids: dict[str, str] = {}
    prompts: dict[str, str] = {}
    loaded = []
    for path in files:
        if not path.exists():
            problems.append(f"{path}: no such file")
            continue
        lines = load(path, problems)
        loaded.append((path, lines))
        for ln in lines:
            ident = str(ln.get("id"))
            if ident in ids:
                problems.append(f"{path.name}: id {ident!r} also in {ids[ident]}")
            ids[ident] = path.name
            key = norm(str(ln.get("prompt", "")))
            if key in prompts:
                problems.append(f"{path.name} ({ident}): prompt duplicated in {prompts[key]}")
            prompts[key] = f"{path.name} ({ident})"
    for path, lines in loaded:
        report(path, lines)
    for problem in problems:
        print(problem, file=sys.stderr)
    print(f"{len(problems)} problems", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
