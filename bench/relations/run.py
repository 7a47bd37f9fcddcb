#!/usr/bin/env python3
"""Run the relation suite and print per-relation pass rates.

Every prompt on N seeds through the release binary, each package judged by judge.py, then
per-relation pass rates, the share of prompts with every relation held, and count
mismatches.

    .cache/venv/bin/python bench/relations/run.py [--seeds 5] [--binary target/release/scenewright]
        [--suite bench/relations/suite.jsonl] [--only ID[,ID]] [--work DIR] [--keep] [--json FILE]
    .cache/venv/bin/python bench/relations/run.py --report FILE   # the tables of an earlier --json

A corpus file (bench/relations/corpus/dev.jsonl) is a suite too. `--summary` prints only the
issue-20 measures (relations held, fully right, count keys exact, object precision, arms), no
per-prompt line: the way to score a held-out set. Keys match the catalog's own names and kinds
(`--vocabulary auto`, from the binary's `assets list --json`; `none` matches them exactly).

Packages are written under --work (a temporary directory, removed at the end unless --keep).
A package that fails to generate counts every one of its relations as not held.
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from judge import judge  # noqa: E402
from judge_common import LineError, use_vocabulary  # noqa: E402
from judge_scene import SceneError  # noqa: E402

ROOT = HERE.parent.parent


def generate(binary: Path, prompt: str, out: Path, seed: int) -> tuple[bool, str, float]:
    """Run `scenewright generate`; return (verified, note, seconds)."""
    if out.exists():
        shutil.rmtree(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    t0 = time.monotonic()
    try:
        p = subprocess.run(
            [str(binary), "generate", prompt, "--out", str(out), "--seed", str(seed), "--json"],
            capture_output=True,
            text=True,
            timeout=600,
            check=False,
        )
    except subprocess.TimeoutExpired:
        return False, "timed out after 600 s", time.monotonic() - t0
    dt = time.monotonic() - t0
    if p.returncode == 0:
        return True, "", dt
    last = (p.stderr.strip().splitlines() or ["?"])[-1]
    return False, f"exit {p.returncode}: {last}", dt


def vocabulary(choice: str, binary: Path, work: Path) -> Path | None:
    """Return the catalog's names for the judge: `auto` asks the binary, `none` matches keys exactly."""
    if choice == "none":
        return None
    if choice != "auto":
        return Path(choice)
    proc = subprocess.run([str(binary), "assets", "list", "--json"], capture_output=True, text=True, timeout=120)
    if proc.returncode != 0:
        raise SystemExit(f"run: `{binary} assets list --json` failed: {proc.stderr.strip()[:200]}")
    work.mkdir(parents=True, exist_ok=True)
    path = work / "vocabulary.json"
    path.write_text(proc.stdout)
    return path


def run(args: argparse.Namespace) -> dict[str, Any]:
    """Generate and judge everything; return every verdict."""
    lines = [json.loads(x) for x in args.suite.read_text().splitlines() if x.strip()]
    if args.only:
        wanted = set(args.only.split(","))
        lines = [x for x in lines if x["id"] in wanted]
    results = []
    for i, line in enumerate(lines, 1):
        for seed in range(1, args.seeds + 1):
            out = args.work / line["id"] / f"seed{seed}"
            verified, note, secs = generate(args.binary, line["prompt"], out, seed)
            try:
                res = judge(out, line) if (out / "scene.xml").is_file() else None
            except (SceneError, LineError) as e:
                res, note = None, f"{note} judge: {e}".strip()
            if res is None:
                res = {
                    "id": line["id"],
                    "package": str(out),
                    "counts": {"held": False, "objects": [], "robots": [], "error": note},
                    "relations": [
                        {**r, "held": False, "measured": {}, "why": f"no package: {note}"} for r in line["relations"]
                    ],
                    "held": 0,
                    "total": len(line["relations"]),
                    "all_held": False,
                }
            res.update({"seed": seed, "verified": verified, "note": note, "seconds": round(secs, 3)})
            results.append(res)
            if args.summary:
                continue
            mark = "ok " if res["all_held"] and res["counts"]["held"] else "-- "
            print(
                f"{mark}[{i}/{len(lines)}] {line['id']} seed {seed}: {res['held']}/{res['total']} held"
                f"{'' if res['counts']['held'] else ', counts off'}{'' if verified else ', ' + note}",
                file=sys.stderr,
                flush=True,
            )
    return {"seeds": args.seeds, "suite": str(args.suite), "results": results}


def _expected(e: Any) -> int | None:
    """Return a count row's expected number (None for an `>= n` row)."""
    return e if isinstance(e, int) else None


def measures(data: dict[str, Any]) -> str:
    """Format the issue-20 measures of a run, with no per-prompt detail (safe for a held-out set)."""
    rs = data["results"]
    held = sum(r["held"] for r in rs)
    total = sum(r["total"] for r in rs)
    full = sum(1 for r in rs if r["all_held"] and r["counts"]["held"] and r["verified"])
    keys = [o for r in rs for o in r["counts"]["objects"] + r["counts"]["robots"]]
    exact = sum(1 for o in keys if o["held"])
    placed = good = 0
    for r in rs:
        c = r["counts"]
        for o in c["objects"] + c["robots"]:
            want = _expected(o["expected"])
            placed += o["found"]
            good += o["found"] if want is None else min(o["found"], want)
        placed += sum(c.get("extra_objects", {}).values()) + len(c.get("unexpected_robots", []))
    clean = sum(1 for r in rs if not (r["counts"].get("extra_objects") or r["counts"].get("unexpected_robots")))
    arms = [r for r in rs if any(x["relation"] == "reach" for x in r["relations"])]
    arms_ok = sum(1 for r in arms if all(x["held"] for x in r["relations"] if x["relation"] == "reach"))

    def pct(a: int, b: int) -> str:
        return f"{a}/{b} = {100.0 * a / max(1, b):.1f} %"

    return "\n".join(
        [
            f"{len(rs)} scenes ({len({r['id'] for r in rs})} prompts x {data['seeds']} seeds)",
            f"relations held {pct(held, total)}",
            f"fully right (every relation held, counts exact, verified) {pct(full, len(rs))}",
            f"count keys exact {pct(exact, len(keys))}",
            f"object precision {pct(good, placed)}; scenes with no unasked object {clean}/{len(rs)}",
            f"arms reaching all their work {arms_ok}/{len(arms)} scenes",
        ]
    )


def report(data: dict[str, Any]) -> str:
    """Format the tables a person reads: per relation, per prompt, counts."""
    res = data["results"]
    per: dict[str, list[int]] = defaultdict(lambda: [0, 0])
    for r in res:
        for x in r["relations"]:
            per[x["relation"]][0] += int(x["held"])
            per[x["relation"]][1] += 1
    out = ["| relation | held / cases | rate |", "|---|---|---|"]
    for name, (h, n) in sorted(per.items(), key=lambda kv: (kv[1][0] / kv[1][1], kv[0])):
        out.append(f"| {name} | {h} / {n} | {100.0 * h / n:.0f} % |")
    th = sum(h for h, _ in per.values())
    tn = sum(n for _, n in per.values())
    out.append(f"| **all** | **{th} / {tn}** | **{100.0 * th / max(1, tn):.1f} %** |")
    n = len(res)
    all_rel = sum(1 for r in res if r["all_held"])
    all_both = sum(1 for r in res if r["all_held"] and r["counts"]["held"])
    counts_ok = sum(1 for r in res if r["counts"]["held"])
    verified = sum(1 for r in res if r["verified"])
    arms = [r for r in res if any(x["relation"] == "reach" for x in r["relations"])]
    arms_ok = sum(1 for r in arms if all(x["held"] for x in r["relations"] if x["relation"] == "reach"))
    out += [
        "",
        f"scenes {n} ({len({r['id'] for r in res})} prompts x {data['seeds']} seeds), verified {verified}/{n}",
        f"every relation held: {all_rel}/{n} ({100.0 * all_rel / max(1, n):.1f} %)",
        f"counts exact: {counts_ok}/{n} ({100.0 * counts_ok / max(1, n):.1f} %)",
        f"every relation held and counts exact: {all_both}/{n} ({100.0 * all_both / max(1, n):.1f} %)",
        f"scenes with an arm whose every reach relation held: {arms_ok}/{len(arms)}",
        "",
        "count mismatches (prompt: key expected -> found, per seed):",
    ]
    seen: dict[str, dict[str, list[int]]] = defaultdict(lambda: defaultdict(list))
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
            seen[r["id"]]["; ".join(bits)].append(r["seed"])
    for ident, rows in sorted(seen.items()):
        parts = [f"{msg} (seeds {','.join(map(str, seeds))})" for msg, seeds in rows.items()]
        out.append(f"- {ident}: " + " | ".join(parts))
    return "\n".join(out)


def main() -> int:
    """Run the command line; see the module's docstring."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=5)
    ap.add_argument("--binary", type=Path, default=ROOT / "target/release/scenewright")
    ap.add_argument("--suite", type=Path, default=HERE / "suite.jsonl")
    ap.add_argument("--only", help="comma-separated suite ids")
    ap.add_argument("--work", type=Path)
    ap.add_argument("--keep", action="store_true", help="keep the packages")
    ap.add_argument("--json", type=Path, help="write every verdict here")
    ap.add_argument("--report", type=Path, help="print the tables of an earlier --json file and stop")
    ap.add_argument(
        "--summary", action="store_true", help="print only the measures, no per-prompt lines (for held-out sets)"
    )
    ap.add_argument(
        "--vocabulary",
        default="auto",
        help="keys match the catalog's names and kinds: `auto` (the binary's `assets list --json`), a file, or `none`",
    )
    args = ap.parse_args()
    if args.report:
        data = json.loads(args.report.read_text())
        print(measures(data) if args.summary else report(data) + "\n\n" + measures(data))
        return 0
    if not args.binary.is_file():
        print(f"run: no binary at {args.binary} (cargo build --release -p sw_cli)", file=sys.stderr)
        return 2
    if args.seeds < 1:
        print("run: --seeds must be at least 1", file=sys.stderr)
        return 2
    temp = args.work is None
    if temp:
        args.work = Path(tempfile.mkdtemp(prefix="relations-"))
    try:
        use_vocabulary(vocabulary(args.vocabulary, args.binary, args.work))
        data = run(args)
    finally:
        if temp and not args.keep:
            shutil.rmtree(args.work, ignore_errors=True)
    if args.json:
        args.json.write_text(json.dumps(data, indent=1))
    print(measures(data) if args.summary else report(data) + "\n\n" + measures(data))
    return 0


if __name__ == "__main__":
    sys.exit(main())
