#!/usr/bin/env bash
# Installs the Debian 12 packages Tessera needs, only those missing (idempotent).
# Run as root, or with sudo available. The list and the reasons: third_party/DEPENDENCIES.md.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libvulkan-dev libvulkan1 libvulkan-volk-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-tools spirv-tools
  libglm-dev libeigen3-dev catch2 libcli11-dev nlohmann-json3-dev libstb-dev robin-map-dev
  libosd-dev
  # tessera view (host/viewer/): the window, and a virtual X server and X input for its tests
  libglfw3-dev xvfb xdotool
  # the Python module (python/, TESSERA_BUILD_PYTHON) and its test
  pybind11-dev python3-dev python3-numpy
  # the sanitizer and fuzz build of scripts/test.sh: clang, and libFuzzer's runtime
  clang libclang-rt-14-dev
  # bench/: the Open CASCADE peer (bench_occt), JSON merging and the plot of scripts/bench.sh
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-visualization-dev jq gnuplot-nox
  # host/cad/ (tessera_cad): the STEP and IGES readers; its tests read FreeCAD's IDF library
  libocct-data-exchange-dev freecad-common
  # bench/bench_reduction: SISL's curve data reduction (s1940), the peer of the reduction
  libsisl-dev
)
# node and npm run the Khronos glTF validator in the tests (scripts/gltf-validate.sh). Debian's
# nodejs and npm only when the commands are missing: a Node.js installed another way (its own
# nodejs package bundles npm and conflicts with Debian's) is used as it is.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
if [[ ${#missing[@]} -eq 0 ]]; then
  echo "deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "deps: installing ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  sudo=()
elif command -v sudo >/dev/null; then
  sudo=(sudo)
else
  echo "deps: missing packages and not root: apt-get install ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
