#!/usr/bin/env bash
# Build interphase and run every test, with each supported compiler in turn:
#  1. gfortran: a strict Debug build (-std=f2008 -Wall -Wextra -fcheck=all, warnings are errors)
#     with the full ctest suite, then an optimised Release build (warnings are errors) with the
#     suite except the slow RVE (FreeFEM) and CalculiX tests (CalculiX: gfortran only);
#  2. LLVM flang 19 (flang-new-19, installed from Debian's flang-19 and libomp-19-dev when
#     missing and possible): the same two builds and suites in BUILD_ROOT/flang-debug and
#     BUILD_ROOT/flang-release (-std=f2018 -pedantic, warnings are errors).
# Every run includes the Python package's suites (ctest label python, docs/python.md).
# Where flang cannot be installed its part is skipped with a message; under CI=true that is a
# failure. Usage: tools/run-tests.sh [BUILD_ROOT]   (default: ./build)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
root=${1:-$here/build}
jobs=$(nproc 2>/dev/null || echo 2)

# flang is installed before the first build: the gfortran builds' one-file Abaqus source check
# (abaqus_user_file_compiles) compiles with every supported compiler found at configure time
bash "$here/tools/ensure-packages.sh" freefem gnuplot pkgconfig valgrind numpy scipy matplotlib pytest flang

# suite <compiler> <name prefix of the build directories>
suite() {
  local compiler=$1 prefix=$2 type dir
  for type in Debug Release; do
    dir="$root/$prefix${type,,}"
    echo "== $type build with $compiler in $dir"
    cmake -S "$here" -B "$dir" -DCMAKE_BUILD_TYPE=$type -DCMAKE_Fortran_COMPILER="$compiler" \
      -DINTERPHASE_WERROR=ON -DINTERPHASE_CALCULIX_CACHE="$root/calculix" >/dev/null
    cmake --build "$dir" -j "$jobs"
    if [ "$type" = Debug ]; then
      ctest --test-dir "$dir" --output-on-failure -j "$jobs"
    else
      ctest --test-dir "$dir" --output-on-failure -j "$jobs" -LE "rve|calculix"
    fi
  done
}

start=$SECONDS
suite "$(command -v gfortran)" ""
echo "== gfortran suite: $((SECONDS - start)) s"

if ! command -v flang-new-19 >/dev/null 2>&1; then
  if [ "${CI:-}" = true ]; then
    echo "run-tests: LLVM flang (flang-new-19) is not installed and could not be installed;" \
         "CI runs the suite with both compilers: failing" >&2
    exit 1
  fi
  echo "== LLVM flang suite SKIPPED: flang-new-19 is not installed and could not be installed" \
       "(as root: apt-get install flang-19 libomp-19-dev); the gfortran suite above passed"
  exit 0
fi
start=$SECONDS
suite "$(command -v flang-new-19)" flang-
echo "== LLVM flang suite: $((SECONDS - start)) s"
