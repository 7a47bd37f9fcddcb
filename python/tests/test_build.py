"""The in-tree build backend: an offline wheel with the package only; the CAD worker that
shares python/ still runs from the checkout."""

from __future__ import annotations

import base64
import csv
import hashlib
import io
import subprocess
import sys
import zipfile
from pathlib import Path

from conftest import ROOT

PYTHON_DIR = ROOT / "python"


def test_wheel_builds_offline_with_the_package_only(tmp_path: Path) -> None:
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-index", "--no-deps", "-q", "-w", str(tmp_path), str(PYTHON_DIR)],
        check=True,
    )
    (wheel,) = tmp_path.glob("scenewright-*.whl")
    with zipfile.ZipFile(wheel) as z:
        names = z.namelist()
        assert all(n.startswith(("scenewright/", "scenewright-0.1.0.dist-info/")) for n in names), names
        assert "scenewright/py.typed" in names and "scenewright/env.py" in names
        assert not any("scenewright_cad" in n or "cad_worker" in n or "__pycache__" in n for n in names)
        # RECORD lists every other file with its real hash and size.
        record = z.read("scenewright-0.1.0.dist-info/RECORD").decode()
        rows = list(csv.reader(io.StringIO(record)))
        assert {r[0] for r in rows} == set(names)
        for name, digest, size in rows:
            if name.endswith("RECORD"):
                continue
            data = z.read(name)
            want = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            assert digest == f"sha256={want}" and int(size) == len(data), name
        meta = z.read("scenewright-0.1.0.dist-info/METADATA").decode()
        assert "Requires-Dist: mujoco>=3.14" in meta and 'Requires-Dist: gymnasium>=1.0; extra == "gym"' in meta


def test_the_cad_worker_still_starts_from_the_checkout() -> None:
    # The forge's runner starts it as `python -I -B cad_worker.py --root DIR`; with -I it
    # finds scenewright_cad next to itself (its own argument check answers). The sandbox
    # itself is tested by crates/sw_forge/tests/sandbox.rs.
    p = subprocess.run(
        [sys.executable, "-I", "-B", str(PYTHON_DIR / "cad_worker.py")], capture_output=True, text=True, check=False
    )
    assert p.returncode == 2 and "--root DIR is required" in p.stderr, p.stderr
    # The installed package brings only `scenewright` (isolated mode: no cwd on the path).
    probe = (
        "import importlib.util as u, sys; "
        "sys.exit(0 if u.find_spec('scenewright') and not u.find_spec('scenewright_cad') else 1)"
    )
    assert subprocess.run([sys.executable, "-I", "-c", probe], check=False).returncode == 0
