#!/usr/bin/env bash
# Configures and builds Tessera (Release) into ${BUILD_DIR:-build}. Extra arguments go to
# CMake's configure step, e.g. scripts/build.sh -DTESSERA_SANITIZE=ON.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
# The Python module (python/) is built for Debian's python3, which python3-numpy and
# pybind11-dev serve, not for whichever python3 comes first on PATH (a pyenv one, say).
python_args=(-DTESSERA_BUILD_PYTHON=ON)
if [[ -x /usr/bin/python3 ]]; then python_args+=(-DPython3_EXECUTABLE=/usr/bin/python3); fi
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} "${python_args[@]}" "$@" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
