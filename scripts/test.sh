#!/usr/bin/env bash
# The project's test command (README, and .ci/run): sets up what the tests need, then
# checks formatting and lints and runs every test. Every scene a test generates is
# compiled and settled in MuJoCo 3.17 in-process, and the end-to-end tests also load
# packages with the official Python bindings of MuJoCo 4.0 as an independent check.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/setup.sh --tests
cargo fmt --all -- --check
cargo clippy --workspace --all-targets --locked -- -D warnings
cargo test --workspace --locked "$@"

# --- The web app (web/, issue 13): type-check and lint its TypeScript (setup.sh --tests
# installed its npm packages and built it), load every robot's and every suite prompt's
# package in the browser's MuJoCo (the WebAssembly build, 3.14), then the end-to-end test
# in headless Chromium against the binary the tests just built. ---
cargo build --locked -p sw_cli
(
  cd web
  npm run --silent typecheck
  npm run --silent lint
  SCENEWRIGHT_BIN="$root/target/debug/scenewright" node tests/wasm-packages.mjs
  SCENEWRIGHT_BIN="$root/target/debug/scenewright" SCREENSHOTS=0 node tests/e2e.mjs
)

# --- The Python package (python/, issue 14): ruff, mypy, then pytest against the binary the
# tests built (setup.sh --tests installed it into .cache/py-venv from ./python). MJX runs
# on a small sample here (its JIT compile on CPU is slow); the whole bench suite runs in
# the benchmark (bench/gpu/targets.py). About 3 minutes. ---
cargo build --locked -p sw_cli
(
  cd python
  ../.cache/py-venv/bin/ruff check .
  ../.cache/py-venv/bin/ruff format --check .
  ../.cache/py-venv/bin/mypy
  SCENEWRIGHT_BIN="$root/target/debug/scenewright" ../.cache/py-venv/bin/python -m pytest -q tests
)
