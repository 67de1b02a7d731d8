#!/usr/bin/env bash
# The paper's section 5.2: the five loading histories with the micromechanical model (built-in
# converged table, and the paper-resolution table for comparison) and with the simplified model
# calibrated to the micromechanical fracture energies (the paper's procedure, computed by
# interphase-calibrate), then Figs 17(a), 17(b), 18(a), 18(b) and 19 as PNGs with both models on
# each plot and the mixed-mode branches O, A, ..., L marked. A third micromechanical variant
# interpolates the paper-resolution table in D (= a/b) instead of the log-ligament variable w,
# as a spline over the paper's 1 mm crack-length steps does (docs/paper.md).
# Usage: tools/paper-section5.sh BUILD_DIR OUT_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:?usage: paper-section5.sh BUILD_DIR OUT_DIR}
out=${2:?usage: paper-section5.sh BUILD_DIR OUT_DIR}
point="$build/drivers/interphase-point"
calibrate="$build/drivers/interphase-calibrate"
cases="$here/drivers/cases"
mkdir -p "$out/cases"

# ---- case files: micromechanical (converged), micromechanical (paper resolution), simplified
# calibrated to each. The &loading groups come from drivers/cases/micro/*.nml.
loading_of() {  # the &loading group of a case file, history made absolute
  sed -n '/^&loading/,/^\//p' "$cases/micro/$1.nml" | sed "s|history = '../|history = '$cases/|"
}
material_of() {  # the &material group of a case file
  sed -n '/^&material/,/^\//p' "$1"
}
sed '1a # interpolation_variable = D' "$here/tables/paper-resolution.dat" > "$out/cases/paper-resolution-D.dat"
for h in h1I h2I h1II h2II mixed; do
  { material_of "$cases/micro/$h.nml"; echo; loading_of "$h" | sed "s|output = '.*'|output = 'micro_$h.csv'|"; } \
    > "$out/cases/micro_$h.nml"
  { material_of "$cases/micro/$h.nml" | sed "s|^/$|  table = '$here/tables/paper-resolution.dat'\n/|"; echo
    loading_of "$h" | sed "s|output = '.*'|output = 'microres_$h.csv'|"; } > "$out/cases/microres_$h.nml"
  { material_of "$cases/micro/$h.nml" | sed "s|^/$|  table = 'paper-resolution-D.dat'\n/|"; echo
    loading_of "$h" | sed "s|output = '.*'|output = 'microresD_$h.csv'|"; } > "$out/cases/microresD_$h.nml"
done

echo "== calibration of the simplified model (paper section 5.2)"
"$calibrate" "$out/cases/micro_h1I.nml" --write "$out/cases/calibrated.nml" | tee "$out/calibration.txt"
echo "== the same with the paper-resolution table (spline in w, then in D)"
"$calibrate" "$out/cases/microres_h1I.nml" --write "$out/cases/calibrated_res.nml" | tee "$out/calibration-paper-resolution.txt"
"$calibrate" "$out/cases/microresD_h1I.nml" --write "$out/cases/calibrated_resD.nml" | tee "$out/calibration-paper-resolution-D.txt"

for h in h1I h2I h1II h2II mixed; do
  { material_of "$out/cases/calibrated.nml"; echo; loading_of "$h" | sed "s|output = '.*'|output = 'simplified_$h.csv'|"; } \
    > "$out/cases/simplified_$h.nml"
  for m in micro microres microresD simplified; do
    "$point" "$out/cases/${m}_$h.nml" --output-dir "$out" --no-plot
  done
done

# ---- summary: peak tractions and dissipated energy at the end of the monotonic tests
{
  printf '%-12s %-11s %14s %14s %14s\n' history model 'peak (MPa)' 'at s (mm)' 'W_dis (N/mm)'
  for h in h1I h1II; do
    col=5; scol=3; [ "$h" = h1II ] && { col=4; scol=2; }
    for m in micro microres microresD simplified; do
      awk -F, -v c=$col -v sc=$scol -v h=$h -v m=$m 'NR>1 { v=$c<0?-$c:$c; if (v>p) {p=v; s=$sc}; w=$10 }
        END { printf "%-12s %-11s %14.6g %14.6g %14.6g\n", h, m, p, s, w }' "$out/${m}_$h.csv"
    done
  done
} | tee "$out/summary.txt"

if ! command -v gnuplot >/dev/null 2>&1; then
  echo "gnuplot not found: figures skipped (install Debian package gnuplot-nox)"
  exit 0
fi

# ---- mixed-mode branch points on the micromechanical curve (paper section 5.2.4):
# O start; A first damage; B end of the first loading (t = 2); C first slip after B; D t = 3;
# E first slip after D; F damage grows again; G D = 1; H t = 4; I first slip after H; J t = 5;
# K first slip after J; L end (t = 6).
branch_points() {
  awk -F, 'NR==1 { print "# the branch points of Fig 19 (docs/paper.md) on the micromechanical mixed history:"
                   print "# columns: label  s_T (mm)  Sigma_T (MPa)"; next }
    { t=$1; s=$2; S=$4; d=$6; st=$8 }
    function mark(n) { printf "%s %.10g %.10g\n", n, s, S }
    NR==2 { mark("O") }
    !a && d>0 { mark("A"); a=1 }
    !b && t>=2 { mark("B"); b=1 }
    b && !c && st=="slip" && t>2 { mark("C"); c=1 }
    !dd && t>=3 { mark("D"); dd=1 }
    dd && !e && st=="slip" && t>3 { mark("E"); e=1; de=d }
    e && !f && d>de { mark("F"); f=1 }
    !g && d>=1 { mark("G"); g=1 }
    !hh && t>=4 { mark("H"); hh=1 }
    hh && !i && st=="slip" && t>4 { mark("I"); i=1 }
    !j && t>=5 { mark("J"); j=1 }
    j && !k && st=="slip" && t>5 { mark("K"); k=1 }
    END { mark("L") }' "$1"
}
branch_points "$out/micro_mixed.csv" > "$out/mixed-branches.txt"

plot() {  # plot NAME TITLE XCOL YCOL XLABEL YLABEL HISTORY [labels-file]
  local name=$1 title=$2 x=$3 y=$4 xl=$5 yl=$6 h=$7 labels=${8:-}
  {
    echo "set terminal pngcairo size 900,680 enhanced font ',11'"
    echo "set output '$out/$name.png'"
    echo "set datafile separator ','"
    echo "set key below box"
    echo "set grid lc rgb '#dddddd'"
    echo "set title \"$title\""
    echo "set xlabel '$xl'"
    echo "set ylabel '$yl'"
    if [ -n "$labels" ]; then
      # room around the curves, so that no point sits on the frame (H, I, J, K)
      echo "set offsets graph 0.04, graph 0.04, graph 0.06, graph 0.06"
      while read -r n sx sy; do
        [ "$n" = "#" ] && continue
        # each label on the side where it meets no curve and no other label (B and F, O and A
        # are close pairs)
        case $n in
          O) off="0.6,-1.1" ;; A) off="0.7,0.5" ;; B) off="-1.6,0.9" ;; F) off="0.8,0.9" ;;
          H) off="-1.0,0.9" ;; I) off="-0.4,1.0" ;; J) off="0.6,0.9" ;; *) off="0.6,0.6" ;;
        esac
        echo "set label '$n' at $sx,$sy offset $off font ',12' tc rgb '#b2182b'"
        echo "set object circle at $sx,$sy size char 0.35 fc rgb '#b2182b' fs solid front"
      done < "$labels"
    fi
    echo "plot '$out/micro_$h.csv' every ::1 using $x:$y with lines lw 2 lc rgb '#2166ac' title 'micromechanical (converged table)', \\"
    echo "     '$out/microres_$h.csv' every ::1 using $x:$y with lines lw 1.5 dt 2 lc rgb '#67a9cf' title 'micromechanical (paper-resolution table, spline in w)', \\"
    echo "     '$out/microresD_$h.csv' every ::1 using $x:$y with lines lw 1.5 dt 4 lc rgb '#1b7837' title 'micromechanical (paper-resolution table, spline in D)', \\"
    echo "     '$out/simplified_$h.csv' every ::1 using $x:$y with lines lw 2 lc rgb '#d6604d' title 'simplified, calibrated to the same G_I, G_{II}'"
  } > "$out/$name.gp"
  gnuplot "$out/$name.gp"
  echo "figure: $out/$name.png"
}
plot fig17a 'Fig. 17(a): mode I, monotonic (h1I)' 3 5 's_N (mm)' '{/Symbol S}_N (MPa)' h1I
plot fig17b 'Fig. 17(b): mode I, cyclic (h2I)' 3 5 's_N (mm)' '{/Symbol S}_N (MPa)' h2I
plot fig18a 'Fig. 18(a): mode II, monotonic (h1II)' 2 4 's_T (mm)' '{/Symbol S}_T (MPa)' h1II
plot fig18b 'Fig. 18(b): mode II, cyclic (h2II)' 2 4 's_T (mm)' '{/Symbol S}_T (MPa)' h2II
plot fig19 'Fig. 19: mixed mode, s_N = -0.005 mm (branches on the micromechanical curve)' 2 4 \
  's_T (mm)' '{/Symbol S}_T (MPa)' mixed "$out/mixed-branches.txt"
