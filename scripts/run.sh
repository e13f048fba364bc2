#!/usr/bin/env bash
# The main job: builds, then shows the model. Until the window and the figure renderer land, it prints the
# friction ratios behind the paper's Figs. 14 and 17 and a short r_x(zeta) table.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
FV=build/app/frictionviz
for args in "--zeta 0.15 --theta 90 --rdisp 2 --i 1" "--zeta 0.15 --theta 90 --rdisp 2 --i 0" \
            "--zeta 0.5 --theta 90 --rdisp 2 --i 1"; do
  echo "== frictionviz ratio $args"
  $FV ratio $args
done
echo "== frictionviz sweep --zeta 0.1:1.5:8 --theta 0,90 --rdisp 2 --i 0,1"
$FV sweep --zeta 0.1:1.5:8 --theta 0,90 --rdisp 2 --i 0,1
