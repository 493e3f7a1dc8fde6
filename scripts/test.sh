#!/usr/bin/env bash
# README command 2: install what is missing, build, and run the whole test suite through
# CTest. GPU tests run on the Vulkan device (lavapipe in CI) with validation layers on. Then
# scripts/check-install.sh: install, build examples/consumer and examples/engine against the
# install, run them (the engine, which needs a Vulkan device, not in a --cpu-only run).
# Then the hardening step, scripts/sanitize.sh (docs/hardening.md): a clang build with
# AddressSanitizer, UndefinedBehaviorSanitizer and libFuzzer runs the CPU tests again and every
# fuzz target for a few seconds.
#   --cpu-only      run only the CPU tests, deliberately (GPU tests are not run at all)
#   --no-sanitize   skip the hardening step, deliberately (for quick local runs; CI runs it)
set -euo pipefail
cd "$(dirname "$0")/.."
labels=()
sanitize=1
for arg in "$@"; do
  case "$arg" in
    --cpu-only) labels=(-LE gpu); echo "test: CPU-only run requested: GPU tests excluded" ;;
    --no-sanitize) sanitize=0; echo "test: --no-sanitize: the sanitizer and fuzz step is skipped" ;;
    *) echo "test: unknown option '$arg' (--cpu-only, --no-sanitize)" >&2; exit 2 ;;
  esac
done
# Each stage prints its seconds ("test: ... N s"), so a CI log shows where the time went.
start=$SECONDS
scripts/deps.sh
echo "test: deps $((SECONDS - start)) s"
start=$SECONDS
scripts/build.sh
echo "test: build $((SECONDS - start)) s"
start=$SECONDS
(cd "${BUILD_DIR:-build}" && ctest --output-on-failure -j "$(nproc)" "${labels[@]}")
echo "test: tests $((SECONDS - start)) s"
# Which Vulkan device the GPU tests ran on (tests/test_gpu_device.cpp), once, in this log.
if [[ ${#labels[@]} -eq 0 ]]; then
  grep -a -m1 -o "Vulkan device of the GPU tests: .*" \
    "${BUILD_DIR:-build}/Testing/Temporary/LastTest.log" ||
    echo "test: the GPU tests' device line is missing from CTest's log" >&2
fi
# The library as a user takes it: install to a prefix, build examples/consumer against it with
# find_package and with pkg-config, run both.
start=$SECONDS
if [[ ${#labels[@]} -gt 0 ]]; then scripts/check-install.sh --cpu-only; else scripts/check-install.sh; fi
echo "test: install check $((SECONDS - start)) s"
if [[ $sanitize == 1 ]]; then
  if [[ ${#labels[@]} -gt 0 ]]; then scripts/sanitize.sh --cpu-only; else scripts/sanitize.sh; fi
fi
