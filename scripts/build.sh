#!/usr/bin/env bash
# Configures and builds Tessera (Release) into ${BUILD_DIR:-build}. Extra arguments go to
# CMake's configure step, e.g. scripts/build.sh -DTESSERA_SANITIZE=ON.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} "$@" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
