#!/usr/bin/env bash
# Runs one libFuzzer target for a fixed time on a working copy of its seed corpus, so the
# seeds in the source tree are never written to. Prints "fuzz: N executions ..." on success;
# on a crash, leak or timeout libFuzzer exits non-zero, this script prints its report and the
# saved input (crash-*) and fails.
#   run_fuzzer.sh <fuzzer binary> <seconds> <working corpus dir> [seed file globs...]
set -euo pipefail
fuzzer=$1 seconds=$2 work=$3
shift 3
mkdir -p "$work"
shopt -s nullglob
for pattern in "$@"; do
  for seed in $pattern; do cp -f "$seed" "$work/"; done
done
name=$(basename "$fuzzer")
log="$work.log"
# -timeout: one input taking over 10 s is a hang; -rss_limit_mb: runaway memory is a finding.
if ! "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
    -print_final_stats=1 -artifact_prefix="$(dirname "$work")/crash-$name-" "$work" >"$log" 2>&1; then
  tail -n 60 "$log"
  echo "fuzz: $name FAILED; the input is saved under $(dirname "$work")/crash-$name-*" >&2
  exit 1
fi
execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
files=$(find "$work" -type f | wc -l)
echo "fuzz: $execs executions of $name in $seconds s, corpus $files files, no crash"
