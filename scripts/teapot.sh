#!/usr/bin/env bash
# README command 1: install what is missing, build, and tessellate the bundled Utah teapot on
# the GPU path (Vulkan; lavapipe when there is no GPU), writing out/teapot.obj.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
mkdir -p out
"${BUILD_DIR:-build}"/tessera tessellate data/teapot.bpt --backend vulkan -o out/teapot.obj "$@"
