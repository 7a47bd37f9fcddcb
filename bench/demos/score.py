"""Scores `scenewright demos` on a suite of task prompts (BENCHMARKS.md, issue 23).

    python bench/demos/score.py bench/demos/dev.txt --episodes 5 --out /tmp/demos-dev

For each prompt of the suite (families are the suite's `# headers`), `scenewright demos`
makes `--episodes` solved episodes (each attempt a new seed: a new scene variant and
randomisation) and records every attempt. Reported per family: expert success (solved /
attempts; a prompt refused up front counts as one failed attempt per wanted episode),
replayed success (every solved episode replayed from its recorded actions in this Python
MuJoCo and judged by `scenewright.tasks`, not by the engine), episodes per minute and
bytes per episode. Needs `pyarrow` and the `mujoco` bindings; SCENEWRIGHT_BIN or
target/debug/scenewright.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "python"))

from scenewright.demos import Demos  # noqa: E402


def suite(path: Path) -> list[tuple[str, str]]:
    family = "other"
    out = []
    for line in path.read_text().splitlines():
        line = line.strip()
        if line.startswith("#"):
            words = line.lstrip("# ").split()
            if words and len(words) <= 6 and not line.startswith("# (") and "suite" not in line:
                family = " ".join(words)
            continue
        if line:
            out.append((family, line))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("suite", type=Path)
    ap.add_argument("--episodes", type=int, default=5)
    ap.add_argument("--out", type=Path, required=True)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--cameras", default="")
    ap.add_argument("--json", type=Path)
    args = ap.parse_args()
    binary = os.environ.get("SCENEWRIGHT_BIN", str(ROOT / "target" / "debug" / "scenewright"))
    fam: dict[str, dict[str, float]] = defaultdict(lambda: defaultdict(float))
    rows = []
    for i, (family, prompt) in enumerate(suite(args.suite)):
        out = args.out / f"p{i:03d}"
        cmd = [binary, "demos", "--prompt", prompt, "--episodes", str(args.episodes), "--out", str(out)]
        cmd += ["--jobs", str(args.jobs), "--json"]
        if args.cameras:
            cmd += ["--cameras", args.cameras]
        t0 = time.time()
        r = subprocess.run(cmd, capture_output=True, text=True, check=False)
        secs = time.time() - t0
        f = fam[family]
        f["prompts"] += 1
        if r.returncode == 2:
            f["attempts"] += args.episodes
            rows.append({"family": family, "prompt": prompt, "refused": r.stderr.strip()})
            continue
        summary = json.loads(r.stdout) if r.stdout.strip() else {}
        lines = [json.loads(x) for x in (out / "attempts.jsonl").read_text().splitlines() if x.strip()]
        # A variant whose start already satisfied the task was drawn again: no attempt.
        attempts = [a for a in lines if a["outcome"] != "resampled"]
        f["resampled"] += len(lines) - len(attempts)
        solved = [a for a in attempts if a["outcome"] == "solved"]
        replayed = 0
        if (out / "meta" / "info.json").is_file():
            for ep in Demos(out).episodes():
                replayed += int(ep.replay().success)
        f["attempts"] += len(attempts)
        f["solved"] += len(solved)
        f["replayed"] += replayed
        f["episodes"] += summary.get("episodes", 0)
        f["bytes"] += summary.get("bytes", 0)
        f["seconds"] += secs
        fails: dict[str, int] = defaultdict(int)
        for a in attempts:
            if a["outcome"] != "solved":
                fails[a["outcome"]] += 1
        rows.append(
            {
                "family": family,
                "prompt": prompt,
                "attempts": len(attempts),
                "solved": len(solved),
                "replayed": replayed,
                "failures": dict(fails),
                "reasons": [a.get("reason", "") for a in attempts if a["outcome"] != "solved"],
            }
        )
        print(f"{family:22} {len(solved):2}/{len(attempts):2} replayed {replayed:2}  {prompt}", flush=True)
    total: dict[str, float] = defaultdict(float)
    print()
    print("| family | prompts | expert success | replayed = expert | starts redrawn | episodes/min | bytes/episode |")
    print("|---|---|---|---|---|---|---|")
    for family, f in fam.items():
        for k, v in f.items():
            total[k] += v
        rate = 60 * f["episodes"] / f["seconds"] if f["seconds"] else 0
        bpe = f["bytes"] / f["episodes"] if f["episodes"] else 0
        succ = 100 * f["solved"] / f["attempts"] if f["attempts"] else 0
        print(
            f"| {family} | {int(f['prompts'])} | {int(f['solved'])}/{int(f['attempts'])} ({succ:.0f} %) | "
            f"{int(f['replayed'])}/{int(f['solved'])} | {int(f['resampled'])} | {rate:.1f} | {bpe:.0f} |"
        )
    succ = 100 * total["solved"] / total["attempts"] if total["attempts"] else 0
    rate = 60 * total["episodes"] / total["seconds"] if total["seconds"] else 0
    print(
        f"| all | {int(total['prompts'])} | {int(total['solved'])}/{int(total['attempts'])} ({succ:.0f} %) | "
        f"{int(total['replayed'])}/{int(total['solved'])} | {int(total['resampled'])} | {rate:.1f} | "
        f"{total['bytes'] / max(total['episodes'], 1):.0f} |"
    )
    if args.json:
        args.json.write_text(json.dumps({"families": fam, "prompts": rows}, indent=1))


if __name__ == "__main__":
    main()
