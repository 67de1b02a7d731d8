#!/usr/bin/env bash
# compare-columns.sh TABLE WORKDIR -- compare-tables.sh checks exactly the --cols columns (an
# I_fNT change must not fail '--cols Tf'), and reads tables as the loader does (CRLF line ends,
# a Fortran d exponent).  Awk only, no FreeFEM: TABLE is a committed format-2 table.
set -u
export LC_ALL=C
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
table=$1; work=$2
mkdir -p "$work" || exit 3
cmp_() { bash "$here/compare-tables.sh" "$@" > "$work/out.txt" 2>&1; }
fail=0
expect() {   # expect WHAT CODE [PATTERN]: the last comparison's exit code and output
  local what=$1 want=$2 pat=${3:-}
  if [ "$rc" -eq "$want" ] && { [ -z "$pat" ] || grep -Eq "$pat" "$work/out.txt"; }; then
    echo "ok   $what (exit $rc)"
  else
    echo "FAIL $what: exit $rc, expected $want${pat:+ and /$pat/}; output:"; cat "$work/out.txt"; fail=1
  fi
}
# column COL of data row ROW times (1 + F)
perturb() { awk -v row="$1" -v col="$2" -v f="$3" '/^#/ || NF == 0 { print; next } { n++; if (n == row) $col = sprintf("%.17g", $col * (1 + f)); print }' "$table"; }
perturb 5 24 0.02 > "$work/I2.dat"
perturb 5 21 0.01 > "$work/Tf1.dat"

cmp_ --tol 0.005 --cols "Tf" "$table" "$work/I2.dat"; rc=$?
expect "I_fNT changed 2 %, --cols Tf: passes" 0 '^ok: all checked columns within 0.005'
grep -Eq '^I_fNT +[0-9.e+-]+ +[0-9.e+-]+ *$' "$work/out.txt" \
  && echo "ok   I_fNT printed, not checked" || { echo "FAIL the I_fNT line carries a check flag:"; grep '^I_fNT' "$work/out.txt"; fail=1; }
cmp_ --tol 0.005 --cols "C_TT C_NN Dbar_TT Dbar_NN Cf_T Tf" "$table" "$work/I2.dat"; rc=$?
expect "I_fNT changed 2 %, convergence.sh's columns: pass" 0
cmp_ --tol 0.005 --cols "Tf I_fNT" "$table" "$work/I2.dat"; rc=$?
expect "I_fNT changed 2 %, --cols 'Tf I_fNT': fails naming I_fNT" 1 '^FAIL: checked column\(s\) I_fNT exceed'
cmp_ --tol 0.005 "$table" "$work/I2.dat"; rc=$?
expect "I_fNT changed 2 %, all columns: fails" 1
cmp_ --tol 0.005 --cols "Tf" "$table" "$work/Tf1.dat"; rc=$?
expect "Tf changed 1 %, --cols Tf: fails" 1 '^Tf .* FAIL$'
cmp_ --tol 0.005 --cols "Tf Xy" "$table" "$table"; rc=$?
expect "unknown column refused" 2 'unknown column Xy'
cmp_ --tol 1e-7 "$table" "$table"; rc=$?
expect "a table against itself" 0
cmp_ --tol 0.5 --tol 1e-7 "$table" "$table"; rc=$?
expect "--tol given twice refused" 2 '^compare-tables.sh: error: --tol given twice'
# CRLF line ends and d exponents: the same numbers
awk '/^#/ || NF == 0 { print; next } { gsub(/e/, "d"); print }' "$table" | sed 's/$/\r/' > "$work/crlf-d.dat"
grep -q 'd-' "$work/crlf-d.dat" || { echo "FAIL no d exponent in the test table"; fail=1; }
cmp_ --tol 0 "$table" "$work/crlf-d.dat"; rc=$?
expect "CRLF and d exponents read as the same numbers (I_fNT compared too)" 0 '^I_fNT .* ok$'
# the columns by name, as the loader reads them: C_TT and C_NN moved to the end (names and
# numbers) compare equal; a misnamed or a missing column is an error
awk '/^# columns: / { sub(/ C_TT/, ""); sub(/ C_NN/, ""); print $0 " C_NN C_TT"; next }
     /^#/ || NF == 0 { print; next } { tt = $3; nn = $6; $3 = ""; $6 = ""; $0 = $0; print $0, nn, tt }' "$table" > "$work/moved.dat"
cmp_ --tol 0 "$table" "$work/moved.dat"; rc=$?
expect "columns moved: the same table" 0 '^ok: all checked columns within 0'
sed '/^# columns: /s/ Dbar_TN / Dbar_Tn /' "$table" > "$work/misnamed.dat"
cmp_ "$table" "$work/misnamed.dat"; rc=$?
expect "a column misnamed" 2 'unknown column Dbar_Tn'
sed '/^# columns: /s/ Sc_N / /' "$table" > "$work/unnamed.dat"
cmp_ "$table" "$work/unnamed.dat"; rc=$?
expect "a column not named" 2 'does not name Sc_N'
# rows and header read as the loader reads them (table-reader.awk): what it refuses is named with
# the file, exit 2, and never compared as numbers
rows() { awk -v prog="$1" '/^#/ || NF == 0 { print; next } { n++; if (prog == "short" && n == 3) $5 = ""; if (prog == "x" && n == 3) $5 = "1.0e-3x"; if (prog == "dup" && n == 3) print; print }' "$table"; }
rows short > "$work/short.dat"
cmp_ "$table" "$work/short.dat"; rc=$?
expect "a row with a field missing, named by file and line" 2 'error: .*short[.]dat:[0-9]+: 23 numbers where the # columns: line names 24'
rows x > "$work/x.dat"
cmp_ "$table" "$work/x.dat"; rc=$?
expect "a field that is not one number (1.0e-3x)" 2 'x[.]dat:[0-9]+: column 5 [(]C_NT[)] is not a finite number: 1[.]0e-3x'
rows dup > "$work/dup.dat"
cmp_ "$table" "$work/dup.dat"; rc=$?
expect "a row given twice" 2 'dup[.]dat:[0-9]+: a = [0-9.e-]+ does not exceed the previous row.s a'
grep -v '^# columns: ' "$table" > "$work/nocols.dat"
cmp_ --tol 1e-3 "$work/nocols.dat" "$work/nocols.dat"; rc=$?
expect "no # columns: line (not read as all zeros)" 2 'nocols[.]dat:[0-9]+: .*before the # columns: line'
sed 's/^# E_m = .*/# E_m = -1000/' "$table" > "$work/negative.dat"
cmp_ "$table" "$work/negative.dat"; rc=$?
expect "a negative modulus in the header" 2 'negative[.]dat:[0-9]+: E_m = "-1000" is not one positive number'
# T^f at a = 0 is a placeholder the loader does not use: not compared
awk '/^#/ || NF == 0 { print; next } { n++; if (n == 1) $21 = "-12345"; print }' "$table" > "$work/tf0.dat"
cmp_ --tol 0 --cols Tf "$table" "$work/tf0.dat"; rc=$?
expect "T^f at a = 0 (a placeholder) not compared" 0 '^ok: all checked columns within 0'
# ufbar at a = 0 is a placeholder too (the smallest crack's, copied): a refined run of a few
# crack lengths copies another one; with the T^f placeholder, not compared
awk '/^#/ || NF == 0 { print; next } { n++; if (n == 1) { $21 = "-12345"; $23 = "0.5" } print }' "$table" > "$work/placeholders0.dat"
cmp_ --tol 0 "$table" "$work/placeholders0.dat"; rc=$?
expect "T^f and ufbar at a = 0 (placeholders) not compared" 0 '^ok: all checked columns within 0'
# the order REF NEW: a refined run of a few crack lengths (NEW) against the table (REF); reversed,
# or with an a the table lacks, exit 2 and a message that says which order or which a
awk '/^#/ || NF == 0 { print; next } { last = $0; n++; if (n == 1 || n == 5 || n == 20) print } END { print last }' "$table" > "$work/few.dat"
cmp_ --tol 0 "$table" "$work/few.dat"; rc=$?
expect "a table and a subset of its crack lengths (REF NEW)" 0 '^4 common a values'
cmp_ --tol 0 "$work/few.dat" "$table"; rc=$?
expect "the order reversed: named, with the order to give" 2 "have no row with the same a in .*few[.]dat .*the order is REF NEW.*: compare-tables[.]sh $table $work/few[.]dat\$"
awk '/^#/ || NF == 0 { print; next } { n++; if (n == 2) $1 = sprintf("%.17g", $1 * 1.001); print }' "$work/few.dat" > "$work/other-a.dat"
cmp_ --tol 0 "$table" "$work/other-a.dat"; rc=$?
expect "an a the table lacks: named" 2 'has no row at a = [0-9.e-]+ mm [(]a refined run.s --a-over-b values must be crack lengths of the table[)]'
# tables of two different RVEs (another E_m in the header): the note says so; with rows missing
# the message names the different RVEs, not the order
sed 's/^# E_m = .*/# E_m = 2000/' "$table" > "$work/other-rve.dat"
cmp_ "$table" "$work/other-rve.dat"; rc=$?
expect "another RVE: noted" 0 'note: .* are tables of different RVEs [(]E_m = 1000 and 2000[)]'
sed 's/^# E_m = .*/# E_m = 2000/' "$work/few.dat" > "$work/few-other-rve.dat"
cmp_ "$work/few-other-rve.dat" "$table"; rc=$?
expect "another RVE with rows missing: named, not the order" 2 'have no row with the same a in .*: they are tables of different RVEs'
if grep -q 'the order is REF NEW' "$work/out.txt"; then echo "FAIL the order named for tables of different RVEs"; fail=1; fi
cmp_ "$table" "$table"; rc=$?
if grep -q 'different RVEs' "$work/out.txt"; then echo "FAIL a table against itself noted as another RVE"; fail=1; fi
# --help and -h: the description, exit 0
for opt in --help -h; do
  cmp_ "$opt"; rc=$?
  expect "$opt" 0 '^  bash rve_freefem/compare-tables[.]sh .*REF[.]dat NEW[.]dat'
done
exit $fail
