#!/usr/bin/env bash
# convergence.sh -- mesh convergence study of an RVE table: rerun at two finer levels and report
# the change of every coefficient.
#
#   bash rve_freefem/convergence.sh [--reuse] PARAMS OUTDIR [BASE.dat]
#   bash rve_freefem/convergence.sh --help      (this text)
#
# --reuse: keep OUTDIR/NAME-r2.dat and -r4.dat if they exist (only redo the comparison).
# Runs make-table.sh at refine x2 and x4 (every tip, far-field and segment size halved and the
# growth ratio square-rooted at each level) into OUTDIR/NAME-r2.dat, OUTDIR/NAME-r4.dat, and at
# x1 into OUTDIR/NAME-r1.dat unless BASE.dat (e.g. the committed table) is given.  Prints, per
# column, the largest relative change base -> x2 and x2 -> x4 (compare-tables.sh), and checks that
# the base is within TOL_CONV of x2 for C_TT, C_NN, Dbar_TT, Dbar_NN, Cf_T and Tf at every a.
# Takes several minutes (x4 has ~16x the unknowns).  The parameters are checked at every level
# (make-table.sh --check) before the first run; each run's output goes to OUTDIR/NAME-rR.log.
# Exit code: 0 converged; 1 some checked column of the base is off x2 by more than TOL_CONV;
# 2 usage or bad parameters (make-table.sh exit 2); 3 an unreadable file, an OUTDIR that cannot
# be made or FreeFem++ missing; 4 a make-table.sh run (FreeFEM) or a comparison of the tables
# failed.  Every failure stops the study with "convergence.sh: error: ...".
set -u
export LC_ALL=C
TOL_CONV=0.005
KEY="C_TT C_NN Dbar_TT Dbar_NN Cf_T Tf"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
prog=convergence.sh
die() { local code=$1; shift; echo "$prog: error: $*" >&2; exit "$code"; }
usage="usage: convergence.sh [--reuse] PARAMS OUTDIR [BASE.dat]"
reuse=0
positional=()
# --reuse anywhere among the arguments, once; another word that starts with '-' is no file
for arg in "$@"; do
  case "$arg" in
    --reuse) [ "$reuse" = 0 ] || die 2 "--reuse given twice ($usage)"; reuse=1 ;;
    -h|--help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;;
    -*) die 2 "unknown option '$arg' ($usage)" ;;
    *) positional+=("$arg") ;;
  esac
done
set -- ${positional[@]+"${positional[@]}"}
[ $# -ge 2 ] && [ $# -le 3 ] || die 2 "$usage"
params=$1; outdir=$2; base=${3:-}
[ -f "$params" ] && [ -r "$params" ] || die 3 "cannot read parameter file '$params'"
[ -z "$base" ] || [ -r "$base" ] || die 3 "cannot read $base"
mkdir -p "$outdir" || die 3 "cannot create $outdir"
name=$(basename "${params%.params}")

# the parameters and the mesh at every level, before minutes of runs (a ligament too short for
# refine x4, say, stops here and not after the x1 and x2 runs)
levels="2 4"
[ -n "$base" ] || levels="1 2 4"
for r in $levels; do
  msg=$(bash "$here/make-table.sh" --check --refine "$r" "$params" 2>&1)
  rc=$?
  if [ $rc -ne 0 ]; then
    printf '%s\n' "$msg" >&2
    die "$rc" "$params: refine x$r: the parameters are refused (see above)"
  fi
done

# run make-table.sh REFINE OUT: its last line on success; its messages and a stop on failure
run_table() {
  local r=$1 out=$2 log=${2%.dat}.log rc
  bash "$here/make-table.sh" --no-fields --refine "$r" "$params" "$out" > "$log" 2>&1
  rc=$?
  if [ $rc -ne 0 ]; then
    grep -v '^\[job ' "$log" | tail -20 | sed 's/^/  /' >&2
    local code=$rc
    case $rc in 2|3|4) ;; *) code=4 ;; esac
    die "$code" "make-table.sh --refine $r failed (exit $rc) for $out (its output: $log)"
  fi
  tail -1 "$log"
}
if [ -z "$base" ]; then
  base="$outdir/$name-r1.dat"
  run_table 1 "$base"
fi
for r in 2 4; do
  [ "$reuse" = 1 ] && [ -r "$outdir/$name-r$r.dat" ] && continue
  run_table "$r" "$outdir/$name-r$r.dat"
done
for f in "$base" "$outdir/$name-r2.dat" "$outdir/$name-r4.dat"; do
  [ -r "$f" ] || die 3 "cannot read $f"
done

echo
echo "== base ($base) -> refine x2: change of every coefficient"
bash "$here/compare-tables.sh" --tol "$TOL_CONV" --cols "$KEY" "$outdir/$name-r2.dat" "$base"
st=$?
[ $st -le 1 ] || die 4 "compare-tables.sh failed (exit $st) on $outdir/$name-r2.dat and $base (see above)"
echo
echo "== refine x2 -> refine x4"
bash "$here/compare-tables.sh" "$outdir/$name-r4.dat" "$outdir/$name-r2.dat" \
  || die 4 "compare-tables.sh failed (exit $?) on $outdir/$name-r4.dat and $outdir/$name-r2.dat (see above)"
echo
echo "== per a: relative change base -> x2 (and x2 -> x4) of $KEY"
# the three tables in the canonical column order (table-reader.awk, as compare-tables.sh read them
# above): the comparison below takes the columns by position
canon=$(mktemp -d) || die 3 "cannot make a temporary directory"
trap 'rm -rf "$canon"' EXIT
k=0
for f in "$base" "$outdir/$name-r2.dat" "$outdir/$name-r4.dat"; do
  k=$((k + 1))
  awk -f "$here/table-reader.awk" -v dest="$canon/$k.dat" -v file="$f" "$f" || die 4 "$f: not read as the loader reads it (above)"
done
awk -v key="$KEY" '
function abs(x) { return x < 0 ? -x : x }
BEGIN { split("a D C_TT C_TN C_NT C_NN Dbar_TT Dbar_TN Dbar_NT Dbar_NN Cc_TT Cc_TN Cc_NT Cc_NN Tc_T Tc_N Sc_T Sc_N Cf_T Cf_N Tf Sf ufbar", nm, " ")
        nk = split(key, k, " "); for (i = 1; i <= nk; i++) for (j = 1; j <= 23; j++) if (nm[j] == k[i]) c[i] = j
        printf "%-14s", "a (mm)"; for (i = 1; i <= nk; i++) printf " %18s", k[i]; printf "\n" }
{ sub(/\r$/, "") }
/^#/ || NF == 0 { next }
FILENAME == ARGV[1] { nb++; for (j = 1; j <= 23; j++) B[nb, j] = $j; rows[nb] = $1; next }
FILENAME == ARGV[2] { for (j = 1; j <= 23; j++) R2[$1 + 0, j] = $j; next }
{ for (j = 1; j <= 23; j++) R4[$1 + 0, j] = $j }
END {
  for (r = 1; r <= nb; r++) { a = rows[r] + 0; if (!((a, 3) in R2)) continue
    printf "%-14.8g", a
    for (i = 1; i <= nk; i++) { j = c[i]; d1 = (R2[a, j] != 0) ? abs(B[r, j] - R2[a, j]) / abs(R2[a, j]) : abs(B[r, j]); d2 = (R2[a, j] != 0) ? abs(R4[a, j] - R2[a, j]) / abs(R2[a, j]) : abs(R4[a, j])
      if (abs(R2[a, j]) < 1e-9) printf " %18s", "exact 0"; else printf "  %7.1e (%7.1e)", d1, d2 }
    printf "\n" } }' "$canon/1.dat" "$canon/2.dat" "$canon/3.dat" \
  || die 4 "the per-a comparison failed (awk exit $?)"
exit $st
