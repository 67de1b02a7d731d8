#!/bin/bash
# ctest calculix_pnewdt_cutback: CalculiX honours interphase's cut-back request. The couplet
# (2-D, simplified, monotonic) runs with ONE increment a history segment through a probe library
# whose UMAT gets a NaN strain increment in any increment longer than 0.3 (umat_cutback_probe.f90),
# which interphase refuses with PNEWDT = 0.25 (CalculiX passes -1: a rule of min(PNEWDT, 0.25)
# would leave it at -1 and the request would be lost). The run must complete on the Coulomb
# plateau, ccx must report the decrease "requested by a material user routine (through pnewdt)",
# and no converged increment may be longer than 0.3.
#   cutback-probe.sh <examples/calculix> <cache> <work> <fortran compiler>
set -uo pipefail
cx=$(cd "$1" && pwd)
cache=$2
work=$3
fc=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
cd "$work"
# no ccx here (calculix_build skipped): skip too, but not in CI
if [ ! -f "$cache/interphase_calculix.f90" ] || [ ! -x "$cache/ccx" ]; then
   if [ "${CI:-}" = true ]; then echo "FAILED: no ccx or user source in $cache (calculix_build)"; exit 1; fi
   echo "SKIP: no ccx or user source in $cache (calculix_build could not build them here)"; exit 77
fi
cache=$(cd "$cache" && pwd)
mkdir -p probe
"$fc" -O2 -fPIC -shared -ffree-line-length-none -J probe -o probe/libINTERPHASEPROBE.so "$cache/interphase_calculix.f90" \
   "$here/umat_cutback_probe.f90" -Wl,--defsym,UMAT=umat_cutback_probe_ -llapack -lblas || { echo "FAILED: probe library"; exit 1; }
ln -sf "$(readlink -f "$cache/ccx")" probe/ccx
ln -sf "$cache/libINTERPHASE.so" probe/libINTERPHASE.so
bash "$cx/make-deck.sh" --dim 2 --model simplified --history "$cx/../../drivers/fe2d/cases/monotonic.txt" \
   --increments 1 -o probe.inp > /dev/null
sed -i 's/@ABAQUS_INTERPHASE_UMAT@JOINT/@ABAQUS_INTERPHASEPROBE_UMAT@JOINT/' probe.inp
INTERPHASE_PROBE_FAIL_ABOVE=0.3 bash "$cx/run-case.sh" probe.inp --cache-dir "$work/probe" --output-dir "$work" --no-plot || {
   echo "FAILED: the run did not complete"; exit 1; }
status=0
requests=$(grep -c "increment size decrease requested by a material user routine (through pnewdt)" probe.log || true)
warnings=$(grep -c "WARNING in interphase" probe.log || true)
longest=$(awk 'NR > 2 && NF >= 7 && $3 !~ /U/ { if ($7 > m) m = $7 } END { printf "%.6g", m }' probe.sta)
end=$(tail -n 1 probe.csv | awk -F, '{ printf "%.6f", $4/(0.75*$5) }')
echo "ccx reported $requests cut-back request(s) through PNEWDT ($warnings interphase warnings); longest converged increment $longest; end force / mu N = $end"
[ "$requests" -ge 2 ] || { echo "FAILED: ccx did not act on interphase's PNEWDT"; status=1; }
awk -v l="$longest" 'BEGIN { exit !(l <= 0.3) }' || { echo "FAILED: an increment longer than 0.3 converged"; status=1; }
awk -v e="$end" 'BEGIN { exit !(e > 0.99999 && e < 1.00001) }' || { echo "FAILED: the run did not end on the plateau"; status=1; }
exit $status
