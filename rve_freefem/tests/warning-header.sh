#!/usr/bin/env bash
# warning-header.sh WORKDIR -- a warning of make-table.sh (here a mortar of 80 MPa, below the
# 100 MPa it warns of) is kept in the table's header as '# warning = ...', which check-table.sh
# and the loader read as provenance.  One FreeFEM run of the small two-crack RVE.
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$1
mkdir -p "$work" || exit 3
grep -v '^#' "$here/tests/two-cracks.params" | sed 's/^E_m = .*/E_m = 80/' > "$work/soft.params"
bash "$here/make-table.sh" "$work/soft.params" "$work/soft.dat" > "$work/make.out" 2>&1 \
  || { echo "FAIL make-table.sh (exit $?):"; cat "$work/make.out"; exit 1; }
pat="^# warning = .*soft[.]params:[0-9]+: 'E_m' = 80 MPa is softer than mortars and bricks usually are"
grep -Eq "$pat" "$work/soft.dat" || { echo "FAIL no '# warning =' line in the header:"; grep '^#' "$work/soft.dat" | head -20; exit 1; }
echo "ok   $(grep -m1 -E "$pat" "$work/soft.dat" | cut -c1-100)..."
bash "$here/check-table.sh" "$work/soft.dat" > "$work/check.out" 2>&1 \
  || { echo "FAIL check-table.sh refuses the table with its warning line:"; cat "$work/check.out"; exit 1; }
echo "ok   check-table.sh reads the table with its warning line"
