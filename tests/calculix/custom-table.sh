#!/bin/bash
# ctest calculix_custom_table: libINTERPHASE.so loads the custom RVE table named by
# INTERPHASE_TABLE when ccx opens it (src/abaqus/calculix_start.c; CalculiX calls no UEXTERNALDB).
# The 2-D micromechanical couplet with PROPS(8) = 1 and INTERPHASE_TABLE = tables/paper.dat must
# give the built-in table's curve, the same CSV digit for digit (the built-in table is compiled from
# that file), and
# a table that cannot be read must stop the run with a message naming the file; a table named
# relative to the caller's folder is found although ccx runs in the output folder.
#   custom-table.sh <repository> <cache> <work>
set -uo pipefail
root=$(cd "$1" && pwd)
cache=$2
work=$3
# no ccx here (calculix_build skipped): skip too, but not in CI
if [ ! -x "$cache/ccx" ] || [ ! -f "$cache/libINTERPHASE.so" ]; then
   if [ "${CI:-}" = true ]; then echo "FAILED: no ccx or libINTERPHASE.so in $cache (calculix_build)"; exit 1; fi
   echo "SKIP: no ccx or libINTERPHASE.so in $cache (calculix_build could not build them here)"; exit 77
fi
cache=$(cd "$cache" && pwd)
rm -rf "$work"
mkdir -p "$work"
cd "$work"
cx=$root/examples/calculix
deck=$cx/decks/couplet2d-micromechanical-monotonic.inp
sed 's/^2., 1., 0.75, 0.00044, 0.04, 0.00072, 0.06, 0.$/2., 1., 0.75, 0.00044, 0.04, 0.00072, 0.06, 1./' "$deck" > custom.inp
grep -q "^2., 1., 0.75, 0.00044, 0.04, 0.00072, 0.06, 1.$" custom.inp || { echo "FAILED: no table selector to set in $deck"; exit 1; }
status=0
bash "$cx/run-case.sh" "$deck" --cache-dir "$cache" --output-dir builtin --no-plot > /dev/null || { echo "FAILED: built-in run"; exit 1; }
INTERPHASE_TABLE=$root/tables/paper.dat bash "$cx/run-case.sh" custom.inp --cache-dir "$cache" --output-dir custom --no-plot \
   > /dev/null || { echo "FAILED: custom-table run"; exit 1; }
grep -q "custom RVE table loaded from .*tables/paper.dat" custom/custom.log || { echo "FAILED: no load message"; status=1; }
if cmp -s builtin/couplet2d-micromechanical-monotonic.csv custom/custom.csv; then
   echo "the custom table tables/paper.dat gives the built-in table's curve (the same CSV)"
else
   echo "FAILED: the custom-table curve differs from the built-in one"; status=1
fi
# a table named relative to the caller's folder (run-case.sh runs ccx in the output folder)
mkdir -p tabledir
cp "$root/tables/paper.dat" tabledir/paper.dat
if INTERPHASE_TABLE=tabledir/paper.dat bash "$cx/run-case.sh" custom.inp --cache-dir "$cache" --output-dir relative \
      --no-plot > relative.out 2>&1 && cmp -s builtin/couplet2d-micromechanical-monotonic.csv relative/custom.csv; then
   echo "a relative INTERPHASE_TABLE is the caller's: the same CSV"
else
   echo "FAILED: INTERPHASE_TABLE=tabledir/paper.dat with --output-dir relative: $(tail -n 3 relative.out)"; status=1
fi
out=$(INTERPHASE_TABLE=$work/missing.dat bash "$cx/run-case.sh" custom.inp --cache-dir "$cache" --output-dir missing --no-plot 2>&1)
if [ $? -eq 1 ] && grep -q "INTERPHASE_TABLE = .*missing.dat: RVE table file cannot be opened" <<< "$out"; then
   echo "a missing table stops the run: $(grep -m 1 'ERROR in interphase' <<< "$out")"
else
   echo "FAILED: a missing table did not stop the run with its name: $out"; status=1
fi
exit $status
