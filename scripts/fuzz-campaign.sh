#!/usr/bin/env bash
# The long libFuzzer campaigns of docs/hardening.md ("Campaigns"), one target at a time on one
# core, each on a working corpus grown from its CTest seeds; not part of CI.
#   scripts/fuzz-campaign.sh [seconds per target = 1800] [targets... = all five]
# Builds the fuzz targets with ASan + UBSan and libFuzzer's coverage feedback in all of
# Tessera's code (TESSERA_FUZZ_COVERAGE=ON) into ${FUZZ_BUILD_DIR:-build-fuzz}: scripts/sanitize.sh's
# build leaves that coverage out of the library, for the CI's speed.
# Writes ${FUZZ_WORK:-fuzz-work}/<target>/{corpus/,log,crash-*} and appends one line per target
# to ${FUZZ_WORK:-fuzz-work}/summary.txt: start, end, exit code, executions, corpus, crashes.
set -uo pipefail
cd "$(dirname "$0")/.."
src=$PWD
build=${FUZZ_BUILD_DIR:-build-fuzz}
command -v clang++ >/dev/null || { echo "fuzz-campaign: clang++ not found (scripts/deps.sh)" >&2; exit 2; }
cmake -S . -B "$build" -DTESSERA_SANITIZE=ON -DTESSERA_FUZZ=ON -DTESSERA_FUZZ_COVERAGE=ON \
  -DTESSERA_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ >/dev/null || exit 2
cmake --build "$build" -j "$(nproc)" --target tessera_fuzzers || exit 2
fuzzers=$build/tests/fuzz
work=${FUZZ_WORK:-fuzz-work}
seconds=${1:-1800}
shift || true
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(fuzz_bpt fuzz_grid fuzz_scene fuzz_obj fuzz_tessellate)
declare -A seeds=(
  [fuzz_bpt]="data/*.bpt tests/bad_inputs/*.bpt"
  [fuzz_grid]="data/*.grid tests/bad_inputs/*.grid tests/fuzz/seeds/*.grid"
  [fuzz_scene]="data/*.json tests/bad_inputs/*.json"
  [fuzz_obj]="tests/bad_inputs/*.obj tests/fuzz/seeds/*.obj"
  [fuzz_tessellate]="")
# The sanitizer settings of scripts/sanitize.sh's CPU tests.
export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$src/tests/lsan.supp:print_suppressions=0
status=0
for t in "${targets[@]}"; do
  [[ -x $fuzzers/$t ]] || { echo "fuzz-campaign: no fuzz target $t in $fuzzers" >&2; exit 2; }
  dir=$work/$t
  mkdir -p "$dir/corpus"
  shopt -s nullglob
  for pattern in ${seeds[$t]}; do for seed in $pattern; do cp -f "$seed" "$dir/corpus/"; done; done
  shopt -u nullglob
  start=$(date -u +%FT%TZ)
  "$fuzzers/$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
    -print_final_stats=1 -artifact_prefix="$dir/crash-" "$dir/corpus" >"$dir/log" 2>&1
  rc=$?
  [[ $rc == 0 ]] || status=1
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log" | tail -n 1)
  crashes=$(find "$dir" -maxdepth 1 -name 'crash-*' | wc -l)
  line="$t start $start end $(date -u +%FT%TZ) rc $rc executions ${execs:-?} corpus $(find "$dir/corpus" -type f | wc -l) crashes $crashes"
  echo "$line" | tee -a "$work/summary.txt"
done
exit $status
