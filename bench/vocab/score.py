"""Scores `scenewright generate` on a noun list (bench/vocab/*.tsv), the way README.md says.

For each noun one scene, "a room with a <noun>", is generated; its layout.json and report.json
are read: the objects placed for the noun (not those marked `added` by a fill), their
categories against the noun and its `accept` list, their sorted extents against `size_m`
within `tol`, and whether the report names the noun (approximated, warnings, left out, not
understood).

    python3 bench/vocab/score.py bench/vocab/dev.tsv [--bin target/release/scenewright] [--json OUT]
        [--summary]

Score heldout.tsv only at the end of a session. Standard library only.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
from collections import Counter, defaultdict
from typing import Any

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
# A guard, not a measure: one generate run that takes longer is an `error` row. On a machine shared
# with builds the in-process model can take minutes to load; VOCAB_TIMEOUT_S raises the guard.
TIMEOUT_S = int(os.environ.get("VOCAB_TIMEOUT_S", "120"))
REAL = ("real", "approximated")


def read_rows(path: str) -> list[dict[str, str]]:
    with open(path, encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines, delimiter="\t", quoting=csv.QUOTE_NONE))


def norm(name: str) -> str:
    return re.sub(r"\s+", " ", name.replace("_", " ").replace("-", " ").lower()).strip()


def head(noun: str) -> str:
    """The word that takes the article and the number: "tin" of "tin of beans"."""
    words = noun.split()
    for sep in ("of", "on"):
        if sep in words[1:]:
            return words[words.index(sep) - 1]
    return words[-1]


def prompt(row: dict[str, str]) -> str:
    noun = row["noun"]
    first = noun.split()[0].lower()
    h = head(noun).lower()
    plural = row["tag"] == "plural" or (h.endswith("s") and not h.endswith(("ss", "us", "os")))
    if plural or first in ("a", "an", "the"):
        return f"a room with {noun}"
    vowel = first[0] in "aeiou" and not first.startswith(("uni", "use", "uri", "eu", "one"))
    return f"a room with {'an' if vowel or first[0] == 'x' else 'a'} {noun}"


def accepted(row: dict[str, str], obj: dict[str, Any]) -> bool:
    """The object's category (or label) is the noun, one of `accept`, or the noun with a
    modifier before it ("electric kettle" for "kettle"); spaces inside a word do not count
    ("hand saw" is "handsaw"). The catalog's own synonyms are not consulted: they are its
    claims, and the scorer does not let the catalog grade itself."""
    wanted = {norm(row["noun"])} | {norm(a) for a in row["accept"].split("|") if a}
    wanted |= {w.replace(" ", "") for w in wanted}
    noun = norm(row["noun"])
    for field in ("category", "label"):
        got = norm(str(obj.get(field) or ""))
        if got and (got in wanted or got.replace(" ", "") in wanted or got.endswith(" " + noun)):
            return True
    return False


def sized(row: dict[str, str], obj: dict[str, Any]) -> bool:
    want = sorted(float(v) for v in row["size_m"].split(","))
    got = sorted(float(v) for v in obj["size"])
    tol = float(row["tol"])
    return all(abs(g - w) <= tol * w for g, w in zip(got, want, strict=True))


def judge(row: dict[str, str], rc: int, out: str) -> tuple[str, bool | None, list[str]]:
    """(outcome, right size or None, the categories placed)."""
    if rc == 2:
        return "refused", None, []
    if rc != 0:
        return "error", None, []
    with open(os.path.join(out, "layout.json"), encoding="utf-8") as f:
        layout = json.load(f)
    with open(os.path.join(out, "report.json"), encoding="utf-8") as f:
        report = json.load(f)
    said = norm(json.dumps([report.get(k) for k in ("approximated", "warnings", "left_out", "not_understood")]))
    named = any(re.search(rf"(?<![a-z]){re.escape(norm(w))}(?![a-z])", said) for w in (row["noun"], head(row["noun"])))
    objs = [o for o in layout.get("objects", []) if not o.get("added")]
    cats = [str(o.get("category")) for o in objs]
    if row["kind"] == "notathing":
        if objs:
            return "placed", None, cats
        return ("warned" if named else "silent"), None, cats
    if not objs:
        return ("left_out_warned" if named else "dropped"), None, cats
    size_ok = all(sized(row, o) for o in objs)
    if all(o.get("category") == "proxy" for o in objs):
        return "proxy", size_ok, cats
    if all(accepted(row, o) for o in objs):
        return ("approximated" if named else "real"), size_ok, cats
    return ("wrong_kind_warned" if named else "silent_substitute"), size_ok, cats


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("nouns")
    ap.add_argument(
        "--bin",
        default=None,
        help="the scenewright binary (default: target/release, else target/debug)",
    )
    ap.add_argument("--json", default=None, help="write every noun's outcome here")
    ap.add_argument("--summary", action="store_true", help="no per-noun lines (for a held-out list)")
    args = ap.parse_args(argv)
    binary = args.bin or next(
        (
            p
            for p in (os.path.join(ROOT, "target", d, "scenewright") for d in ("release", "debug"))
            if os.path.exists(p)
        ),
        "scenewright",
    )
    rows = read_rows(args.nouns)
    results: list[dict[str, Any]] = []
    with tempfile.TemporaryDirectory(prefix="vocab-score-") as tmp:
        for i, row in enumerate(rows):
            out = os.path.join(tmp, str(i))
            text = prompt(row)
            try:
                p = subprocess.run(
                    [binary, "generate", text, "--out", out],
                    capture_output=True,
                    text=True,
                    timeout=TIMEOUT_S,
                    check=False,
                )
                rc, err = p.returncode, p.stderr.strip()
            except subprocess.TimeoutExpired:
                rc, err = -1, "timeout"
            outcome, size_ok, cats = judge(row, rc, out)
            results.append(
                {
                    "noun": row["noun"],
                    "prompt": text,
                    "kind": row["kind"],
                    "tag": row["tag"],
                    "outcome": outcome,
                }
                | {"size_ok": size_ok, "categories": cats, "stderr": err[-200:]}
            )
    things = [r for r in results if r["kind"] != "notathing"]
    real_ok = sum(1 for r in things if r["outcome"] in REAL and r["size_ok"])
    kind_ok = sum(1 for r in things if r["outcome"] in (*REAL, "proxy"))
    print(
        f"{os.path.basename(args.nouns)}: {len(things)} things: real model of the right kind and size {real_ok}"
        f" ({100 * real_ok / max(len(things), 1):.1f} %), right kind or honest proxy {kind_ok}"
    )
    print("  outcomes: " + ", ".join(f"{k} {n}" for k, n in Counter(r["outcome"] for r in things).most_common()))
    sizes = Counter(r["outcome"] for r in things if r["size_ok"] is False)
    print("  of which wrong size: " + ", ".join(f"{k} {n}" for k, n in sizes.most_common()))
    nots = [r for r in results if r["kind"] == "notathing"]
    print(
        f"  notathing ({len(nots)}): " + ", ".join(f"{k} {n}" for k, n in Counter(r["outcome"] for r in nots).items())
    )
    by: dict[str, Counter[str]] = defaultdict(Counter)
    for r in things:
        by[f"kind {r['kind']}"][r["outcome"]] += 1
        by[f"tag {r['tag'] or '-'}"][r["outcome"]] += 1
    for key in sorted(by):
        print(f"  {key:18s} " + " ".join(f"{k} {n}" for k, n in by[key].most_common()))
    for r in [] if args.summary else things:
        if r["outcome"] in (
            "silent_substitute",
            "wrong_kind_warned",
            "dropped",
            "error",
        ):
            tail = r["stderr"][-100:] if r["outcome"] == "error" else ""
            print(f"  {r['outcome']}: {r['noun']!r} -> {r['categories']} {tail}")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(results, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
