#!/usr/bin/env bash
# Runs the whole bench/ suite (Release build) and writes, under bench/results/:
#   latest.json  machine, device, driver, commit, and every case of every run (work size,
#                min/median time over >= 5 runs, throughput, ratio to its table's baseline,
#                fraction of the host-memory bandwidth cap where it applies)
#   latest.md    the summary table (also printed) and each benchmark's own output
#   throughput.png  throughput vs work size of the main cases (gnuplot)
# Every bench_* binary in the build is run (new ones join by themselves, with their default
# sizes); the main ones run at several sizes, listed below. The whole run is sized for about
# ten minutes on a 2-core machine running lavapipe.
# Usage: BUILD_DIR=build scripts/bench.sh [--quick]   (--quick: the smallest size of each)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
quick=0
[[ "${1:-}" == "--quick" ]] && quick=1
scripts/deps.sh >/dev/null
# Configure (Release) and build only what bench/ needs: the benchmarks and the library.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
make -C "$build/bench" -j "$(nproc)" >/dev/null

# Arguments of each run, runs separated by '|'.
declare -A sizes=(
  [bench_eval]="64 32 65536|256 32 65536|1024 32 262144|2048 32 262144"
  [bench_quadtree]="10 2|40 4|160 8"
  [bench_mesh]="10|40|160"
  [bench_occt]="0.01,0.001 ABT"
  [bench_tess_shader]="300 100 1"
  [bench_realtime]="300 100 1"
  [bench_scale]="1000000 64"
)

out=bench/results
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
dirty=$(git status --porcelain --untracked-files=no 2>/dev/null | grep -q . && echo true || echo false)
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')
jq -n --arg date "$(date -u +%Y-%m-%dT%H:%MZ)" --arg commit "$commit" --argjson dirty "$dirty" \
  --arg cpu "$cpu" --argjson cores "$(nproc)" \
  --argjson mem "$(free -g | awk '/Mem:/{print $2}')" --arg kernel "$(uname -r)" \
  --arg load "$(cut -d' ' -f1-3 /proc/loadavg)" \
  '{date: $date, commit: $commit, uncommittedChanges: $dirty,
    machine: {cpu: $cpu, cores: $cores, memoryGiB: $mem, kernel: $kernel,
              loadAverageAtStart: $load}}' > "$work/header.json"

n=0
: > "$work/outputs.md"
for b in "$build"/bench/bench_*; do
  [[ -x "$b" && -f "$b" ]] || continue
  name=$(basename "$b")
  IFS='|' read -r -a runs <<< "${sizes[$name]:-}"
  [[ ${#runs[@]} -eq 0 ]] && runs=("")
  [[ $quick -eq 1 ]] && runs=("${runs[0]}")
  for args in "${runs[@]}"; do
    n=$((n + 1))
    echo "== $name $args" >&2
    # shellcheck disable=SC2086  # args are words on purpose
    if "$b" $args --json "$work/run-$n.json" > "$work/run-$n.txt" 2>&1; then
      if [[ -f "$work/run-$n.json" ]]; then
        jq --arg args "$args" '. + {args: $args}' "$work/run-$n.json" > "$work/run-$n.tagged.json"
      else  # a benchmark without --json support yet: its text output is in latest.md
        echo "   $name wrote no JSON (no --json support): text output only" >&2
        jq -n --arg b "$name" --arg args "$args" '{bench: $b, args: $args, noJson: true, tables: []}' \
          > "$work/run-$n.tagged.json"
      fi
    else
      echo "   $name $args FAILED (output in latest.md)" >&2
      jq -n --arg b "$name" --arg args "$args" '{bench: $b, args: $args, failed: true, tables: []}' \
        > "$work/run-$n.tagged.json"
    fi
    { echo "## $name $args"; echo; echo '```'; cat "$work/run-$n.txt"; echo '```'; echo; } \
      >> "$work/outputs.md"
  done
done

jq -s '.[0] + {device: ([.[1:][] | .notes.device? // empty] | first),
               runs: .[1:]}' "$work/header.json" "$work"/run-*.tagged.json > "$work/latest.json"
mv "$work/latest.json" "$out/latest.json"

# The summary table, one row per case of every run.
{
  jq -r '"# Benchmark results\n\n- date: \(.date)\n- commit: \(.commit)" +
         (if .uncommittedChanges then " (with uncommitted changes)" else "" end) +
         "\n- machine: \(.machine.cores) cores, \(.machine.cpu), \(.machine.memoryGiB) GiB, load average at start \(.machine.loadAverageAtStart)" +
         "\n- device: \(.device.name // "none") (\(.device.driver // "") \(.device.driverInfo // ""))" +
         ([.runs[] | select(.bandwidthCap) | .bandwidthCap] | first |
           if . then "\n- bandwidth cap: host memcpy \(.hostCopyBytesPerSecond / 1e9 * 100 | round / 100) GB/s measured → \(.capVerticesPerSecond / 1e6 | round) M vertices/s of 32 B; the issue assumes 5 GB/s → 156 M/s" else "" end) +
         "\n\n| benchmark | table | path | work | min s | median s | runs | throughput | ratio | of cap (measured / 5 GB/s) |\n|---|---|---|---|---|---|---|---|---|---|"' \
     "$out/latest.json"
  jq -r '.runs[] | . as $r | if .failed then "| \(.bench) \(.args) | FAILED | | | | | | | | |"
         elif .noJson then "| \(.bench) \(.args) | (no JSON report: see its output below) | | | | | | | | |" else
         .tables[] | . as $t | .cases[] |
         "| \($r.bench) \($r.args) | \($t.name) | \(.path) | \(.workSize | round) \($t.workUnit) | \(.minSeconds * 1e4 | round / 1e4) | \(.medianSeconds * 1e4 | round / 1e4) | \(.runs) | \(.throughput | if . >= 1e6 then "\(. / 1e4 | round / 100) M" elif . >= 1e3 then "\(. / 10 | round / 100) k" else "\(. * 100 | round / 100)" end)/s | \(.ratioToBaseline * 100 | round / 100) | \(if .fractionOfCap then "\(.fractionOfCap * 100 | round) % / \(.fractionOfAssumedCap * 100 | round) %" else "—" end) |" end' \
     "$out/latest.json"
} > "$work/summary.md"
cat "$work/summary.md"
{ cat "$work/summary.md"; echo; echo "![throughput vs work size](throughput.png)"; echo;
  cat "$work/outputs.md"; } > "$out/latest.md.tmp"
mv "$out/latest.md.tmp" "$out/latest.md"

# Throughput vs work size of the main cases: one panel per table, one line per path.
if command -v gnuplot >/dev/null; then
  plot="$work/plot.gp"
  echo "set terminal pngcairo size 1500,450 font ',9'; set output '$out/throughput.png.tmp'
set multiplot layout 1,3 title 'Tessera throughput vs work size ($commit)'
set logscale xy; set grid; set key bottom right font ',8'" > "$plot"
  for t in "evaluation" "quad-tree B" "mesh"; do
    unit=$(jq -r --arg t "$t" '[.runs[].tables[] | select(.name == $t) | .workUnit] | first // "items"' "$out/latest.json")
    mapfile -t paths < <(jq -r --arg t "$t" '[.runs[].tables[] | select(.name == $t) | .cases[].path] | unique | .[]' "$out/latest.json")
    [[ ${#paths[@]} -eq 0 ]] && continue
    cmds=()
    for i in "${!paths[@]}"; do
      jq -r --arg t "$t" --arg p "${paths[$i]}" \
        '[.runs[].tables[] | select(.name == $t) | .cases[] | select(.path == $p)] | sort_by(.workSize) | .[] | "\(.workSize) \(.throughput)"' \
        "$out/latest.json" > "$work/series-${t// /_}-$i.dat"
      cmds+=("'$work/series-${t// /_}-$i.dat' using 1:2 with linespoints title '${paths[$i]//\'/}'")
    done
    { echo "set title '$t'; set xlabel '$unit'; set ylabel '$unit / s'"
      echo "plot $(IFS=,; echo "${cmds[*]}")"; } >> "$plot"
  done
  echo "unset multiplot" >> "$plot"
  gnuplot "$plot" && mv "$out/throughput.png.tmp" "$out/throughput.png"
else
  echo "gnuplot missing (scripts/deps.sh installs gnuplot-nox): no plot" >&2
fi
echo "wrote $out/latest.md, $out/latest.json, $out/throughput.png" >&2
