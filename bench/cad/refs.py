"""Builds the reference parts of a CAD suite and writes its references table.

For SUITE (standard_100, features …) it runs every section of SUITE.ref.py — one CadQuery
program per prompt, written by hand from the prompt's words — measures the exact solid
(OCCT's volume and tight bounding box), checks it against the closed formulas of
formulas_SUITE.py (written separately; the two routes must agree) and writes
SUITE.refs.tsv, which `scenewright bench cad` compares the synthesizer's parts with.
Nothing here reads or imports the synthesizer.

Run from the checkout root with the CadQuery venv:
    .cache/cad-venv/bin/python bench/cad/refs.py standard_100 features
Exit status 1 when a program fails or the two routes disagree.
"""

from __future__ import annotations

import importlib
import os
import sys
from typing import Any

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

# Extents: relative plus absolute slack; volumes relative.
EXTENT_TOL = 1e-3
EXTENT_SLACK = 0.01
VOLUME_TOL = 1e-3


def sections(path: str) -> dict[str, str]:
    """The programs of a .ref.py file by id ("_prelude" included)."""
    out: dict[str, str] = {}
    current: str | None = None
    lines: list[str] = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("# ref: "):
                if current is not None:
                    out[current] = "".join(lines)
                current = line[len("# ref: ") :].strip()
                lines = []
            elif current is not None:
                lines.append(line)
    if current is not None:
        out[current] = "".join(lines)
    return out


def build(prelude: str, code: str) -> Any:  # noqa: ANN401 - a CadQuery shape (cadquery has no types)
    """Runs one program and returns its shape."""
    import cadquery as cq

    scope: dict[str, Any] = {}
    exec(compile(prelude + "\n" + code, "<ref>", "exec"), scope)
    result = scope["result"]
    if isinstance(result, cq.Workplane):
        vals = [v for v in result.vals() if isinstance(v, cq.Shape)]
        return vals[0] if len(vals) == 1 else cq.Compound.makeCompound(vals)
    return result


def measure(shape: Any) -> tuple[list[float], float, int, bool]:  # noqa: ANN401 - a CadQuery shape
    """Tight extents, volume, number of solids and OCCT's validity of a shape."""
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib

    box = Bnd_Box()
    BRepBndLib.AddOptimal_s(shape.wrapped, box, False, False)
    x0, y0, z0, x1, y1, z1 = box.Get()
    return [x1 - x0, y1 - y0, z1 - z0], float(shape.Volume()), len(shape.Solids()), bool(shape.isValid())


def agree(got: list[float], want: tuple[float, float, float]) -> float:
    """The largest relative difference of the sorted extents."""
    g, w = sorted(got), sorted(want)
    return max(abs(a - b) / b if abs(a - b) > EXTENT_SLACK else 0.0 for a, b in zip(g, w, strict=True))


def run(suite: str) -> int:
    programs = sections(os.path.join(HERE, f"{suite}.ref.py"))
    prelude = programs.pop("_prelude", "")
    formulas: dict[str, tuple[tuple[float, float, float], float | None]] = {}
    if os.path.exists(os.path.join(HERE, f"formulas_{suite}.py")):
        formulas = importlib.import_module(f"formulas_{suite}").table()
    problems = 0
    rows = []
    worst_extent, worst_volume, checked = 0.0, 0.0, 0
    for ref_id, code in programs.items():
        try:
            shape = build(prelude, code)
            size, volume, solids, valid = measure(shape)
        except Exception as e:
            print(f"{ref_id}: the program failed: {type(e).__name__}: {e}")
            problems += 1
            continue
        if solids != 1 or not valid:
            print(f"{ref_id}: {solids} solids, valid {valid}")
            problems += 1
        formula = formulas.get(ref_id)
        if formula is not None:
            checked += 1
            fe = agree(size, formula[0])
            worst_extent = max(worst_extent, fe)
            if fe > EXTENT_TOL:
                print(f"{ref_id}: extents {[round(s, 4) for s in size]} vs formula {formula[0]}")
                problems += 1
            if formula[1] is not None:
                ve = abs(volume - formula[1]) / formula[1]
                worst_volume = max(worst_volume, ve)
                if ve > VOLUME_TOL:
                    print(f"{ref_id}: volume {volume:.3f} vs formula {formula[1]:.3f} ({100 * ve:.3f} %)")
                    problems += 1
        rows.append(f"{ref_id}\t{size[0]:.4f}\t{size[1]:.4f}\t{size[2]:.4f}\t{volume:.3f}\t-\n")
    missing = sorted(set(formulas) - set(programs))
    if missing:
        print(f"formulas without a program: {missing}")
        problems += 1
    out = os.path.join(HERE, f"{suite}.refs.tsv")
    with open(out, "w", encoding="utf-8") as f:
        f.write(
            f"# Reference extents and volumes of {suite}: the exact solids of {suite}.ref.py (one CadQuery\n"
            f"# program per prompt, written by hand from its words), checked against closed formulas\n"
            f"# (formulas_{suite}.py, where one is at hand) by bench/cad/refs.py, which wrote this file.\n"
            "# Columns: id<TAB>size_x_mm<TAB>size_y_mm<TAB>size_z_mm<TAB>volume_mm3<TAB>reference mesh (- none).\n"
        )
        f.writelines(rows)
    print(
        f"{suite}: {len(rows)} references, {checked} checked against formulas "
        f"(largest difference: extents {100 * worst_extent:.4f} %, volume {100 * worst_volume:.4f} %), "
        f"{problems} problem(s); wrote {os.path.relpath(out)}"
    )
    return problems


if __name__ == "__main__":
    suites = sys.argv[1:] or ["standard_100"]
    sys.exit(1 if sum(run(s) for s in suites) else 0)
