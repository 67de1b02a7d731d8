#!/bin/bash
# ctest calculix_step_start: the 2-D simplified monotonic couplet with mu = 0.5 and 1.0 MPa, which
# ccx could not run while make-deck.sh wrote one step a history segment (*ERROR: too many cutbacks
# at the start of the second shear step: ccx's linear first iteration of a step opened the nearly
# broken joint, docs/calculix.md 'When ccx cuts back at the start of a step'). make-deck.sh writes
# the two segments of monotonic.txt as one step now: the run must go through without a cut-back
# and end on the Coulomb plateau mu N = 10000 N.
#   step-start.sh EXAMPLES_CALCULIX_DIR CACHE_DIR WORK_DIR
set -uo pipefail
cx=$(cd "$1" && pwd)
cache=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
if [ ! -x "$cache/ccx" ] || [ ! -f "$cache/libINTERPHASE.so" ]; then
   if [ "${CI:-}" = true ]; then echo "FAILED: no ccx or libINTERPHASE.so in $cache (calculix_build)"; exit 1; fi
   echo "SKIP: no ccx or libINTERPHASE.so in $cache (calculix_build could not build them here)"; exit 77
fi
cd "$work"
bash "$cx/make-deck.sh" --dim 2 --model simplified --history "$cx/../../drivers/fe2d/cases/monotonic.txt" \
   --mu 0.5 --precompression 1.0 -o step-start.inp > /dev/null || { echo "FAILED: make-deck.sh"; exit 1; }
steps=$(grep -c '^\*STEP' step-start.inp)
[ "$steps" -eq 2 ] || { echo "FAILED: the deck has $steps steps, expected 2 (the precompression and one shear step)"; exit 1; }
bash "$cx/run-case.sh" step-start.inp --cache-dir "$cache" --output-dir "$work" --no-plot || {
   echo "FAILED: the run did not complete"; exit 1; }
status=0
cutbacks=$(awk 'NR > 2 && $3 ~ /U/' step-start.sta | wc -l)
end=$(tail -n 1 step-start.csv | awk -F, '{ printf "%.8f", $4/10000 }')
echo "cut-backs: $cutbacks; end force / mu N = $end"
[ "$cutbacks" -eq 0 ] || { echo "FAILED: ccx cut back $cutbacks increment(s)"; status=1; }
awk -v e="$end" 'BEGIN { exit !(e > 0.99999 && e < 1.00001) }' || { echo "FAILED: the run did not end on the plateau"; status=1; }
exit $status
