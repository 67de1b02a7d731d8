#!/usr/bin/env bash
# bench-compilers.sh: the UMAT and VUMAT benchmarks of a gfortran and an LLVM flang Release build,
# side by side in one session (docs/performance.md, "gfortran and flang").
#
#   tools/bench-compilers.sh [GFORTRAN_BUILD FLANG_BUILD]   (default: build/release build/flang-release)
#
# Sizes (smaller than the benchmarks' defaults: the flang build is far slower, docs/compilers.md):
# UMAT_CALLS calls per run and UMAT_RUNS runs (default 120000 and 3), VUMAT_POINTS points
# (default 4096), USER_FILE_FLAGS for flang's one-file source (default one set).
#
# Both build directories must be configured and built (tools/run-tests.sh makes them). Runs, in
# turn, each build's interphase-bench (UMAT, best of 5 per case) twice, alternating the builds;
# each build's interphase-bench-vumat (VUMAT, best of 5 per case) twice, alternating; then the
# one-file Abaqus/Explicit source (examples/abaqus/bench-user-file.sh) with each compiler's flag
# sets. Prints everything to standard output; times only, nothing is checked.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
gnu=${1:-$here/build/release}
llvm=${2:-$here/build/flang-release}
for dir in "$gnu" "$llvm"; do
  for exe in drivers/interphase-bench tests/threads/interphase-bench-vumat; do
    if [ ! -x "$dir/$exe" ]; then
      echo "bench-compilers.sh: $dir/$exe is missing: build both Release trees first (tools/run-tests.sh)" >&2
      exit 2
    fi
  done
done
compiler_of() { grep -m1 '^CMAKE_Fortran_COMPILER:' "$1/CMakeCache.txt" | cut -d= -f2; }
echo "== $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "== gfortran build: $gnu ($(compiler_of "$gnu"))"
echo "== flang build:    $llvm ($(compiler_of "$llvm"))"
for round in 1 2; do
  for dir in "$gnu" "$llvm"; do
    echo "== UMAT, round $round: $dir"
    "$dir/drivers/interphase-bench" "${UMAT_CALLS:-120000}" "${UMAT_RUNS:-3}"
  done
done
for round in 1 2; do
  for dir in "$gnu" "$llvm"; do
    echo "== VUMAT, round $round: $dir"
    "$dir/tests/threads/interphase-bench-vumat" "${VUMAT_POINTS:-4096}"
  done
done
echo "== one-file Abaqus/Explicit source, gfortran"
FC=$(compiler_of "$gnu") bash "$here/examples/abaqus/bench-user-file.sh" --build-dir "$gnu"
echo "== one-file Abaqus/Explicit source, flang"
FC=$(compiler_of "$llvm") bash "$here/examples/abaqus/bench-user-file.sh" --build-dir "$llvm" \
  "${USER_FILE_FLAGS:--O3 -march=native -ffp-contract=off}"
echo "== load at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
