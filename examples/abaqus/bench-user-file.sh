#!/bin/bash
# bench-user-file.sh: how fast is the one-file Abaqus/Explicit source with given compiler flags?
#
#   examples/abaqus/bench-user-file.sh [--build-dir DIR] [--work-dir DIR] ["FLAGS" ...]
#
# Writes the one-file source with make-user-file.sh --explicit, compiles it ALONE with each set of
# flags (as Abaqus compiles a user subroutine; gfortran, or $FC: LLVM flang too), links it with the driver
# bench_user_file.f90 (one block of 4096 points in the L2 cache, 2000 increments of a cyclic shear
# under compression, best of 5 runs) and LAPACK, and prints ns per point update for each set.
# Default flag sets: the recommended one (docs/abaqus.md; with gfortran also without GCC's
# inlining flags), -O3 -march=native without -fno-trapping-math (with flang: without
# -ffp-contract=off), and -O2. --build-dir: a configured and built interphase build directory
# (default ./build/release), for the generated sources of the built-in table.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build_dir=$PWD/build/release
work=${TMPDIR:-/tmp}/interphase-bench-user-file
fc=${FC:-gfortran}
flag_sets=()
while [ $# -gt 0 ]; do
   case "$1" in
      --build-dir) build_dir=$2; shift ;;
      --work-dir) work=$2; shift ;;
      -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
      *) flag_sets+=("$1") ;;
   esac
   shift
done
if [ ${#flag_sets[@]} -eq 0 ]; then
   case "$("$fc" --version 2>&1 | head -n 1)" in
      *flang*)  # LLVM flang: locals on the stack without a flag, no -fno-trapping-math
         flag_sets=("-O3 -march=native -ffp-contract=off"
                    "-O3 -march=native"
                    "-O2") ;;
      *)
         # (GCC's inlining flags: those of the CMake Release build, CMakeLists.txt)
         gcc_inline="--param=max-inline-insns-auto=400 --param=inline-unit-growth=200"
         gcc_inline+=" --param=large-function-growth=400 -fno-ipa-icf"
         flag_sets=("-O3 -march=native -fno-trapping-math -ffp-contract=off -frecursive $gcc_inline"
                    "-O3 -march=native -fno-trapping-math -ffp-contract=off -frecursive"
                    "-O3 -march=native -frecursive"
                    "-O2 -frecursive") ;;
   esac
fi
if [ ! -d "$build_dir/generated" ]; then
   echo "bench-user-file.sh: $build_dir is not a built interphase build directory (no generated/);" \
        "build one first: cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release && cmake --build build/release" >&2
   exit 2
fi
rm -rf "$work"
mkdir -p "$work"
"$here/make-user-file.sh" --explicit --build-dir "$build_dir" -o "$work/interphase_abaqus_explicit.f90" >/dev/null
for flags in "${flag_sets[@]}"; do
   mkdir -p "$work/obj"
   # the user file with the flags under test, then the driver (it uses the file's modules)
   # shellcheck disable=SC2086  # the flags are meant to split
   (cd "$work/obj" && "$fc" $flags -c ../interphase_abaqus_explicit.f90 -o user.o \
      && "$fc" -O2 -c "$here/bench_user_file.f90" -o driver.o)
   "$fc" "$work/obj/driver.o" "$work/obj/user.o" -llapack -lblas -o "$work/bench"
   printf '%-72s %s\n' "$flags" "$("$work/bench")"
   rm -rf "$work/obj"
done
