#!/usr/bin/env bash
# Does `umat` hand its calls to the right update? The UMAT's four 2-D paths of their own
# (src/abaqus/interphase_umat_simplified.f90, interphase_umat_micromechanical.f90 for the
# displacement law, interphase_umat_simplified_fracture.f90,
# interphase_umat_micromechanical_fracture.f90 for the fracture law) return the general path's
# numbers bit for bit by design (tests/test_umat_simplified_path.f90), so no result shows
# whether `umat` calls them at all, or goes on to the general path after them: only the call
# graph does. This check runs the UMAT benchmark (drivers/bench_umat.f90) under valgrind's
# callgrind, which counts every call exactly, and reads from its output how often `umat_` called
# each path's `cohesive_path` and the general path's update (the kernel's `update_point`),
# against how often `umat_` itself was called:
#   case 1 (simplified model, displacement law, 2-D):      the simplified path every call, the general path never;
#   case 3 (micromechanical model, displacement law, 2-D): the micromechanical path every call, the general path never;
#   case 5 (simplified model, fracture law, 2-D):          its fracture path every call, the general path never;
#   case 7 (micromechanical model, fracture law, 2-D):     its fracture path every call, the general path never;
#   case 2 (simplified model, displacement law, 3-D) and case 6 (fracture law, 3-D): the general
#   path every call, no path (which also shows that the check sees the general path's calls).
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

# expect CASE SIMPLIFIED MICROMECHANICAL SIMPLIFIED_FRACTURE MICROMECHANICAL_FRACTURE GENERAL: the
# four paths' and the general path's calls, each "all" (every umat_ call) or "none"
expect() {
  local case=$1 out="$work/cg.$1" umat simplified micro simplified_fracture micro_fracture general name want got
  if ! valgrind --tool=callgrind --compress-strings=no --compress-pos=no --callgrind-out-file="$out" \
       "$bench" "$calls" 1 "$case" >"$work/log.$case" 2>&1; then
    echo "check_umat_dispatch: case $case: the benchmark failed under valgrind:" >&2
    tail -n 20 "$work/log.$case" >&2
    failed=1
    return
  fi
  umat=$(calls_to "$out" '*' '^umat_$')
  # (a module's procedure: __MODULE_MOD_NAME with gfortran, _QMmodulePname with flang)
  simplified=$(calls_to "$out" umat_ 'interphase_umat_simplified(_MOD_|P)cohesive_path')
  micro=$(calls_to "$out" umat_ 'interphase_umat_micromechanical(_MOD_|P)cohesive_path')
  simplified_fracture=$(calls_to "$out" umat_ 'interphase_umat_simplified_fracture(_MOD_|P)cohesive_path')
  micro_fracture=$(calls_to "$out" umat_ 'interphase_umat_micromechanical_fracture(_MOD_|P)cohesive_path')
  general=$(calls_to "$out" umat_ 'interphase_kernel.*update_point')
  if [ "$umat" -lt "$calls" ]; then
    echo "FAIL case $case: callgrind saw $umat calls of umat_, the benchmark makes at least $calls" \
         "(symbol names not recognised?)"
    failed=1
    return
  fi
  for name in simplified micro simplified_fracture micro_fracture general; do
    case "$name" in
      simplified) want=$2; got=$simplified ;;
      micro) want=$3; got=$micro ;;
      simplified_fracture) want=$4; got=$simplified_fracture ;;
      micro_fracture) want=$5; got=$micro_fracture ;;
      general) want=$6; got=$general ;;
    esac
    if { [ "$want" = all ] && [ "$got" -ne "$umat" ]; } || { [ "$want" = none ] && [ "$got" -ne 0 ]; }; then
      echo "FAIL case $case: umat_ called $umat times, the $name update $got times (expected: $want)"
      failed=1
    fi
  done
  echo "case $case: umat_ $umat calls; simplified path $simplified, micromechanical path $micro," \
       "simplified fracture path $simplified_fracture, micromechanical fracture path $micro_fracture," \
       "general path (update_point) $general"
}

expect 1 all none none none none
expect 3 none all none none none
expect 5 none none all none none
expect 7 none none none all none
expect 2 none none none none all
expect 6 none none none none all
if [ "$failed" -ne 0 ]; then
  echo "check_umat_dispatch: FAILED" >&2
  exit 1
fi
echo "check_umat_dispatch: every call took the expected update"
