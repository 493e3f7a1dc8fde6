#!/usr/bin/env bash
# README command 2: install what is missing, build, and run the whole test suite through
# CTest. GPU tests run on the Vulkan device (lavapipe in CI) with validation layers on.
#   --cpu-only   run only the CPU tests, deliberately (GPU tests are not run at all)
set -euo pipefail
cd "$(dirname "$0")/.."
labels=()
if [[ "${1:-}" == "--cpu-only" ]]; then
  labels=(-LE gpu)
  echo "test: CPU-only run requested: GPU tests excluded"
fi
scripts/deps.sh
scripts/build.sh
cd "${BUILD_DIR:-build}"
ctest --output-on-failure -j "$(nproc)" "${labels[@]}"
