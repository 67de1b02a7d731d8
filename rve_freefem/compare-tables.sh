#!/usr/bin/env bash
# compare-tables.sh -- change of every coefficient between two RVE tables, row by row (same a).
#
#   bash rve_freefem/compare-tables.sh [--tol TOL] [--cols "C_TT C_NN ..."] REF.dat NEW.dat
#
# For each column: the largest relative change |new - ref| / max(|ref|, floor) over the rows whose
# a appears in both tables (a matched to 1e-12 b), and the a where it occurs.  floor = 1e-6 times
# the largest |ref| of the column's family (C: C, C^c, T^c, S^c columns; Dbar; C^f; T^f, S^f;
# ufbar; I_fNT), so columns that are zero by symmetry are measured against their family's scale
# instead of their own round-off.  With --tol, exit 1 if any of the --cols columns (default: all)
# exceeds TOL; exit 2 if a row of NEW has no row with the same a in REF. I_fNT (format 2) is
# compared when both tables have it; otherwise the 23 columns of format 1 are.
set -u
export LC_ALL=C
tol=""
cols=""
while [ $# -gt 0 ]; do
  case "$1" in
    --tol) tol=$2; shift 2 ;;
    --cols) cols=$2; shift 2 ;;
    *) break ;;
  esac
done
[ $# -eq 2 ] || { echo "usage: compare-tables.sh [--tol TOL] [--cols LIST] REF.dat NEW.dat" >&2; exit 2; }
for f in "$1" "$2"; do [ -r "$f" ] || { echo "compare-tables.sh: error: cannot read $f" >&2; exit 3; }; done

awk -v tol="$tol" -v cols="$cols" '
function abs(x) { return x < 0 ? -x : x }
BEGIN {
  nc = split("a D C_TT C_TN C_NT C_NN Dbar_TT Dbar_TN Dbar_NT Dbar_NN Cc_TT Cc_TN Cc_NT Cc_NN Tc_T Tc_N Sc_T Sc_N Cf_T Cf_N Tf Sf ufbar I_fNT", name, " ")
  for (j = 3; j <= 24; j++) fam[j] = (j <= 6 || (j >= 11 && j <= 18)) ? "C" : (j <= 10) ? "D" : (j <= 20) ? "Cf" : (j <= 22) ? "Tf" : (j == 23) ? "u" : "I"
  if (cols != "") { m = split(cols, cl, " "); for (i = 1; i <= m; i++) { ok = 0; for (j = 1; j <= nc; j++) if (name[j] == cl[i]) { sel[j] = 1; ok = 1 } if (!ok) { print "unknown column " cl[i] > "/dev/stderr"; exit 2 } } }
  else for (j = 3; j <= 24; j++) sel[j] = 1
}
/^#/ { if (FNR == 1) file++; if ($0 ~ /^# b = /) b = $4 + 0; if ($0 ~ /^# columns: .* I_fNT$/) withI[FILENAME] = 1; next }
NF == 0 { next }
FNR == 1 || file == 0 { }
{
  if (FILENAME == ARGV[1]) { nr++; for (j = 1; j <= 24; j++) R[nr, j] = $j + 0
    for (j = 3; j <= 24; j++) if (abs($j) > S[fam[j]]) S[fam[j]] = abs($j) }
  else { nn++; for (j = 1; j <= 24; j++) N[nn, j] = $j + 0 }
}
END {
  if (b <= 0) b = 1
  last = (withI[ARGV[1]] && withI[ARGV[2]]) ? 24 : 23
  if (cols != "" && sel[24] && last == 23) { print "I_fNT asked for, but not in both tables" > "/dev/stderr"; exit 2 }
  matched = 0
  for (i = 1; i <= nn; i++) {
    for (k = 1; k <= nr; k++) if (abs(R[k, 1] - N[i, 1]) <= 1e-12 * b) break
    if (k > nr) continue
    matched++
    for (j = 3; j <= last; j++) {
      fl = 1e-6 * S[fam[j]]; den = abs(R[k, j]); if (den < fl) den = fl; if (den == 0) den = 1
      r = abs(N[i, j] - R[k, j]) / den
      if (r > mx[j] || !(j in at)) { mx[j] = r; at[j] = N[i, 1] }
    }
  }
  if (matched == 0) { print "no common a values" > "/dev/stderr"; exit 2 }
  if (matched < nn) { printf "%d rows of %s have no row with the same a in %s\n", nn - matched, ARGV[2], ARGV[1] > "/dev/stderr"; exit 2 }
  printf "%d common a values\n", matched
  printf "%-8s %14s %14s %s\n", "column", "max rel change", "at a (mm)", (tol != "" ? "check" : "")
  bad = 0
  for (j = 3; j <= last; j++) {
    flag = ""
    if (tol != "" && (j in sel)) { if (mx[j] > tol + 0) { flag = "FAIL"; bad = 1 } else flag = "ok" }
    printf "%-8s %14.3e %14.10g %s\n", name[j], mx[j], at[j], flag
  }
  if (tol != "") printf "%s: all checked columns within %s\n", bad ? "FAIL" : "ok", tol
  exit bad
}' "$1" "$2"
