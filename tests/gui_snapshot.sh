#!/usr/bin/env bash
# Renders a scripted app session headless and compares the last frame with its baseline (same tolerance as
# the figure snapshots: max channel difference 32, at most 0.05 % of the pixels). FV_UPDATE_SNAPSHOTS=1
# writes the baseline instead (then review and commit it).
set -euo pipefail
exe=$1 compare=$2 script=$3 frames=$4 baseline=$5 out=$6
mkdir -p "$out"
name=$(basename "$baseline" .png)
rm -f "$out/$name.png"
"$exe" gui --headless --frames "$frames" --script "$script" --screenshot "$out/$name.png"
if [[ "${FV_UPDATE_SNAPSHOTS:-}" == 1 ]]; then
    cp "$out/$name.png" "$baseline"
    echo "updated $baseline"
    exit 0
fi
[[ -f "$baseline" ]] || { echo "no baseline $baseline; create it with FV_UPDATE_SNAPSHOTS=1"; exit 1; }
"$compare" "$out/$name.png" "$baseline" 32 0.0005 "$out/$name.diff.png"
