#!/usr/bin/env bash
# The main job: build interphase (Release) and run the single-point driver on the paper's five
# loading histories (and the 3-D mixed case) with the built-in default model, writing CSV and,
# when gnuplot is available, PNG traction-separation curves into OUT_DIR.
# Usage: tools/run-paper-cases.sh [OUT_DIR]   (default: ./out/paper-cases)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$here/out/paper-cases}
build=${INTERPHASE_BUILD_DIR:-$here/build/release}
jobs=$(nproc 2>/dev/null || echo 2)

bash "$here/tools/ensure-packages.sh" gnuplot
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$jobs" --target interphase-point
mkdir -p "$out"
for case in "$here"/drivers/cases/*.nml; do
  echo "== $(basename "$case")"
  "$build/drivers/interphase-point" "$case" --output-dir "$out"
done
echo "Results in $out:"
ls "$out"
