#!/usr/bin/env bash
# convergence.sh -- mesh convergence study of an RVE table: rerun at two finer levels and report
# the change of every coefficient.
#
#   bash rve_freefem/convergence.sh [--reuse] PARAMS OUTDIR [BASE.dat]
#
# --reuse: keep OUTDIR/NAME-r2.dat and -r4.dat if they exist (only redo the comparison).
# Runs make-table.sh at refine x2 and x4 (every tip, far-field and segment size halved and the
# growth ratio square-rooted at each level) into OUTDIR/NAME-r2.dat, OUTDIR/NAME-r4.dat, and at
# x1 into OUTDIR/NAME-r1.dat unless BASE.dat (e.g. the committed table) is given.  Prints, per
# column, the largest relative change base -> x2 and x2 -> x4 (compare-tables.sh), and checks that
# the base is within TOL_CONV of x2 for C_TT, C_NN, Dbar_TT, Dbar_NN, Cf_T and Tf at every a.
# Exit 1 if that check fails.  Takes several minutes (x4 has ~16x the unknowns).
set -u
export LC_ALL=C
TOL_CONV=0.005
KEY="C_TT C_NN Dbar_TT Dbar_NN Cf_T Tf"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
reuse=0
if [ "${1:-}" = "--reuse" ]; then reuse=1; shift; fi
[ $# -ge 2 ] && [ $# -le 3 ] || { echo "usage: convergence.sh [--reuse] PARAMS OUTDIR [BASE.dat]" >&2; exit 2; }
params=$1; outdir=$2; base=${3:-}
mkdir -p "$outdir" || exit 3
name=$(basename "${params%.params}")
if [ -z "$base" ]; then
  base="$outdir/$name-r1.dat"
  bash "$here/make-table.sh" --no-fields "$params" "$base" | tail -1 || exit 4
fi
[ -r "$base" ] || { echo "convergence.sh: error: cannot read $base" >&2; exit 3; }
for r in 2 4; do
  [ "$reuse" = 1 ] && [ -r "$outdir/$name-r$r.dat" ] && continue
  bash "$here/make-table.sh" --no-fields --refine "$r" "$params" "$outdir/$name-r$r.dat" | tail -1 || exit 4
done
echo
echo "== base ($base) -> refine x2: change of every coefficient"
bash "$here/compare-tables.sh" --tol "$TOL_CONV" --cols "$KEY" "$outdir/$name-r2.dat" "$base"
st=$?
echo
echo "== refine x2 -> refine x4"
bash "$here/compare-tables.sh" "$outdir/$name-r4.dat" "$outdir/$name-r2.dat"
echo
echo "== per a: relative change base -> x2 (and x2 -> x4) of $KEY"
awk -v key="$KEY" '
function abs(x) { return x < 0 ? -x : x }
BEGIN { split("a D C_TT C_TN C_NT C_NN Dbar_TT Dbar_TN Dbar_NT Dbar_NN Cc_TT Cc_TN Cc_NT Cc_NN Tc_T Tc_N Sc_T Sc_N Cf_T Cf_N Tf Sf ufbar", nm, " ")
        nk = split(key, k, " "); for (i = 1; i <= nk; i++) for (j = 1; j <= 23; j++) if (nm[j] == k[i]) c[i] = j
        printf "%-14s", "a (mm)"; for (i = 1; i <= nk; i++) printf " %18s", k[i]; printf "\n" }
/^#/ || NF == 0 { next }
FILENAME == ARGV[1] { nb++; for (j = 1; j <= 23; j++) B[nb, j] = $j; rows[nb] = $1; next }
FILENAME == ARGV[2] { for (j = 1; j <= 23; j++) R2[$1 + 0, j] = $j; next }
{ for (j = 1; j <= 23; j++) R4[$1 + 0, j] = $j }
END {
  for (r = 1; r <= nb; r++) { a = rows[r] + 0; if (!((a, 3) in R2)) continue
    printf "%-14.8g", a
    for (i = 1; i <= nk; i++) { j = c[i]; d1 = (R2[a, j] != 0) ? abs(B[r, j] - R2[a, j]) / abs(R2[a, j]) : abs(B[r, j]); d2 = (R2[a, j] != 0) ? abs(R4[a, j] - R2[a, j]) / abs(R2[a, j]) : abs(R4[a, j])
      if (abs(R2[a, j]) < 1e-9) printf " %18s", "exact 0"; else printf "  %7.1e (%7.1e)", d1, d2 }
    printf "\n" } }' "$base" "$outdir/$name-r2.dat" "$outdir/$name-r4.dat"
exit $st
