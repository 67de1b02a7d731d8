#!/usr/bin/env bash
# sparse-rows.sh TABLES WORKDIR -- check-table.sh warns (a warning line; the exit status is that
# of the checks) when a table's rows are sparser near a = b than docs/rve.md recommends for the
# law: the shortest ligament (b - a)/b above 1e-4, or fewer than 3 rows per decade of the
# ligament below 0.1.  The law's tables (paper.dat, paper-dense.dat) give no warning; the two
# committed tables that are no law's (paper-resolution.dat, the paper's own 1 mm squares, and
# paper-small-d.dat, the short-crack reference) give it.  Awk only, no FreeFEM.
set -u
export LC_ALL=C
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
tables=$1; work=$2
mkdir -p "$work" || exit 3
fail=0
# check WHAT FILE WARN-REGEX|none: exit 0, and the warning matched (or no warning line at all)
check() {
  local what=$1 file=$2 pat=$3 rc
  bash "$here/check-table.sh" "$file" > "$work/out.txt" 2>&1; rc=$?
  if [ $rc -eq 0 ] && { { [ "$pat" = none ] && ! grep -q '^warning:' "$work/out.txt"; } \
                        || { [ "$pat" != none ] && grep -Eq "^warning: rows too sparse near a = b for the law: $pat" "$work/out.txt"; }; }; then
    echo "ok   $what (exit $rc)$(grep -m1 '^warning:' "$work/out.txt" | sed 's/^/: /')"
  else
    echo "FAIL $what: exit $rc, expected ${pat/none/no warning}; output:"; cat "$work/out.txt"; fail=1
  fi
}
table=$tables/paper.dat
check "paper.dat (6 ligaments per decade down to 1e-4 b)" "$table" none
check "paper-dense.dat (12 per decade)" "$tables/paper-dense.dat" none
check "paper-resolution.dat (a = 0, 1, ..., 25 mm) warns" "$tables/paper-resolution.dat" \
  'the shortest ligament [(]b - a[)]/b is 0[.]04 [(]a = 24 mm, b = 25 mm[)], above 0[.]0001'
check "paper-small-d.dat (up to a/b = 0.09) warns" "$tables/paper-small-d.dat" \
  'the shortest ligament [(]b - a[)]/b is 0[.]91 [(]a = 2[.]25 mm, b = 25 mm[)], above 0[.]0001'
# rows kept by their ligament l = (b - a)/b: keep LO HI keeps a = b and the rows with l outside (LO, HI)
keep() { awk -v lo="$1" -v hi="$2" '/^#/ || NF == 0 { print; next }
  { n++; row[n] = $0; a[n] = $1 }
  END { b = a[n]; for (i = 1; i <= n; i++) { l = (b - a[i]) / b; if (i == n || !(l > lo && l < hi)) print row[i] } }' "$table"; }
# the ligaments 1e-2 > l > 1e-3 deleted: one decade without a row
keep 1.0001e-3 0.9999e-2 > "$work/gap.dat"
check "a decade of ligaments without rows" "$work/gap.dat" \
  'between the ligaments [(]b - a[)]/b = 0[.]01 [(]a = 24[.]75 mm[)] and 0[.]001 [(]a = 24[.]975 mm[)] the rows are 1 per decade, fewer than 3'
# every other row of its ligament_over_b = 0.1 1e-4 6 deleted (l = 0.1 10^(-k/6), k odd): 3 per
# decade down to 1e-4 b, no warning
awk '/^#/ || NF == 0 { print; next } { n++; row[n] = $0; a[n] = $1 }
  END { b = a[n]; for (i = 1; i <= n; i++) { l = (b - a[i]) / b
          if (l > 0) { k = 6 * log(0.1 / l) / log(10); r = int(k + 0.5); if (r % 2 == 1 && (k - r) ^ 2 < 1e-12) continue }
          print row[i] } }' "$table" > "$work/three.dat"
[ "$(awk '!/^#/ && NF' "$work/three.dat" | wc -l)" -eq 37 ] || { echo "FAIL three.dat has not 37 rows"; fail=1; }
check "3 ligaments per decade" "$work/three.dat" none
# the ligaments below 1e-3 deleted: the shortest ligament 1e-3 b
keep 0 0.9999e-3 > "$work/short.dat"
check "the shortest ligament 1e-3 b" "$work/short.dat" \
  'the shortest ligament [(]b - a[)]/b is 0[.]001 [(]a = 24[.]975 mm, b = 25 mm[)], above 0[.]0001; .*add rows geometrically close to b down to 0[.]0001 b'
# 4 rows: a/b = 0, 0.3, 0.6, 1 (the spline's minimum, passes every identity)
awk '/^#/ || NF == 0 { print; next } $2 == 0 || $2 == 0.3 || $2 == 0.6 || $2 == 1' "$table" > "$work/four.dat"
[ "$(awk '!/^#/ && NF' "$work/four.dat" | wc -l)" -eq 4 ] || { echo "FAIL four.dat has not 4 rows"; fail=1; }
check "4 rows (a/b = 0, 0.3, 0.6, 1)" "$work/four.dat" 'the shortest ligament [(]b - a[)]/b is 0[.]4 [(]a = 15 mm'
# the warning does not hide a failure: the 4-row table with C_TT(0) wrong still fails (exit 1)
awk '/^#/ || NF == 0 { print; next } { if (++k == 1) $3 = 1; print }' "$work/four.dat" > "$work/four-bad.dat"
bash "$here/check-table.sh" "$work/four-bad.dat" > "$work/out.txt" 2>&1; rc=$?
if [ $rc -eq 1 ] && grep -q '^warning: rows too sparse' "$work/out.txt" && grep -Eq '^closed +FAIL' "$work/out.txt"; then
  echo "ok   4 rows and a wrong C_TT(0): warning and exit 1"
else
  echo "FAIL 4 rows and a wrong C_TT(0): exit $rc"; cat "$work/out.txt"; fail=1
fi
exit $fail
