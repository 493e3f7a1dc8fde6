#!/usr/bin/env bash
# Prints one line per tea-set mesh: model, rule, backend, format and the SHA-256 of the file
# `tessera tessellate` writes. Two builds that print the same lines give the same meshes byte
# for byte (how a refactor shows that behaviour is unchanged).
#   scripts/mesh-hashes.sh [path/to/tessera] [data dir]
set -euo pipefail
tessera=${1:-build/tessera}
data=${2:-$(dirname "$0")/../../shared/data}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for model in teapot teacup teaspoon; do
  for rule in A B C D; do
    for backend in cpu vulkan; do
      for format in obj ply glb; do
        out="$work/$model-$rule-$backend.$format"
        if "$tessera" tessellate "$data/$model.bpt" -m "$rule" --backend "$backend" -q \
            --no-deviation -o "$out" 2>"$work/err"; then
          echo "$model $rule $backend $format $(sha256sum <"$out" | cut -c1-16)"
        else
          echo "$model $rule $backend $format exit=$? $(head -c 120 "$work/err")"
        fi
      done
    done
  done
done
