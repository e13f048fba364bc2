#!/usr/bin/env bash
# Benchmarks (not tests): prints figures on this machine.
#   render --figure all at 1280x800 (median of 5 runs; target <= 5 s)
#   accuracy contract of the default ratio (worst |default - dtau->0 limit| on a grid; contract 1e-5)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh bench
bash scripts/build.sh app >/dev/null
cmake --build build -j"$(nproc)" --target fv_accuracy_contract >/dev/null
FV=build/app/frictionviz
out=$(mktemp -d)
times=()
for k in 1 2 3 4 5; do
  s=$(date +%s.%N)
  $FV render --figure all --out "$out" >/dev/null
  e=$(date +%s.%N)
  times+=("$(echo "$e - $s" | bc)")
done
sorted=$(printf '%s\n' "${times[@]}" | sort -n)
echo "render --figure all 1280x800: median $(echo "$sorted" | sed -n 3p) s  (runs: $(echo $sorted))"
rm -rf "$out"
if [ "${1:-}" != "--render-only" ]; then
  echo "accuracy contract (450 points, takes ~40 s):"
  build/bench/fv_accuracy_contract | tail -n 1
fi
