#!/usr/bin/env bash
# The main job: build interphase (Release) and run the single-point driver on the paper's five
# loading histories (and the 3-D mixed case) with the simplified model and with the
# micromechanical model on the built-in default RVE table, writing CSV and, when gnuplot is
# available, PNG traction-separation curves into OUT_DIR; then reproduce the paper's section 5.2
# (calibration, Figs 17-19 with both models) into OUT_DIR/section5.
# Usage: tools/run-paper-cases.sh [OUT_DIR]   (default: ./out/paper-cases)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$here/out/paper-cases}
build=${INTERPHASE_BUILD_DIR:-$here/build/release}
jobs=$(nproc 2>/dev/null || echo 2)

bash "$here/tools/ensure-packages.sh" gnuplot
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
# (interphase-check-deck too: README.md names it among the programs this command provides)
cmake --build "$build" -j "$jobs" --target interphase-point interphase-calibrate interphase-check-deck
mkdir -p "$out"
for case in "$here"/drivers/cases/*.nml "$here"/drivers/cases/micro/*.nml "$here"/drivers/cases/fracture/*.nml; do
  echo "== $(basename "$case")"
  "$build/drivers/interphase-point" "$case" --output-dir "$out"
done
echo "== the shear test under three precompressions (drivers/cases/shear) and its envelope"
bash "$here/tools/shear-envelope.sh" "$build" "$out/shear-envelope" || [ $? -eq 77 ]
echo "== the paper's section 5.2"
bash "$here/tools/paper-section5.sh" "$build" "$out/section5"
echo "Results in $out (section 5.2 figures in $out/section5):"
ls "$out" "$out/section5"
