#!/usr/bin/env bash
# The project's test command (README, and .ci/run): sets up what the tests need, then
# checks formatting and lints and runs every test. Every scene a test generates is
# compiled and settled in MuJoCo 3.17 in-process, and the end-to-end tests also load
# packages with the official Python bindings of MuJoCo 4.0 as an independent check.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
scripts/setup.sh --tests
cargo fmt --all -- --check
cargo clippy --workspace --all-targets --locked -- -D warnings
cargo test --workspace --locked "$@"
