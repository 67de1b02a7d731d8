#!/bin/bash
# run-study.sh: one couplet shear case in CalculiX against interphase-fe2d and the single-point
# driver (docs/calculix.md, 'Agreement').
#
#   examples/calculix/run-study.sh --dim 2|3 --model simplified|micromechanical
#                                  --history monotonic|cyclic [--thickness T] [--cache-dir DIR]
#                                  [--build-dir DIR] [--output-dir DIR] [--check] [--no-plot]
#
#   1. make-deck.sh writes the deck (t = 0.1 mm unless --thickness), run-case.sh runs it in ccx;
#   2. interphase-fe2d runs the same test with zero-thickness interface elements: the case
#      drivers/fe2d/cases/couplet-simplified-<history>.nml or couplet-micro-viscous-<history>.nml,
#      with Gauss integration (the layer's 2 x 2 Gauss points) and 20 increments a segment, as
#      the deck;
#   3. interphase-point replays the history of the replay element's first integration point
#      (separations s = t eps from ccx's strains, one UMAT call a ccx increment) and compares its
#      tractions with ccx's stresses.
# Prints the peak shear force, the end force against mu N, the joint's work (stored + dissipated,
# N mm) and the replay's largest traction difference, and writes NAME-vs-fe2d.png.
#   --check   exit 1 unless: peak and joint work within 1e-3 of fe2d's, end force within 1e-5 of
#             mu N, replay within 1e-5 of the largest traction (the tolerances of ctest -L calculix)
# --build-dir: the interphase build tree with interphase-fe2d and interphase-point (default
# build/release). Exit 77 (skip) when ccx cannot be built here and CI is not set.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
dim=""; model=""; history=""; thickness=0.1
cache=$root/build/calculix
build_dir=$root/build/release
outdir=$PWD
check=no
plot=yes
while [ $# -gt 0 ]; do
   case "$1" in
      --dim) dim=$2; shift ;;
      --model) model=$2; shift ;;
      --history) history=$2; shift ;;
      --thickness) thickness=$2; shift ;;
      --cache-dir) cache=$2; shift ;;
      --build-dir) build_dir=$2; shift ;;
      --output-dir) outdir=$2; shift ;;
      --check) check=yes ;;
      --no-plot) plot=no ;;
      -h|--help) awk 'NR > 1 && /^#/ { print; next } NR > 1 { exit }' "$0"; exit 0 ;;
      *) echo "run-study.sh: unknown argument '$1' (try --help)" >&2; exit 2 ;;
   esac
   shift
done
case "$history" in monotonic|cyclic) ;; *) echo "run-study.sh: --history must be monotonic or cyclic" >&2; exit 2 ;; esac
case "$model" in
   simplified) fe_case=couplet-simplified-$history ;;
   micromechanical) fe_case=couplet-micro-viscous-$history ;;
   *) echo "run-study.sh: --model must be simplified or micromechanical" >&2; exit 2 ;;
esac
fe2d=$build_dir/drivers/fe2d/interphase-fe2d
point=$build_dir/drivers/interphase-point
for p in "$fe2d" "$point"; do
   [ -x "$p" ] || { echo "run-study.sh: $p not found (build interphase: cmake --build $build_dir)" >&2; exit 1; }
done
mkdir -p "$outdir"
outdir=$(cd "$outdir" && pwd)
name=couplet${dim}d-${model}-${history}

# ccx and the library (cached); 77 when they cannot be had here
set +e
bash "$here/build-calculix.sh" --cache-dir "$cache" --build-dir "$build_dir" > "$outdir/$name.build.log" 2>&1
rc=$?
set -e
if [ $rc -ne 0 ]; then
   cat "$outdir/$name.build.log" >&2
   if [ $rc -eq 77 ] && [ "${CI:-}" != true ]; then exit 77; fi
   echo "run-study.sh: CalculiX could not be built (exit $rc)" >&2
   exit 1
fi

# 1. CalculiX
fe_dir=$root/drivers/fe2d/cases
bash "$here/make-deck.sh" --dim "$dim" --model "$model" --history "$fe_dir/$history.txt" --thickness "$thickness" \
   -o "$outdir/$name.inp" > /dev/null
bash "$here/run-case.sh" "$outdir/$name.inp" --cache-dir "$cache" --output-dir "$outdir" --no-plot

# 2. interphase-fe2d, the same test with interface elements (Gauss, 20 increments a segment)
sed -e "s/integration = 'lobatto'/integration = 'gauss'/" -e "s/^\( *increments *= *\)[0-9]*/\120/" \
    -e "s|history = '\([^']*\)'|history = '$fe_dir/\1'|" -e "s|output = '[^']*'|output = '$name.fe2d.csv'|" \
    "$fe_dir/$fe_case.nml" > "$outdir/$name.fe2d.nml"
"$fe2d" "$outdir/$name.fe2d.nml" --output-dir "$outdir" --no-plot > "$outdir/$name.fe2d.out" 2>&1 || {
   cat "$outdir/$name.fe2d.out" >&2; echo "run-study.sh: interphase-fe2d failed" >&2; exit 1; }

# 3. the single-point replay: separations s = t eps (engineering shears 2 eps_12, 2 eps_23), the
# layer's normal being axis 2; the material without the layer and host options
awk -F, -v t="$thickness" 'NR == 1 { print "# t s_T1 s_T2 s_N (mm): ccx replay element, integration point 1"; next }
   { printf "%s %.9e %.9e %.9e\n", $1, 2*t*$5, 2*t*$7, t*$3 }' "$outdir/$name.point.csv" > "$outdir/$name.replay.txt"
{
   echo "&material"
   if [ "$model" = simplified ]; then
      echo "  model = 'simplified', damage_law = 'displacement', mu = 0.75"
      echo "  s0_n = 0.00044, sf_n = 0.04, s0_t = 0.00072, sf_t = 0.06"
      echo "  k_n = 482.69742679680568, k_t = 198.75776397515528"
   else
      echo "  model = 'micromechanical', damage_law = 'displacement', mu = 0.75"
      echo "  s0_n = 0.00044, sf_n = 0.04, s0_t = 0.00072, sf_t = 0.06"
      echo "  contact_band = 0.6, viscosity = 0.001"
   fi
   echo "/"
   echo "&loading"
   echo "  history = '$name.replay.txt', increments = 1, output = '$name.replay.csv', plot = .false."
   echo "/"
} > "$outdir/$name.replay.nml"
"$point" "$outdir/$name.replay.nml" --output-dir "$outdir" --no-plot > "$outdir/$name.replay.out" 2>&1 || {
   cat "$outdir/$name.replay.out" >&2; echo "run-study.sh: interphase-point failed on the replay" >&2; exit 1; }

# the comparison
summary=$(awk -F, -v ccx="$outdir/$name.csv" -v fe="$outdir/$name.fe2d.csv" -v pt="$outdir/$name.point.csv" \
      -v rp="$outdir/$name.replay.csv" '
   function abs(x) { return x < 0 ? -x : x }
   BEGIN {
      while ((getline line < ccx) > 0) { split(line, f, ","); if (f[1] == "step") continue
         if (f[1] >= 2 && abs(f[4]) > cpeak) cpeak = abs(f[4]); cend = f[4]; cn = f[5]; cw = f[7] }
      while ((getline line < fe) > 0) { split(line, f, ","); if (f[1] ~ /step/) continue
         if (f[1] >= 2 && abs(f[4]) > fpeak) fpeak = abs(f[4]); fend = f[4]; fw = f[11] + f[12]; fstored = f[11] }
      n = 0
      while ((getline line < pt) > 0) { split(line, f, ","); if (f[1] == "t") continue
         n++; sn[n] = f[9]; st1[n] = f[11]; st2[n] = f[13] }
      m = 0; worst = 0; smax = 0
      while ((getline line < rp) > 0) { split(line, f, ","); if (f[1] == "t") continue
         m++; if (m > n) break
         d = abs(f[7] - sn[m]); if (abs(f[5] - st1[m]) > d) d = abs(f[5] - st1[m]); if (abs(f[6] - st2[m]) > d) d = abs(f[6] - st2[m])
         if (d > worst) worst = d
         if (abs(sn[m]) > smax) smax = abs(sn[m]); if (abs(st1[m]) > smax) smax = abs(st1[m]) }
      mun = 0.75*cn
      printf "%.6f %.6f %.8g %.8g %.6f %.6f %.6g %d %d %.6g %.6g\n", cpeak, fpeak, cend, mun, cw, fw, fstored, n, m, worst, smax
   }')
read -r cpeak fpeak cend mun cw fw fstored npt nrp worst smax <<< "$summary"
[ "$npt" -ge 2 ] && [ "$npt" -eq "$nrp" ] || { echo "run-study.sh: the replay has $nrp rows for ccx's $npt" >&2; exit 1; }
result=$(awk -v cp="$cpeak" -v fp="$fpeak" -v ce="$cend" -v mun="$mun" -v cw="$cw" -v fw="$fw" -v w="$worst" -v sm="$smax" -v fs="$fstored" '
   function abs(x) { return x < 0 ? -x : x }
   BEGIN {
      dp = (cp - fp)/fp; dw = (cw - fw)/fw; de = (abs(ce) - mun)/mun; dr = w/sm
      printf "peak shear force: CalculiX %.2f N, fe2d %.2f N (%+.2e)\n", cp, fp, dp
      printf "end shear force:  CalculiX %.2f N, mu N %.2f N (%+.2e)\n", ce, mun, de
      printf "joint work (stored + dissipated): CalculiX %.3f N mm, fe2d %.3f N mm (%+.2e; stored at the end %.3f N mm)\n", cw, fw, dw, fs
      printf "replay through interphase-point: largest traction difference %.3e MPa (%.2e of the largest traction %.4f MPa)\n", w, dr, sm
      ok = abs(dp) <= 1e-3 && abs(dw) <= 1e-3 && abs(de) <= 1e-5 && dr <= 1e-5
      print ok ? "AGREEMENT: within the tolerances" : "AGREEMENT: OUTSIDE the tolerances (peak, work 1e-3; end 1e-5; replay 1e-5)"
   }')
echo "run-study.sh: $name (t = $thickness mm)"
echo "$result" | sed 's/^/  /'
echo "$result" > "$outdir/$name.summary.txt"

if [ $plot = yes ] && command -v gnuplot >/dev/null 2>&1; then
   negative=$(awk -F, 'NR > 1 && $3 < 0 { n = 1 } END { print n + 0 }' "$outdir/$name.csv")
   mirror=""
   [ "$negative" = 1 ] && mirror=", '' every ::1 using 3:(-0.75*\$5) with lines dt 2 lc rgb '#0000c0' notitle"
   gnuplot <<EOF || echo "run-study.sh: gnuplot failed; no plot" >&2
set terminal pngcairo size 900,600 noenhanced
set output '$outdir/$name-vs-fe2d.png'
set datafile separator ','
set title "couplet shear test, ${dim}-D, $model model, $history history\nCalculiX with a joint layer t = $thickness mm against interphase-fe2d"
set xlabel 'shear displacement u (mm)'
set ylabel 'shear force (N)'
set key below
set grid
plot '$outdir/$name.fe2d.csv' every ::1 using 3:4 with lines lw 3 lc rgb '#999999' title 'interphase-fe2d (interface elements)', \
     '$outdir/$name.csv' every ::1 using 3:4 with lines lw 1 lc rgb '#c00000' title 'CalculiX + interphase UMAT (${dim}-D layer)', \
     '' every ::1 using 3:(0.75*\$5) with lines dt 2 lc rgb '#0000c0' title 'mu N'$mirror
EOF
fi
if [ $check = yes ] && ! grep -q "within the tolerances" <<< "$result"; then exit 1; fi
exit 0
