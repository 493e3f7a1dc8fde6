#!/usr/bin/env bash
# The hardening step of scripts/test.sh (docs/hardening.md), runnable alone: builds Tessera
# with clang, AddressSanitizer + UndefinedBehaviorSanitizer and the libFuzzer targets into
# ${SANITIZE_BUILD_DIR:-build-sanitize}, runs the CPU tests there (any sanitizer report fails
# the test that triggered it), then every fuzz target for ${TESSERA_FUZZ_SECONDS:-5} s.
# The GPU tests run too (ASan + UBSan, LeakSanitizer off: see below and docs/hardening.md).
#   --cpu-only   leave the GPU tests out, deliberately (scripts/test.sh --cpu-only passes it on)
# Without clang it FAILS, unless TESSERA_SKIP_FUZZ=1: then GCC builds the sanitizer suite and
# no fuzz target runs.
set -euo pipefail
cd "$(dirname "$0")/.."
gpu=1
for arg in "$@"; do
  case "$arg" in
    --cpu-only) gpu=0; echo "sanitize: --cpu-only: GPU tests not run under the sanitizers" ;;
    *) echo "sanitize: unknown option '$arg' (--cpu-only)" >&2; exit 2 ;;
  esac
done
build_dir=${SANITIZE_BUILD_DIR:-build-sanitize}
config=(-DTESSERA_SANITIZE=ON -DTESSERA_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo)
if command -v clang++ >/dev/null; then
  # The fuzz targets' coverage feedback stays in their own code (TESSERA_FUZZ_COVERAGE=OFF):
  # in the whole library its per-compare hooks slowed every sanitizer test 1.3-2x. The long
  # campaigns build with it (scripts/fuzz-campaign.sh). Line tables are all a report needs
  # (file:line in every frame, inlined ones too). Together: build 577 s -> 369 s on 2 cores.
  config+=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DTESSERA_FUZZ=ON
           -DTESSERA_FUZZ_COVERAGE=OFF -DTESSERA_FUZZ_SECONDS="${TESSERA_FUZZ_SECONDS:-5}"
           "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG"
           "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG")
  fuzz=1
elif [[ "${TESSERA_SKIP_FUZZ:-0}" == 1 ]]; then
  echo "sanitize: no clang++; TESSERA_SKIP_FUZZ=1: GCC sanitizer build, fuzz targets not run"
  fuzz=0
else
  echo "sanitize: clang++ not found: run scripts/deps.sh (or TESSERA_SKIP_FUZZ=1)" >&2
  exit 1
fi
start=$SECONDS
cmake -S . -B "$build_dir" "${config[@]}" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
echo "sanitize: build $((SECONDS - start)) s"

# Leaks inside the Vulkan loader and driver are theirs, not ours: tests/lsan.supp lists each.
export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0
# The statistical sweeps (never under-divides, rule T's random patches, fp32 against double)
# run a share of their samples here (tests/sweep_share.h): the Release run has the full
# statistics; the sanitizers look for memory and UB errors (docs/hardening.md).
export TESSERA_TEST_SWEEP_SHARE=0.25
cd "$build_dir"
start=$SECONDS
# Paper 002's division table (the Catch2 case and the `tessera divisions` CLI case) runs the
# division methods the never-under-divides sweeps above also run, over 20 views: 80 s of CPU
# under ASan for no path of its own, so it runs in the Release suite only; so does the per-patch
# N_min report (tests/test_tolerance_patch_share.cpp), rule T's tree and the curvature
# integral that other cases here run already.
ctest --output-on-failure -j "$(nproc)" -L cpu -LE fuzz \
  -E "Division table: |divisions prints the comparison table|each patch's share of N_min"
echo "sanitize: CPU tests $((SECONDS - start)) s"
if [[ $gpu == 1 ]]; then
  # The Vulkan loader dlcloses the driver and the validation layer before LeakSanitizer's
  # check at exit, so their allocations show as "<unknown module>" frames that no suppression
  # can name. Leaks of our own code are what the CPU tests above check; here ASan and UBSan
  # look for memory errors and undefined behaviour on every GPU path.
  start=$SECONDS
  ASAN_OPTIONS=${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0} \
    ctest --output-on-failure -j "$(nproc)" -L gpu
  echo "sanitize: GPU tests (ASan + UBSan, no LSan) $((SECONDS - start)) s"
fi
if [[ $fuzz == 1 ]]; then
  start=$SECONDS
  # Each target prints "fuzz: N executions of <target> ..."; -V shows those lines.
  ctest --output-on-failure -j "$(nproc)" -L fuzz -V | grep -E "fuzz: |tests passed|Failed|\*\*\*"
  echo "sanitize: fuzzing $((SECONDS - start)) s"
fi
