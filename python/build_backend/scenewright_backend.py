"""The build backend of the `scenewright` Python package (PEP 517 and PEP 660).

`pip install ./python` must work offline from a checkout, so the package builds with this
in-tree backend and needs nothing from an index: `[build-system] requires = []`. It
packs `scenewright/` (and nothing else in `python/`: the CAD worker and `scenewright_cad`
are the asset forge's and run from the checkout) into a pure-Python wheel, and records
where the checkout is, so that the installed package finds the `scenewright` binary of
the checkout it came from (see `scenewright._engine`).
"""

from __future__ import annotations

import base64
import hashlib
import io
import os
import tarfile
import zipfile
from pathlib import Path

import tomllib

_HERE = Path(__file__).resolve().parent
_PROJECT = _HERE.parent
_PACKAGE = "scenewright"
# Fixed timestamp for reproducible archives (zip cannot store dates before 1980).
_EPOCH = (1980, 1, 1, 0, 0, 0)


def _project() -> dict:
    with open(_PROJECT / "pyproject.toml", "rb") as f:
        return tomllib.load(f)["project"]


def _dist_name() -> str:
    return _project()["name"].replace("-", "_")


def _version() -> str:
    return str(_project()["version"])


def _metadata() -> str:
    p = _project()
    lines = [
        "Metadata-Version: 2.1",
        f"Name: {p['name']}",
        f"Version: {p['version']}",
        f"Summary: {p.get('description', '')}",
        f"Requires-Python: {p.get('requires-python', '>=3.10')}",
    ]
    if "license" in p and isinstance(p["license"], dict) and "text" in p["license"]:
        lines.append(f"License: {p['license']['text']}")
    for dep in p.get("dependencies", []):
        lines.append(f"Requires-Dist: {dep}")
    for extra, deps in sorted(p.get("optional-dependencies", {}).items()):
        lines.append(f"Provides-Extra: {extra}")
        for dep in deps:
            lines.append(f'Requires-Dist: {dep}; extra == "{extra}"')
    readme = _PROJECT / "README.md"
    body = readme.read_text(encoding="utf-8") if readme.is_file() else ""
    if body:
        lines.append("Description-Content-Type: text/markdown")
    return "\n".join(lines) + "\n\n" + body


def _wheel_info() -> str:
    return "Wheel-Version: 1.0\nGenerator: scenewright_backend\nRoot-Is-Purelib: true\nTag: py3-none-any\n"


def _package_files() -> list[tuple[str, bytes]]:
    """Every file of the package, as (archive path, bytes), sorted; caches are skipped."""
    out: list[tuple[str, bytes]] = []
    root = _PROJECT / _PACKAGE
    for path in sorted(root.rglob("*")):
        if path.is_dir() or "__pycache__" in path.parts or path.suffix in {".pyc", ".pyo"}:
            continue
        if path.name == "_checkout.json":
            continue
        out.append((path.relative_to(_PROJECT).as_posix(), path.read_bytes()))
    return out


def _checkout_record() -> tuple[str, bytes] | None:
    """Where the checkout is, when the package is built from one (its launcher exists)."""
    root = _PROJECT.parent
    if (root / "scenewright").is_file() and (root / "Cargo.toml").is_file():
        text = '{"root": ' + _json_string(str(root)) + "}\n"
        return (f"{_PACKAGE}/_checkout.json", text.encode())
    return None


def _json_string(s: str) -> str:
    import json

    return json.dumps(s)


def _record_line(name: str, data: bytes) -> str:
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def _write_wheel(wheel_directory: str, files: list[tuple[str, bytes]]) -> str:
    dist, version = _dist_name(), _version()
    info = f"{dist}-{version}.dist-info"
    files = [
        *files,
        (f"{info}/METADATA", _metadata().encode()),
        (f"{info}/WHEEL", _wheel_info().encode()),
        (f"{info}/top_level.txt", f"{_PACKAGE}\n".encode()),
    ]
    record = "\n".join(_record_line(n, d) for n, d in files) + f"\n{info}/RECORD,,\n"
    files.append((f"{info}/RECORD", record.encode()))
    name = f"{dist}-{version}-py3-none-any.whl"
    os.makedirs(wheel_directory, exist_ok=True)
    target = os.path.join(wheel_directory, name)
    with zipfile.ZipFile(target, "w", compression=zipfile.ZIP_DEFLATED) as z:
        for arc, data in files:
            zi = zipfile.ZipInfo(arc, date_time=_EPOCH)
            zi.external_attr = 0o644 << 16
            zi.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(zi, data)
    return name


# ---- PEP 517 hooks


def get_requires_for_build_wheel(config_settings: dict | None = None) -> list[str]:
    return []


def get_requires_for_build_sdist(config_settings: dict | None = None) -> list[str]:
    return []


def get_requires_for_build_editable(config_settings: dict | None = None) -> list[str]:
    return []


def build_wheel(
    wheel_directory: str, config_settings: dict | None = None, metadata_directory: str | None = None
) -> str:
    files = _package_files()
    checkout = _checkout_record()
    if checkout is not None:
        files.append(checkout)
    return _write_wheel(wheel_directory, files)


def build_editable(
    wheel_directory: str, config_settings: dict | None = None, metadata_directory: str | None = None
) -> str:
    """A wheel holding a `.pth` file that puts the package's source directory on the path.

    The package then finds the checkout from its own location; `python/` also holds the
    CAD worker's modules, which become importable too (they import nothing on import).
    """
    pth = (f"{_dist_name()}.pth", (str(_PROJECT) + "\n").encode())
    return _write_wheel(wheel_directory, [pth])


def build_sdist(sdist_directory: str, config_settings: dict | None = None) -> str:
    dist, version = _dist_name(), _version()
    base = f"{dist}-{version}"
    name = f"{base}.tar.gz"
    os.makedirs(sdist_directory, exist_ok=True)
    members = [
        *_package_files(),
        ("pyproject.toml", (_PROJECT / "pyproject.toml").read_bytes()),
        ("build_backend/scenewright_backend.py", Path(__file__).read_bytes()),
        ("PKG-INFO", _metadata().encode()),
    ]
    with tarfile.open(os.path.join(sdist_directory, name), "w:gz") as tar:
        for arc, data in members:
            ti = tarfile.TarInfo(f"{base}/{arc}")
            ti.size = len(data)
            ti.mode = 0o644
            tar.addfile(ti, io.BytesIO(data))
    return name
