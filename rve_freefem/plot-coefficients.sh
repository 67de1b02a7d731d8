#!/usr/bin/env bash
# plot-coefficients.sh -- PNG plots of every RVE coefficient against a, with the simplified
# (Alfano-Sacco) model's lines beside them: the paper's Figs 7, 8, 11-14, 16, plus the
# distributions D(x) and u^f(x) (Figs 9, 10, 15) from the side file, ufbar and the symmetry zeros.
#
#   bash rve_freefem/plot-coefficients.sh TABLE.dat OUTDIR
#   bash rve_freefem/plot-coefficients.sh --help      (this text)
#
# The side file is TABLE-fields.dat (made by make-table.sh) when it exists.  Needs gnuplot
# (Debian gnuplot-nox); without it, prints a message and exits 0.
set -u
export LC_ALL=C
prog=plot-coefficients.sh
# the help is the comment block at the top of this file
case "${1:-}" in -h|--help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;; esac
[ $# -eq 2 ] || { echo "usage: $prog TABLE.dat OUTDIR (or --help)" >&2; exit 2; }
table=$1
out=$2
if ! command -v gnuplot > /dev/null 2>&1; then
  echo "$prog: gnuplot not found (Debian package gnuplot-nox): no plots made"
  exit 0
fi
[ -r "$table" ] || { echo "$prog: error: cannot read $table" >&2; exit 3; }
mkdir -p "$out" || { echo "$prog: error: cannot create $out" >&2; exit 3; }
fields=${table%.dat}-fields.dat
name=$(basename "${table%.dat}")
# the table as the loader reads it, in the canonical column order (table-reader.awk: the plots
# below take the columns by position, whatever the order of the file's '# columns:' line)
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d) || { echo "$prog: error: cannot make a temporary directory" >&2; exit 3; }
trap 'rm -rf "$work"' EXIT
if ! awk -f "$here/table-reader.awk" -v dest="$work/table.dat" -v file="$table" "$table" > "$work/why.txt"; then
  PREFIX="$prog: error: " awk '{ print ENVIRON["PREFIX"] $0 }' "$work/why.txt" >&2
  exit 3
fi
source_table=$table
table=$work/table.dat
# (the PNG files this run writes are counted against this mark: not those of an earlier run)
touch "$work/mark"
hdr() { awk -v k="$1" '$1 == "#" && $2 == k && $3 == "=" { print $4; exit }' "$table"; }
CT=$(hdr Chat_TT); CN=$(hdr Chat_NN); h=$(hdr h); b=$(hdr b)
[ -n "$CT" ] && [ -n "$CN" ] && [ -n "$h" ] && [ -n "$b" ] || { echo "$prog: error: $source_table lacks Chat_TT, Chat_NN, h or b in its header" >&2; exit 3; }
if gnuplot -e "set terminal pngcairo" > /dev/null 2>&1; then term="pngcairo size 1000,700 font ',11'"; else term="png size 1000,700"; fi

gp() { gnuplot 2>&1 <<EOF | grep -v '^ *$' | grep -vi 'warning: empty' >&2
set terminal $term
CT = $CT; CN = $CN; h = $h; b = $b
set datafile commentschars "#"
set key top right box opaque
set grid
set xlabel "crack half-length a (mm)"
set xrange [0:b]
$1
EOF
}
pt="pt 7 ps 0.8"
simple="lw 2 dt 4 lc rgb '#d62728'"

# Figs 7, 8: C_TT, C_NN (a) against a, (b) against the ligament b - a on a log axis
for c in TT:3:CT:7 NN:6:CN:8; do
  IFS=: read -r comp col chat fig <<< "$c"
  gp "set output '$out/fig$(printf %02d "$fig")-C_$comp.png'
set multiplot layout 1,2 title '$name: overall elastic modulus C_{$comp} (paper Fig. $fig)'
set ylabel 'C_{$comp} (MPa)'
plot '$table' u 1:$col w lp $pt lw 1.5 t 'RVE (FreeFEM)', $chat*(1-x/b) $simple t 'simplified (1-D) Chat'
set logscale x; set format x '10^{%T}'; set xrange [*:*]; set xlabel 'ligament b - a (mm)'; set key top left
plot '$table' u (b-\$1):(\$1 > 0 && \$1 < b ? \$$col : 1/0) w lp $pt lw 1.5 t 'RVE', $chat*x/b $simple t 'simplified'
unset multiplot"
done

# Fig 11: mean crack jumps Dbar_TT, Dbar_NN
gp "set output '$out/fig11-Dbar.png'
set title '$name: mean crack jump per unit E (paper Fig. 11)'
set ylabel 'Dbar (mm)'; set key bottom right
plot '$table' u 1:7 w lp $pt lw 1.5 t 'Dbar_{TT}', '' u 1:10 w lp pt 5 ps 0.8 lw 1.5 t 'Dbar_{NN}', h $simple t 'simplified: h'"

# Figs 12, 13: C^c
for c in TT:11:CT:12 NN:14:CN:13; do
  IFS=: read -r comp col chat fig <<< "$c"
  gp "set output '$out/fig$fig-Cc_$comp.png'
set title '$name: overall contact modulus C^c_{$comp} (paper Fig. $fig); C + C^c = C(0)'
set ylabel 'C^c_{$comp} (MPa)'; set key top left
plot '$table' u 1:$col w lp $pt lw 1.5 t 'RVE', $chat*x/b $simple t 'simplified D Chat', '' u 1:($((col - 8)) + \$$col) w l lw 1 lc rgb 'gray' t 'C + C^c'"
done

# Fig 14: crack stresses of p2
gp "set output '$out/fig14-Tc_Sc.png'
set title '$name: crack stresses per unit E, T^c_T and S^c_N (paper Fig. 14)'
set ylabel 'MPa'; set key center right; set yrange [0:1.2*(CT > CN ? CT : CN)]
plot '$table' u 1:15 w lp $pt lw 1.5 t 'T^c_T', '' u 1:18 w lp pt 5 ps 0.8 lw 1.5 t 'S^c_N', CT $simple t 'simplified Chat_{TT}', CN lw 2 dt 4 lc rgb '#9467bd' t 'simplified Chat_{NN}'"

# Fig 16: C^f_T and T^f
gp "set output '$out/fig16-Cf_Tf.png'
set multiplot layout 1,2 title '$name: slip coefficients per unit slip (paper Fig. 16)'
set ylabel 'C^f_T (MPa/mm)'; set key top right
plot '$table' u 1:19 w lp $pt lw 1.5 t 'C^f_T (RVE)', -CT/h*x/b $simple t 'simplified -D Chat_{TT}/h'
set ylabel '-T^f (MPa/mm), log scale'; set logscale y; set key top right
plot '$table' u 1:(\$1 > 0 ? -\$21 : 1/0) w lp $pt lw 1.5 t '-T^f (RVE)', CT/h $simple t 'simplified Chat_{TT}/h'
unset multiplot"

# ufbar
gp "set output '$out/ufbar.png'
set title '$name: mean slip shape ufbar (max u^f = 1); simplified model: 1'
set ylabel 'ufbar'; set yrange [0.7:1.02]; set key bottom right
plot '$table' u 1:(\$1 > 0 ? \$23 : 1/0) w lp $pt lw 1.5 t 'ufbar (RVE)', 1 $simple t 'simplified', pi/4 lw 1 dt 2 lc rgb 'gray' t 'pi/4 (Griffith ellipse)'"

# symmetry zeros
gp "set output '$out/symmetry-zeros.png'
set title '$name: coefficients that vanish by symmetry (absolute values, relative to their scale)'
set ylabel '|value| / scale'; set logscale y; set format y '10^{%T}'; set yrange [1e-20:1e-6]; set key top right
plot '$table' u 1:(abs(\$4)/CT+1e-20) w p pt 1 t 'C_{TN}/Chat', '' u 1:(abs(\$5)/CT+1e-20) w p pt 2 t 'C_{NT}/Chat', \
     '' u 1:(abs(\$8)/h+1e-20) w p pt 4 t 'Dbar_{TN}/h', '' u 1:(abs(\$9)/h+1e-20) w p pt 6 t 'Dbar_{NT}/h', \
     '' u 1:(abs(\$16)/CT+1e-20) w p pt 8 t 'T^c_N/Chat', '' u 1:(abs(\$17)/CT+1e-20) w p pt 10 t 'S^c_T/Chat', \
     '' u 1:(abs(\$20)*h/CT+1e-20) w p pt 12 t 'C^f_N h/Chat', '' u 1:(abs(\$22)*h/CT+1e-20) w p pt 3 t 'S^f h/Chat'"

# Figs 9, 10, 15: distributions
if [ -r "$fields" ]; then
  nblk=$(grep -c '^# a = ' "$fields")
  alist=$(awk '/^# a = / { printf "%s%.6g", sep, $4; sep = " " }' "$fields")
  for c in 9:3:4:TT:NT:1 10:5:6:TN:NN:2; do
    IFS=: read -r fig c1 c2 n1 n2 col <<< "$c"
    gp "set output '$out/fig$(printf %02d "$fig")-D-column$col.png'
set multiplot layout 1,2 title '$name: column $col of D(x), crack jump per unit E (paper Fig. $fig)'
alist = '$alist'
set xlabel 'x (mm)'; set xrange [0:2*b]; set key top right font ',9'
set ylabel 'D_{$n1} (mm)'
plot for [i=0:$((nblk - 1))] '$fields' index i u 2:$c1 w l lw 1.5 t sprintf('a = %s mm', word(alist, i + 1))
set ylabel 'D_{$n2} (mm)'
plot for [i=0:$((nblk - 1))] '$fields' index i u 2:$c2 w l lw 1.5 t sprintf('a = %s mm', word(alist, i + 1))
unset multiplot"
  done
  gp "set output '$out/fig15-uf.png'
set title '$name: slip shape u^f(x) under uniform crack shear stress, max 1 (paper Fig. 15)'
alist = '$alist'
set xlabel 'x (mm)'; set xrange [0:2*b]; set ylabel 'u^f'; set yrange [0:1.05]; set key top right
plot for [i=0:$((nblk - 1))] '$fields' index i u 2:7 w l lw 1.5 t sprintf('a = %s mm', word(alist, i + 1))"
else
  echo "$prog: no side file $fields: Figs 9, 10, 15 not made"
fi
echo "$prog: wrote $(find "$out" -maxdepth 1 -name '*.png' -newer "$work/mark" | wc -l) PNG files to $out"
