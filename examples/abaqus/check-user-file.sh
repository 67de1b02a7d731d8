#!/bin/bash
# check-user-file.sh <build-dir> <fortran-compiler> <work-dir>
# ctest abaqus_user_file_compiles: makes the one-file Abaqus sources (Standard and Explicit, each
# without and with its start-of-analysis hook UEXTERNALDB / VEXTERNALDB; and CalculiX's, whose
# message hook calls the C library's exit and which defines interphase_calculix_start) with
# make-user-file.sh and compiles each ALONE with the strict flags (-c, no module path, no include
# path), proving it is self-contained; then checks that the object leaves undefined only Abaqus's
# message routine, the Fortran/C runtime and LAPACK -- no interphase symbol.
set -euo pipefail
build_dir=$1
fc=$2
work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
cd "$work"
status=0
for variant in standard explicit standard-externaldb explicit-externaldb calculix; do
   solver=${variant%-externaldb}
   extra=()
   if [ "$variant" != "$solver" ]; then extra=(--uexternaldb); fi
   if [ $solver = standard ]; then entry=umat_; hook=stdb_abqerr_; db=uexternaldb_
   elif [ $solver = calculix ]; then entry=umat_; hook=exit; db=interphase_calculix_start
   else entry=vumat_; hook=xplb_abqerr_; db=vexternaldb_; fi
   "$here/make-user-file.sh" --$solver "${extra[@]}" --build-dir "$build_dir" -o interphase_abaqus_$variant.f90
   "$fc" -c -std=f2008 -fimplicit-none -frecursive -ffree-line-length-132 -Wall -Wextra -Werror \
      -Wno-unused-dummy-argument -Wimplicit-interface interphase_abaqus_$variant.f90 -o $variant.o
   # nm's output is read whole first: under pipefail, grep -q closing the pipe early would make
   # nm die of SIGPIPE and the test fail at random
   symbols=$(nm $variant.o)
   if { [ "$variant" != "$solver" ] || [ $solver = calculix ]; } && ! grep -q " T $db\$" <<< "$symbols"; then
      echo "FAILED: $variant: $db is not defined"
      status=1
   fi
   solver_o=$variant.o
   undefined=$(nm -u $solver_o | awk '{print $2}')
   if grep -qi interphase <<< "$undefined"; then
      echo "FAILED: $solver: undefined interphase symbols:" $(grep -i interphase <<< "$undefined")
      status=1
   fi
   if ! grep -qx $hook <<< "$undefined"; then
      echo "FAILED: $solver: the hook does not call $hook"
      status=1
   fi
   if ! grep -q " T $entry\$" <<< "$symbols"; then
      echo "FAILED: $solver: $entry is not defined"
      status=1
   fi
   echo "$variant: interphase_abaqus_$variant.f90 compiles alone; undefined outside the runtime:" \
      $(grep -v -E '^_gfortran|^(mem|str)[a-z]+$|^(malloc|free|realloc|hypot|log|exp|sqrt|pow)$' <<< "$undefined")
done
exit $status
