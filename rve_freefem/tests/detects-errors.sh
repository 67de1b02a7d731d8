#!/usr/bin/env bash
# detects-errors.sh TABLE DIAG WORKDIR -- check-table.sh must FAIL on tables that violate the
# identities by a little more than its tolerances (so the identity tests can fail for real).
set -u
export LC_ALL=C
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
table=$1; diag=$2; work=$3
mkdir -p "$work" || exit 3
bash "$here/check-table.sh" "$table" "$diag" > /dev/null || { echo "the unperturbed table must pass"; exit 1; }
# a format-1 table (no I_fNT column, as written before the Betti relations were checked) must pass
awk '/^# columns: / { sub(/ I_fNT$/, "") } /^#/ || NF == 0 { print; next } { NF = 23; print }' "$table" > "$work/format1.dat"
bash "$here/check-table.sh" "$work/format1.dat" "$diag" > /dev/null || { echo "the table without I_fNT must pass"; exit 1; }
# perturb column COL of data row ROW by the relative amount F
perturb() { awk -v row="$1" -v col="$2" -v f="$3" '/^#/ || NF == 0 { print; next } { n++; if (n == row) $col = sprintf("%.17g", $col * (1 + f)); print }' "$table"; }
fail=0
expect_fail() {
  local what=$1 file=$2 d=${3:-$diag}
  if bash "$here/check-table.sh" "$file" "$d" > "$work/out.txt" 2>&1; then
    echo "NOT DETECTED: $what"; fail=1
  else
    echo "detected: $what ($(grep -m1 FAIL "$work/out.txt" | awk '{ print $1 }'))"
  fi
}
perturb 3 11 1e-7 > "$work/t1.dat"; expect_fail "C^c_TT off by 1e-7 (eq 52, reciprocity)" "$work/t1.dat"
perturb 3 15 1e-9 > "$work/t2.dat"; expect_fail "T^c_T off by 1e-9" "$work/t2.dat"
perturb 1 3 1e-9 > "$work/t3.dat"; expect_fail "C_TT(0) off the closed form by 1e-9" "$work/t3.dat"
awk '/^#/ || NF == 0 { print; next } { if (++n == 4) $4 = "1e-6"; print }' "$table" > "$work/t4.dat"
expect_fail "C_TN = 1e-6 MPa instead of 0 (1e-9 Chat)" "$work/t4.dat"
n=$(awk '!/^#/ && NF' "$table" | wc -l)
perturb "$n" 21 1e-9 > "$work/t5.dat"; expect_fail "T^f(b) off -Chat_TT/h by 1e-9" "$work/t5.dat"
perturb 3 19 1e-7 > "$work/t6.dat"; expect_fail "C^f_T off by 1e-7 (reciprocity)" "$work/t6.dat"
perturb 3 24 1e-7 > "$work/t10.dat"; expect_fail "I_fNT off by 1e-7 ((ii'), (iii'))" "$work/t10.dat"
perturb 2 21 1e-9 > "$work/t11.dat"; expect_fail "T^f at the shortest crack off by 1e-9 ((ii'), (iii'))" "$work/t11.dat"
awk '/^#/ || NF == 0 { print; next } { if (++n == 1) $24 = "1e-3"; print }' "$table" > "$work/t12.dat"
expect_fail "I_fNT = 1e-3 at a = 0 (limit 0)" "$work/t12.dat"
# the columns are read by name, in any order, as the loader reads them: the table with its
# columns C_TT and C_NN moved to the end (names and numbers) must pass; with only their names
# swapped (C_NN's numbers read as C_TT's), or a column misnamed or missing, it must fail
awk '/^# columns: / { sub(/ C_TT/, ""); sub(/ C_NN/, ""); print $0 " C_NN C_TT"; next }
     /^#/ || NF == 0 { print; next } { tt = $3; nn = $6; $3 = ""; $6 = ""; $0 = $0; print $0, nn, tt }' "$table" > "$work/moved.dat"
bash "$here/check-table.sh" "$work/moved.dat" "$diag" > /dev/null || { echo "the table with columns moved must pass"; exit 1; }
sed '/^# columns: /s/ C_NN C_TT$/ C_TT C_NN/' "$work/moved.dat" > "$work/t7.dat"; expect_fail "C_TT and C_NN named the other way round" "$work/t7.dat"
sed '/^# columns: /s/ Dbar_TN / Dbar_Tn /' "$table" > "$work/t13.dat"; expect_fail "a column misnamed" "$work/t13.dat"
sed '/^# columns: /s/ Sc_N / /' "$table" > "$work/t14.dat"; expect_fail "a column not named" "$work/t14.dat"
awk '!/^#/ && NF { n++; if (n == 2) next } { print }' "$table" | sed '/^0 0 /d' > "$work/t8.dat"; expect_fail "a = 0 row missing" "$work/t8.dat"
awk '{ for (i = 1; i < NF; i++) if ($i == "resTfpt=" && ++k == 2) $(i + 1) = "2e-9"; print }' "$diag" > "$work/d9.txt"
expect_fail "p3 crack shear stress not uniform (2e-9)" "$table" "$work/d9.txt"
# a diag file that is not the table's: its residuals must not count as 0
awk '{ for (i = 1; i < NF; i++) if ($i == "resuf=" && ++k == 2) $(i + 1) = "nan"; print }' "$diag" > "$work/d15.txt"
expect_fail "a residual nan in the diag file" "$table" "$work/d15.txt"
awk '{ for (i = 1; i < NF; i++) if ($i == "resTc=" && ++k == 2) { $i = ""; $(i + 1) = "" } print }' "$diag" > "$work/d16.txt"
expect_fail "a residual missing in the diag file" "$table" "$work/d16.txt"
awk '!/^#/ && NF && ++k == 2 { next } { print }' "$diag" > "$work/d17.txt"
expect_fail "a line missing in the diag file" "$table" "$work/d17.txt"
sed 's/^a= 0 /a= 0.5 /' "$diag" > "$work/d18.txt"
expect_fail "the diag file of another table (a differs)" "$table" "$work/d18.txt"
fields=${diag%-diag.txt}-fields.dat
if [ -r "$fields" ]; then expect_fail "the side file given as the diag file" "$table" "$fields"; fi
exit $fail
