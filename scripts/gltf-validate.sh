#!/usr/bin/env bash
# Validates .glb/.gltf files with the Khronos glTF validator (the npm package gltf-validator,
# pinned below), installing it on first use into a folder under the build directory; later runs
# find it there and start at once. Used by the CTest test "gltf: ..." (tests/CMakeLists.txt).
#
#   scripts/gltf-validate.sh [--strict] FILE...
#     --strict              warnings fail too (errors always do)
#   TESSERA_NODE_TOOLS=DIR  where the validator lives (default: build/node_tools)
#   TESSERA_SKIP_NODE=1     without node/npm, skip (exit 77, CTest's "skipped") instead of
#                           failing; only ever set deliberately
#
# node and npm come from Debian's nodejs and npm packages (scripts/deps.sh installs them when
# the commands are missing). The first run needs the npm registry.
set -euo pipefail
validator_version=2.0.0-dev.3.10
root=$(cd "$(dirname "$0")/.." && pwd)
tools=${TESSERA_NODE_TOOLS:-$root/build/node_tools}

if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  if [[ "${TESSERA_SKIP_NODE:-}" == 1 ]]; then
    echo "gltf-validate: SKIPPED: node/npm not found and TESSERA_SKIP_NODE=1"
    exit 77
  fi
  echo "gltf-validate: node and npm are required to run the Khronos glTF validator, and" \
       "$(command -v node >/dev/null && echo npm || echo node) is not installed." \
       "Install them with scripts/deps.sh (Debian packages nodejs npm), or set" \
       "TESSERA_SKIP_NODE=1 to skip this check deliberately." >&2
  exit 1
fi

installed_version() {
  node -e "process.stdout.write(require(process.argv[1]).version)" \
    "$tools/node_modules/gltf-validator/package.json" 2>/dev/null || true
}

if [[ "$(installed_version)" != "$validator_version" ]]; then
  mkdir -p "$tools"
  # One installer at a time (parallel ctest, two build dirs sharing TESSERA_NODE_TOOLS).
  exec 9>"$tools/.install.lock"
  flock 9
  if [[ "$(installed_version)" != "$validator_version" ]]; then
    echo "gltf-validate: installing gltf-validator@$validator_version into $tools"
    if ! npm install --prefix "$tools" --no-save --no-package-lock --no-audit --no-fund \
         --loglevel=error "gltf-validator@$validator_version" >&2; then
      echo "gltf-validate: npm could not install gltf-validator@$validator_version" \
           "(is the npm registry reachable?)" >&2
      exit 1
    fi
  fi
  flock -u 9
fi

exec node "$root/tests/gltf_validate.mjs" --validator "$tools/node_modules/gltf-validator" "$@"
