#!/usr/bin/env bash
# Real X input to `tessera view`, under a virtual X server (run by xvfb-run, tests/viewer/
# CMakeLists.txt): xdotool presses every key, drags and turns the wheel through the X server,
# so the events take GLFW's callbacks as a user's would. Each input waits for its effect in
# the viewer's log before the next is sent (no fixed sleeps): a slow machine only takes longer.
# A --script whose one step is far away keeps the log of every frame on (docs/cli.md).
# Usage: real_input.sh TESSERA SCENE OUT_DIR; then `viewer_check keys-log OUT_DIR/real.log 60 -20`.
set -euo pipefail
tessera=$1 scene=$2 out=$3
log=$out/real.log
mkdir -p "$out"
rm -f "$log"
echo "1000000 key Esc" > "$out/real_script.txt"
"$tessera" view "$scene" --validation --size 320x180 --script "$out/real_script.txt" >"$log" 2>&1 &
viewer=$!
trap 'kill $viewer 2>/dev/null || true' EXIT

fail() {
  echo "real_input: $*" >&2
  cat "$log" >&2
  exit 1
}
# Waits up to 60 s for at least $2 lines (default 1) of the log to match the extended regular
# expression $1.
await() {
  for _ in $(seq 600); do
    [[ $(grep -Ec "$1" "$log" || true) -ge ${2:-1} ]] && return 0
    kill -0 $viewer 2>/dev/null || fail "the viewer ended before '$1'"
    sleep 0.1
  done
  fail "no '$1' in the log after 60 s"
}
# Presses key $1, then waits for one more log line matching $2: its effect (viewer/view_state.h,
# applyKey), so that no two keys act in one frame.
press() {
  local before
  before=$(grep -Ec "$2" "$log" || true)
  xdotool key "$1"
  await "$2" $((before + 1))
}

await "^view: frame 1: "  # drawing, so polling its events
window=$(timeout 60 xdotool search --sync --onlyvisible --name "^tessera view ")
timeout 60 xdotool mousemove --sync --window "$window" 160 90
timeout 60 xdotool windowfocus --sync "$window"
press w ": wireframe on$"
press w ": wireframe off$"
press c ": colour patch$"
press c ": colour level$"
press c ": colour shaded$"
press plus ": tolerance 2 px$"
press minus ": tolerance 1 px$"
press KP_Subtract ": tolerance 0.5 px$"
press KP_Add ": tolerance 1 px$"
press f ": frozen$"
await "FROZEN$" 2  # a second frame drawn frozen, before F again
press f ": unfrozen$"
# A drag with the left button: 60 right, 20 up, in one motion each way.
xdotool mousedown 1
timeout 60 xdotool mousemove_relative --sync -- 60 -20
xdotool mouseup 1
await ": drag "
xdotool click 4  # the wheel, one step away from the user
await ", wheel 1$"
press Escape ": quit$"
wait $viewer || fail "tessera view exited with $?"
trap - EXIT
