#!/usr/bin/env bash
# The classical shear test of a mortar joint at three precompressions (0.1, 0.5, 1.0 MPa) with
# both models (drivers/cases/shear): Sigma_N imposed, s_T imposed. Runs the six cases, tabulates
# the peak shear traction and the residual one (the plateau after full damage) against the
# precompression, checks that the plateau is mu |Sigma_N| (to 1e-12 MPa) and draws one PNG:
# the six curves Sigma_T(s_T) and the envelope (peak and residual against |Sigma_N|, with the
# Coulomb line mu |Sigma_N|).
# Usage: tools/shear-envelope.sh [BUILD_DIR] [OUT_DIR]
#   BUILD_DIR (default build/release) holds drivers/interphase-point; OUT_DIR (default
#   out/shear-envelope) receives the CSVs, envelope.dat and shear-envelope.png.
# Exit status 77 when gnuplot is missing (the table and the check are made all the same).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
usage="usage: tools/shear-envelope.sh [BUILD_DIR] [OUT_DIR]"
for arg in "$@"; do
  case "$arg" in
    -h|--help) echo "$usage"; exit 0 ;;
    -*) echo "shear-envelope.sh: unknown option '$arg' ($usage)" >&2; exit 2 ;;
  esac
done
if [ $# -gt 2 ]; then
  echo "shear-envelope.sh: $# arguments, at most 2 ($usage)" >&2
  exit 2
fi
build=${1:-$here/build/release}
out=${2:-$here/out/shear-envelope}
point=$build/drivers/interphase-point
mu=0.75   # the cases' friction coefficient
[ -x "$point" ] || { echo "shear-envelope.sh: $point not found (build it first)" >&2; exit 1; }
mkdir -p "$out"
table=$out/envelope.dat
echo "# model precompression(MPa) peak_Sigma_T(MPa) residual_Sigma_T(MPa) mu|Sigma_N|(MPa)" > "$table"
for model in simplified micro; do
  for p in 0.1 0.5 1.0; do
    name=shear-$p
    [ $model = micro ] && name=micro-shear-$p
    "$point" "$here/drivers/cases/shear/$name.nml" --no-plot --output-dir "$out" > /dev/null
    # columns: t,s_T,s_N,Sigma_T,Sigma_N,D,...; the residual is the last row's Sigma_T
    awk -F, -v model=$model -v p=$p -v mu=$mu 'NR > 1 { if ($4 > peak) peak = $4; last = $4; sn = $5 }
      END { res = mu * (sn < 0 ? -sn : sn); d = last - res; if (d < 0) d = -d
            if (d > 1e-12) { printf "shear-envelope.sh: %s at %s MPa: plateau %.17g is not mu|Sigma_N| = %.17g\n", model, p, last, res > "/dev/stderr"; exit 1 }
            printf "%s %s %.10f %.10f %.10f\n", model, p, peak, last, res }' "$out/$name.csv" >> "$table"
  done
done
cat "$table"
if ! command -v gnuplot > /dev/null 2>&1; then
  echo "shear-envelope.sh: gnuplot not found: PNG skipped (install Debian package gnuplot-nox)"
  exit 77
fi
cd "$out"
gnuplot <<GP
set encoding utf8
set datafile separator ","
if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) { set terminal pngcairo enhanced size 1400,560 font ",11" } else { set terminal png enhanced size 1400,560 }
set output "shear-envelope.png"
set multiplot layout 1,2 title "Shear test under constant precompression: simplified and micromechanical models, displacement law, {/Symbol m} = $mu, Table 1 data" font ",13"
set grid
set key top right
set title "shear traction against shear separation"
set xlabel "s_T (mm)"
set ylabel "\U+03A3_T (MPa)"
plot for [p in "0.1 0.5 1.0"] "shear-".p.".csv" using 2:4 skip 1 with lines lw 2 title "simplified, \U+03A3_N = -".p." MPa", \
     for [p in "0.1 0.5 1.0"] "micro-shear-".p.".csv" using 2:4 skip 1 with lines lw 2 dt 2 title "micromechanical, \U+03A3_N = -".p." MPa"
set datafile separator whitespace
set title "envelope: peak and residual shear traction"
set xlabel "|\U+03A3_N| (MPa)"
set key top left
set xrange [0:1.1]
set yrange [0:*]
plot "envelope.dat" using (strcol(1) eq "simplified" ? \$2 : NaN):3 with linespoints pt 7 ps 1.5 lw 2 title "peak, simplified", \
     "envelope.dat" using (strcol(1) eq "micro" ? \$2 : NaN):3 with linespoints pt 5 ps 1.5 lw 2 title "peak, micromechanical", \
     "envelope.dat" using (strcol(1) eq "simplified" ? \$2 : NaN):4 with points pt 6 ps 2.5 lw 2 title "residual, simplified", \
     "envelope.dat" using (strcol(1) eq "micro" ? \$2 : NaN):4 with points pt 4 ps 2 lw 2 title "residual, micromechanical", \
     $mu*x with lines lw 1 lc rgb "black" title "Coulomb: {/Symbol m}|\U+03A3_N|"
unset multiplot
GP
echo "shear-envelope.sh: $out/shear-envelope.png"
