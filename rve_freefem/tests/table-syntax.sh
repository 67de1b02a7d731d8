#!/usr/bin/env bash
# table-syntax.sh TABLE DIAG WORKDIR -- check-table.sh reads a table as the loader does
# (src/interphase_text_input.f90: a carriage return ending a line is dropped; a number is
# [sign](digits[.[digits]] | .digits)[(e|E|d|D)[sign]digits], finite), and refuses what the
# loader refuses (1e400, fewer than the 4 rows its spline needs).  Awk only, no FreeFEM.
set -u
export LC_ALL=C
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
table=$1; diag=$2; work=$3
mkdir -p "$work" || exit 3
fail=0
check() {   # check WHAT WANT(pass|fail) FILE [PATTERN]
  local what=$1 want=$2 file=$3 pat=${4:-} rc
  bash "$here/check-table.sh" "$file" > "$work/out.txt" 2>&1; rc=$?
  if { [ "$want" = pass ] && [ $rc -eq 0 ]; } || { [ "$want" = fail ] && [ $rc -eq 1 ]; } \
     && { [ -z "$pat" ] || grep -Eq "$pat" "$work/out.txt"; }; then
    echo "ok   $what (exit $rc)"
  else
    echo "FAIL $what: exit $rc, expected to $want${pat:+ with /$pat/}; output:"; head -20 "$work/out.txt"; fail=1
  fi
}
data() { awk -v row="$1" -v col="$2" -v val="$3" '/^#/ || NF == 0 { print; next } { if (++n == row) $col = val; print }' "$table"; }
check "the table as committed" pass "$table"
grep -q '^note: the header says n_a' "$work/out.txt" && { echo "FAIL the committed table's n_a is noted"; fail=1; }
# rows deleted by hand (the 10th to the 14th): the header's n_a no longer counts them, a note
awk '/^#/ || NF == 0 { print; next } { if (++n < 10 || n > 14) print }' "$table" > "$work/rows-deleted.dat"
check "rows deleted: n_a noted, still passes" pass "$work/rows-deleted.dat" \
  '^note: the header says n_a = [0-9]+ but the table has [0-9]+ rows: the provenance'
sed 's/$/\r/' "$table" > "$work/crlf.dat"
check "CRLF line ends" pass "$work/crlf.dat" '^format +ok'
awk '/^#/ || NF == 0 { print; next } { gsub(/e/, "d"); print }' "$table" > "$work/d.dat"
grep -q '^[^#].*d-' "$work/d.dat" || { echo "FAIL no d exponent in the test table"; fail=1; }
check "Fortran d exponents (every e written d)" pass "$work/d.dat"
awk '/^#/ || NF == 0 { print; next } { gsub(/e/, "D"); print }' "$table" | sed 's/$/\r/' > "$work/D-crlf.dat"
check "D exponents and CRLF" pass "$work/D-crlf.dat"
# a tab in a header line is a blank, as the loader reads it ('# Chat_TT<TAB>= 1' is the key Chat_TT)
sed '/^#/s/ /\t/g' "$table" > "$work/header-tabs.dat"
grep -q '^#	Chat_TT	=	' "$work/header-tabs.dat" || { echo "FAIL no tab in the test table's header"; fail=1; }
check "tabs for every blank of the header" pass "$work/header-tabs.dat" '^format +ok'
# a d exponent is read as one: C_TT(0) = 1d3 is 1000, not 1 (and not the closed form)
data 1 3 1d3 > "$work/d3.dat"
check "C_TT(0) = 1d3 read as 1000 (closed form fails)" fail "$work/d3.dat" '^closed +FAIL'
data 3 20 1e400 > "$work/inf.dat"
check "1e400 (beyond a double) refused" fail "$work/inf.dat" 'not a finite number: 1e400'
data 3 20 1x-3 > "$work/x.dat"
check "1x-3 refused" fail "$work/x.dat" 'not a finite number: 1x-3'
data 3 20 1-3 > "$work/minus.dat"
check "1-3 (no exponent letter) refused" fail "$work/minus.dat" 'not a finite number: 1-3'
n=$(awk '!/^#/ && NF' "$table" | wc -l)
awk -v n="$n" '/^#/ || NF == 0 { print; next } { k++; if (k == 1 || k == 2 || k == n) print }' "$table" > "$work/three.dat"
check "3 rows (a = 0, one a, a = b) refused" fail "$work/three.dat" 'three[.]dat: 3 rows: a table needs at least 4'
awk -v n="$n" '/^#/ || NF == 0 { print; next } { k++; if (k == 1 || k == 2 || k == 3 || k == n) print }' "$table" > "$work/four.dat"
check "4 rows accepted" pass "$work/four.dat" '4 rows of'
# the header as the loader reads it: its numbers in range, a key it reads given once, h = h_m +
# h_b, b and h given, no byte-order mark; a repeated row named
hdrset() { sed "s/^# $1 = .*/# $1 = $2/" "$table"; }
hdrset E_m -1000 > "$work/Em.dat"
check "E_m = -1000 refused (not an identity passed with a negative scale)" fail "$work/Em.dat" 'E_m = "-1000" is not one positive number'
hdrset nu_m 0.7 > "$work/num.dat"
check "nu_m = 0.7 refused" fail "$work/num.dat" 'nu_m = "0.7" is not one number in [(]-1, 0.5[)]'
hdrset E_m 1000x > "$work/Emx.dat"
check "E_m = 1000x refused" fail "$work/Emx.dat" 'E_m = "1000x" is not one positive number'
hdrset h 40 > "$work/h.dat"
check "h not h_m + h_b refused" fail "$work/h.dat" "the header's h = 40 mm is not h_m [+] h_b = 5 mm"
grep -v '^# h = ' "$table" > "$work/noh.dat"
check "h missing refused" fail "$work/noh.dat" 'must give "b = [.][.][.]" and "h = [.][.][.]"'
awk '{ print } /^# E_b = / { print }' "$table" > "$work/Eb2.dat"
check "E_b given twice refused" fail "$work/Eb2.dat" 'key "E_b" given twice'
printf '\357\273\277' | cat - "$table" > "$work/bom.dat"
check "a byte-order mark refused and named" fail "$work/bom.dat" 'byte-order mark'
awk '/^#/ || NF == 0 { print; next } { if (++k == 5) print; print }' "$table" > "$work/dup.dat"
check "a repeated row named" fail "$work/dup.dat" 'dup[.]dat:44: a = [0-9.e-]+ does not exceed the previous row.s a = [0-9.e-]+ [(]line 43[)]'
# the header's forms the loader reads: blanks and tabs before and after "#", "#columns:" with no
# blank; a key the loader reads after the columns line is refused, as the loader refuses it
awk '/^# / { sub(/^# /, (NR % 2 ? "  #\t" : "#")) } { print }' "$table" > "$work/blanks.dat"
grep -q '^#columns:' "$work/blanks.dat" && grep -q '^  #' "$work/blanks.dat" || { echo "FAIL the header forms were not made"; fail=1; }
check "blanks around # and #columns: read as the loader reads them" pass "$work/blanks.dat"
awk '{ print } /^# columns:/ { print "# b = 25" }' "$table" > "$work/late-key.dat"
check "a key the loader reads after the columns line refused" fail "$work/late-key.dat" 'key "b" after the "# columns:" line'
# h = h_m + h_b is checked whenever both layers are given, with or without E and nu (the loader too)
grep -v '^# [En]' "$table" | sed 's/^# h = .*/# h = 40/' > "$work/h-no-elastic.dat"
check "h not h_m + h_b refused without E and nu" fail "$work/h-no-elastic.dat" "the header's h = 40 mm is not h_m [+] h_b = 5 mm"
# what the loader refuses and the reader took: a value that underflows (mawk compares "1e-400" as
# a string), one beyond the 1e100 window, a key spelt like one the loader reads, a header number
# out of its window, a_Tf_limit out of [-1e20, 0] or against the elastic constants, a key
# without its partner
data 3 4 1e-400 > "$work/under.dat"
check "1e-400 (underflows to 0) refused" fail "$work/under.dat" 'under[.]dat:41: column 4 [(]C_TN[)] is out of range [(][|]x[|] < 2.2e-308[)]: 1e-400'
data 3 4 1e-310 > "$work/subnormal.dat"
check "1e-310 (subnormal) refused" fail "$work/subnormal.dat" 'column 4 [(]C_TN[)] is out of range [(][|]x[|] < 2.2e-308[)]: 1e-310'
data 3 4 0.000e-999 > "$work/zero.dat"
check "0.000e-999 (a zero) accepted" pass "$work/zero.dat"
data 3 21 -1.7e308 > "$work/tfhuge.dat"
check "Tf = -1.7e308 (beyond 1e100) refused" fail "$work/tfhuge.dat" 'column 21 [(]Tf[)] lies beyond 1e100 in magnitude'
sed 's/^# h = 5$/&\n# B = 25/' "$table" > "$work/B.dat"
check "key B (wrong case) refused" fail "$work/B.dat" 'unknown key "B": is it "b"'
sed 's/^# h = 5$/&\n# fromat = x/' "$table" > "$work/fromat.dat"
check "key fromat refused" fail "$work/fromat.dat" 'unknown key "fromat": is it "format"'
sed 's/^# h = 5$/&\n# Chat_NT = 1/' "$table" > "$work/chatnt.dat"
check "a provenance key one letter from a read one (Chat_NT) accepted" pass "$work/chatnt.dat"
hdrset E_m 1e-21 > "$work/Em-tiny.dat"
check "E_m = 1e-21 refused" fail "$work/Em-tiny.dat" 'E_m = "1e-21" lies outside [[]1e-20, 1e20[]]'
sed 's/^# h = 5$/&\n# a_Tf_limit = -1e308/' "$table" > "$work/limit-huge.dat"
check "a_Tf_limit = -1e308 refused" fail "$work/limit-huge.dat" 'a_Tf_limit = "-1e308" is not one number in [[]-1e20, 0[]]'
sed 's/^# h = 5$/&\n# a_Tf_limit = -1/' "$table" > "$work/limit-wrong.dat"
check "a_Tf_limit = -1 against E, nu refused" fail "$work/limit-wrong.dat" "a_Tf_limit = -1 contradicts the header's E_m, nu_m, E_b, nu_b, which give -554.63"
grep -v '^# h_b = ' "$table" > "$work/no-hb.dat"
check "h_m without h_b refused" fail "$work/no-hb.dat" 'the header gives h_m but not h_b'
grep -v '^# E_b = ' "$table" > "$work/no-Eb.dat"
check "E_m without E_b refused" fail "$work/no-Eb.dat" 'E_m, nu_m, E_b, nu_b but not E_b'
# the a = 0 row's Dbar: 0 within 1e-8 h with the header's elastic constants (the loader's check)
data 1 10 3 > "$work/dbar0-three.dat"
check "Dbar_NN = 3 at a = 0 refused" fail "$work/dbar0-three.dat" 'Dbar_NN = 3 at a = 0, where the limit a -> 0[+] is 0'
data 1 7 1e-6 > "$work/dbar0-small.dat"
check "Dbar_TT = 1e-6 at a = 0 refused (1e-8 h = 5e-8)" fail "$work/dbar0-small.dat" 'Dbar_TT = 1e-06 at a = 0'
# a number the reader cannot read is named by the file, its line and the column's name, and the
# reading stops there (as the loader's): a decimal comma in the a column gives no follow-on
# "a = 0 does not exceed the previous a" (line 47: the 9th row of the committed table)
data 9 3 12,5 > "$work/comma.dat"
check "a decimal comma named by file, line and column" fail "$work/comma.dat" \
  'comma[.]dat:47: column 3 [(]C_TT[)] is not a finite number: 12,5 [(]a decimal comma[?] write a point: 12[.]5[)]'
data 9 1 12,5 > "$work/comma-a.dat"
check "a decimal comma in the a column, no follow-on error" fail "$work/comma-a.dat" 'comma-a[.]dat:47: column 1 [(]a[)] is not a finite number'
if grep -q 'does not exceed' "$work/out.txt" || [ "$(grep -c . "$work/out.txt")" -ne 2 ]; then
  echo "FAIL more than the one refusal after the decimal comma:"; cat "$work/out.txt"; fail=1
else
  echo "ok   the reading stopped at the decimal comma"
fi
# a folder given for the table or the diag file: named as a folder, exit 3 (not awk's read error)
mkdir -p "$work/folder.dat"
for args in "$work/folder.dat" "$table $work/folder.dat"; do
  # shellcheck disable=SC2086
  bash "$here/check-table.sh" $args > "$work/out.txt" 2>&1; rc=$?
  if [ $rc -eq 3 ] && grep -q "folder[.]dat is a directory, not a file" "$work/out.txt" && ! grep -q 'awk' "$work/out.txt"; then
    echo "ok   a folder refused ($args)"
  else
    echo "FAIL a folder ($args): exit $rc, output:"; cat "$work/out.txt"; fail=1
  fi
done
# --help and -h: the description, exit 0 (standard output)
for opt in --help -h; do
  bash "$here/check-table.sh" "$opt" > "$work/help.txt" 2>&1; rc=$?
  if [ $rc -eq 0 ] && grep -q '^  bash rve_freefem/check-table[.]sh TABLE[.]dat' "$work/help.txt"; then
    echo "ok   $opt"
  else
    echo "FAIL $opt: no description or a non-zero exit"; fail=1
  fi
done
exit $fail
