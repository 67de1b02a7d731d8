#!/bin/bash
# check-user-file.sh <build-dir> <fortran-compiler> <work-dir>
# ctest abaqus_user_file_compiles: makes the one-file Abaqus sources (Standard and Explicit) with
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
for solver in standard explicit; do
   if [ $solver = standard ]; then entry=umat_; hook=stdb_abqerr_; else entry=vumat_; hook=xplb_abqerr_; fi
   "$here/make-user-file.sh" --$solver --build-dir "$build_dir" -o interphase_abaqus_$solver.f90
   "$fc" -c -std=f2008 -fimplicit-none -frecursive -ffree-line-length-132 -Wall -Wextra -Werror \
      -Wno-unused-dummy-argument -Wimplicit-interface interphase_abaqus_$solver.f90 -o $solver.o
   undefined=$(nm -u $solver.o | awk '{print $2}')
   if grep -qi interphase <<< "$undefined"; then
      echo "FAILED: $solver: undefined interphase symbols:" $(grep -i interphase <<< "$undefined")
      status=1
   fi
   if ! grep -qx $hook <<< "$undefined"; then
      echo "FAILED: $solver: the hook does not call $hook"
      status=1
   fi
   if ! nm $solver.o | grep -q " T $entry\$"; then
      echo "FAILED: $solver: $entry is not defined"
      status=1
   fi
   echo "$solver: interphase_abaqus_$solver.f90 compiles alone; undefined outside the runtime:" \
      $(grep -v -E '^_gfortran|^(mem|str)[a-z]+$|^(malloc|free|realloc|hypot|log|exp|sqrt|pow)$' <<< "$undefined")
done
exit $status
