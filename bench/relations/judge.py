#!/usr/bin/env python3
"""The relation judge: does a written scene hold what its prompt states.

An independent check of scenewright's output. It reads only the package's `scene.xml`
(official MuJoCo bindings, the `home` keyframe, `mj_forward`), never the generator's code
or its `layout.json`/`report.json`, and measures each expected relation of a suite line
(see README.md for the line format and every relation's definition) plus the counts of
object bodies per category and robots per model.

    judge.py PACKAGE --line '{"id": …, "counts": …, "robots": …, "relations": […]}'
    judge.py PACKAGE --suite suite.jsonl --id aisle-facing
    judge.py --batch CASES.jsonl      # one {"package": DIR, "line": {…}} per line

Prints one JSON verdict per package on stdout. Exit 0 when judged (whatever the verdict),
2 on bad input (a one-line message on stderr).
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import judge_rel_fit as fit
import judge_rel_groups as groups
import judge_rel_place as place
import judge_rel_sides as sides
import judge_rel_support as support
from judge_common import LineError, Relation, Verdict, bind_line, line_keys, matches, names_category, use_vocabulary
from judge_scene import Scene, SceneError, load

CHECKS: dict[str, Callable[[Relation, Scene], Verdict]] = {
    "on": support.on,
    "under": support.under,
    "against_wall": place.against_wall,
    "on_two_walls": place.on_two_walls,
    "next_to": place.next_to,
    "near": place.near,
    "between": place.between,
    "in_row": groups.in_row,
    "in_rows": groups.in_rows,
    "in_aisles": groups.in_aisles,
    "facing_each_other": groups.facing_each_other,
    "around": groups.around,
    "in_front_of": place.in_front_of,
    "behind": place.behind,
    "at_end_of_row": place.at_end_of_row,
    "at_end": place.at_end,
    "in_middle": place.in_middle,
    "in_corner": place.in_corner,
    "near_door": place.near_door,
    "stacked": support.stacked,
    "loaded": support.loaded,
    "full_of": support.full_of,
    "leaning": support.leaning,
    "each_with": support.each_with,
    "reach": support.reach,
    "inside": fit.inside,
    "set_into": fit.set_into,
    "on_edge_of": fit.on_edge_of,
    "size": fit.size,
    "at_end_of": sides.at_end_of,
    "on_each_side_of": sides.on_each_side_of,
    "facing": sides.facing,
    "on_opposite_walls": sides.on_opposite_walls,
    "in_corners": sides.in_corners,
    "back_to_back": sides.back_to_back,
}
NEEDS_TARGET = {
    "on",
    "under",
    "next_to",
    "near",
    "between",
    "in_front_of",
    "behind",
    "at_end_of_row",
    "around",
    "loaded",
    "full_of",
    "each_with",
    "reach",
    "inside",
    "set_into",
    "on_edge_of",
    "at_end_of",
    "on_each_side_of",
    "facing",
}


def parse_line(line: dict[str, Any]) -> list[Relation]:
    """Check a suite line's shape and read its relations."""
    for f in ("counts", "robots", "relations"):
        if not isinstance(line.get(f), (dict if f != "relations" else list)):
            raise LineError(f"suite line {line.get('id', '?')!r}: {f!r} missing or of the wrong type")
    rels = [Relation.parse(r) for r in line["relations"]]
    for r in rels:
        if r.relation not in CHECKS:
            raise LineError(f"suite line {line.get('id', '?')!r}: unknown relation {r.relation!r}")
        if r.relation in NEEDS_TARGET and not r.target:
            raise LineError(f"suite line {line.get('id', '?')!r}: {r.relation} needs a target")
        if r.relation == "size" and not r.dims:
            raise LineError(f"suite line {line.get('id', '?')!r}: size needs dims")
    for f in ("room_size_m",):
        v = line.get(f)
        if v is not None and (
            not isinstance(v, list) or len(v) != 2 or not all(isinstance(x, (int, float)) for x in v)
        ):
            raise LineError(f"suite line {line.get('id', '?')!r}: {f} must be [a, b] in metres")
    h = line.get("room_height_m")
    if h is not None and not isinstance(h, (int, float)):
        raise LineError(f"suite line {line.get('id', '?')!r}: room_height_m must be a number")
    return rels


def check_counts(scene: Scene, line: dict[str, Any]) -> dict[str, Any]:
    """Object bodies per key and robots per model against the line's expectations."""
    objs = Counter(t.category for t in scene.objects)
    rows: list[dict[str, Any]] = []
    ok = True
    for field, exact in (("counts", True), ("min_counts", False)):
        for key, n in line.get(field, {}).items():
            found = sum(1 for t in scene.objects if matches(t, key))
            good = found == n if exact else found >= n
            ok &= good
            rows.append({"key": key, "expected": n if exact else f">= {n}", "found": found, "held": good})
    robot_rows = []
    for key, n in line["robots"].items():
        found = sum(1 for r in scene.robots if matches(r, key))
        ok &= found == n
        robot_rows.append({"key": key, "expected": n, "found": found, "held": found == n})
    stray = sorted(r.name for r in scene.robots if not any(matches(r, k) for k in line["robots"]))
    mentioned = line_keys(line)
    # A mount an arm stands on (a pedestal under "a Panda") is not an extra object.
    mounts = {o.category for o in scene.objects if any(support.rests_on(r, o) for r in scene.robots)}
    mounts -= {o.category for o in scene.objects if not any(support.rests_on(r, o) for r in scene.robots)}
    extra = {
        c: k for c, k in sorted(objs.items()) if not any(names_category(c, a) for a in mentioned) and c not in mounts
    }
    ok = ok and not stray and not extra
    return {"held": ok, "objects": rows, "robots": robot_rows, "unexpected_robots": stray, "extra_objects": extra}


def judge(package: Path, line: dict[str, Any]) -> dict[str, Any]:
    """Judge one package against one suite line."""
    rels = parse_line(line)
    bind_line(line)
    scene = load(package)
    out = []
    for r in rels:
        v = CHECKS[r.relation](r, scene)
        row: dict[str, Any] = {"subject": r.subject, "relation": r.relation}
        if r.target:
            row["target"] = r.target
        if r.target2:
            row["target2"] = r.target2
        if r.implied:
            row["implied"] = True
        row.update({"held": v.held, "measured": v.measured})
        if v.why:
            row["why"] = v.why
        out.append(row)
    held = sum(1 for r in out if r["held"])
    counts = check_counts(scene, line)
    res = {
        "id": line.get("id"),
        "package": str(package),
        "counts": counts,
        "relations": out,
        "held": held,
        "total": len(out),
        "all_held": held == len(out),
    }
    if line.get("room_size_m") is not None or line.get("room_height_m") is not None:
        room = fit.room_size(scene.room, line.get("room_size_m") or [], line.get("room_height_m"))
        res["room"] = room
        res["all_held"] = res["all_held"] and room["held"]
    return res


def _suite_line(suite: Path, ident: str) -> dict[str, Any]:
    for raw in suite.read_text().splitlines():
        if raw.strip():
            line = json.loads(raw)
            if line.get("id") == ident:
                return dict(line)
    raise LineError(f"no line with id {ident!r} in {suite}")


def main(argv: list[str]) -> int:
    """Run the command line; see the module's docstring."""
    ap = argparse.ArgumentParser(description="Judge a scenewright package against a relation-suite line.")
    ap.add_argument("package", nargs="?", type=Path)
    ap.add_argument("--line", help="the suite line as JSON")
    ap.add_argument("--suite", type=Path, help="a suite file (with --id)")
    ap.add_argument("--id", help="the suite line's id")
    ap.add_argument("--batch", type=Path, help='a JSONL file of {"package": DIR, "line": {…}}')
    ap.add_argument(
        "--vocabulary", type=Path, help="`scenewright assets list --json` output: keys match the catalog's names"
    )
    args = ap.parse_args(argv)
    try:
        use_vocabulary(args.vocabulary)
        if args.batch:
            for raw in args.batch.read_text().splitlines():
                if not raw.strip():
                    continue
                case = json.loads(raw)
                try:
                    res = judge(Path(case["package"]), case["line"])
                except (SceneError, LineError) as e:
                    res = {"package": case.get("package"), "id": case.get("line", {}).get("id"), "error": str(e)}
                print(json.dumps(res), flush=True)
            return 0
        if args.package is None:
            raise LineError("give a PACKAGE directory (or --batch FILE)")
        if args.line:
            line = json.loads(args.line)
        elif args.suite and args.id:
            line = _suite_line(args.suite, args.id)
        else:
            raise LineError("give --line JSON, or --suite FILE with --id ID")
        print(json.dumps(judge(args.package, line), indent=1))
        return 0
    except (SceneError, LineError, OSError, json.JSONDecodeError, KeyError) as e:
        print(f"judge: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
