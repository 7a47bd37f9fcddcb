#!/usr/bin/env bash
# The Python package as a new user meets it (issue 14's target: under 2 minutes): a fresh
# venv, `pip install ./python` (mujoco and numpy from PyPI, or pip's cache), then generate a
# scene and load it at its home keyframe. Uses the built binary (SCENEWRIGHT_BIN, else
# target/release/scenewright): the checkout's ./scenewright launcher rebuilds when sources
# changed, which is not what a new user of an installed binary waits for.
# Time it with: farm-bench -n 3 --timeout 600 -- bash bench/python/fresh_venv.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
export SCENEWRIGHT_BIN="${SCENEWRIGHT_BIN:-$root/target/release/scenewright}"
[ -x "$SCENEWRIGHT_BIN" ] || { echo "no binary at $SCENEWRIGHT_BIN: cargo build --release -p sw_cli" >&2; exit 2; }
tmp="$(mktemp -d /tmp/sw-fresh-venv.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
t0=$(date +%s.%N)
python3 -m venv "$tmp/venv"
"$tmp/venv/bin/python" -m pip install --quiet --disable-pip-version-check "$root/python"
echo "venv + pip install ./python: $(echo "$(date +%s.%N) - $t0" | bc) s"
cd "$tmp"
"$tmp/venv/bin/python" - <<'PY'
import time
import scenewright

t0 = time.perf_counter()
pkg = scenewright.generate("a lab with a UR5e on a workbench and three bins on the bench", seed=1, out="package")
model, data = pkg.load()
assert pkg.verified and model.nu == 6 and data.qpos.shape == (model.nq,)
print(f"generated and loaded {pkg.path} ({model.nbody} bodies) in {time.perf_counter() - t0:.2f} s")
PY
