#!/usr/bin/env python3
"""Score the reader on a corpus file (issue 20): generate every prompt, judge every package.

Prints what issue 20 measures: relations held, prompts fully right (every relation held and
counts exact), counts exact, precision of object categories (object bodies of a category the
line names, over all object bodies) and arms reaching all their work; per relation and per
style. Relations today's judge cannot measure (issue-20 names before the judge has them) and
`room_size_m` are counted apart as unmeasured, never as held.

    .cache/venv/bin/python bench/relations/corpus_run.py --corpus bench/relations/corpus/dev.jsonl
        [--binary target/release/scenewright] [--seeds 1] [--only ID[,ID]] [--json FILE] [--keep]
    .cache/venv/bin/python bench/relations/corpus_run.py --report FILE   # tables of an earlier --json

Only ever run it on heldout.jsonl to score at the end of a session (the lead does that).
"""

from __future__ import annotations

import argparse
import json
import shutil
import sys
import tempfile
from collections import defaultdict
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from judge import CHECKS, check_counts  # noqa: E402
from judge_common import LineError, Relation  # noqa: E402
from judge_scene import SceneError, load  # noqa: E402
from run import generate  # noqa: E402

ROOT = HERE.parent.parent


def split_line(line: dict[str, Any]) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    """The line with only the relations the judge measures, and the others."""
    known = [r for r in line["relations"] if r["relation"] in CHECKS]
    unknown = [r for r in line["relations"] if r["relation"] not in CHECKS]
    return {**line, "relations": known}, unknown


def judge_one(package: Path, line: dict[str, Any]) -> dict[str, Any]:
    """Judge one package: relations, counts, and the object bodies for precision."""
    measured, unmeasured = split_line(line)
    scene = load(package)
    rows = []
    for raw in measured["relations"]:
        r = Relation.parse(raw)
        v = CHECKS[r.relation](r, scene)
        row: dict[str, Any] = {"subject": r.subject, "relation": r.relation, "held": v.held}
        if r.target:
            row["target"] = r.target
        if v.why:
            row["why"] = v.why
        rows.append(row)
    counts = check_counts(scene, measured)
    extra = sum(counts["extra_objects"].values())
    return {
        "relations": rows,
        "unmeasured": [u["relation"] for u in unmeasured] + (["room_size_m"] if "room_size_m" in line else []),
        "counts": counts,
        "objects": len(scene.objects),
        "extra": extra,
    }


def run(args: argparse.Namespace) -> dict[str, Any]:
    lines = [json.loads(x) for x in args.corpus.read_text().splitlines() if x.strip()]
    if args.only:
        wanted = set(args.only.split(","))
        lines = [x for x in lines if x["id"] in wanted]
    results = []
    for i, line in enumerate(lines, 1):
        for seed in range(1, args.seeds + 1):
            out = args.work / line["id"] / f"seed{seed}"
            verified, note, secs = generate(args.binary, line["prompt"], out, seed)
            try:
                res = judge_one(out, line) if (out / "scene.xml").is_file() else None
            except (SceneError, LineError) as e:
                res, note = None, f"{note} judge: {e}".strip()
            if res is None:
                measured, unmeasured = split_line(line)
                res = {
                    "relations": [
                        {**r, "held": False, "why": f"no package: {note}"} for r in measured["relations"]
                    ],
                    "unmeasured": [u["relation"] for u in unmeasured],
                    "counts": {"held": False, "objects": [], "robots": [], "extra_objects": {}, "error": note},
                    "objects": 0,
                    "extra": 0,
                }
            held = sum(1 for r in res["relations"] if r["held"])
            res.update(
                {
                    "id": line["id"],
                    "style": line.get("style", []),
                    "seed": seed,
                    "verified": verified,
                    "note": note,
                    "seconds": round(secs, 3),
                    "held": held,
                    "total": len(res["relations"]),
                    "all_held": held == len(res["relations"]),
                }
            )
            results.append(res)
            mark = "ok " if res["all_held"] and res["counts"]["held"] else "-- "
            print(
                f"{mark}[{i}/{len(lines)}] {line['id']} seed {seed}: {held}/{res['total']} held"
                f"{'' if res['counts']['held'] else ', counts off'}{'' if verified else ', ' + note}",
                file=sys.stderr,
                flush=True,
            )
    return {"seeds": args.seeds, "corpus": str(args.corpus), "results": results}


def pct(a: int, b: int) -> str:
    return f"{a}/{b} ({100.0 * a / max(1, b):.1f} %)"


def report(data: dict[str, Any]) -> str:
    res = data["results"]
    per: dict[str, list[int]] = defaultdict(lambda: [0, 0])
    unmeasured: dict[str, int] = defaultdict(int)
    for r in res:
        for x in r["relations"]:
            per[x["relation"]][0] += int(x["held"])
            per[x["relation"]][1] += 1
        for u in r["unmeasured"]:
            unmeasured[u] += 1
    out = ["| relation | held / cases | rate |", "|---|---|---|"]
    for name, (h, n) in sorted(per.items(), key=lambda kv: (kv[1][0] / kv[1][1], kv[0])):
        out.append(f"| {name} | {h} / {n} | {100.0 * h / n:.0f} % |")
    th = sum(h for h, _ in per.values())
    tn = sum(n for _, n in per.values())
    out.append(f"| **all measured** | **{th} / {tn}** | **{100.0 * th / max(1, tn):.1f} %** |")
    n = len(res)
    right = sum(1 for r in res if r["all_held"] and r["counts"]["held"])
    counts_ok = sum(1 for r in res if r["counts"]["held"])
    verified = sum(1 for r in res if r["verified"])
    objects = sum(r["objects"] for r in res)
    extra = sum(r["extra"] for r in res)
    arms = [r for r in res if any(x["relation"] == "reach" for x in r["relations"])]
    arms_ok = sum(1 for r in arms if all(x["held"] for x in r["relations"] if x["relation"] == "reach"))
    out += [
        "",
        f"scenes {n} ({len({r['id'] for r in res})} prompts x {data['seeds']} seeds), verified {pct(verified, n)}",
        f"relations held (measured): {pct(th, tn)}",
        f"prompts fully right (every measured relation held, counts exact): {pct(right, n)}",
        f"counts exact: {pct(counts_ok, n)}",
        f"precision of object categories (bodies of a named category / all bodies): "
        f"{(objects - extra) / max(1, objects):.3f} ({extra} extra of {objects})",
        f"scenes whose every arm reaches all its work: {pct(arms_ok, len(arms))}",
        "unmeasured (the judge has no check yet): "
        + (", ".join(f"{k} {v}" for k, v in sorted(unmeasured.items())) or "none"),
        "",
        "per style (prompts fully right):",
    ]
    styles: dict[str, list[int]] = defaultdict(lambda: [0, 0])
    for r in res:
        for s in r["style"]:
            styles[s][0] += int(r["all_held"] and r["counts"]["held"])
            styles[s][1] += 1
    for s, (a, b) in sorted(styles.items()):
        out.append(f"- {s}: {pct(a, b)}")
    out += ["", "count mismatches:"]
    for r in res:
        c = r["counts"]
        bits = [
            f"{o['key']} {o['expected']}->{o['found']}"
            for o in c.get("objects", []) + c.get("robots", [])
            if not o["held"]
        ]
        if c.get("extra_objects"):
            bits.append("extra " + ", ".join(f"{k} {v}" for k, v in c["extra_objects"].items()))
        if c.get("unexpected_robots"):
            bits.append("unexpected robots " + ", ".join(c["unexpected_robots"]))
        if c.get("error"):
            bits.append(c["error"])
        if bits:
            out.append(f"- {r['id']} (seed {r['seed']}): " + "; ".join(bits))
    return "\n".join(out)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", type=Path, default=HERE / "corpus" / "dev.jsonl")
    ap.add_argument("--binary", type=Path, default=ROOT / "target/release/scenewright")
    ap.add_argument("--seeds", type=int, default=1)
    ap.add_argument("--only", help="comma-separated ids")
    ap.add_argument("--work", type=Path)
    ap.add_argument("--keep", action="store_true", help="keep the packages")
    ap.add_argument("--json", type=Path, help="write every verdict here")
    ap.add_argument("--report", type=Path, help="print the tables of an earlier --json file and stop")
    args = ap.parse_args()
    if args.report:
        print(report(json.loads(args.report.read_text())))
        return 0
    if not args.binary.is_file():
        print(f"corpus_run: no binary at {args.binary} (cargo build --release -p sw_cli)", file=sys.stderr)
        return 2
    if not args.corpus.is_file():
        print(f"corpus_run: no corpus at {args.corpus}", file=sys.stderr)
        return 2
    if args.seeds < 1:
        print("corpus_run: --seeds must be at least 1", file=sys.stderr)
        return 2
    temp = args.work is None
    if temp:
        args.work = Path(tempfile.mkdtemp(prefix="corpus-"))
    try:
        data = run(args)
    finally:
        if temp and not args.keep:
            shutil.rmtree(args.work, ignore_errors=True)
    if args.json:
        args.json.write_text(json.dumps(data, indent=1))
    print(report(data))
    return 0


if __name__ == "__main__":
    sys.exit(main())
