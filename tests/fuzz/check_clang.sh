#!/usr/bin/env bash
# CTest "fuzz: clang and libFuzzer are installed": the fuzz targets need clang and libFuzzer's
# runtime. Missing, this FAILS (scripts/deps.sh installs clang and libclang-rt-14-dev);
# TESSERA_SKIP_FUZZ=1 skips it deliberately (exit 77, reported as skipped).
set -euo pipefail
if [[ "${TESSERA_SKIP_FUZZ:-0}" == 1 ]]; then
  echo "fuzz: TESSERA_SKIP_FUZZ=1: fuzz targets deliberately not checked"
  exit 77
fi
if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ not found: apt-get install clang libclang-rt-14-dev (or TESSERA_SKIP_FUZZ=1)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%s\n' '#include <cstddef>' '#include <cstdint>' \
  'extern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }' >"$work/t.cpp"
if ! clang++ -fsanitize=fuzzer,address,undefined "$work/t.cpp" -o "$work/t" 2>"$work/err"; then
  cat "$work/err" >&2
  echo "fuzz: clang++ cannot link libFuzzer: apt-get install libclang-rt-14-dev (or TESSERA_SKIP_FUZZ=1)" >&2
  exit 1
fi
"$work/t" -runs=10 >/dev/null 2>&1
echo "fuzz: clang++ $(clang++ -dumpversion) links and runs a libFuzzer target"
