#!/usr/bin/env bash
# reproduce.sh PARAMS COMMITTED.dat WORKDIR "a/b values" -- rerun some rows of a committed table
# with its own parameter file and mesh level and compare every column with the committed rows.
# Tolerance TOL_REPRODUCE (relative, see compare-tables.sh for the scale of zero columns): the
# run is deterministic, so only round-off of a different FreeFEM/UMFPACK/BLAS build may differ.
set -u
TOL_REPRODUCE=1e-7
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
params=$1; ref=$2; work=$3; alist=$4
mkdir -p "$work" || exit 3
bash "$here/make-table.sh" --no-fields --a-over-b "$alist" "$params" "$work/reproduced.dat" || exit 1
# the committed table must have been made with the same script and parameters
for key in h_m h_b b E_m nu_m E_b nu_b element hmax ftip htipmax grow fseg refine script_sha256; do
  r=$(grep -m1 "^# $key = " "$ref"); n=$(grep -m1 "^# $key = " "$work/reproduced.dat")
  if [ "$r" != "$n" ]; then
    echo "header differs: committed '$r', rerun '$n'"
    [ "$key" = script_sha256 ] && echo "(rve.edp changed since the table was made: regenerate the table)"
    exit 1
  fi
done
bash "$here/compare-tables.sh" --tol "$TOL_REPRODUCE" "$ref" "$work/reproduced.dat"
