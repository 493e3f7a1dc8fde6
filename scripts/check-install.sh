#!/usr/bin/env bash
# Installs Tessera from ${BUILD_DIR:-build} into a temporary prefix, builds examples/consumer
# against the installed copy twice (CMake find_package(tessera) and pkg-config), runs both on
# data/teapot.bpt and checks that they print the same triangle count. Also checks that the
# exported interface carries none of Tessera's build defines and that a consumer can include
# <tessera/tessera.h> beside <vulkan/vulkan.h> and glm with their normal definitions, that
# examples/engine (an engine lending its own Vulkan device) builds and runs against it, and
# that add_subdirectory leaves the caller's build type alone and configures no tests. The
# commands: bin/tessera, and with the cad component bin/tessera-cad, which the installed
# tessera (no Open CASCADE linked) hands a STEP model to. The Python package where it is built:
# tessera/_core (no Open CASCADE) and with the cad component tessera/_cad.
#   --cpu-only   build the engine example but do not run it (it needs a Vulkan device)
set -euo pipefail
cd "$(dirname "$0")/.."
run_engine=1
for arg in "$@"; do
  case "$arg" in
    --cpu-only) run_engine=0 ;;
    *) echo "check-install: unknown option '$arg' (--cpu-only)" >&2; exit 2 ;;
  esac
done
build_dir=${BUILD_DIR:-build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build_dir" --prefix "$prefix" >/dev/null
config=$(find "$prefix" -name tesseraConfig.cmake)
pc=$(find "$prefix" -name tessera.pc)
[[ -n $config && -n $pc && -f $prefix/include/tessera/tessera.h ]] || {
  echo "check-install: the install lacks tesseraConfig.cmake, tessera.pc or the headers" >&2
  exit 1
}
if grep -rnE "VK_NO_PROTOTYPES|GLM_FORCE|GLM_ENABLE|ffp-contract|TESSERA_VULKAN_BACKEND|/host" \
    "$(dirname "$config")" "$pc"; then
  echo "check-install: a build-internal setting leaks into the exported interface (above)" >&2
  exit 1
fi

# 1. CMake: find_package(tessera) and tessera::tessera.
cmake -S examples/consumer -B "$work/cmake-build" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/cmake-build" >/dev/null
# 2. pkg-config.
export PKG_CONFIG_PATH=$(dirname "$pc")
c++ -std=c++17 -O2 examples/consumer/main.cpp -o "$work/consumer-pc" \
  $(pkg-config --cflags --libs tessera)

# The public headers next to Vulkan's and glm's, as an engine includes them: prototypes and
# glm's colour swizzles must be there. Linked with the loader too and run: the engine's own
# Vulkan call reaches the loader, not a name of the archive's volk (tests/engine/).
cat > "$work/beside.cpp" <<'CPP'
#include <tessera/tessera.h>
#include <tessera/vulkan.h>
#include <vulkan/vulkan.h>
#include <glm/glm.hpp>
#include <cstdio>
PFN_vkEnumerateInstanceVersion enumerate = &vkEnumerateInstanceVersion;
float red(const glm::vec4& colour) { return colour.r; }
int main() {
  uint32_t version = 0;
  if (enumerate(&version) != VK_SUCCESS) return 1;
  auto lend = &tessera::tessellatorOnDevice;  // the interop API links from the archive
  std::printf("check-install: an engine's own vkEnumerateInstanceVersion: %u.%u\n",
              VK_VERSION_MAJOR(version), VK_VERSION_MINOR(version));
  return lend != nullptr && red(glm::vec4(1.0f)) == 1.0f ? 0 : 1;
}
CPP
c++ -std=c++17 -O1 "$work/beside.cpp" -o "$work/beside" $(pkg-config --cflags --libs tessera) -lvulkan
"$work/beside"
# The engine example against the installed copy: its own instance and device, lent to Tessera
# (tessera/vulkan.h), a real-time frame recorded into its own buffer (docs/api.md).
cmake -S examples/engine -B "$work/engine-build" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/engine-build" >/dev/null
if [[ $run_engine == 1 ]]; then
  engine_out=$("$work/engine-build/engine" data/teapot.bpt) || {
    echo "check-install: the engine example failed" >&2
    exit 1
  }
  echo "check-install: ${engine_out%%$'\n'*}"
else
  echo "check-install: --cpu-only: the engine example built, not run (it needs a Vulkan device)"
fi

# As a subproject: the caller's build type stands (here none), and the tests, with spirv-val,
# are not configured.
mkdir -p "$work/parent"
cat > "$work/parent/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.22)
project(parent LANGUAGES C CXX)
add_subdirectory("$PWD" tessera)
if(NOT TARGET tessera::tessera OR TARGET tessera_tests OR TARGET tessera)
  message(FATAL_ERROR "as a subproject: want tessera::tessera and no tests or CLI")
endif()
CMAKE
cmake -S "$work/parent" -B "$work/parent/build" >/dev/null
if grep -E "^(CMAKE_BUILD_TYPE:STRING=.+|SPIRV_VAL:)" "$work/parent/build/CMakeCache.txt"; then
  echo "check-install: as a subproject Tessera set a build type or looked for spirv-val" >&2
  exit 1
fi

# Runs the CMake-built and pkg-config-built consumer ($1, $2) on $3, checks that both print the
# same triangle count, > 0, and leaves it in $agreed.
same_triangles() {
  local counts=() consumer out
  for consumer in "$1" "$2"; do
    out=$("$consumer" "$3")
    echo "check-install: $(basename "$consumer"): ${out%%$'\n'*}"
    [[ $out =~ :\ ([0-9]+)\ triangles ]] || { echo "check-install: no triangle count in: $out" >&2; exit 1; }
    counts+=("${BASH_REMATCH[1]}")
  done
  if [[ ${counts[0]} -eq 0 || ${counts[0]} != "${counts[1]}" ]]; then
    echo "check-install: the two builds disagree or made nothing on $3: ${counts[*]}" >&2
    exit 1
  fi
  agreed=${counts[0]}
}

same_triangles "$work/cmake-build/consumer" "$work/consumer-pc" data/teapot.bpt
echo "check-install: OK (installed to a prefix, find_package and pkg-config builds agree: $agreed triangles)"
# The command, where it is built (bin/tessera-cad beside it: below, with the cad component).
if [[ -x $build_dir/tessera && ! -x $prefix/bin/tessera ]]; then
  echo "check-install: the build has tessera but the install has no bin/tessera" >&2
  exit 1
fi

# The CAD component, where Tessera was built with Open CASCADE: find_package(tessera COMPONENTS
# cad) and pkg-config tessera-cad, on a model of FreeCAD's IDF library (scripts/deps.sh).
# Without the component, its header is not installed either.
cad_header=$prefix/include/tessera/cad.h
if [[ -f $(dirname "$pc")/tessera-cad.pc ]]; then
  [[ -f $cad_header ]] || { echo "check-install: tessera-cad.pc but no $cad_header" >&2; exit 1; }
  model=/usr/share/freecad/Mod/Idf/Idflibs/SOT23.stp
  cmake -S examples/cad_consumer -B "$work/cad-build" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
  cmake --build "$work/cad-build" >/dev/null
  c++ -std=c++17 -O2 examples/cad_consumer/main.cpp -o "$work/cad-consumer-pc" \
    $(pkg-config --cflags --libs tessera-cad)
  same_triangles "$work/cad-build/cad_consumer" "$work/cad-consumer-pc" "$model"
  cad_triangles=$agreed
  echo "check-install: OK (the cad component: $agreed triangles on $(basename "$model"))"
  # The installed tessera links no Open CASCADE and hands the model to the installed
  # tessera-cad beside it (host/cli/cad_job.h): the same mesh as the library's.
  if [[ -x $build_dir/tessera-cad ]]; then
    [[ -x $prefix/bin/tessera-cad ]] || { echo "check-install: no bin/tessera-cad" >&2; exit 1; }
    if readelf -d "$prefix/bin/tessera" | grep -E "NEEDED.*lib(TK|tbb)"; then
      echo "check-install: the installed tessera links Open CASCADE (above)" >&2
      exit 1
    fi
    out=$("$prefix/bin/tessera" tessellate "$model" --backend cpu -o "$work/model.obj")
    [[ $out == *"triangles $agreed,"* && -s $work/model.obj ]] || {
      echo "check-install: bin/tessera on $model, through bin/tessera-cad, not $agreed triangles: $out" >&2
      exit 1
    }
    echo "check-install: OK (bin/tessera ran $(basename "$model") in bin/tessera-cad: $agreed triangles)"
  fi
fi
if [[ ! -f $(dirname "$pc")/tessera-cad.pc && -f $cad_header ]]; then
  echo "check-install: $cad_header installed without the cad component" >&2
  exit 1
fi

# The Python package (python/), where it is built: imported from the prefix, `import tessera`
# and a .bpt run map no Open CASCADE; with the cad component, tessera/_cad is installed and
# tessellate_cad (which imports it) gives the C++ consumers' triangle count.
if compgen -G "$build_dir/python/tessera/_core*.so" >/dev/null; then
  init=$(find "$prefix" -path "*/tessera/__init__.py")
  [[ -n $init ]] && compgen -G "$(dirname "$init")/_core*.so" >/dev/null || {
    echo "check-install: the build has the Python package but the install lacks tessera/__init__.py or _core" >&2
    exit 1
  }
  package=$(dirname "$init")
  if compgen -G "$build_dir/python/tessera/_cad*.so" >/dev/null; then
    compgen -G "$package/_cad*.so" >/dev/null || { echo "check-install: no $package/_cad*.so" >&2; exit 1; }
  fi
  if readelf -d "$package"/_core*.so | grep -E "NEEDED.*lib(TK|tbb)"; then
    echo "check-install: the installed tessera._core links Open CASCADE (above)" >&2
    exit 1
  fi
  python=$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' "$build_dir/CMakeCache.txt")
  teapot=$PWD/data/teapot.bpt  # run from $work: no folder named tessera beside the script
  out=$(cd "$work" && PYTHONPATH=$(dirname "$package") "${python:-python3}" - "$teapot" \
    "$package" ${cad_triangles:+"$model"} <<'PY'
import re, sys
import tessera
assert tessera.__file__.startswith(sys.argv[2]), tessera.__file__
t = tessera.Tessellator(device="cpu")
print("teapot", t.tessellate(sys.argv[1]).indices.shape[0])
occt = re.findall(r"/lib(?:TK|tbb)\S*", open("/proc/self/maps").read())
assert not occt, "import tessera and a .bpt run loaded " + " ".join(sorted(set(occt)))
if len(sys.argv) > 3:
    print("cad", t.tessellate_cad(sys.argv[3]).mesh.indices.shape[0])
PY
  ) || { echo "check-install: the installed Python package failed: $out" >&2; exit 1; }
  [[ $out =~ teapot\ [1-9] ]] || { echo "check-install: python: no teapot mesh: $out" >&2; exit 1; }
  if [[ -n ${cad_triangles:-} && $out != *$'\n'"cad $cad_triangles" ]]; then
    echo "check-install: python tessellate_cad on $model, not $cad_triangles triangles: $out" >&2
    exit 1
  fi
  echo "check-install: OK (the Python package from the prefix: no Open CASCADE at import${cad_triangles:+, tessellate_cad $cad_triangles triangles})"
fi
