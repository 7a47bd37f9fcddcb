#!/usr/bin/env python3
"""Compare the two routes over the same suite and seeds: judge.py and the CLI's report.

    .cache/venv/bin/python bench/relations/run.py --seeds 5 --json judge.json
    target/release/scenewright bench scenes --suite bench/relations/suite.jsonl --seeds 5 --json > cli.json
    .cache/venv/bin/python bench/relations/compare.py judge.json cli.json

The judge measures every relation of the suite on scene.xml; the CLI counts a relation as
held when the package's report.json states it and measured it as held on the written scene.
Each (prompt, seed, relation) on which they disagree is printed with both reasons, grouped:
relations the report does not state (the planner did not read them, or the suite implies
them), and relations both measured but judged differently. Nothing is reconciled here.
"""

from __future__ import annotations

import json
import sys
from collections import Counter
from pathlib import Path


def key(ident: str, seed: int, r: dict) -> tuple:
    """Return what identifies one relation of one scene in both outputs."""
    return (ident, seed, r["relation"], r["subject"], r.get("target"))


def main() -> int:
    """Print the agreement and every disagreement."""
    if len(sys.argv) != 3:
        print("usage: compare.py JUDGE.json CLI.json", file=sys.stderr)
        return 2
    judge = json.loads(Path(sys.argv[1]).read_text())
    cli = json.loads(Path(sys.argv[2]).read_text())
    cli_missed = {key(m["id"], m["seed"], m): m["why"] for m in cli["misses"]}
    total = agree = 0
    unstated: list[str] = []
    differ: list[str] = []
    kinds: Counter[str] = Counter()
    for res in judge["results"]:
        for r in res["relations"]:
            k = key(res["id"], res["seed"], r)
            total += 1
            cli_held = k not in cli_missed
            if cli_held == r["held"]:
                agree += 1
                continue
            kinds[r["relation"]] += 1
            why_cli = cli_missed.get(k, "held")
            why_judge = "held" if r["held"] else r.get("why", "")
            row = f"{res['id']} seed {res['seed']}: {r['subject']} {r['relation']} {r.get('target') or ''}".rstrip()
            row += f" | judge: {why_judge} | cli: {why_cli}"
            (unstated if "not among the report" in why_cli else differ).append(row)
    print(f"agreement {agree}/{total} ({100.0 * agree / max(1, total):.1f} %)")
    print("disagreements per relation: " + ", ".join(f"{k} {n}" for k, n in sorted(kinds.items())))
    print(f"\nnot stated in the report ({len(unstated)}):")
    print("\n".join(f"- {x}" for x in unstated))
    print(f"\nmeasured by both, judged differently ({len(differ)}):")
    print("\n".join(f"- {x}" for x in differ))
    return 0


if __name__ == "__main__":
    sys.exit(main())
