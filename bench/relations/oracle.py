#!/usr/bin/env python3
"""The solver alone on a corpus: each line's annotation as a plan, laid out and judged.

The relation suite and the corpora measure reader and solver together. This measures the
solver (layout, forge sizes, report) apart from the reader: every line becomes the plan a
perfect reader would return — a group per `counts` / `min_counts` key (its first
alternative; a key with no catalog category becomes a labelled proxy), a robot group per
`robots` key, every relation as written (an arm's `on` becomes its mount, `size` its
group's stated size) — and the packages are judged by judge.py exactly as run.py does.

    .cache/venv/bin/python bench/relations/oracle.py --corpus bench/relations/corpus/dev.jsonl --seeds 1

Needs the sw_pipeline test binary that generates from plan files
(`cargo test -p sw_pipeline --test plan_files --no-run`); the script runs it through cargo.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(HERE))

import judge  # noqa: E402

ROOMS = {
    "warehouse", "storage_room", "lab", "kitchen", "office", "workshop", "garage", "clean_room",
    "retail_store", "pharmacy", "classroom", "data_centre", "loading_dock", "greenhouse", "closet",
    "factory", "hospital", "living_room", "tabletop", "room",
}  # fmt: skip
ROOM_ALIASES = {"shop": "retail_store", "store": "retail_store", "laboratory": "lab", "data_center": "data_centre"}
ROBOT_ALIASES = {"arm": "ur5e", "mobile": "turtlebot3"}
TARGETED = {
    "on", "under", "next_to", "near", "between", "in_front_of", "behind", "around", "at_end_of_row", "loaded",
    "full_of", "each_with", "reach", "inside", "set_into", "at_end_of", "on_edge_of", "on_each_side_of", "facing",
}  # fmt: skip


def catalog() -> set[str]:
    """Return the catalog's categories (`scenewright assets list --json`, else the source)."""
    out = set()
    for f in (ROOT / "crates/sw_catalog/src/categories").glob("*.rs"):
        for line in f.read_text().splitlines():
            s = line.strip()
            if s.startswith('name: "') and s.endswith('",'):
                out.add(s[len('name: "') : -2])
    return out


RESTING = {"on", "inside", "on_edge_of", "set_into", "stacked"}


def proxy(key: str, label: str, relations: list[dict[str, Any]]) -> dict[str, Any]:
    """Return a stand-in with the prior a reader gives a noun in this place.

    A thing said to rest on or in something is a tabletop item; a thing others rest on is a
    low surface; anything else a floor object.
    """
    rests = any(r["subject"] == key and r["relation"] in RESTING for r in relations) or any(
        r.get("target") == key and r["relation"] == "each_with" and r.get("where") == "on" for r in relations
    )
    carries = any(r.get("target") == key and r["relation"] in RESTING for r in relations)
    if rests:
        prior, size, movable = "tabletop item", (0.12, 0.12, 0.12), True
    elif carries:
        prior, size, movable = "surface", (0.9, 0.6, 0.75), False
    else:
        prior, size, movable = "floor object", (0.5, 0.5, 0.8), False
    return {
        "label": label.replace("_", " "),
        "prior": prior,
        "size": {"width": size[0], "depth": size[1], "height": size[2]},
        "movable": movable,
    }


def room_kind(name: str) -> str:
    """Map a line's room word to a RoomKind."""
    k = name.strip().lower().replace(" ", "_").replace("-", "_")
    k = ROOM_ALIASES.get(k, k)
    return k if k in ROOMS else "room"


def to_plan(line: dict[str, Any], cats: set[str]) -> dict[str, Any]:
    """Return the plan a perfect reader would make of a corpus line."""
    groups: dict[str, str] = {}
    objects = []
    for field in ("counts", "min_counts"):
        for key, n in line.get(field, {}).items():
            if key in groups or n <= 0:
                continue
            alts = key.split("|")
            cat = next((a for a in alts if a in cats), None)
            gid = f"g{len(groups)}"
            groups[key] = gid
            o: dict[str, Any] = {"id": gid, "category": cat or "proxy", "phrase": alts[0].replace("_", " "), "count": n}
            if cat is None:
                o["proxy"] = proxy(key, alts[0], line["relations"])
            objects.append(o)
    robots = []
    rids: dict[str, str] = {}
    for key, n in line.get("robots", {}).items():
        model = ROBOT_ALIASES.get(key.split("|")[0], key.split("|")[0])
        rid = f"r{len(rids)}"
        rids[key] = rid
        robots.append({"id": rid, "model": model, "phrase": key, "count": n, "mount": {"mount": "auto"}})

    def ref(key: str | None) -> str | None:
        if key is None:
            return None
        return (
            groups.get(key)
            or rids.get(key)
            or next((v for k, v in {**groups, **rids}.items() if key in k.split("|")), None)
        )

    # An arm on a pedestal or cart: the pipeline makes its stand; what is said of the
    # stand is said of the arm (the report measures it on the stand).
    stands = {
        r["target"]: r["subject"]
        for r in line["relations"]
        if r["relation"] == "on" and r["subject"] in rids and r.get("target") in groups
        and any(o["id"] == groups[r["target"]] and o["category"] in ("pedestal", "mobile_cart") for o in objects)
    }  # fmt: skip
    relations = []
    for r in line["relations"]:
        if r["subject"] in stands and r["relation"] != "on":
            r = {**r, "subject": stands[r["subject"]]}
        rel, subj = r["relation"], ref(r["subject"])
        if subj is None:
            continue
        if rel == "size":
            sized = next((x for x in objects if x["id"] == subj), None)
            if sized is None:
                continue
            ex = sized.setdefault("size", {}).setdefault("explicit", {})
            for k, (lo, hi) in r["dims"].items():
                ex[k] = round((lo + hi) / 2.0, 4)
            continue
        out: dict[str, Any] = {"subject": subj, "relation": "in_middle" if rel == "in_middle" else rel}
        if rel in TARGETED:
            t = ref(r.get("target"))
            if t is None or (t == subj and rel != "between"):
                continue
            if rel == "between":
                out["first"] = t
                out["second"] = ref(r.get("target2")) or t
            else:
                out["target"] = t
        if subj in rids.values() and rel == "on":
            robot = next(x for x in robots if x["id"] == subj)
            carrier = next((o for o in objects if o["id"] == out["target"]), None)
            if carrier is not None and carrier["category"] in ("pedestal", "mobile_cart"):
                # The robot's own stand: the pipeline makes it.
                robot["mount"] = {"mount": "pedestal" if carrier["category"] == "pedestal" else "mobile_base"}
                objects.remove(carrier)
            else:
                robot["mount"] = {"mount": "on_surface", "target": out["target"]}
            continue
        for f in ("wall", "n", "m", "stacks", "end"):
            if r.get(f) is not None:
                out[f] = r[f]
        if r.get("long"):
            out["long"] = True
        if rel == "on_two_walls":
            out.pop("walls", None)
        relations.append(out)
    size = line.get("room_size_m")
    kind = room_kind(line.get("room", "room"))
    return {
        "schema_version": 3,
        "prompt": line.get("prompt", ""),
        "room": {
            "kind": kind,
            "size": {"width": max(size), "depth": min(size), "height": line.get("room_height_m", 3.0)}
            if size
            else {"width": 8.0, "depth": 6.0, "height": 3.0},
            "size_fixed": bool(size),
            "door": "south",
        },
        "objects": objects,
        "relations": relations,
        "robots": robots,
        "rules_profile": "general",
        "understanding": {"not_understood": [], "approximated": []},
    }


def main(argv: list[str]) -> int:
    """Run the command line; see the module's docstring."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", type=Path, required=True)
    ap.add_argument("--seeds", type=int, default=1)
    ap.add_argument("--work", type=Path)
    ap.add_argument("--json", type=Path, help="write every verdict here")
    args = ap.parse_args(argv)
    cats = catalog()
    lines = [json.loads(x) for x in args.corpus.read_text().splitlines() if x.strip()]
    work = args.work or Path(tempfile.mkdtemp(prefix="oracle-"))
    plans = work / "plans"
    plans.mkdir(parents=True, exist_ok=True)
    for i, line in enumerate(lines):
        (plans / f"{i:04d}.json").write_text(json.dumps(to_plan(line, cats)))
    env = {"PLAN_FILES": str(plans), "PLAN_OUT": str(work / "out"), "PLAN_SEEDS": str(args.seeds)}
    cmd = ["cargo", "test", "-q", "-p", "sw_pipeline", "--test", "plan_files", "--", "--ignored", "--nocapture"]
    proc = subprocess.run(cmd, cwd=ROOT, env={**__import__("os").environ, **env}, capture_output=True, text=True)
    if proc.returncode != 0:
        print(proc.stdout[-3000:], proc.stderr[-3000:], file=sys.stderr)
        return 1
    kinds: Counter[str] = Counter()
    held: Counter[str] = Counter()
    scenes = all_held = counts_ok = 0
    verdicts = []
    for i, line in enumerate(lines):
        for seed in range(1, args.seeds + 1):
            pkg = work / "out" / f"{i:04d}-{seed}"
            if not (pkg / "scene.xml").is_file():
                err = pkg / "error.txt"
                why = err.read_text().strip() if err.exists() else "not generated"
                print(f"{line['id']} seed {seed}: no package ({why})")
                for r in line["relations"]:
                    kinds[r["relation"]] += 1
                scenes += 1
                continue
            v = judge.judge(pkg, line)
            verdicts.append(v)
            scenes += 1
            all_held += int(v["all_held"])
            counts_ok += int(v["counts"]["held"])
            for r in v["relations"]:
                kinds[r["relation"]] += 1
                held[r["relation"]] += int(r["held"])
                if not r["held"]:
                    what = f"{r['subject']} {r['relation']} {r.get('target', '')}"
                    print(f"{line['id']} seed {seed}: {what}: {r.get('why', '')}")
    print("\n| relation | held / cases | rate |\n|---|---|---|")
    for k in sorted(kinds, key=lambda k: (held[k] / kinds[k], k)):
        print(f"| {k} | {held[k]} / {kinds[k]} | {100 * held[k] / kinds[k]:.0f} % |")
    t, h = sum(kinds.values()), sum(held.values())
    print(f"| **all** | **{h} / {t}** | **{100 * h / max(t, 1):.1f} %** |")
    print(f"\nscenes {scenes}: every relation held {all_held}, counts exact {counts_ok}")
    if args.json:
        args.json.write_text("\n".join(json.dumps(v) for v in verdicts))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
