#!/usr/bin/env bash
# Runs every benchmark in bench/ (Release build) and writes bench/results/latest.md with the
# machine, the commit and each benchmark's tables. Extra arguments are passed to none;
# sizes are each benchmark's defaults (see bench/README.md).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh >/dev/null
scripts/build.sh >/dev/null
out=bench/results/latest.md
mkdir -p bench/results
{
  echo "# Benchmark results"
  echo
  echo "- date: $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "- commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo "- machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(free -g | awk '/Mem:/{print $2}') GiB"
  echo
  for b in "${BUILD_DIR:-build}"/bench/bench_*; do
    [[ -x "$b" ]] || continue
    echo "## $(basename "$b")"
    echo
    echo '```'
    "$b"
    echo '```'
    echo
  done
} | tee "$out.tmp"
mv "$out.tmp" "$out"
echo "wrote $out"
