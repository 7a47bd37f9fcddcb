"""Which nouns of the public object lists (bench/vocab/public_lists/*.txt) the catalog covers.

A noun is read as the list spells it: underscores and hyphens as spaces, a YCB id prefix
dropped, "a/b" as two alternatives, a plural also tried singular. It is

- **named** when it (or an alternative) is one of a category's names: its display name,
  registry name or a synonym (`scenewright assets list --json`), plurals read singular on
  both sides;
- **a kind** when its head (last two words, else last word) is such a name: "tomato soup
  can" is a kind of can, and the open-vocabulary route makes it as one;
- **out of scope** when out_of_scope.txt lists it (living things, road/air/water vehicles,
  street furniture and scenery: not things a scene of a room holds, see README.md);
- **uncovered** otherwise.

    python3 bench/vocab/public_lists/coverage.py --bin target/debug/scenewright [--uncovered LIST]

Standard library only.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
LISTS = ["coco", "objects365", "ycb", "lvis_frequent", "lvis_common", "lvis_rare", "robocasa", "shapenet", "behavior"]


def norm(s: str) -> str:
    s = re.sub(r"\([^)]*\)", " ", s)
    s = re.sub(r"^\d+(-[a-z])?_", "", s.strip())
    s = s.replace("_", " ").replace("-", " ").lower()
    return re.sub(r"\s+", " ", re.sub(r"[^a-z0-9' ]", " ", s)).strip()


def singulars(w: str) -> list[str]:
    out = [w]
    if w.endswith("ies") and len(w) > 4:
        out.append(w[:-3] + "y")
    if w.endswith(("ches", "shes", "xes", "sses", "oes")):
        out.append(w[:-2])
    if w.endswith("s") and not w.endswith("ss"):
        out.append(w[:-1])
    return out


def forms(noun: str) -> list[str]:
    """The noun's alternatives, each as written and with its last word singular."""
    out = []
    for alt in noun.split("/"):
        a = norm(alt)
        if not a:
            continue
        words = a.split()
        for last in singulars(words[-1]):
            out.append(" ".join(words[:-1] + [last]))
    return out


def read_list(name: str) -> list[str]:
    with open(os.path.join(HERE, name + ".txt"), encoding="utf-8") as f:
        return [line.rstrip("\n") for line in f if line.strip() and not line.startswith("#")]


def out_of_scope() -> dict[str, str]:
    out: dict[str, str] = {}
    with open(os.path.join(HERE, "out_of_scope.txt"), encoding="utf-8") as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                noun, why = line.rstrip("\n").split("\t")
                out[norm(noun)] = why
    return out


def catalog_names(binary: str) -> set[str]:
    env = dict(os.environ)
    env.setdefault("LD_LIBRARY_PATH", "/work/main/.cache/mujoco/lib")
    cats = json.loads(subprocess.run([binary, "assets", "list", "--json"], capture_output=True, text=True,
                                     check=True, env=env).stdout)
    names: set[str] = set()
    for c in cats:
        for n in [c["name"], c["display"], *c.get("synonyms", [])]:
            # A plural name ("earphones") names the singular too, as the planner reads it.
            names.update(forms(n))
    return names


def classify(noun: str, names: set[str], oos: dict[str, str]) -> str:
    fs = forms(noun)
    if any(f in oos for f in fs) or norm(noun) in oos:
        return "out of scope"
    if any(f in names for f in fs):
        return "named"
    for f in fs:
        w = f.split()
        for n in (2, 1):
            if len(w) > n and " ".join(w[-n:]) in names:
                return "a kind"
    return "uncovered"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", default=os.path.join(HERE, "..", "..", "..", "target", "debug", "scenewright"))
    ap.add_argument("--uncovered", help="print the uncovered nouns of this list")
    args = ap.parse_args()
    names = catalog_names(args.bin)
    oos = out_of_scope()
    print(f"catalog names (display, registry, synonyms): {len(names)}")
    print(f"{'list':<14} {'nouns':>5} {'out of scope':>12} {'in scope':>8} {'named':>6} {'a kind':>6} "
          f"{'uncovered':>9} {'covered':>8}")
    for name in LISTS:
        nouns = read_list(name)
        got = [classify(n, names, oos) for n in nouns]
        k = {c: got.count(c) for c in ("out of scope", "named", "a kind", "uncovered")}
        scope = len(nouns) - k["out of scope"]
        cov = k["named"] + k["a kind"]
        print(f"{name:<14} {len(nouns):>5} {k['out of scope']:>12} {scope:>8} {k['named']:>6} {k['a kind']:>6} "
              f"{k['uncovered']:>9} {100.0 * cov / max(scope, 1):>7.1f}%")
        if args.uncovered == name:
            for n, c in zip(nouns, got):
                if c == "uncovered":
                    print("   ", n)
    return 0


if __name__ == "__main__":
    sys.exit(main())
