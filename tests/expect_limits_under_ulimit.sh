#!/bin/sh
# expect_limits_under_ulimit.sh TESSERA BIG_DIR TORUS: runs issue 18's big inputs (scaled down,
# tests/make_big_inputs.cmake) under `ulimit -v` of 3 GiB with the default memory budget,
# which then comes from that limit; each must end with exit 0 or 4 (a clear limit message),
# never 70 (std::bad_alloc as a bug) or a signal (/dev/zero as x.bpt or x.json may end 2: the
# first line is too long, the first byte is no JSON). Prints each case's exit code and message.
tessera=$1 big=$2 torus=$3
out=$(mktemp -d) || exit 1
trap 'rm -rf "$out"' EXIT
ulimit -v 3145728 || { echo "cannot set ulimit -v"; exit 1; }
failed=0
# run ALLOWED TESSERA ARGS...: ALLOWED is the other exit code the case may end with ("-": none).
run() {
  allowed=$1
  shift
  "$@" -o "$out/m.obj" >"$out/stdout" 2>"$out/stderr"
  code=$?
  echo "exit $code: $* : $(tail -c 300 "$out/stderr")"
  case $code in
    0 | "$allowed") ;;
    4) grep -q -e "--memory-budget\|--max-input-size\|node budget" "$out/stderr" ||
         { echo "  exit 4 without naming the limit's option"; failed=1; } ;;
    *) failed=1 ;;
  esac
}
run - "$tessera" tessellate "$big/grid_4096.grid" --backend cpu -q
run - "$tessera" tessellate "$big/patches_30k.bpt" --backend cpu -q -m A --grid 64
run 2 "$tessera" tessellate "$big/x.json" --backend cpu -q
run 2 "$tessera" tessellate "$big/x.bpt" --backend cpu -q
run - "$tessera" loop "$torus" -l 8 --backend cpu
# A budget above the address space: the estimate passes, the allocation fails, and the
# std::bad_alloc backstop still exits 4, naming the budget.
run - "$tessera" tessellate "$big/patches_30k.bpt" --backend cpu -q -m A --grid 64 \
  --node-budget 1000000000000 --memory-budget 1T
grep -q "out of memory (the memory budget is 1.00 TiB" "$out/stderr" ||
  { echo "  the backstop's message is missing"; failed=1; }
exit $failed
