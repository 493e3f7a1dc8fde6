#!/bin/bash
# Usage: expect_signal_cleanup.sh <tessera> <surface> <work dir> <TERM|INT>
# Starts a run whose mesh is staged long before the end (a fine mesh, then --deviation), waits
# until its temporary file appears, sends the signal, and checks that tessera died of that
# signal and left no file behind (host/io/pending_temp_files.h; issue 18). Not -q: a quiet run
# with no report skips the deviation (nothing would print it), which left the file staged
# only while it was written (~0.3 s), and a poller starved on a loaded machine missed it.
set -um  # job control: a background job's SIGINT is not ignored
tessera=$1 surface=$2 dir=$3 sig=$4
rm -rf "$dir" && mkdir -p "$dir" || exit 1
# env --default-signal: a shell's background job (or a test run from one) inherits SIGINT
# ignored, and tessera keeps an ignored signal ignored; this test wants it delivered.
env --default-signal=INT,TERM "$tessera" tessellate "$surface" --backend cpu -m B --linearity 0.001 --flatness 0.001 \
  --deviation -o "$dir/mesh.obj" > /dev/null &
pid=$!
for _ in $(seq 2000); do  # up to 20 s
  compgen -G "$dir/.mesh.obj.tmp-*" > /dev/null && break
  sleep 0.01
done
if ! compgen -G "$dir/.mesh.obj.tmp-*" > /dev/null; then
  wait $pid
  echo "no temporary file seen while the run lasted (exit $?)"; exit 1
fi
kill -s "$sig" $pid
wait $pid
code=$?
expected=$((128 + $(kill -l "$sig")))
left=$(ls -A "$dir")
echo "exit $code after SIG$sig (expected $expected); left in $dir: ${left:-nothing}"
[ "$code" -eq "$expected" ] && [ -z "$left" ]
