#!/bin/bash
# run-case.sh: run a couplet deck (make-deck.sh) in CalculiX with interphase's UMAT and write its
# load-displacement curve (docs/calculix.md).
#
#   examples/calculix/run-case.sh DECK.inp [--cache-dir DIR] [--output-dir DIR] [--no-plot]
#
# Runs DIR/ccx (build-calculix.sh) with DIR on LD_LIBRARY_PATH, so that the material
# @ABAQUS_INTERPHASE_UMAT@JOINT loads DIR/libINTERPHASE.so, and writes into the output directory
# (default: the current one), for a deck NAME.inp:
#   NAME.csv    step, t (total time), u (mm), shear_force (N, the reaction on the top face),
#               normal_force (N, compressive, on the top face), v_top (mm), joint_work (N mm: the
#               joint's integral of sigma:d(eps), ccx's ELSE, stored + dissipated energy)
#   NAME.point.csv  the replay element's first integration point: t, the strains (E11 ... E23,
#               tensor shears as ccx prints them), the stresses S11 ... S23 (MPa) and STATEV
#   NAME.png    shear force and mu x normal force against u (with gnuplot; mu is PROPS(3) of the
#               deck's first @ABAQUS_... material)
#   NAME.dat, NAME.sta, NAME.log  ccx's own output
# Refuses a ccx without external-behaviour support, and a run whose joint carried no stress
# (what such a ccx does with a material named @ABAQUS_...: "Job finished" with zero stress).
# Exit status 0 on success, 1 on a failed run (the log's last lines are shown).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
cache=$root/build/calculix
outdir=$PWD
plot=yes
deck=""
while [ $# -gt 0 ]; do
   case "$1" in
      --cache-dir) cache=$2; shift ;;
      --output-dir) outdir=$2; shift ;;
      --no-plot) plot=no ;;
      -h|--help) awk 'NR > 1 && /^#/ { print; next } NR > 1 { exit }' "$0"; exit 0 ;;
      -*) echo "run-case.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
      *) [ -z "$deck" ] || { echo "run-case.sh: one deck only" >&2; exit 2; }; deck=$1 ;;
   esac
   shift
done
[ -n "$deck" ] || { echo "run-case.sh: no deck given (try --help)" >&2; exit 2; }
[ -f "$deck" ] || { echo "run-case.sh: deck '$deck' not found" >&2; exit 2; }
# A material named ABAQUS... without the leading @ is CalculiX's own example UMAT (a linear
# elastic law of PROPS(1), PROPS(2)), not interphase: such a run ends "Job finished" with
# meaningless numbers, so it is refused before ccx runs
abaqus_plain=$(grep -i -o -E '^\*MATERIAL *,.*NAME *= *ABAQUS[^ ,]*' "$deck" | sed -E 's/.*= *//' | head -n 1 || true)
if [ -n "$abaqus_plain" ]; then
   echo "run-case.sh: $deck: material $abaqus_plain has no leading @: CalculiX runs its own example UMAT" >&2
   echo "  for it, not interphase; name it @ABAQUS_INTERPHASE_UMAT@<name> (docs/calculix.md, 'Material naming')" >&2
   exit 1
fi
# mu of the deck's first interphase material (PROPS(3)), for the plot's mu x normal force line
mu=$(awk '{ u = toupper($0) }
   u ~ /^\*MATERIAL/ { inmat = (u ~ /NAME *= *@ABAQUS_/); next }
   inmat && u ~ /^\*USER MATERIAL/ { want = 1; next }
   want && /^\*/ { exit }
   want && NF { n = split($0, f, ","); if (n >= 3) { gsub(/ /, "", f[3]); print f[3] + 0 }; exit }' "$deck")
[ -n "$mu" ] || mu=0.75
ccx=$cache/ccx
if [ ! -x "$ccx" ] || ! grep -q -a "unable to load function" "$ccx"; then
   echo "run-case.sh: $ccx is missing or has no external-behaviour support: run examples/calculix/build-calculix.sh" >&2
   exit 1
fi
[ -f "$cache/libINTERPHASE.so" ] || { echo "run-case.sh: no $cache/libINTERPHASE.so: run build-calculix.sh" >&2; exit 1; }
mkdir -p "$outdir"
name=$(basename "$deck" .inp)
deck_abs=$(cd "$(dirname "$deck")" && pwd)/$(basename "$deck")
[ "$deck_abs" -ef "$outdir/$name.inp" ] || cp "$deck" "$outdir/$name.inp"
# the library's start-up hook reads INTERPHASE_TABLE and INTERPHASE_RCURVE in ccx's folder, the
# output folder: a relative path is the caller's
for var in INTERPHASE_TABLE INTERPHASE_RCURVE; do
   val=${!var:-}
   if [ -n "$val" ] && [ "${val#/}" = "$val" ]; then export "$var=$PWD/$val"; fi
done
cd "$outdir"
rm -f "$name.dat" "$name.csv" "$name.point.csv" "$name.png"
start=$(date +%s)
# (GFORTRAN_UNBUFFERED_ALL: ccx's Fortran messages reach the log even when ccx then crashes, as
# it does on a *USER MATERIAL whose constants and temperature lines do not add up)
rc=0
LD_LIBRARY_PATH="$cache${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} \
   GFORTRAN_UNBUFFERED_ALL=1 "$ccx" -i "$name" > "$name.log" 2>&1 || rc=$?
if [ $rc -ne 0 ] || ! grep -q "Job finished" "$name.log" || grep -q "\*ERROR" "$name.log"; then
   echo "run-case.sh: ccx failed on $deck (exit status $rc; last lines of $outdir/$name.log):" >&2
   grep -E "\*ERROR|\*WARNING in interphase" "$name.log" | tail -n 5 >&2 || true
   tail -n 5 "$name.log" >&2
   exit 1
fi
seconds=$(( $(date +%s) - start ))

# ccx's .dat: blocks "<what> ... for set <SET> and time <t>", then data lines. The shear history
# is step 2, from total time 1 on.
awk -v csv="$name.csv" -v pcsv="$name.point.csv" '
function flush_row() {
   if (have_rf && have_u && have_e) {
      printf "%d,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", (time > 1.0 + 1e-12) ? 2 : 1, time, u, fx, -fy, v, ew >> csv
   }
   have_rf = have_u = have_e = 0
}
BEGIN { print "step,t,u,shear_force,normal_force,v_top,joint_work" > csv
        print "t,E11,E22,E33,E12,E13,E23,S11,S22,S33,S12,S13,S23,SDV1,SDV2,SDV3,SDV4,SDV5" > pcsv }
/for set/ && /and time/ {
   what = ""; t = $NF + 0
   if (t != time) { flush_row(); time = t }
   if ($0 ~ /total force/) what = "rf"
   else if ($0 ~ /^ *displacements/ && $0 ~ /TOPREF/) what = "u"
   else if ($0 ~ /total internal energy/) what = "e"
   else if ($0 ~ /strains/ && $0 ~ /REPLAY/) what = "pe"
   else if ($0 ~ /stresses/ && $0 ~ /REPLAY/) what = "ps"
   else if ($0 ~ /internal state variables/ && $0 ~ /REPLAY/) what = "pv"
   first = 1
   next
}
NF == 0 { next }
what == "rf" && first { fx = $1; fy = $2; have_rf = 1; first = 0; next }
what == "u" && first { u = $2; v = $3; have_u = 1; first = 0; next }
what == "e" && first { ew = $1; have_e = 1; first = 0; next }
what == "pe" && first { for (k = 1; k <= 6; k++) pe[k] = $(k + 2); first = 0; next }
what == "ps" && first { for (k = 1; k <= 6; k++) ps[k] = $(k + 2); first = 0; next }
what == "pv" && first {
   row = t
   for (k = 1; k <= 6; k++) row = row "," pe[k]
   for (k = 1; k <= 6; k++) row = row "," ps[k]
   for (k = 3; k <= NF; k++) row = row "," $k
   for (k = NF - 1; k < 5; k++) row = row ","
   print row >> pcsv
   first = 0; next }
END { flush_row() }' "$name.dat"

rows=$(($(wc -l < "$name.csv") - 1))
[ "$rows" -ge 2 ] || { echo "run-case.sh: no load-displacement rows in $outdir/$name.dat: run-case.sh reads the sets TOP, TOPREF and JOINT that make-deck.sh's couplet decks print (a deck of your own: run ccx itself, docs/calculix.md, 'Running a deck of your own')" >&2; exit 1; }
# a ccx that did not call interphase (stock binary): the joint carried no stress
# (its work, ccx's ELSE over the joint, and the replay element's stresses: the top face's
# reactions are the loads whatever the joint does)
if awk -F, 'NR > 1 && $7 != 0 { nz = 1 } END { exit !nz }' "$name.csv" && \
   awk -F, 'NR > 1 { for (k = 8; k <= 13; k++) if ($k != 0) nz = 1 } END { exit !nz }' "$name.point.csv"; then :; else
   echo "run-case.sh: the joint carried no stress and did no work: this ccx did not call interphase's UMAT" >&2
   exit 1
fi
peak=$(awk -F, 'NR > 1 && $1 == 2 { if ($4 > m) m = $4 } END { printf "%.6g", m }' "$name.csv")
echo "run-case.sh: $name: ${rows} increments written, peak shear force $peak N, ccx ${seconds} s -> $outdir/$name.csv"

if [ $plot = yes ] && command -v gnuplot >/dev/null 2>&1; then
   gnuplot <<EOF || echo "run-case.sh: gnuplot failed; no plot" >&2
set terminal pngcairo size 900,600 noenhanced
set output '$name.png'
set datafile separator ','
set title "CalculiX + interphase UMAT: $name"
set xlabel 'shear displacement u (mm)'
set ylabel 'force (N)'
set key below
set grid
plot '$name.csv' every ::1 using (\$1 == 2 ? \$3 : 1/0):4 with lines lw 2 title 'shear force (CalculiX)', \
     '' every ::1 using (\$1 == 2 ? \$3 : 1/0):($mu*\$5) with lines dt 2 title 'mu x normal force (mu = $mu, PROPS(3) of the deck)', \
     '' every ::1 using (\$1 == 2 ? \$3 : 1/0):(-$mu*\$5) with lines dt 2 notitle
EOF
fi
