#!/usr/bin/env bash
# convergence-failures.sh PARAMS TABLE WORKDIR -- convergence.sh stops with a message and its
# documented exit code when a step fails, and passes a converged study.  No FreeFEM is run:
# failing runs use a stand-in FreeFem++ that fails; the comparisons use --reuse with copies of
# TABLE (a committed format-2 table made from PARAMS) as the refined tables.
set -u
export LC_ALL=C
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
params=$1; table=$2; work=$3
rm -rf "$work"; mkdir -p "$work/bin" || exit 3
fail=0
conv() { bash "$here/convergence.sh" "$@" > "$work/out.txt" 2>&1; rc=$?; }
expect() {   # expect WHAT CODE PATTERN: the last run's exit code and a line of its output
  local what=$1 want=$2 pat=$3
  if [ "$rc" -eq "$want" ] && grep -Eq -- "$pat" "$work/out.txt"; then
    echo "ok   $what: exit $rc: $(grep -m1 -E -- "$pat" "$work/out.txt")"
  else
    echo "FAIL $what: exit $rc, expected $want and /$pat/; output:"; tail -30 "$work/out.txt"; fail=1
  fi
}
# (a small valid RVE: the edits below make it bad; its comment lines dropped)
good=$(grep -v '^#' "$here/tests/two-cracks.params")

# --help and -h: the description at the top (its exit codes), exit 0, no line of code
for opt in --help -h; do
  conv "$opt"
  expect "$opt" 0 '^Exit code: 0 converged'
  ! grep -q -e 'set -u' -e '^#' "$work/out.txt" || { echo "FAIL $opt printed code or comment marks"; fail=1; }
done

# a bad parameter file: exit 2 (make-table.sh's code), before any run
printf '%s\nthickness = 3\n' "$good" > "$work/unknown.params"
conv "$work/unknown.params" "$work/unknown"
expect "unknown key" 2 '^convergence.sh: error: .*refine x1: the parameters are refused'
[ ! -e "$work/unknown/unknown-r1.log" ] || { echo "FAIL a run was started"; fail=1; }

# a ligament that refine x1 and x2 mesh but x4 cannot: stops before the x1 run, not after it
printf '%s\n' "$good" | sed 's/^a_over_b_list = .*/a_over_b_list = 0.5 0.999994/' > "$work/ligament.params"
conv "$work/ligament.params" "$work/ligament"
expect "ligament too short at refine x4" 2 'too short for this mesh .* at refine 4'
grep -q '^convergence.sh: error: .*refine x4' "$work/out.txt" || { echo "FAIL no convergence.sh error line"; fail=1; }
[ ! -e "$work/ligament/ligament-r1.log" ] || { echo "FAIL the x1 run was started"; fail=1; }

# a FreeFEM run that fails: exit 4 with the run's message (a stand-in FreeFem++ that fails)
printf '#!/bin/sh\necho "stand-in FreeFem++: failed on purpose" >&2\nexit 1\n' > "$work/bin/FreeFem++"
chmod +x "$work/bin/FreeFem++"
printf '%s\n' "$good" > "$work/good.params"
PATH="$work/bin:$PATH" conv "$work/good.params" "$work/good"
expect "failed FreeFEM run" 4 '^convergence.sh: error: make-table.sh --refine 1 failed \(exit 4\)'
grep -q 'stand-in FreeFem++: failed on purpose' "$work/out.txt" || { echo "FAIL the run's message is not shown"; fail=1; }
grep -q '^== ' "$work/out.txt" && { echo "FAIL it went on to compare"; fail=1; }

# --reuse with given tables: the study of TABLE against copies of itself
name=$(basename "${params%.params}")
mkdir -p "$work/reuse"
perturb() { awk -v col="$1" -v f="$2" '/^#/ || NF == 0 { print; next } { n++; if (n == 5) $col = sprintf("%.17g", $col * (1 + f)); print }' "$table"; }
# I_fNT 2 % off at x2: not a convergence.sh column, so the study passes (it failed before)
perturb 24 0.02 > "$work/reuse/$name-r2.dat"; cp "$table" "$work/reuse/$name-r4.dat"
conv --reuse "$params" "$work/reuse" "$table"
expect "I_fNT changed 2 % (not checked)" 0 '^ok: all checked columns within 0.005'
# T^f 1 % off: not converged, exit 1
perturb 21 0.01 > "$work/reuse/$name-r2.dat"
conv --reuse "$params" "$work/reuse" "$table"
expect "T^f changed 1 %" 1 '^FAIL: checked column\(s\) Tf exceed 0.005'
# the x4 table has other a values: the comparison fails, exit 4
cp "$table" "$work/reuse/$name-r2.dat"
awk '/^#/ || NF == 0 { print; next } { n++; if (n == 3) $1 = $1 * 1.5; print }' "$table" > "$work/reuse/$name-r4.dat"
conv --reuse "$params" "$work/reuse" "$table"
expect "x4 table with another a" 4 '^convergence.sh: error: compare-tables.sh failed'
# a base table that cannot be read: exit 3 before any run
conv --reuse "$params" "$work/reuse" "$work/no-such.dat"
expect "unreadable base" 3 '^convergence.sh: error: cannot read'
# --reuse after the files is the same option (it was taken for a file name: 'cannot read --reuse');
# given twice, or an unknown option, is a usage error
conv "$params" "$work/reuse" "$work/no-such.dat" --reuse
expect "--reuse last" 3 "^convergence.sh: error: cannot read $work/no-such.dat"
conv --reuse "$params" "$work/reuse" --reuse
expect "--reuse twice" 2 '^convergence.sh: error: --reuse given twice'
conv --refine 2 "$params" "$work/reuse"
expect "unknown option" 2 "^convergence.sh: error: unknown option '--refine'"
exit $fail
