#!/usr/bin/env bash
# Install the build tree into a scratch prefix, then import the installed package with only
# PYTHONPATH=<prefix>/<python dir> (no INTERPHASE_LIBRARY) and replay a history: the package
# must load the installed libinterphase.so by itself, not the build tree's.
# Usage: check-install.sh CMAKE BUILD_DIR WORK_DIR CONFIG PYTHON_DIR SKIP_CODE
set -euo pipefail
cmake=$1 build=$2 work=$3 config=$4 python_dir=$5 skip=$6
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
prefix=$work/prefix
"$cmake" --install "$build" --prefix "$prefix" --config "$config" >/dev/null
unset INTERPHASE_LIBRARY
export PYTHONPATH=$prefix/$python_dir
cd "$work"
exec bash "$here/run-python.sh" "$skip" -c '
import os, sys
import interphase
prefix = os.path.realpath(sys.argv[1])
assert os.path.realpath(interphase.__file__).startswith(prefix), interphase.__file__
assert os.path.realpath(interphase.library_path).startswith(prefix), interphase.library_path
m = interphase.Material(model="simplified", damage_law="displacement", mu=0.75, s0_n=0.00044,
                        sf_n=0.04, s0_t=0.00072, sf_t=0.06, k_n=482.7, k_t=198.8)
r = m.run([[0, 0], [0.05, 0]], increments=50)
assert r.damage[-1] == 1.0
print("installed package", interphase.__file__, "with", interphase.library_path)
' "$prefix"
