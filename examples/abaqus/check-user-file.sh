#!/bin/bash
# check-user-file.sh <build-dir> <work-dir> <fortran-compiler>...
# ctest abaqus_user_file_compiles: makes the one-file Abaqus sources (Standard and Explicit, each
# without and with its start-of-analysis hook UEXTERNALDB / VEXTERNALDB; and CalculiX's, whose
# message hook calls the C library's exit and which defines interphase_calculix_start) with
# make-user-file.sh and compiles each ALONE, with each compiler given (gfortran and LLVM flang),
# with that compiler's strict flags (-c, no module path, no include path), proving it is
# self-contained; then checks that the object leaves undefined only Abaqus's message routine,
# the Fortran/C runtime and LAPACK -- no interphase symbol.
# A compiler given as "missing:NAME" was not found at configure time: the others are checked,
# then the script exits with $INTERPHASE_SKIP_CODE (77, a ctest skip; 1 under strict CI).
set -euo pipefail
build_dir=$1
work=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
cd "$work"
status=0
missing=()
# the strict flags of each compiler family (CMakeLists.txt has the same choice)
strict_flags() {
   case "$("$1" --version 2>&1 | head -n 1)" in
      *"GNU Fortran"*)
         echo "-std=f2008 -fimplicit-none -frecursive -ffree-line-length-132 -Wall -Wextra -Werror" \
              "-Wno-unused-dummy-argument -Wimplicit-interface" ;;
      *flang*) echo "-std=f2018 -pedantic -fimplicit-none -Werror" ;;
      *) echo "" ;;
   esac
}
for fc in "$@"; do
 if [ "${fc#missing:}" != "$fc" ]; then
   missing+=("${fc#missing:}")
   continue
 fi
 flags=$(strict_flags "$fc")
 if [ -z "$flags" ]; then
   echo "FAILED: $fc is neither gfortran nor LLVM flang"
   status=1
   continue
 fi
 mkdir -p "$work/$(basename "$fc")"
 cd "$work/$(basename "$fc")"
 echo "== $fc $flags"
 for variant in standard explicit standard-externaldb explicit-externaldb calculix; do
   solver=${variant%-externaldb}
   extra=()
   if [ "$variant" != "$solver" ]; then extra=(--uexternaldb); fi
   if [ $solver = standard ]; then entry=umat_; hook=stdb_abqerr_; db=uexternaldb_
   elif [ $solver = calculix ]; then entry=umat_; hook=exit; db=interphase_calculix_start
   else entry=vumat_; hook=xplb_abqerr_; db=vexternaldb_; fi
   "$here/make-user-file.sh" --$solver "${extra[@]}" --build-dir "$build_dir" -o interphase_abaqus_$variant.f90
   # shellcheck disable=SC2086  # the flags are meant to split
   "$fc" -c $flags interphase_abaqus_$variant.f90 -o $variant.o
   # nm's output is read whole first: under pipefail, grep -q closing the pipe early would make
   # nm die of SIGPIPE and the test fail at random
   symbols=$(nm $variant.o)
   if { [ "$variant" != "$solver" ] || [ $solver = calculix ]; } && ! grep -q " T $db\$" <<< "$symbols"; then
      echo "FAILED: $fc: $variant: $db is not defined"
      status=1
   fi
   solver_o=$variant.o
   undefined=$(nm -u $solver_o | awk '{print $2}')
   if grep -qi interphase <<< "$undefined"; then
      echo "FAILED: $fc: $solver: undefined interphase symbols:" $(grep -i interphase <<< "$undefined")
      status=1
   fi
   if ! grep -qx $hook <<< "$undefined"; then
      echo "FAILED: $fc: $solver: the hook does not call $hook"
      status=1
   fi
   if ! grep -q " T $entry\$" <<< "$symbols"; then
      echo "FAILED: $fc: $solver: $entry is not defined"
      status=1
   fi
   # (runtimes: libgfortran's _gfortran_*, flang's _Fortran*)
   echo "$variant: interphase_abaqus_$variant.f90 compiles alone with $(basename "$fc"); undefined outside the runtime:" \
      $(grep -v -E '^_gfortran|^_Fortran|^(mem|str)[a-z]+$|^(malloc|free|realloc|hypot|log|exp|sqrt|pow)$' <<< "$undefined")
 done
done
if [ $status -eq 0 ] && [ ${#missing[@]} -gt 0 ]; then
   echo "not checked: ${missing[*]} not found (install it: tools/ensure-packages.sh flang for LLVM flang)"
   exit "${INTERPHASE_SKIP_CODE:-77}"
fi
exit $status
