#!/usr/bin/env bash
# compare-tables.sh -- change of every coefficient between two RVE tables, row by row (same a).
#
#   bash rve_freefem/compare-tables.sh [--tol TOL] [--cols "C_TT C_NN ..."] REF.dat NEW.dat
#   bash rve_freefem/compare-tables.sh --help      (this text)
#
# The order matters: every a of NEW must be an a of REF (REF may have more). To check your table
# against a refined run of a few of its crack lengths, REF is your table and NEW the refined run:
#   compare-tables.sh mybrick.dat mybrick-r2.dat
# (each --a-over-b value of that run must be a crack length of your table; its rows a = 0 and
# a = b are).
# For each column: the largest relative change |new - ref| / max(|ref|, floor) over the rows whose
# a appears in both tables (a matched to 1e-12 b), and the a where it occurs.  floor = 1e-6 times
# the largest |ref| of the column's family (C: C, C^c, T^c, S^c columns; Dbar; C^f; T^f, S^f;
# ufbar; I_fNT), so columns that are zero by symmetry are measured against their family's scale
# instead of their own round-off.  With --tol, exit 1 if any of the --cols columns (default: all)
# exceeds TOL (the other columns are printed, not checked); exit 2 if a row of NEW has no row
# with the same a in REF, for a usage error or an unknown column; 3 for an unreadable file.
# I_fNT (format 2) is compared when both tables have it; otherwise the 23 columns of format 1 are.
# Tables are read as the loader reads them (rve_freefem/table-reader.awk, the reader of every
# rve_freefem tool): the columns by the names of their '# columns:' line, in any order; a carriage
# return ending a line is dropped, and a Fortran exponent letter d/D is read as e; what the loader
# refuses (a row with a field missing or not a number, a repeated or unordered a, no columns
# line, a bad header value) is named with its file and line, exit 2. T^f and ufbar at a = 0,
# placeholders the loader does not use (the values of the table's smallest crack, copied: the
# a0_row header line), are not compared. Tables of two different RVEs (their headers'
# h_m h_b b E_m nu_m E_b nu_b differ, e.g. a parameter file edited between the two runs) are
# compared all the same, with a note on standard error that names the values that differ.
set -u
export LC_ALL=C
usage() { echo "usage: compare-tables.sh [--tol TOL] [--cols LIST] REF.dat NEW.dat (or --help)" >&2; exit 2; }
tol=""
cols=""
given=" "
while [ $# -gt 0 ]; do
  # (an option given twice: which of its values counts is not guessed)
  case "$1" in
    --tol|--cols)
      case "$given" in *" $1 "*) echo "compare-tables.sh: error: $1 given twice" >&2; exit 2 ;; esac
      given="$given$1 " ;;
  esac
  case "$1" in
    --tol) [ $# -ge 2 ] || usage; tol=$2; shift 2 ;;
    --cols) [ $# -ge 2 ] || usage; cols=$2; shift 2 ;;
    # the help is the comment block at the top of this file
    -h|--help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;;
    -*) echo "compare-tables.sh: error: unknown option $1" >&2; usage ;;
    *) break ;;
  esac
done
[ $# -eq 2 ] || usage
if [ -n "$tol" ]; then
  printf '%s\n' "$tol" | awk '{ exit !($0 ~ /^([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$/) }' \
    || { echo "compare-tables.sh: error: --tol '$tol' is not a number >= 0" >&2; exit 2; }
fi
for f in "$1" "$2"; do [ -f "$f" ] && [ -r "$f" ] || { echo "compare-tables.sh: error: cannot read $f" >&2; exit 3; }; done

# both tables as the loader reads them, in the canonical column order (table-reader.awk: the one
# reader of the rve_freefem tools; what it refuses is named, with the file, exit 2)
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d) || { echo "compare-tables.sh: error: cannot make a temporary directory" >&2; exit 3; }
trap 'rm -rf "$work"' EXIT
k=0
for f in "$1" "$2"; do
  k=$((k + 1))
  if ! awk -f "$here/table-reader.awk" -v dest="$work/$k.dat" -v file="$f" "$f" > "$work/$k.txt"; then
    PREFIX="compare-tables.sh: error: " awk '{ print ENVIRON["PREFIX"] $0 }' "$work/$k.txt" >&2
    exit 2
  fi
done

awk -v tol="$tol" -v cols="$cols" -v ref="$1" -v new="$2" '
function abs(x) { return x < 0 ? -x : x }
BEGIN {
  nc = split("a D C_TT C_TN C_NT C_NN Dbar_TT Dbar_TN Dbar_NT Dbar_NN Cc_TT Cc_TN Cc_NT Cc_NN Tc_T Tc_N Sc_T Sc_N Cf_T Cf_N Tf Sf ufbar I_fNT", name, " ")
  for (j = 3; j <= 24; j++) fam[j] = (j <= 6 || (j >= 11 && j <= 18)) ? "C" : (j <= 10) ? "D" : (j <= 20) ? "Cf" : (j <= 22) ? "Tf" : (j == 23) ? "u" : "I"
  if (cols != "") { m = split(cols, cl, " "); for (i = 1; i <= m; i++) { ok = 0; for (j = 1; j <= nc; j++) if (name[j] == cl[i]) { sel[j] = 1; ok = 1 } if (!ok) { print "compare-tables.sh: error: unknown column " cl[i] > "/dev/stderr"; stop = 1; exit 2 } } }
  else for (j = 3; j <= 24; j++) sel[j] = 1
}
FNR == 1 { fi++ }
# the canonical tables: "# columns: a D ... ufbar [I_fNT]", rows in that order
/^# columns:/ { withI[fi] = (NF - 2 == 24); next }
/^#/ {
  if ($0 ~ /^# b = /) b = $4 + 0
  # (the RVE of each table: tables of two different RVEs are no mesh comparison)
  if ($2 ~ /^(h_m|h_b|b|E_m|nu_m|E_b|nu_b)$/ && $3 == "=") rve[fi, $2] = $4
  next
}
NF == 0 { next }
{
  if (fi == 1) { nr++; for (k = 1; k <= NF; k++) R[nr, k] = $k + 0
    for (j = 3; j <= 24; j++) if (abs(R[nr, j]) > S[fam[j]]) S[fam[j]] = abs(R[nr, j]) }
  else { nn++; for (k = 1; k <= NF; k++) N[nn, k] = $k + 0 }
}
END {
  if (stop) exit 2
  if (b <= 0) b = 1
  last = (withI[1] && withI[2]) ? 24 : 23
  # (j in sel) only: a test like sel[24] would create the element and check I_fNT unasked
  if (cols != "" && (24 in sel) && last == 23) { print "I_fNT asked for, but not in both tables" > "/dev/stderr"; exit 2 }
  matched = 0
  for (i = 1; i <= nn; i++) {
    for (k = 1; k <= nr; k++) if (abs(R[k, 1] - N[i, 1]) <= 1e-12 * b) break
    if (k > nr) { nmiss++; if (nmiss <= 5) missing = missing (nmiss > 1 ? ", " : "") sprintf("%.10g", N[i, 1]); else if (nmiss == 6) missing = missing ", ..."; continue }
    matched++
    for (j = 3; j <= last; j++) {
      # (T^f and ufbar at a = 0 are placeholders, the values of the smallest crack copied: the
      # loader does not use them, and a table of other crack lengths copies other values)
      if ((j == 21 || j == 23) && N[i, 1] == 0) continue
      fl = 1e-6 * S[fam[j]]; den = abs(R[k, j]); if (den < fl) den = fl; if (den == 0) den = 1
      r = abs(N[i, j] - R[k, j]) / den
      if (r > mx[j] || !(j in at)) { mx[j] = r; at[j] = N[i, 1] }
    }
  }
  nk = split("h_m h_b b E_m nu_m E_b nu_b", rk, " "); diff = ""
  for (i = 1; i <= nk; i++)
    if (((1, rk[i]) in rve) && ((2, rk[i]) in rve) && rve[1, rk[i]] + 0 != rve[2, rk[i]] + 0)
      diff = diff (diff == "" ? "" : ", ") rk[i] " = " sprintf("%.10g", rve[1, rk[i]]) " and " sprintf("%.10g", rve[2, rk[i]])
  if (diff != "") printf "compare-tables.sh: note: %s and %s are tables of different RVEs (%s): the changes are not those of a finer mesh\n", ref, new, diff > "/dev/stderr"
  if (matched == 0) { print "no common a values" > "/dev/stderr"; exit 2 }
  if (matched < nn) {
    printf "%d rows of %s have no row with the same a in %s (every a of the second table must be an a of the first)", nn - matched, new, ref > "/dev/stderr"
    if (diff != "") printf ": they are tables of different RVEs (above)\n" > "/dev/stderr"
    else if (nn > nr) printf ": the order is REF NEW, the table with every crack length first; for a table and a refined run of a few of its crack lengths: compare-tables.sh %s %s\n", new, ref > "/dev/stderr"
    else printf ": %s has no row at a = %s mm (a refined run'"'"'s --a-over-b values must be crack lengths of the table)\n", ref, missing > "/dev/stderr"
    exit 2
  }
  printf "%d common a values\n", matched
  printf "%-8s %14s %14s %s\n", "column", "max rel change", "at a (mm)", (tol != "" ? "check" : "")
  bad = 0; over = ""
  for (j = 3; j <= last; j++) {
    flag = ""
    if (tol != "" && (j in sel)) { if (!(mx[j] <= tol + 0)) { flag = "FAIL"; bad = 1; over = over " " name[j] } else flag = "ok" }
    printf "%-8s %14.3e %14.10g %s\n", name[j], mx[j], at[j], flag
  }
  if (tol != "") { if (bad) printf "FAIL: checked column(s)%s exceed %s\n", over, tol; else printf "ok: all checked columns within %s\n", tol }
  exit bad
}' "$work/1.dat" "$work/2.dat"
