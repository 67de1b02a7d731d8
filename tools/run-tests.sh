#!/usr/bin/env bash
# Build interphase and run every test: a strict Debug build (-std=f2008 -Wall -Wextra
# -fcheck=all, warnings are errors) with the full ctest suite, then an optimised Release build
# (warnings are errors) with the suite except the slow RVE (FreeFEM) tests. Both runs include
# the Python package's suites (ctest label python, docs/python.md).
# Usage: tools/run-tests.sh [BUILD_ROOT]   (default: ./build)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
root=${1:-$here/build}
jobs=$(nproc 2>/dev/null || echo 2)

bash "$here/tools/ensure-packages.sh" freefem gnuplot pkgconfig numpy scipy matplotlib pytest

for type in Debug Release; do
  dir="$root/${type,,}"
  echo "== $type build in $dir"
  cmake -S "$here" -B "$dir" -DCMAKE_BUILD_TYPE=$type -DINTERPHASE_WERROR=ON \
    -DINTERPHASE_CALCULIX_CACHE="$root/calculix" >/dev/null
  cmake --build "$dir" -j "$jobs"
  if [ "$type" = Debug ]; then
    ctest --test-dir "$dir" --output-on-failure -j "$jobs"
  else
    ctest --test-dir "$dir" --output-on-failure -j "$jobs" -LE "rve|calculix"
  fi
done
