#!/usr/bin/env bash
# Idempotent set-up for a fresh machine: everything scenewright needs that is not a crate.
#
#   scripts/setup.sh            MuJoCo 3.17.0's shared library (for building and running)
#   scripts/setup.sh --tests    also a Python venv with the official `mujoco` 4.0.0 bindings,
#                               used by the tests as an independent second loader
#
# Everything lands under .cache/ in the repository (git-ignored); nothing is installed
# system-wide. Safe to run any number of times; it only downloads what is missing.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="$root/.cache"
mujoco_version="3.17.0"
check_version="4.0.0"
want_tests=0
for arg in "$@"; do
  case "$arg" in
    --tests) want_tests=1 ;;
    *) echo "setup.sh: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done

say() { echo "setup: $*" >&2; }

# --- MuJoCo shared library, taken from the PyPI wheel (the crate links it dynamically) ---
lib_dir="$cache/mujoco/lib"
if [ ! -f "$lib_dir/libmujoco.so.$mujoco_version" ] || [ ! -L "$lib_dir/libmujoco.so" ]; then
  say "fetching MuJoCo $mujoco_version (PyPI wheel) ..."
  wheels="$cache/wheels"
  mkdir -p "$wheels" "$lib_dir"
  python3 -m pip download --quiet --disable-pip-version-check --no-deps \
    --only-binary=:all: --python-version 3.11 --platform manylinux_2_28_x86_64 \
    "mujoco==$mujoco_version" -d "$wheels"
  wheel="$(ls "$wheels"/mujoco-"$mujoco_version"-*.whl | head -n 1)"
  tmp="$(mktemp -d "$cache/unpack.XXXXXX")"
  python3 - "$wheel" "$tmp" <<'PY'
import sys, zipfile
with zipfile.ZipFile(sys.argv[1]) as z:
    for name in z.namelist():
        if name.startswith("mujoco/libmujoco.so") or name.startswith("mujoco/include/"):
            z.extract(name, sys.argv[2])
PY
  cp "$tmp/mujoco/libmujoco.so.$mujoco_version" "$lib_dir/"
  rm -rf "$cache/mujoco/include"
  mv "$tmp/mujoco/include" "$cache/mujoco/include"
  rm -rf "$tmp"
  ln -sfn "libmujoco.so.$mujoco_version" "$lib_dir/libmujoco.so"
  say "MuJoCo $mujoco_version ready in $lib_dir"
fi

# --- Tests only: official Python bindings of another MuJoCo version, an independent check ---
if [ "$want_tests" = 1 ]; then
  venv="$cache/venv"
  if [ ! -x "$venv/bin/python" ] || ! "$venv/bin/python" -c "import mujoco, sys; sys.exit(mujoco.__version__ != '$check_version')" 2>/dev/null; then
    say "creating $venv with mujoco==$check_version ..."
    rm -rf "$venv"
    python3 -m venv "$venv"
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check "mujoco==$check_version"
    say "python mujoco $check_version ready"
  fi
fi
