#!/usr/bin/env bash
# plots.sh TABLE OUTDIR -- plot-coefficients.sh makes every PNG (skip, 77, without gnuplot).
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# --help and -h: the description on standard output, exit 0 (with or without gnuplot)
for opt in --help -h; do
  out=$(bash "$here/plot-coefficients.sh" "$opt" 2>&1) && grep -q '^  bash rve_freefem/plot-coefficients[.]sh TABLE[.]dat OUTDIR' <<< "$out" \
    || { echo "FAIL plot-coefficients.sh $opt: no description or a non-zero exit"; printf '%s\n' "$out"; exit 1; }
  echo "ok   plot-coefficients.sh $opt"
done
command -v gnuplot > /dev/null 2>&1 || { echo "gnuplot not found: plot test skipped"; exit 77; }
rm -rf "$2"
bash "$here/plot-coefficients.sh" "$1" "$2" || exit 1
fail=0
for f in fig07-C_TT fig08-C_NN fig09-D-column1 fig10-D-column2 fig11-Dbar fig12-Cc_TT fig13-Cc_NN \
         fig14-Tc_Sc fig15-uf fig16-Cf_Tf ufbar symmetry-zeros; do
  p="$2/$f.png"
  if [ -s "$p" ] && [ "$(head -c 4 "$p" | od -An -c | tr -d ' ')" = '211PNG' ]; then echo "ok   $f.png"; else echo "FAIL $f.png missing or not a PNG"; fail=1; fi
done
exit $fail
