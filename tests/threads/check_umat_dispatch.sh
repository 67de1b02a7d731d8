#!/usr/bin/env bash
# Does `umat` hand its calls to the right update? The UMAT's paths of their own (for the 2-D
# cohesive element src/abaqus/interphase_umat_simplified.f90, interphase_umat_micromechanical.f90
# for the displacement law, interphase_umat_simplified_fracture.f90,
# interphase_umat_micromechanical_fracture.f90 for the fracture law; for the 3-D element their
# twins, the same names with _3d) return the general path's numbers bit for bit by design
# (tests/test_umat_simplified_path.f90), so no result shows whether `umat` calls them at all, or
# goes on to the general path after them: only the call graph does. This check runs the UMAT
# benchmark (drivers/bench_umat.f90) under valgrind's callgrind, which counts every call exactly,
# and reads from its output how often `umat_` called each path's `cohesive_path` and the general
# path's update (the kernel's `update_point`), against how often `umat_` itself was called:
#   cases 1 and 2 (simplified model, displacement law, 2-D and 3-D): the simplified path of the
#   element every call, no other path, the general path never;
#   cases 3 and 4 (micromechanical model, displacement law): its path, as above;
#   cases 5 and 6 (simplified model, fracture law): its fracture path, as above;
#   cases 7 and 8 (micromechanical model, fracture law): its fracture path, as above;
#   cases 9 and 14 (cases 1 and 6 with an option constant at its default, NPROPS 10 and 14): the
#   general path every call, no path asked (which also shows that the check sees the general
#   path's calls);
#   cases 11 and 12 (cases 3 and 4 with the option, NPROPS 9: the simplified model's count): the
#   simplified path of the element asked at every call, which declines (another model), and
#   then the general path every call.
# Meant for a build without link-time optimisation or inlining across units (the Debug build),
# where each of these procedures is a call of its own; gfortran's and LLVM flang's symbol names
# are both recognised.
#
# Usage: check_umat_dispatch.sh BENCH      (BENCH: the interphase-bench executable)
# Without valgrind: a skip (exit status INTERPHASE_SKIP_CODE, 77 by default), a failure under
# strict CI, where the build sets INTERPHASE_SKIP_CODE=1.
set -euo pipefail
bench=${1:?usage: check_umat_dispatch.sh BENCH}
skip_code=${INTERPHASE_SKIP_CODE:-77}
if ! command -v valgrind >/dev/null 2>&1; then
  echo "INTERPHASE-SKIP: valgrind is not installed (Debian package valgrind; tools/ensure-packages.sh" \
       "valgrind installs it): umat's dispatch to its paths not checked"
  exit "$skip_code"
fi
if [ ! -x "$bench" ]; then
  echo "check_umat_dispatch: no executable $bench" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
calls=120
failed=0

# calls_to FILE CALLER CALLEE_REGEX: the calls callgrind recorded from the function named CALLER
# (any caller where CALLER is '*') to functions whose names match CALLEE_REGEX
calls_to() {
  awk -v caller="$2" -v callee="$3" '
    /^fn=/ { fn = substr($0, 4) }
    /^cfn=/ { cfn = substr($0, 5) }
    /^calls=/ {
      if ((caller == "*" || fn == caller) && cfn ~ callee) { split(substr($0, 7), f, " "); n += f[1] }
    }
    END { print n + 0 }' "$1"
}

# expect CASE PATH [ASKED]: the path that must take every umat_ call of the case, by the name of
# its module without interphase_umat_ (simplified, micromechanical, simplified_fracture,
# micromechanical_fracture, each maybe with _3d), or "general": every other path's calls must
# be none, and the general path's all (PATH general) or none; with ASKED (and PATH general)
# the path ASKED is called at every call too (and declines)
PATHS="simplified micromechanical simplified_fracture micromechanical_fracture simplified_3d micromechanical_3d
  simplified_fracture_3d micromechanical_fracture_3d"
expect() {
  local case=$1 want_path=$2 asked=${3:-} out="$work/cg.$1" umat general name got want summary
  if ! valgrind --tool=callgrind --compress-strings=no --compress-pos=no --callgrind-out-file="$out" \
       "$bench" "$calls" 1 "$case" >"$work/log.$case" 2>&1; then
    echo "check_umat_dispatch: case $case: the benchmark failed under valgrind:" >&2
    tail -n 20 "$work/log.$case" >&2
    failed=1
    return
  fi
  umat=$(calls_to "$out" '*' '^umat_$')
  if [ "$umat" -lt "$calls" ]; then
    echo "FAIL case $case: callgrind saw $umat calls of umat_, the benchmark makes at least $calls" \
         "(symbol names not recognised?)"
    failed=1
    return
  fi
  summary="case $case: umat_ $umat calls;"
  for name in $PATHS; do
    # (a module's procedure: __MODULE_MOD_NAME with gfortran, _QMmodulePname with flang; the
    # pattern is anchored at the module's name, which the 2-D path's names are prefixes of)
    got=$(calls_to "$out" umat_ "interphase_umat_${name}(_MOD_|P)cohesive_path")
    want=none
    [ "$name" = "$want_path" ] && want=all
    [ "$name" = "$asked" ] && want=all
    if { [ "$want" = all ] && [ "$got" -ne "$umat" ]; } || { [ "$want" = none ] && [ "$got" -ne 0 ]; }; then
      echo "FAIL case $case: umat_ called $umat times, the $name path $got times (expected: $want)"
      failed=1
    fi
    [ "$got" -ne 0 ] && summary="$summary $name path $got,"
  done
  general=$(calls_to "$out" umat_ 'interphase_kernel.*update_point')
  want=none
  [ "$want_path" = general ] && want=all
  if { [ "$want" = all ] && [ "$general" -ne "$umat" ]; } || { [ "$want" = none ] && [ "$general" -ne 0 ]; }; then
    echo "FAIL case $case: umat_ called $umat times, the general path (update_point) $general times (expected: $want)"
    failed=1
  fi
  echo "$summary general path (update_point) $general"
}

expect 1 simplified
expect 2 simplified_3d
expect 3 micromechanical
expect 4 micromechanical_3d
expect 5 simplified_fracture
expect 6 simplified_fracture_3d
expect 7 micromechanical_fracture
expect 8 micromechanical_fracture_3d
expect 9 general
expect 14 general
expect 11 general simplified
expect 12 general simplified_3d
if [ "$failed" -ne 0 ]; then
  echo "check_umat_dispatch: FAILED" >&2
  exit 1
fi
echo "check_umat_dispatch: every call took the expected update"
