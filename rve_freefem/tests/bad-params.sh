#!/usr/bin/env bash
# bad-params.sh WORKDIR -- bad input must stop with a clear message and a non-zero exit code,
# both through make-table.sh and when rve.edp is run directly.
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$1
mkdir -p "$work" || exit 3
# (a small valid RVE: the edits below make it bad; its comment lines dropped)
good=$(grep -v '^#' "$here/tests/two-cracks.params")
fail=0
# case NAME EXPECTED-MESSAGE-REGEX sed-expression-applied-to-good
case_() {
  local name=$1 pat=$2 expr=$3
  printf '%s\n' "$good" | sed "$expr" > "$work/$name.params"
  bash "$here/make-table.sh" "$work/$name.params" "$work/$name.dat" > "$work/$name.out" 2>&1
  local rc=$?
  if [ $rc -ne 0 ] && grep -Eq "$pat" "$work/$name.out" && [ ! -e "$work/$name.dat" ]; then
    echo "ok   $name: exit $rc: $(grep -m1 -E "$pat" "$work/$name.out")"
  else
    echo "FAIL $name: exit $rc, output:"; cat "$work/$name.out"; fail=1
  fi
}
case_ a_gt_b          "a must not exceed b"            's/^a_over_b_list = .*/a_over_b_list = 0.4 0.5 1.2/'
case_ a_mm_gt_b       "a = 30 > b"                     '$a a_list_mm = 30'
case_ nu_half         "Poisson.s ratio must be < 0.5"  's/^nu_m = .*/nu_m = 0.5/'
case_ nu_big          "Poisson.s ratio must be < 0.5"  's/^nu_b = .*/nu_b = 0.7/'
case_ hm_zero         "'h_m' = 0 must be positive"     's/^h_m = .*/h_m = 0/'
case_ hb_negative     "'h_b' = -3 must be positive"    's/^h_b = .*/h_b = -3/'
case_ b_negative      "'b' = -25 must be positive"     's/^b = .*/b = -25/'
case_ E_zero          "'E_b' = 0 must be positive"     's/^E_b = .*/E_b = 0/'
case_ E_negative      "'E_m' = -1000 must be positive" 's/^E_m = .*/E_m = -1000/'
case_ hmax_negative   "'hmax' = -1 must be positive"   's/^hmax = .*/hmax = -1/'
case_ not_a_number    "is not a number"                's/^E_m = .*/E_m = soft/'
case_ missing_key     "'nu_b' missing"                 '/^nu_b/d'
case_ unknown_key     '^make-table.sh: error: .*unknown_key[.]params:[0-9]+: unknown key "thickness"$' '$a thickness = 3'
case_ syntax          '^make-table.sh: error: .*syntax[.]params:[0-9]+: expected key = value' '$a h_m 2'
case_ ligament_tiny   'too short for this mesh .*[(]this crack length: [^)]*ligament_tiny[.]params:[0-9]+: a_over_b_list[)]$' 's/^a_over_b_list = .*/a_over_b_list = 0.5 0.999999/'
case_ E_infinite      "'E_m' = '1e400' is not a finite number" 's/^E_m = .*/E_m = 1e400/'
case_ E_huge          "'E_b' = '1e200' is out of range"  's/^E_b = .*/E_b = 1e200/'
case_ E_underflow     "'E_m' = '1e-400' is out of range" 's/^E_m = .*/E_m = 1e-400/'
case_ nu_underflow    "'nu_m' = '-1e-400' is out of range" 's/^nu_m = .*/nu_m = -1e-400/'
case_ list_underflow  "a_over_b_list: value = '1e-400' is out of range" 's/^a_over_b_list = .*/a_over_b_list = 1e-400 0.5/'
case_ d_exponent      "'hmax' = '1d0' is not a number here: write the exponent with e" 's/^hmax = .*/hmax = 1d0/'
case_ list_empty      "a_over_b_list is empty"         's/^a_over_b_list = .*/a_over_b_list =/'
case_ three_rows      "a_over_b_uniform = 0.1 0.1 5: 1 distinct .* 3 rows, but it needs at least 4" 's/^a_over_b_list = .*/a_over_b_uniform = 0.1 0.1 5/'
# the ranges of ligament_over_b and a_over_b_uniform: the value and the condition it fails named
case_ ligament_from   "ligament_over_b = 2 0.1 3: from = 2 must lie in [(]0, 1[]]" 's/^a_over_b_list = .*/ligament_over_b = 2 0.1 3/'
case_ ligament_to     "ligament_over_b = 0.1 0 3: to = 0 must be > 0" 's/^a_over_b_list = .*/ligament_over_b = 0.1 0 3/'
case_ ligament_order  "ligament_over_b = 0.1 0.5 3: to = 0.5 exceeds from = 0.1" 's/^a_over_b_list = .*/ligament_over_b = 0.1 0.5 3/'
case_ ligament_decade "ligament_over_b = 0.1 0.01 0.5: per-decade = 0.5 must be >= 1" 's/^a_over_b_list = .*/ligament_over_b = 0.1 0.01 0.5/'
case_ uniform_step    "a_over_b_uniform = 0.1 0.5 0: step = 0 must be > 0" 's/^a_over_b_list = .*/a_over_b_uniform = 0.1 0.5 0/'
case_ uniform_start   "a_over_b_uniform = -0.1 0.5 0.1: start = -0.1 must be >= 0" 's/^a_over_b_list = .*/a_over_b_uniform = -0.1 0.5 0.1/'
case_ uniform_stop    "a_over_b_uniform = 0.1 1.5 0.1: stop = 1.5 must be <= 1" 's/^a_over_b_list = .*/a_over_b_uniform = 0.1 1.5 0.1/'
case_ uniform_order   "a_over_b_uniform = 0.5 0.1 0.1: start = 0.5 exceeds stop = 0.1" 's/^a_over_b_list = .*/a_over_b_uniform = 0.5 0.1 0.1/'
case_ grow_one        "grow = 1, ftip = 0.05, .* at a = 0.05 mm the mesh would need 10000 elements along the interface" 's/^grow = .*/grow = 1/; $a a_list_mm = 0.05'
case_ huni_b          "'huni' = 0.3: the uniform mesh needs b = 25 to be a whole multiple of huni" '$a huni = 0.3'
case_ huni_a          "'huni' = 1: the crack half-lengths a = 12.5 mm are not multiples of huni" '$a huni = 1'
# --a-over-b: a = 0 and a = b are added, and the table still needs 4 rows
printf '%s\n' "$good" > "$work/good.params"
bash "$here/make-table.sh" --a-over-b "0.3" "$work/good.params" "$work/x.dat" > "$work/aob.out" 2>&1
rc=$?
if [ $rc -eq 2 ] && grep -q -- '--a-over-b "0.3": 1 distinct .* 3 rows' "$work/aob.out" && [ ! -e "$work/x.dat" ]; then echo "ok   a_over_b_one_value: exit $rc"; else echo "FAIL a_over_b_one_value (exit $rc)"; cat "$work/aob.out"; fail=1; fi
# option values: an underflowing --refine, --jobs beyond the shell's integers (--check: no FreeFEM run)
for opt in "--refine 1e-400|--refine = '1e-400' is out of range" \
           "--jobs 99999999999999999999|--jobs = 99999999999999999999 is too large" \
           "--jobs 0|--jobs = 0 must be >= 1" \
           "--refine 2 --refine 4|--refine given twice" \
           "--jobs 2 --jobs 2|--jobs given twice" \
           "--check|--check given twice"; do
  args=${opt%%|*}; pat=${opt#*|}
  bash "$here/make-table.sh" --check $args "$work/good.params" > "$work/opt.out" 2>&1
  rc=$?
  if [ $rc -eq 2 ] && grep -q -- "$pat" "$work/opt.out"; then echo "ok   $args: exit 2"; else echo "FAIL $args (exit $rc)"; cat "$work/opt.out"; fail=1; fi
done
# --check names a misspelt key as every other error: "make-table.sh: error: FILE:LINE: ..."
printf '%s\nhtipmx = 0.01\n' "$good" > "$work/misspelt.params"
bash "$here/make-table.sh" --check "$work/misspelt.params" > "$work/opt.out" 2>&1
rc=$?
if [ $rc -eq 2 ] && grep -Eq '^make-table.sh: error: .*misspelt[.]params:[0-9]+: unknown key "htipmx"$' "$work/opt.out"; then echo "ok   --check, a misspelt key: exit 2"; else echo "FAIL --check, a misspelt key (exit $rc)"; cat "$work/opt.out"; fail=1; fi
# leading zeros: --jobs 00002 and 08 are 2 and 8
for args in "--jobs 00002" "--jobs 08"; do
  bash "$here/make-table.sh" --check $args "$work/good.params" > "$work/opt.out" 2>&1
  rc=$?
  if [ $rc -eq 0 ]; then echo "ok   $args: exit 0"; else echo "FAIL $args (exit $rc)"; cat "$work/opt.out"; fail=1; fi
done
# Windows line ends: the same file is good (--check: the parameters only, no FreeFEM run)
printf '%s\n' "$good" | sed 's/$/\r/' > "$work/crlf.params"
bash "$here/make-table.sh" --check "$work/crlf.params" > "$work/crlf.out" 2>&1
rc=$?
if [ $rc -eq 0 ] && grep -q "parameters ok (4 crack half-lengths" "$work/crlf.out"; then echo "ok   crlf_line_ends: exit 0"; else echo "FAIL crlf_line_ends (exit $rc)"; cat "$work/crlf.out"; fail=1; fi
# --help: the comment block at the top, no line of code
bash "$here/make-table.sh" --help > "$work/help.out" 2>&1
rc=$?
if [ $rc -eq 0 ] && grep -q "^Options:" "$work/help.out" && grep -q "Exit code" "$work/help.out" \
   && ! grep -q -e "set -u" -e "LC_ALL" -e '^#' "$work/help.out"; then echo "ok   help: exit 0, $(wc -l < "$work/help.out") lines"; else echo "FAIL help (exit $rc)"; cat "$work/help.out"; fail=1; fi
# unreadable parameter file
bash "$here/make-table.sh" "$work/does-not-exist.params" "$work/x.dat" > "$work/nofile.out" 2>&1
rc=$?
if [ $rc -ne 0 ] && grep -q "cannot read parameter file" "$work/nofile.out"; then echo "ok   missing_file: exit $rc"; else echo "FAIL missing_file"; cat "$work/nofile.out"; fail=1; fi
mkdir -p "$work/a-directory.params"
bash "$here/make-table.sh" "$work/a-directory.params" "$work/x.dat" > "$work/dir.out" 2>&1
rc=$?
if [ $rc -ne 0 ] && grep -q "cannot read parameter file" "$work/dir.out"; then echo "ok   directory_as_file: exit $rc"; else echo "FAIL directory_as_file"; cat "$work/dir.out"; fail=1; fi
# the output named like the parameter file (or its diag file): refused before any run, the
# parameter file left as it was
printf '%s\n' "$good" > "$work/self.params"; cp "$work/self.params" "$work/self-diag.txt"
for args in "$work/self.params $work/self.params" "$work/self-diag.txt $work/self.dat"; do
  # shellcheck disable=SC2086
  set -- $args
  cp "$1" "$work/before.params"
  bash "$here/make-table.sh" "$1" "$2" > "$work/self.out" 2>&1; rc=$?
  if [ $rc -eq 2 ] && grep -q "is the parameter file" "$work/self.out" && cmp -s "$1" "$work/before.params" && [ ! -e "$work/self.dat" ]; then
    echo "ok   output_is_params ($(basename "$1") $(basename "$2")): exit $rc"
  else
    echo "FAIL output_is_params ($args): exit $rc"; cat "$work/self.out"; fail=1
  fi
done
# rve.edp itself validates its arguments
printf '1\n30\n' > "$work/a.count"
for args in "-nub 0.5" "-hm -2" "-Em 0" "-ftipp 0.05" "-Em 2500x" "-Em 1-2" "-Em 1e" "-Em ." "-Em 1e+" "-Em -" ; do
  FreeFem++ -nw -v 0 "$here/rve.edp" -hm 2 -hb 3 -b 25 -Em 1000 -num 0.15 -Eb 16000 -nub 0.15 $args -alist "$work/a.count" -out "$work/rows" > "$work/edp.out" 2>&1
  rc=$?
  if [ $rc -eq 2 ] && grep -q "rve.edp: error:" "$work/edp.out"; then echo "ok   rve.edp $args: exit 2: $(grep -m1 'rve.edp: error' "$work/edp.out")"; else echo "FAIL rve.edp $args (exit $rc)"; cat "$work/edp.out"; fail=1; fi
done
# (the messages of the malformed numbers, and the unknown key)
for args in "-Em 2500x" "-Em 1-2" "-Em 1e" "-Em ." ; do
  FreeFem++ -nw -v 0 "$here/rve.edp" -hm 2 -hb 3 -b 25 -Em 1000 -num 0.15 -Eb 16000 -nub 0.15 $args -alist "$work/a.count" -out "$work/rows" > "$work/edp.out" 2>&1
  if grep -q "is not a number" "$work/edp.out"; then echo "ok   rve.edp $args: not a number"; else echo "FAIL rve.edp $args: no 'is not a number'"; cat "$work/edp.out"; fail=1; fi
done
FreeFem++ -nw -v 0 "$here/rve.edp" -hm 2 -hb 3 -b 25 -Em 1000 -num 0.15 -Eb 16000 -nub 0.15 -ftipp 0.05 -alist "$work/a.count" -out "$work/rows" > "$work/edp.out" 2>&1
if grep -q "unknown argument -ftipp" "$work/edp.out"; then echo "ok   rve.edp -ftipp: unknown argument"; else echo "FAIL rve.edp -ftipp"; cat "$work/edp.out"; fail=1; fi
# well-formed numbers are read (the run stops later, at a = 30 > b)
for args in "-Em 1.5e+3" "-Em +1000." "-Em .5e4" "-Em 1E3" ; do
  FreeFem++ -nw -v 0 "$here/rve.edp" -hm 2 -hb 3 -b 25 -Em 1000 -num 0.15 -Eb 16000 -nub 0.15 $args -alist "$work/a.count" -out "$work/rows" > "$work/edp.out" 2>&1
  rc=$?
  if [ $rc -eq 2 ] && grep -q "> b" "$work/edp.out"; then echo "ok   rve.edp $args: read"; else echo "FAIL rve.edp $args (exit $rc)"; cat "$work/edp.out"; fail=1; fi
done
FreeFem++ -nw -v 0 "$here/rve.edp" -hm 2 -hb 3 -b 25 -Em 1000 -num 0.15 -Eb 16000 -nub 0.15 -alist "$work/a.count" -out "$work/rows" > "$work/edp.out" 2>&1
rc=$?
if [ $rc -eq 2 ] && grep -q "> b" "$work/edp.out"; then echo "ok   rve.edp a > b: exit 2: $(grep -m1 'rve.edp: error' "$work/edp.out")"; else echo "FAIL rve.edp a > b (exit $rc)"; cat "$work/edp.out"; fail=1; fi
FreeFem++ -nw -v 0 "$here/rve.edp" -hm 2 -hb 3 -b 25 -Em 1000 -num 0.15 -Eb 16000 -nub 0.15 -alist "$work/none.count" -out "$work/rows" > "$work/edp.out" 2>&1
rc=$?
if [ $rc -ne 0 ]; then echo "ok   rve.edp unreadable a-list: exit $rc"; else echo "FAIL rve.edp unreadable a-list"; fail=1; fi
exit $fail
