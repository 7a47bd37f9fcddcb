#!/usr/bin/env bash
# Opt-in: LeRobot 0.6.1 itself loads a dataset `scenewright demos` made (issue 23). Needs
# `scripts/setup.sh --lerobot` (PyTorch, several GB) and a built binary (SCENEWRIGHT_BIN or
# target/debug/scenewright).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${SCENEWRIGHT_BIN:-$root/target/debug/scenewright}"
py="$root/.cache/lerobot-venv/bin/python"
[ -x "$py" ] || { echo "test_lerobot: run scripts/setup.sh --lerobot first" >&2; exit 2; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
"$bin" demos --prompt "a Panda on a table that puts the red cube in the bowl" --episodes 3 \
  --cameras front,wrist --image-size 128x96 --out "$out/demos" --jobs 2
"$py" "$root/python/tests_lerobot/check_lerobot.py" "$out/demos"
