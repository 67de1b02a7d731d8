#!/usr/bin/env bash
# plausibility.sh WORKDIR -- make-table.sh --check warns (exit 0, no refusal) about parameters
# that pass every identity check but cannot be what the user meant: moduli in GPa or Pa, lengths
# in m, a far-field mesh size larger than a layer (a table that is not converged although
# check-table.sh and the loader accept it), and graded-mesh keys or --refine given with huni,
# which has no use for them.  The shipped parameter files give no warning.
# No FreeFEM run.
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$1
mkdir -p "$work" || exit 3
good=$(grep -v '^#' "$here/tests/two-cracks.params")
fail=0
# case NAME EXPECTED-WARNING-REGEX sed-expression-applied-to-good
case_() {
  local name=$1 pat=$2 expr=$3
  printf '%s\n' "$good" | sed "$expr" > "$work/$name.params"
  bash "$here/make-table.sh" --check "$work/$name.params" > "$work/$name.out" 2>&1
  local rc=$?
  if [ $rc -eq 0 ] && grep -Eq "make-table.sh: warning: .*$name.params:[0-9]+: $pat" "$work/$name.out"; then
    echo "ok   $name: $(grep -m1 -E "$pat" "$work/$name.out")"
  else
    echo "FAIL $name: exit $rc, expected a warning matching '$pat', output:"; cat "$work/$name.out"; fail=1
  fi
}
case_ gpa_mortar  "'E_m' = 1 MPa is softer than mortars and bricks usually are: moduli are in MPa"    's/^E_m = .*/E_m = 1/'
case_ gpa_brick   "'E_b' = 16 MPa is softer than mortars and bricks usually are"                      's/^E_b = .*/E_b = 16/'
case_ pa_brick    "'E_b' = 1.6e10 MPa is stiffer than any mortar or brick"                 's/^E_b = .*/E_b = 1.6e10/'
case_ metre       "'h_m' = 0.002 mm is smaller than any mortar joint or brick dimension"  's/^h_m = .*/h_m = 0.002/'
case_ coarse_mesh "hmax/refine = 4 mm is larger than the thinner layer \(h_m = 2 mm\)"     's/^hmax = .*/hmax = 4/'
case_ coarse_brick "hmax/refine = 2 mm is larger than the thinner layer \(h_b = 1 mm\)"    's/^h_b = .*/h_b = 1/'
# the uniform mesh (huni) uses none of the graded mesh's keys: each one given is named, at its line
case_ huni_unused "'hmax' = 3 is not used: with huni = 0.5 [(].*huni_unused[.]params:13[)] the mesh is uniform squares of side huni: neither the graded mesh's keys [(]hmax, ftip, htipmax, grow, fseg[)] nor the refinement level refine have an effect" \
  's/^hmax = .*/hmax = 3/; $a huni = 0.5'
out=$(cat "$work/huni_unused.out")
for key in ftip htipmax grow; do
  printf '%s\n' "$out" | grep -Eq "^make-table.sh: warning: .*huni_unused[.]params:[0-9]+: '$key' = [0-9.]+ is not used: with huni = 0.5" \
    && echo "ok   huni_unused: $key named" || { echo "FAIL huni_unused: no warning for $key:"; printf '%s\n' "$out"; fail=1; }
done
printf '%s\n' "$out" | grep -q "'fseg'" && { echo "FAIL huni_unused: fseg (not in the file) named"; fail=1; }
# ... and --refine does not refine it
bash "$here/make-table.sh" --check --refine 2 "$here/params/paper-resolution.params" > "$work/huni-refine.out" 2>&1; rc=$?
if [ $rc -eq 0 ] && grep -q "^make-table.sh: warning: --refine 2 is not used: with huni = 1 (.*paper-resolution[.]params:[0-9]*) the mesh is uniform squares of side huni" "$work/huni-refine.out"; then
  echo "ok   huni with --refine 2: warned"
else
  echo "FAIL huni with --refine 2: exit $rc, no warning:"; cat "$work/huni-refine.out"; fail=1
fi
# --refine divides hmax: the same file at refine 2 is no longer coarser than the layer
printf '%s\n' "$good" | sed 's/^hmax = .*/hmax = 4/' > "$work/refined.params"
if bash "$here/make-table.sh" --check --refine 2 "$work/refined.params" 2>&1 | grep -q warning; then
  echo "FAIL refined: hmax = 4 at --refine 2 (2 mm, = h_m) warned"; fail=1
else
  echo "ok   refined: hmax = 4 at --refine 2 gives no warning"
fi
for p in "$here"/params/*.params "$here/tests/two-cracks.params"; do
  out=$(bash "$here/make-table.sh" --check "$p" 2>&1)
  if [ $? -ne 0 ] || printf '%s\n' "$out" | grep -q warning; then
    echo "FAIL $(basename "$p"): a shipped parameter file warns or fails:"; printf '%s\n' "$out"; fail=1
  else
    echo "ok   $(basename "$p"): no warning"
  fi
done
exit $fail
