#!/usr/bin/env bash
# messages.sh WORKDIR -- a refusal of make-table.sh names its real cause and the entry it comes
# from: a mesh too large for a far-field size hmax that is too small (not grow), a crack length
# too short named by the key that gave it (not every list of the file), an empty --a-over-b told
# as an option (no line to remove), and the diagnostics file of a table that would overwrite
# the parameter file.  make-table.sh --check only: no FreeFEM run.
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$1
mkdir -p "$work" || exit 3
# (a small valid RVE: the edits below make it bad; its comment lines dropped)
good=$(grep -v '^#' "$here/tests/two-cracks.params")
fail=0
# case NAME EXPECTED-REGEX UNEXPECTED-REGEX sed-expression-applied-to-good [options...]
case_() {
  local name=$1 pat=$2 notpat=$3 expr=$4; shift 4
  printf '%s\n' "$good" | sed "$expr" > "$work/$name.params"
  bash "$here/make-table.sh" --check "$@" "$work/$name.params" > "$work/$name.out" 2>&1
  local rc=$?
  if [ $rc -eq 2 ] && grep -Eq "$pat" "$work/$name.out" && { [ -z "$notpat" ] || ! grep -Eq "$notpat" "$work/$name.out"; }; then
    echo "ok   $name: exit $rc: $(grep -m1 -E "$pat" "$work/$name.out")"
  else
    echo "FAIL $name: exit $rc, expected /$pat/${notpat:+ and not /$notpat/}, output:"; cat "$work/$name.out"; fail=1
  fi
}
# a mesh too large because hmax is small: hmax named as the cause with its value, grow (1.6, a
# usual value) not blamed; the crack length a = 0 is in every table
case_ hmax_small \
  "^make-table.sh: error: grow = 1.6, .*hmax = 0.01, .* at a = 0 mm the mesh would need 2500 elements along the interface and 1000 along the sides .*: 3500 of them at the far-field spacing hmax/refine = 0.01 mm, .*: hmax = 0.01 mm is too small for this RVE [(]grow = 1.6 is not the cause[)]; use a larger hmax [(]this crack length: a = 0 [(]in every table[)][)]$" \
  "use grow > 1" 's/^hmax = .*/hmax = 0.01/'
# the same far-field size reached by --refine: the level named, and lowering it offered
case_ hmax_refined \
  "hmax/refine = 2/200 mm is too small for this RVE [(]grow = 1.6 is not the cause[)]; use a larger hmax or a lower --refine" \
  "use grow > 1" '' --refine 200
# grow = 1 with a short crack: grow is the cause, and the crack length's key and line are named
case_ grow_one \
  "at a = 0.05 mm the mesh would need 10000 elements along the interface .*: 14000 of them grow from the tip spacing .* = 0.0025 mm by only grow\^[(]1/refine[)] = 1 per element: grow = 1 keeps the spacing at the tip size; use grow > 1 .*[(]this crack length: .*grow_one[.]params:[0-9]+: a_list_mm[)]$" \
  "too small for this RVE" 's/^grow = .*/grow = 1/; $a a_list_mm = 0.05'
# fseg tiny: fseg named
case_ fseg_small "fseg = 0.0001 is too small [(]grow = 1.6 is not the cause[)]; use a larger fseg" "use grow > 1" '$a fseg = 0.0001'
# a ligament too short that ligament_over_b gives is named by that key and line alone
case_ ligament_key \
  "^make-table.sh: error: a = 24.999975 mm .*too short for this mesh .*[(]this crack length: .*ligament_key[.]params:13: ligament_over_b[)]$" \
  "a_over_b_list" '$a ligament_over_b = 0.1 1e-7 1'
# ... and one --a-over-b gives by the option, not by the file's keys it replaces
case_ ligament_option \
  "too short for this mesh .*[(]this crack length: --a-over-b[)]$" \
  "a_over_b_list|ligament_over_b" '$a ligament_over_b = 0.1 1e-3 1' --a-over-b "0.5 0.9999999"
# an empty --a-over-b: what to do with the option (there is no line to remove)
for v in '' ' '; do
  case_ "a_over_b_empty${v:+_blank}" \
    '^make-table.sh: error: --a-over-b is empty: give at least one value of a/b in [(]0, 1[)], e[.]g[.] --a-over-b "0[.]5 0[.]9" [(]a = 0 and a = b are added[)], or leave the option out' \
    "line" '' --a-over-b "$v"
done
# the parameter file named like the diagnostics file of the table: the table and the file it
# would write named, the parameter file left as it was, nothing else suggested that collides
printf '%s\n' "$good" > "$work/p-diag.txt"; cp "$work/p-diag.txt" "$work/before.params"
bash "$here/make-table.sh" --check "$work/p-diag.txt" "$work/p.dat" > "$work/collide.out" 2>&1; rc=$?
if [ $rc -eq 2 ] && grep -Eq "^make-table.sh: error: the table '.*/p[.]dat' would write its diagnostics file '.*/p-diag[.]txt' [(]the table's name without [.]dat, then -diag[.]txt[)], which is the parameter file '.*/p-diag[.]txt': it would overwrite it; name the table otherwise [(]e[.]g[.] .*/p-table[.]dat[)]" "$work/collide.out" \
   && ! grep -q 'p-diag[.]txt[.]dat' "$work/collide.out" && cmp -s "$work/p-diag.txt" "$work/before.params"; then
  echo "ok   diag_is_params: exit $rc: $(cat "$work/collide.out")"
else
  echo "FAIL diag_is_params: exit $rc, output:"; cat "$work/collide.out"; fail=1
fi
# the side file likewise, and with --no-fields (no side file written) the name is free
printf '%s\n' "$good" > "$work/q-fields.dat"
bash "$here/make-table.sh" --check "$work/q-fields.dat" "$work/q.dat" > "$work/collide.out" 2>&1; rc=$?
if [ $rc -eq 2 ] && grep -q "would write its side file '.*/q-fields[.]dat' .*which is the parameter file" "$work/collide.out"; then
  echo "ok   fields_is_params: exit $rc"
else
  echo "FAIL fields_is_params: exit $rc, output:"; cat "$work/collide.out"; fail=1
fi
bash "$here/make-table.sh" --check --no-fields "$work/q-fields.dat" "$work/q.dat" > "$work/collide.out" 2>&1; rc=$?
if [ $rc -eq 0 ]; then echo "ok   fields_is_params --no-fields: exit 0"; else echo "FAIL fields_is_params --no-fields: exit $rc"; cat "$work/collide.out"; fail=1; fi
exit $fail
